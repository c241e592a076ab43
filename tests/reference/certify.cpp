// The producer of certificates (reference/certify.hpp), in named steps: the degenerate case, the
// cover level (basin and cover, once), the working level (enclosures to the digits asked).
#include "reference/certify.hpp"

#include <algorithm>
#include <optional>

#include "reference/cover.hpp"
#include "reference/proof_steps.hpp"
#include <gyrores/core/error.hpp>

namespace gyrores {

namespace {

using proof::I;
using proof::P;

certificate_obligation degenerate_obligation(const resonant_pair<big_int>& p) {
  return {"degenerate",
          "delta = 2 mod 4 forces tau, sigma odd with tau + sigma = 0 mod 4, so cos(tau pi/2) = cos(sigma pi/2) = 0 "
          "and sin(tau pi/2) = -sin(sigma pi/2): q(pi/2) = q'(pi/2) = 0, r_res = 0. R = 0 only where the line "
          "(tau theta, sigma theta) meets P+ or P-, at offsets (pi/2)|a - 4N| = 0 for the single N = a/4: the zeros "
          "in [0, 2 pi) are pi/2 and 3 pi/2 (proofs/global-minimality.md, section 1).",
          {{"delta_mod4", std::to_string(p.delta_mod4())},
           {"tau_mod4", int_mod(p.tau(), big_int(4)).str()},
           {"sigma_mod4", int_mod(p.sigma(), big_int(4)).str()}}};
}

// delta = 2 mod 4: r_res = 0 exactly, theta_first = pi/2, t_first = sqrt(tau sigma) pi/2.
certificate certify_degenerate(const resonant_pair<big_int>& p, const certify_options& opt, certificate cert) {
  for (unsigned bits = opt.start_bits; bits <= opt.max_bits; bits *= 2) {
    scoped_digits sd(digits10_for_bits(bits));
    auto K = proof::constants_of(p);
    I th = K.c.pi / 2, t = K.c.sqrt_ts * th;
    if (!proof::meets_digits(th, cert.digits) || !proof::meets_digits(t, cert.digits)) continue;
    unsigned d = certificate_digits_for_bits(bits);
    cert.working_bits = cert.cover_bits = bits;
    cert.global_minimality = true;
    cert.global_minimality_note = degenerate_note;
    cert.r_res = {"0", "0"};
    cert.theta_first = interval_to_decimal(th, d);
    cert.t_first = interval_to_decimal(t, d);
    cert.minimiser_count = 2;
    cert.obligations.push_back(degenerate_obligation(p));
    return cert;
  }
  throw compute_error("certify: could not reach " + std::to_string(cert.digits) + " digits");
}

// What the cover level proves, as the certificate writes it.
struct cover_level {
  unsigned bits = 0;
  proof::cover_result cover;
  std::string Y_lo, Y_hi, bound;
};

// The basin: start at a quarter of the room to the lobe edge (and to 0), shrink until proved.
I find_basin(const resonant_pair<big_int>& p, const proof::constants& K, const I& mu, const I& X) {
  P u = interval_mid_point(X);
  P room = interval_lower(K.c.pi) / 2 - abs(u);
  P rho = (abs(u) < room ? abs(u) : room) / 2;
  for (int tries = 0; tries < 24; ++tries, rho /= 4) {
    I cand = interval_of(u - rho, u + rho);
    if (certainly_subset(X, cand) && proof::certify_basin(K, mu, cand)) return cand;
  }
  throw compute_error("certify: no basin could be proved around the minimiser of " + p.str());
}

// Basin and cover at `bits` (64 bits plus the bits of the order: the mirror images of the
// minimiser lie about 1/a apart, theta near pi/b for b = 1). Y's ends are proof parameters:
// they are written exactly enough that the checker rebuilds Y, and the basin is re-proved on
// the Y the checker will read.
cover_level prove_cover_level(const resonant_pair<big_int>& p, const certify_options& opt, unsigned bits) {
  scoped_digits sd(digits10_for_bits(bits));
  auto K = proof::constants_of(p);
  auto loc = proof::enclose_minimisers(p, K);
  I mu = proof::mu_of(K, loc.frame.m);
  I Y = find_basin(p, K, mu, loc.X);
  cover_level out;
  out.bits = bits;
  unsigned d = certificate_digits_for_bits(bits) + 2;
  out.Y_lo = format_scientific(interval_lower(Y), d + 4);
  out.Y_hi = format_scientific(interval_upper(Y), d + 4);
  I Yp = interval_from_decimal(out.Y_lo, out.Y_hi);
  if (!certainly_subset(loc.X, Yp) || !proof::certify_basin(K, mu, Yp))
    throw compute_error("certify: the basin of " + p.str() + " does not survive decimal rounding");
  I bound = interval_point(interval_upper(interval_sqr(loc.r)));
  out.bound = cover_bound_text(interval_upper(bound), bits);
  out.cover = proof::run_cover(K, proof::basins_by_lobe(K, loc.images, Yp), bound, opt, "", "");
  return out;
}

void add_local_obligations(certificate& cert, const proof::minimiser_enclosures& loc, const cover_level& level,
                           unsigned d) {
  auto X = interval_to_decimal(loc.X, d);
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
       {{"Y_lo", level.Y_lo}, {"Y_hi", level.Y_hi}, {"bits", std::to_string(level.bits)}}});
  cert.obligations.push_back(
      {"symmetry",
       "R(2 pi - theta) = R(theta), and R(theta + pi) = R(theta) when tau and sigma are odd: the images of the "
       "minimiser (lobe frames (a-k, b-1-j, -u) and (k+a/2, j+b/2, u)) have equal R",
       {{"images", std::to_string(loc.images.size())}}});
}

