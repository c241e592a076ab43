// Certificates: interval enclosures of r_res, theta_first and t_first for v = qdot0 = 1
// (r_res scales linearly with v), with the obligations the proof rests on, and an independent
// checker.
//
// certify_pair (producer): fast floating point finds the answer (the lattice method in MPFR),
// interval arithmetic (MPFI) proves it:
//   local-root  interval Newton proves a unique root of q' in X and encloses r_res = |q| there;
//   basin       on Y around X, q' is strictly monotone with a sign change and z' != 0, so the
//               root is the only critical point of R in Y;
//   symmetry    the other minimisers are the exact images theta -> 2 pi - theta (and theta + pi
//               for odd tau, sigma), with equal R;
//   cover       R > r_hi^2 everywhere outside the basins: by bisection over every fast lobe
//               ("all-lobes", orders up to max_lobes), or, for x < 1/2, by the Rayleigh bound
//               away from the slow nodes plus bisection over the few lobes at each node
//               ("slow-nodes", up to max_nodes nodes, any order: (10^30+1, 10^30) has one node).
// Precision is adaptive: enclosures start at 64 bits and double until r_res, theta_first and
// t_first all have relative width <= 10^-digits (absolute for 0). The cover runs once, at
// cover_bits (the first level), against that level's r_hi.
// Degenerate pairs (delta = 2 mod 4) are certified by integer arithmetic (degenerate.hpp).
// If the cover cannot be completed (order too high, or an undecided box), the certificate says
// "not proved" and claims only r_res <= r_hi (a point of the trajectory attains it).
//
// check_certificate (checker): re-derives every obligation from the pair and the proof
// parameters (working bits, Y, strategy, Rayleigh t), never from the producer's numbers, and
// accepts only if each claim contains the checker's own enclosure, meets the stated digits, and
// every required obligation is present. The written argument: proofs/global-minimality.md.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/certify/proof_steps.hpp>