void add_cover_obligations(certificate& cert, const cover_level& level) {
  const auto& cover = level.cover;
  cert.obligations.push_back(
      {"cover",
       cover.proved ? "R > bound on [0, 2 pi) outside the basins (interval bisection of every listed lobe, Rayleigh "
                      "bound as a filter)"
                    : cover.note,
       {{"strategy", cover.strategy}, {"bound", level.bound}, {"bits", std::to_string(level.bits)},
        {"lobes", std::to_string(cover.stats.lobes)}, {"boxes", std::to_string(cover.stats.boxes)}}});
  if (cover.strategy == "slow-nodes" && cover.proved)
    cert.obligations.push_back(
        {"rayleigh",
         "for |cos beta| >= sin(t x): R >= (1-x^2) c^4/(2 (1-x^2) c^2 + x^2) with c = sin(t x), which exceeds the "
         "bound; every other theta lies in a listed lobe around a slow node",
         {{"t", cover.rayleigh_t}}});
}

// The claims at the first precision from the cover level on where they meet the digits.
certificate certify_working_level(const resonant_pair<big_int>& p, const certify_options& opt,
                                  const cover_level& level, certificate cert) {
  const bool proved = level.cover.proved;
  for (unsigned bits = level.bits; bits <= opt.max_bits; bits *= 2) {
    scoped_digits sd(digits10_for_bits(bits));
    auto K = proof::constants_of(p);
    auto loc = proof::enclose_minimisers(p, K);
    auto enough = [&](const I& x) { return proof::meets_digits(x, cert.digits); };
    if (!enough(loc.r) || (proved && (!enough(loc.theta_first) || !enough(loc.t_first)))) continue;
    unsigned d = certificate_digits_for_bits(bits);
    cert.working_bits = bits;
    auto r = interval_to_decimal(loc.r, d);
    if (proved) {
      cert.r_res = r;
      cert.theta_first = interval_to_decimal(loc.theta_first, d);
      cert.t_first = interval_to_decimal(loc.t_first, d);
      cert.minimiser_count = loc.images.size();
    } else {
      cert.r_res = {"0", r.second};
    }
    add_local_obligations(cert, loc, level, d);
    add_cover_obligations(cert, level);
    return cert;
  }
  throw compute_error("certify: could not reach " + std::to_string(cert.digits) + " digits by " +
                      std::to_string(opt.max_bits) + " bits");
}

}  // namespace

certificate certify_pair(const resonant_pair<big_int>& p, unsigned digits, const certify_options& opt) {
  if (digits < 1 || digits > 10000) throw usage_error("digits must be in [1, 10000]");
  certificate cert;
  cert.tau = p.tau();
  cert.sigma = p.sigma();
  cert.digits = digits;
  cert.degenerate = p.degenerate();
  if (p.degenerate()) return certify_degenerate(p, opt, std::move(cert));
  const unsigned cover_bits = std::max(opt.start_bits, 64u + unsigned(boost::multiprecision::msb(p.order())));
  cover_level level = prove_cover_level(p, opt, cover_bits);
  cert.cover_bits = cover_bits;
  cert.global_minimality = level.cover.proved;
  cert.global_minimality_note = level.cover.proved ? proved_note(level.cover.strategy) : level.cover.note;
  return certify_working_level(p, opt, level, std::move(cert));
}

}  // namespace gyrores