namespace gyrores {

inline constexpr const char* certificate_format = "gyrores-certificate/1";

struct certificate_obligation {
  std::string id;         // local-root, basin, symmetry, cover, rayleigh, degenerate
  std::string statement;  // what was proved, in words
  std::map<std::string, std::string> data;  // inputs and results, decimal strings
};

struct certificate {
  std::string format = certificate_format;
  big_int tau, sigma;
  unsigned digits = 0, working_bits = 0, cover_bits = 0;
  bool degenerate = false;
  bool global_minimality = false;  // false: only r_res <= r_res.second is claimed
  std::string global_minimality_note;
  std::pair<std::string, std::string> r_res, theta_first, t_first;  // empty strings when not claimed
  std::size_t minimiser_count = 0;                                   // 0 when not claimed
  std::vector<certificate_obligation> obligations;
};

struct certify_options {
  std::int64_t max_lobes = 20000;  // "all-lobes" cover up to this order tau + sigma
  std::int64_t max_nodes = 20000;  // "slow-nodes" cover up to this many nodes b = tau - sigma
  unsigned start_bits = 64;
  unsigned max_bits = 1u << 17;
};

namespace detail {

// Decimal digits printed for an enclosure computed at `bits` bits: all it carries, plus 3.
inline unsigned decimal_digits_for_bits(unsigned bits) { return bits_to_digits10(bits) + 3u; }

inline std::string dec_down(const mpfr_real& v, unsigned d) { return format_scientific(v, d, MPFR_RNDD); }
inline std::string dec_up(const mpfr_real& v, unsigned d) { return format_scientific(v, d, MPFR_RNDU); }

struct local_result {
  lobe_frame<big_int> frame;
  proof::I X, r, theta_first, t_first;
  std::vector<proof::image> images;
  std::vector<proof::I> thetas;
};

// The local part at the current MPFI/MPFR precision: guess by the lattice method, prove by
// interval Newton, enclose r, the minimiser images and the first one.
inline local_result local_enclosures(const resonant_pair<big_int>& p, const proof::constants& K) {
  using namespace proof;
  auto lat = inscribed_lattice<mpfr_real>(p, mpfr_real(1));
  local_result out;
  out.frame = {lat.first.k, lat.first.j, lat.first.m};
  I mu = mu_of(K, out.frame.m);
  P guess = lat.first.u;
  P scale = abs(guess);
  P floor = abs(interval_lower(mu)) / 1024;
  if (scale < floor) scale = floor;
  auto X = certify_root(K, mu, guess, scale);
  if (!X) throw compute_error("certify: interval Newton could not prove the root of q' near u = " +
                              format_scientific(guess, 20) + " for " + p.str());
  out.X = *X;
  out.r = abs_q_of(K, mu, out.X);
  out.images = images_of(K, out.frame.k, out.frame.j, p.strand_offset_min() == 2);
  for (auto& im : out.images) out.thetas.push_back(theta_of(K, im.k, im.negate_u ? I(-out.X) : out.X));
  std::size_t first = 0;
  for (std::size_t i = 0; i < out.thetas.size(); ++i)
    for (std::size_t j = 0; j < out.thetas.size(); ++j)
      if (i != j && !certainly_less(out.thetas[i], out.thetas[j]) && !certainly_less(out.thetas[j], out.thetas[i]))
        throw compute_error("certify: minimiser images of " + p.str() + " are not separated at " +
                            std::to_string(real_bits<P>()) + " bits");
  for (std::size_t i = 1; i < out.thetas.size(); ++i)
    if (certainly_less(out.thetas[i], out.thetas[first])) first = i;
  out.theta_first = out.thetas[first];
  out.t_first = K.c.sqrt_ts * out.theta_first;
  return out;
}

// Basins (u-intervals) per lobe k mod a, from the minimiser's Y and its images.
inline std::map<big_int, std::vector<proof::I>> basins_by_lobe(const proof::constants& K,
                                                                const std::vector<proof::image>& imgs,
                                                                const proof::I& Y) {
  std::map<big_int, std::vector<proof::I>> out;
  for (auto& im : imgs) out[int_mod(im.k, K.a)].push_back(im.negate_u ? proof::I(-Y) : Y);
  return out;
}

struct cover_result {
  bool proved = false;
  std::string strategy, note;
  std::string rayleigh_t;
  proof::cover_stats stats;
};

// The cover: R > bound outside the basins. strategy "" chooses; otherwise the given one is run
// with the given Rayleigh t (checker).
inline cover_result run_cover(const resonant_pair<big_int>& p, const proof::constants& K,
                              const std::map<big_int, std::vector<proof::I>>& basins, const proof::I& bound,
                              const certify_options& opt, const std::string& strategy, const std::string& t_text) {
  using namespace proof;
  cover_result res;
  const bool small_x = 2 * K.b < K.a;
  auto lobe_basins = [&](const big_int& k) {
    auto it = basins.find(int_mod(k, K.a));
    return it == basins.end() ? std::vector<I>{} : it->second;
  };
  std::string chosen = strategy;
  if (chosen.empty()) {
    if (small_x && K.b <= big_int(opt.max_nodes)) chosen = "slow-nodes";
    else if (K.a <= big_int(opt.max_lobes)) chosen = "all-lobes";
    else {
      res.note = "not proved: order " + K.a.str() + " above max_lobes and (x >= 1/2 or " + K.b.str() +
                 " slow nodes above max_nodes)";
      return res;
    }
  }
  res.strategy = chosen;
  if (chosen == "all-lobes") {
    if (K.a > big_int(opt.max_lobes) && strategy.empty()) return res;
    for (big_int k = 0; k < K.a; ++k) {
      auto L = lobe_at(K, k);
      if (!exclude_lobe(K, L, lobe_basins(k), bound, res.stats)) {
        res.note = "not proved: an undecided box in lobe k = " + k.str();
        return res;
      }
    }
    res.proved = true;
    return res;
  }
  if (chosen != "slow-nodes") {
    res.note = "unknown cover strategy '" + chosen + "'";
    return res;
  }
  if (!small_x) {
    res.note = "slow-nodes cover needs x < 1/2";
    return res;
  }
  // Rayleigh cut-off w1 = t x: for |w| >= w1 (|cos beta| >= sin w1), R >= lambda(sin^2 w1) > bound.
  P t;
  if (!t_text.empty()) {
    if (mpfr_set_str(t.backend().data(), t_text.c_str(), 10, MPFR_RNDN) != 0 || !(t > 0)) {
      res.note = "bad Rayleigh parameter t = '" + t_text + "'";
      return res;
    }
  } else {
    t = 1;
  }
  for (;;) {
    I w1 = I(t) * K.c.x;
    bool below_half_pi = certainly_less(w1, K.c.pi / 2);
    I c2 = interval_sqr(sin(w1));
    if (below_half_pi && certainly_less(bound, rayleigh_lower(K, interval_point(interval_lower(c2))))) break;
    if (!t_text.empty() || !below_half_pi) {
      res.note = "not proved: the Rayleigh bound at w1 = t x (t = " + format_scientific(t, 6) + ") does not exceed r_hi^2";
      return res;
    }
    t *= 2;
  }
  res.rayleigh_t = format_scientific(t, 6);
  // Lobes around node j: alpha/pi in [c_j - t/pi, c_j + t/pi], c_j = (2j+1) a/(2b) in [Q, Q+1).
  big_int spread = big_int(static_cast<long>(std::floor(static_cast<double>(t) / 3.0))) + 3;
  for (big_int j = 0; j < K.b; ++j) {
    big_int Q = int_floor_div(big_int((2 * j + 1) * K.a), big_int(2 * K.b));
    for (big_int k = Q - spread; k <= Q + spread + 1; ++k) {
      if (!exclude_lobe(K, lobe{k, j}, lobe_basins(k), bound, res.stats)) {
        res.note = "not proved: an undecided box in lobe k = " + k.str() + " at node j = " + j.str();
        return res;
      }
    }
  }
  res.proved = true;
  return res;
}

inline std::pair<std::string, std::string> enclosure_text(const proof::I& x, unsigned d) {
  return {dec_down(interval_lower(x), d), dec_up(interval_upper(x), d)};
}

inline bool meets_digits(const proof::I& x, unsigned digits) {
  mpfr_real w = interval_rel_width(x);
  mpfr_real lim = pow(mpfr_real(10), -int(digits));
  return w <= lim;
}

}  // namespace detail

// Produce a certificate for (tau, sigma) with at least `digits` correct digits in every claim.
inline certificate certify_pair(const resonant_pair<big_int>& p, unsigned digits, const certify_options& opt = {}) {
  using namespace proof;
  using namespace detail;
  if (digits < 1 || digits > 10000) throw usage_error("digits must be in [1, 10000]");
  certificate cert;
  cert.tau = p.tau();
  cert.sigma = p.sigma();
  cert.digits = digits;
  cert.degenerate = p.degenerate();

  if (p.degenerate()) {
    for (unsigned bits = opt.start_bits; bits <= opt.max_bits; bits *= 2) {
      scoped_digits sd(digits10_for_bits(bits));
      auto K = constants_of(p);
      I th = K.c.pi / 2, t = K.c.sqrt_ts * th;
      if (!meets_digits(th, digits) || !meets_digits(t, digits)) continue;
      unsigned d = decimal_digits_for_bits(bits);
      cert.working_bits = cert.cover_bits = bits;
      cert.global_minimality = true;
      cert.global_minimality_note = "proved (integer arithmetic: delta = 2 mod 4)";
      cert.r_res = {"0", "0"};
      cert.theta_first = enclosure_text(th, d);
      cert.t_first = enclosure_text(t, d);
      cert.minimiser_count = 2;
      cert.obligations.push_back(
          {"degenerate",
           "delta = 2 mod 4 forces tau, sigma odd with tau + sigma = 0 mod 4, so cos(tau pi/2) = cos(sigma pi/2) = 0 "
           "and sin(tau pi/2) = -sin(sigma pi/2): q(pi/2) = q'(pi/2) = 0, r_res = 0. R = 0 only where the line "
           "(tau theta, sigma theta) meets P+ or P-, at offsets (pi/2)|a - 4N| = 0 for the single N = a/4: the zeros "
           "in [0, 2 pi) are pi/2 and 3 pi/2 (proofs/global-minimality.md, section 1).",
           {{"delta_mod4", std::to_string(p.delta_mod4())},
            {"tau_mod4", int_mod(p.tau(), big_int(4)).str()},
            {"sigma_mod4", int_mod(p.sigma(), big_int(4)).str()}}});
      return cert;
    }
    throw compute_error("certify: could not reach " + std::to_string(digits) + " digits");
  }

  // Cover at the first level: 64 bits plus the bits of the order, since the mirror images of
  // the minimiser lie about 1/a apart (theta near pi/b for b = 1).
  const unsigned cover_bits =
      std::max(opt.start_bits, 64u + unsigned(boost::multiprecision::msb(p.order())));
  cover_result cover;
  std::string Ylo, Yhi, bound_text;
  {
    scoped_digits sd(digits10_for_bits(cover_bits));
    auto K = constants_of(p);
    auto loc = local_enclosures(p, K);
    I mu = mu_of(K, loc.frame.m);
    // Basin radius: start at a quarter of the room to the lobe edge (and to 0), shrink until proved.
    P u = interval_mid_point(loc.X);
    P room = interval_lower(K.c.pi) / 2 - abs(u);
    P rho = (abs(u) < room ? abs(u) : room) / 2;
    std::optional<I> Y;
    for (int tries = 0; tries < 24 && !Y; ++tries, rho /= 4) {
      I cand = interval_of(u - rho, u + rho);
      if (certainly_subset(loc.X, cand) && certify_basin(K, mu, cand)) Y = cand;
    }
    if (!Y) throw compute_error("certify: no basin could be proved around the minimiser of " + p.str());
    unsigned d = decimal_digits_for_bits(cover_bits) + 2;
    // Y's ends are proof parameters: write them exactly enough that the checker rebuilds Y.
    Ylo = format_scientific(interval_lower(*Y), d + 4);
    Yhi = format_scientific(interval_upper(*Y), d + 4);
    I Yp = interval_from_decimal(Ylo, Yhi);
    if (!certainly_subset(loc.X, Yp) || !certify_basin(K, mu, Yp))
      throw compute_error("certify: the basin of " + p.str() + " does not survive decimal rounding");
    I bound = interval_point(interval_upper(interval_sqr(loc.r)));
    bound_text = dec_up(interval_upper(bound), d);
    auto basins = basins_by_lobe(K, loc.images, Yp);
    cover = run_cover(p, K, basins, bound, opt, "", "");
    cert.cover_bits = cover_bits;
  }
  cert.global_minimality = cover.proved;
  cert.global_minimality_note = cover.proved ? "proved (" + cover.strategy + ")" : cover.note;

  for (unsigned bits = cover_bits; bits <= opt.max_bits; bits *= 2) {
    scoped_digits sd(digits10_for_bits(bits));
    auto K = constants_of(p);
    auto loc = local_enclosures(p, K);
    if (!meets_digits(loc.r, digits) || (cover.proved && (!meets_digits(loc.theta_first, digits) ||
                                                          !meets_digits(loc.t_first, digits))))
      continue;
    unsigned d = decimal_digits_for_bits(bits);
    cert.working_bits = bits;
    auto r = enclosure_text(loc.r, d);
    if (cover.proved) {
      cert.r_res = r;
      cert.theta_first = enclosure_text(loc.theta_first, d);
      cert.t_first = enclosure_text(loc.t_first, d);
      cert.minimiser_count = loc.images.size();
    } else {
      cert.r_res = {"0", r.second};
    }
    auto X = enclosure_text(loc.X, d);
    cert.obligations.push_back(
        {"local-root",
         "interval Newton: N(X) lies in the interior of X, so q' has exactly one root in X (lobe frame k, j); there "
         "R = q^2 and |q| lies in the r_res enclosure",
         {{"k", loc.frame.k.str()}, {"j", loc.frame.j.str()}, {"m", loc.frame.m.str()}, {"X_lo", X.first},
          {"X_hi", X.second}}});
    cert.obligations.push_back(
        {"basin",
         "on Y: q' is strictly monotone (d/du q' excludes 0) and changes sign, and z' excludes 0, so the root in X is "
         "the only critical point of R in Y (dR/dt = -2 n q' z')",
         {{"Y_lo", Ylo}, {"Y_hi", Yhi}, {"bits", std::to_string(cert.cover_bits)}}});
    cert.obligations.push_back(
        {"symmetry",
         "R(2 pi - theta) = R(theta), and R(theta + pi) = R(theta) when tau and sigma are odd: the images of the "
         "minimiser (lobe frames (a-k, b-1-j, -u) and (k+a/2, j+b/2, u)) have equal R",
         {{"images", std::to_string(loc.images.size())}}});
    certificate_obligation cov{
        "cover",
        cover.proved ? "R > bound on [0, 2 pi) outside the basins (interval bisection of every listed lobe, Rayleigh "
                       "bound as a filter)"
                     : cover.note,
        {{"strategy", cover.strategy}, {"bound", bound_text}, {"bits", std::to_string(cert.cover_bits)},
         {"lobes", std::to_string(cover.stats.lobes)}, {"boxes", std::to_string(cover.stats.boxes)}}};
    cert.obligations.push_back(cov);
    if (cover.strategy == "slow-nodes" && cover.proved)
      cert.obligations.push_back(
          {"rayleigh",
           "for |cos beta| >= sin(t x): R >= (1-x^2) c^4/(2 (1-x^2) c^2 + x^2) with c = sin(t x), which exceeds the "
           "bound; every other theta lies in a listed lobe around a slow node",
           {{"t", cover.rayleigh_t}}});
    return cert;
  }
  throw compute_error("certify: could not reach " + std::to_string(digits) + " digits by " +
                      std::to_string(opt.max_bits) + " bits");
}

// The checker's verdict: holds, or the first failing claim/obligation by name.
struct check_verdict {
  bool holds = false;
  std::string failure;
};

inline const certificate_obligation* find_obligation(const certificate& c, const std::string& id) {
  for (auto& o : c.obligations)
    if (o.id == id) return &o;
  return nullptr;
}

// Re-prove a certificate. Throws usage_error for malformed content (unparsable numbers, missing
// fields); returns a failing verdict for anything that does not hold.
inline check_verdict check_certificate(const certificate& c, const certify_options& opt = {}) {
  using namespace proof;
  using namespace detail;
  auto fail = [](const std::string& why) { return check_verdict{false, why}; };
  if (c.format != certificate_format) return fail("format: expected " + std::string(certificate_format));
  std::optional<resonant_pair<big_int>> pp;
  try {
    pp.emplace(c.tau, c.sigma);
  } catch (const usage_error& e) {
    return fail(std::string("pair: ") + e.what());
  }
  const auto& p = *pp;
  if (c.degenerate != p.degenerate()) return fail("degenerate: the pair's delta mod 4 says otherwise");
  if (c.working_bits < 16 || c.working_bits > opt.max_bits || c.cover_bits < 16 || c.cover_bits > opt.max_bits)
    return fail("working_bits: out of range");
  if (c.digits < 1 || c.digits > 10000) return fail("digits: out of range");

  // Claims are parsed 64 bits finer than the working precision, so that a decimal bound moved
  // inward by one unit of its last digit no longer rounds back onto the enclosure.
  auto contains = [&](const std::pair<std::string, std::string>& claim, const I& mine) {
    scoped_digits fine(digits10_for_bits(c.working_bits + 64));
    I cl = interval_from_decimal(claim.first, claim.second);
    return certainly_subset(mine, cl);
  };
  auto claim_digits = [&](const std::pair<std::string, std::string>& claim) {
    scoped_digits sd(digits10_for_bits(c.working_bits) + 10);
    return meets_digits(interval_from_decimal(claim.first, claim.second), c.digits);
  };

  if (p.degenerate()) {
    const auto* o = find_obligation(c, "degenerate");
    if (!o) return fail("obligation degenerate: missing");
    if (p.delta_mod4() != 2 || int_mod(big_int(p.tau() + p.sigma()), big_int(4)) != 0)
      return fail("obligation degenerate: integer facts do not hold");
    scoped_digits sd(digits10_for_bits(c.working_bits));
    auto K = constants_of(p);
    I th = K.c.pi / 2, t = K.c.sqrt_ts * th;
    if (c.r_res.first != "0" || c.r_res.second != "0") return fail("claim r_res: must be exactly [0, 0]");
    if (!contains(c.theta_first, th)) return fail("claim theta_first: does not contain pi/2");
    if (!contains(c.t_first, t)) return fail("claim t_first: does not contain sqrt(tau sigma) pi/2");
    if (!claim_digits(c.theta_first) || !claim_digits(c.t_first)) return fail("claims: fewer digits than stated");
    if (c.minimiser_count != 2) return fail("claim minimiser_count: degenerate pairs have exactly 2 zeros");
    if (!c.global_minimality) return fail("claim global_minimality: must be true for a degenerate pair");
    return {true, ""};
  }

  for (const char* id : {"local-root", "basin", "symmetry", "cover"})
    if (!find_obligation(c, id)) return fail(std::string("obligation ") + id + ": missing");
  const auto& basin = *find_obligation(c, "basin");
  const auto& cov = *find_obligation(c, "cover");
  auto get = [](const certificate_obligation& o, const char* key) {
    auto it = o.data.find(key);
    if (it == o.data.end()) throw usage_error("obligation " + o.id + ": missing field " + key);
    return it->second;
  };

  // Cover level: local root, basin, bound, cover.
  {
    scoped_digits sd(digits10_for_bits(c.cover_bits));
    auto K = constants_of(p);
    auto loc = local_enclosures(p, K);
    I mu = mu_of(K, loc.frame.m);
    I Y = interval_from_decimal(get(basin, "Y_lo"), get(basin, "Y_hi"));
    if (!certainly_subset(loc.X, Y)) return fail("obligation basin: Y does not contain the certified root");
    if (!certify_basin(K, mu, Y)) return fail("obligation basin: does not hold on Y");
    I bound = interval_point(interval_upper(interval_sqr(loc.r)));
    if (c.global_minimality) {
      std::string strategy = get(cov, "strategy");
      std::string t;
      if (strategy == "slow-nodes") {
        const auto* ray = find_obligation(c, "rayleigh");
        if (!ray) return fail("obligation rayleigh: missing");
        t = get(*ray, "t");
      }
      auto basins = basins_by_lobe(K, loc.images, Y);
      certify_options big = opt;
      big.max_lobes = std::numeric_limits<std::int64_t>::max();
      auto res = run_cover(p, K, basins, bound, big, strategy, t);
      if (!res.proved) return fail("obligation cover: " + res.note);
    }
  }

  // Working level: enclosures against the claims.
  scoped_digits sd(digits10_for_bits(c.working_bits));
  auto K = constants_of(p);
  auto loc = local_enclosures(p, K);
  if (c.global_minimality) {
    if (!contains(c.r_res, loc.r)) return fail("claim r_res: does not contain the checker's enclosure");
    if (!contains(c.theta_first, loc.theta_first))
      return fail("claim theta_first: does not contain the checker's enclosure");
    if (!contains(c.t_first, loc.t_first)) return fail("claim t_first: does not contain the checker's enclosure");
    if (!claim_digits(c.r_res)) return fail("claim r_res: fewer digits than stated");
    if (!claim_digits(c.theta_first)) return fail("claim theta_first: fewer digits than stated");
    if (!claim_digits(c.t_first)) return fail("claim t_first: fewer digits than stated");
    if (c.minimiser_count != loc.images.size())
      return fail("claim minimiser_count: the symmetry images number " + std::to_string(loc.images.size()));
  } else {
    scoped_digits fine(digits10_for_bits(c.working_bits + 64));
    I hi = interval_from_decimal(c.r_res.second, c.r_res.second);
    if (!certainly_subset(loc.r, interval_of(mpfr_real(0), interval_upper(hi))))
      return fail("claim r_res: upper bound below the checker's enclosure");
    if (!c.theta_first.first.empty() || !c.t_first.first.empty() || c.minimiser_count != 0)
      return fail("claims: theta_first, t_first and minimiser_count need global minimality");
  }
  return {true, ""};
}

}  // namespace gyrores
