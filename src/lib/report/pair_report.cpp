// include/gyrores/report/pair_report.hpp: every real of a pair's report, proved and rounded.
#include <gyrores/report/pair_report.hpp>

#include <algorithm>
#include <map>
#include <memory>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/refine.hpp>
#include <gyrores/report/scales.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

namespace {

using iv = fixed_mpfi;

// Rounds the enclosures of one precision into proved_reals; remembers the first field it could
// not decide (the precision then doubles). The names are static texts (proof_status reasons).
class rounder {
 public:
  rounder(unsigned digits, bool enclosures, bool doubles) : digits_(digits), enclosures_(enclosures), doubles_(doubles) {}
  void operator()(proved_real& out, const iv& x, const char* name) { round(out, x, name, digits_); }
  // The same with its own digits (a share of H_q(0), report/scales.hpp).
  void round(proved_real& out, const iv& x, const char* name, unsigned digits) {
    std::optional<double> nearest;
    if (doubles_) nearest = nearest_double(x.left(), x.right());
    if (!enclosure_rounding(x.left(), x.right(), digits, out.value) || (doubles_ && !nearest)) {
      if (!undecided_) undecided_ = name;
      return;
    }
    if (nearest) out.nearest = *nearest;
    enclosure(out, x, digits);
  }
  // A field whose exact value is the rational q (x: its enclosure at this precision).
  void exact(proved_real& out, const big_rational& q, iv& x, unsigned digits = 0) {
    if (digits == 0) digits = digits_;
    out.value = format_rational_scientific(q, digits);
    mpfi_set_q(x, q.backend().data());
    if (doubles_) out.nearest = nearest_double(q);
    enclosure(out, x, digits);
  }
  // Proved when every rounding was decided; else undecided, naming the first field that was not.
  proof_status status() const { return undecided_ ? proof_status::undecided(undecided_) : proof_status::proved(); }

 private:
  void enclosure(proved_real& out, const iv& x, unsigned digits) const {
    if (enclosures_)
      out.enclosure = {format_scientific(x.left(), digits + 3, MPFR_RNDD), format_scientific(x.right(), digits + 3, MPFR_RNDU)};
  }
  unsigned digits_;
  bool enclosures_, doubles_;
  const char* undecided_ = nullptr;
};

// Calls fill(bits, rounder) at doubling precisions from `start` (core/refine.hpp) until its
// proofs hold with every rounding decided. A requested stop is honoured before each precision
// (one fill at the highest precision is the longest wait: about a second at 10000 digits).
template <class Fill>
void round_refined(const resonant_pair<big_int>& p, unsigned digits, bool enclosures, bool doubles, unsigned start, Fill&& fill,
                   const stop_token& stop = {}) {
  refine(precision_plan{mpfr_prec_t(start)}, stop, "pair " + p.str() + ": the report to " + std::to_string(digits) + " digits",
         [&](mpfr_prec_t bits, proof_status& status) {
           rounder r(digits, enclosures, doubles);
           status = fill(unsigned(bits), r);
           if (status) status = r.status();
           return status ? std::optional<bool>(true) : std::nullopt;
         });
}

// The exact rationals of a pair (pair_report.hpp): squares decide which fields are rational.
struct exact_values {
  big_rational v;
  std::optional<big_rational> n, rho0, omega1, omega2;
};

exact_values exact_values_of(const resonant_pair<big_int>& p, const big_rational& qdot0) {
  exact_values e;
  e.v = qdot0;
  if (!(e.v > 0)) throw usage_error("qdot0 must be > 0, got " + rational_str(qdot0));
  const big_int a = p.order(), b = big_int(p.delta());
  big_int rts, rt, rs;
  if (int_is_square(big_int(p.tau() * p.sigma()), rts)) {
    e.n = big_rational(b, rts);
    e.rho0 = e.v * big_rational(rts, a);
  }
  if (int_is_square(p.tau(), rt) && int_is_square(p.sigma(), rs)) {
    e.omega1 = big_rational(rt, rs);
    e.omega2 = big_rational(rs, rt);
  }
  return e;
}

// The model's fields: beat ratio a/b, qdot0, n = b/sqrt(tau sigma), omega1 = sqrt(tau/sigma),
// omega2 = 1/omega1, rho0 = v sqrt(tau sigma)/a, t_min_paper = pi/n.
void model_fields(pair_report& r, const theorem_constants& K, const resonant_pair<big_int>& p, const exact_values& e,
                  const iv& v, rounder& round) {
  iv x(K.prec), y(K.prec);
  round.exact(r.beat_ratio, big_rational(p.order(), big_int(p.delta())), x);
  round.exact(r.qdot0, e.v, x);
  if (e.n) round.exact(r.n, *e.n, x);
  else {
    mpfi_div(x, K.b, K.sqrt_ts);
    round(r.n, x, "n");
  }
  if (e.omega1) {
    round.exact(r.omega1, *e.omega1, x);
    round.exact(r.omega2, *e.omega2, x);
  } else {
    mpfi_set_z(y, p.tau().backend().data());
    mpfi_set_z(x, p.sigma().backend().data());
    mpfi_div(x, y, x);
    mpfi_sqrt(x, x);
    round(r.omega1, x, "omega1");
    mpfi_ui_div(x, 1, x);
    round(r.omega2, x, "omega2");
  }
  if (e.rho0) round.exact(r.rho0, *e.rho0, x);
  else {
    mpfi_mul(x, v, K.sqrt_ts);
    mpfi_div(x, x, K.a);
    round(r.rho0, x, "rho0");
  }
  mpfi_mul(x, K.pi, K.sqrt_ts);
  mpfi_div(x, x, K.b);
  round(r.t_min_paper, x, "t_min_paper");
}

// The minimum's fields from its enclosures.
void minimum_fields(pair_report& r, const theorem_constants& K, const minimum_enclosure& M, const exact_values& e,
                    rounder& round) {
  iv x(K.prec);
  const unsigned share_d = std::min(r.digits, share_digits);
  if (r.degenerate) {
    round.exact(r.r_res, 0, x);
    round.exact(r.h_min, 0, x);
    round.exact(r.h_min_share, 0, x, share_d);
    round.exact(r.h_z_max, e.v * e.v / 2, x);
  } else {
    round(r.r_res, M.r_res, "r_res");
    round(r.h_min, M.h_min, "h_min");
    // H_q min / H_q(0) in percent: the enclosure times the exact 200/qdot0^2 (outward, by MPFI).
    const big_rational k = share_factor(e.v);
    mpfi_mul_q(x, M.h_min, k.backend().data());
    round.round(r.h_min_share, x, "the share of H_q(0)", share_d);
    round(r.h_z_max, M.h_z_max, "h_z_max");
  }
  r.minimisers.assign(M.minimisers.size(), {});
  for (std::size_t i = 0; i < M.minimisers.size(); ++i) round(r.minimisers[i], *M.minimisers[i], "minimisers");
  r.theta_first = r.minimisers.front();
  mpfi_mul(x, K.sqrt_ts, *M.minimisers.front());
  round(r.t_first, x, "t_first");
}

// Root enclosures by offset |m|, each proved once per precision (the tie's two lobes, m_min and
// the fast node often share them).
class root_cache {
 public:
  explicit root_cache(const theorem_constants& K) : K_(K) {}
  // H^{-1}(pi |m|/(2a)) (theorem) or the root of u + tan u = pi |m|/(2b) (paper); nullptr, with
  // the reason in `status`, if the proof failed at this precision.
  const root_enclosure* get(const big_int& m, bool theorem, proof_status& status) {
    auto& slot = (theorem ? theorem_ : paper_)[m];
    if (!slot) {
      slot = std::make_unique<root_enclosure>(K_.prec);
      status_[{m, theorem}] = theorem ? prove_theorem_root(*slot, K_, m) : prove_paper_root(*slot, K_, m);
    }
    status = status_[{m, theorem}];
    return status ? slot.get() : nullptr;
  }
  // Seeds the theorem's root for m_min from the minimum's proof.
  void put_theorem(const big_int& m, const root_enclosure& r) {
    auto& slot = theorem_[m];
    slot = std::make_unique<root_enclosure>(K_.prec);
    mpfi_set(slot->U, r.U);
    mpfi_set(slot->T, r.T);
    status_[{m, true}] = proof_status::proved();
  }

 private:
  const theorem_constants& K_;
  std::map<big_int, std::unique_ptr<root_enclosure>> theorem_, paper_;
  std::map<std::pair<big_int, bool>, proof_status> status_;
};

// U (and T = tan U) of a signed root: the cached root of |m|, negated for m < 0; exact 0 for m = 0.
proof_status signed_root(iv& U, iv* T, root_cache& cache, const big_int& m, bool theorem) {
  if (m == 0) {
    mpfi_set_ui(U, 0);
    if (T) mpfi_set_ui(*T, 0);
    return proof_status::proved();
  }
  proof_status status;
  const root_enclosure* r = cache.get(big_int(abs(m)), theorem, status);
  if (!r) return status;
  mpfi_set(U, r->U);
  if (T) mpfi_set(*T, r->T);
  if (m < 0) {
    mpfi_neg(U, U);
    if (T) mpfi_neg(*T, *T);
  }
  return proof_status::proved();
}

// The enclosures of one paper lobe k: s, u_asy (and tan u_asy in Ta), theta_asy, u_c (in Uc),
// theta_c, error, bound, ratio.
struct lobe_enclosures {
  explicit lobe_enclosures(mpfr_prec_t p) : s(p), u_asy(p), Ta(p), theta_asy(p), Uc(p), Tc(p), theta_c(p), error(p), bound(p), ratio(p) {}
  iv s, u_asy, Ta, theta_asy, Uc, Tc, theta_c, error, bound, ratio;
};

proof_status prove_lobe(lobe_enclosures& L, const theorem_constants& K, root_cache& cache, const big_int& k,
                        const big_int& m) {
  GYRORES_TRY_PROOF(signed_root(L.u_asy, &L.Ta, cache, m, false));
  GYRORES_TRY_PROOF(signed_root(L.Uc, &L.Tc, cache, m, true));
  pi_ratio(L.s, K, m, K.bi);
  lobe_theta(L.theta_asy, K, k, L.u_asy);
  lobe_theta(L.theta_c, K, k, L.Uc);
  iv d(K.prec);
  mpfi_sub(d, L.Uc, L.u_asy);
  mpfi_abs(d, d);
  paper_error_bound(L.error, L.bound, K, d);
  mpfi_div(L.ratio, L.error, L.bound);
  return proof_status::proved();
}

std::vector<big_int> fast_nodes(const big_int& a, const big_int& b) {
  const auto node = paper_fast_node(a, b);
  std::vector<big_int> ks{node.k};
  if (node.tie) ks.push_back(big_int(node.k + 1));
  return ks;
}

std::string asymptotic_remarks(const resonant_pair<big_int>& p, bool tie) {
  std::string reason;
  if (tie) reason = "a/(2b) is a half-integer (b = 1): both lobes k = (a-1)/2 and (a+1)/2 are reported (mirror images)";
  if (p.degenerate()) {
    if (!reason.empty()) reason += "; ";
    reason += "degenerate pair (delta = 2 mod 4): r_res = 0 exactly at theta = pi/2 (integer arithmetic); the "
              "lobe root near pi/b is still reported, and it is that zero only when b = 2";
  }
  return reason;
}

// r_res_asy = v x |sin u_a tan u_a| = v x t^2/sqrt(1 + t^2), t = tan u_a (|u_a| < pi/2), and its
// relative error against r_res (absolute when r_res = 0: degenerate pairs, where both are 0).
proof_status asymptotic_radius(pair_report& r, const theorem_constants& K, root_cache& cache,
                               const minimum_enclosure& M, const iv& v, rounder& round) {
  iv U(K.prec), T(K.prec), ra(K.prec), x(K.prec);
  GYRORES_TRY_PROOF(signed_root(U, &T, cache, big_int(r.m_min), false));
  mpfi_sqr(ra, T);
  mpfi_add_ui(x, ra, 1);
  mpfi_sqrt(x, x);
  mpfi_div(ra, ra, x);
  mpfi_mul(ra, ra, K.x);
  mpfi_mul(ra, ra, v);
  r.r_res_asy.emplace();
  r.r_res_asy_rel_error.emplace();
  round(*r.r_res_asy, ra, "r_res_asy");
  mpfi_sub(x, ra, M.r_res);
  mpfi_abs(x, x);
  if (r.m_min > 0) mpfi_div(x, x, M.r_res);
  round(*r.r_res_asy_rel_error, x, "r_res_asy_rel_error");
  return proof_status::proved();
}

proof_status asymptotic_fields(pair_report& r, const theorem_constants& K, const resonant_pair<big_int>& p, root_cache& cache,
                       const minimum_enclosure& M, const iv& v, rounder& round) {
  const big_int a = p.order(), b = big_int(p.delta());
  r.lobes.clear();
  for (const big_int& k : fast_nodes(a, b)) {
    paper_lobe_report lo;
    lo.k = k;
    lo.m = a - 2 * k * b;
    lo.holds_global_min = abs(lo.m) == r.m_min;
    lobe_enclosures L(K.prec);
    GYRORES_TRY_PROOF(prove_lobe(L, K, cache, k, lo.m));
    round(lo.s, L.s, "asymptotic s");
    round(lo.u_asy, L.u_asy, "u_asy");
    round(lo.theta_asy, L.theta_asy, "theta_asy");
    round(lo.theta_c, L.theta_c, "theta_c");
    round(lo.error, L.error, "the asymptotic error");
    round(lo.bound, L.bound, "the asymptotic bound");
    round(lo.ratio, L.ratio, "the asymptotic ratio");
    r.lobes.push_back(std::move(lo));
  }
  return asymptotic_radius(r, K, cache, M, v, round);
}

// Guard bits beyond the digits: 32, plus 2 log2(a) where the asymptotics cancel (theta_c -
// theta_asy is O(x^2 u^3) against u; r_res_asy - r_res is O(x^2) relative).
unsigned start_bits(const resonant_pair<big_int>& p, unsigned digits, bool asymptotics) {
  unsigned bits = digits10_to_bits(digits) + 32;
  if (asymptotics && 2 * big_int(p.delta()) < p.order()) bits += 2 * unsigned(boost::multiprecision::msb(p.order()) + 1);
  return bits;
}

}  // namespace

pair_report prove_pair(const resonant_pair<big_int>& p, const pair_report_options& opt) {
  check_report_digits(opt.digits);
  const exact_values e = exact_values_of(p, opt.qdot0);
  const big_int a = p.order(), b = big_int(p.delta());
  pair_report r;
  r.digits = opt.digits;
  r.degenerate = p.degenerate();
  r.m_min = p.strand_offset_min();
  r.asymptotic_applicable = opt.asymptotics && 2 * b < a;
  if (opt.asymptotics && !r.asymptotic_applicable)
    r.asymptotic_reason = "x = b/a = " + b.str() + "/" + a.str() +
                          " >= 1/2: the lobe equation x tan u = tan(mu - x u) need not have a unique root in "
                          "|u| < pi/2 and the slow-node reduction (mu and x u small) does not apply";
  if (r.asymptotic_applicable) r.asymptotic_reason = asymptotic_remarks(p, paper_fast_node(a, b).tie);
  round_refined(p, opt.digits, opt.enclosures, opt.doubles, start_bits(p, opt.digits, r.asymptotic_applicable), [&](unsigned bits, rounder& round) {
    r.bits = bits;
    theorem_constants K(bits, p);
    iv v(bits);
    mpfi_set_q(v, e.v.backend().data());
    minimum_enclosure M(bits);
    GYRORES_TRY_PROOF(prove_minimum(M, K, p, v));
    model_fields(r, K, p, e, v, round);
    minimum_fields(r, K, M, e, round);
    if (!r.asymptotic_applicable) return proof_status::proved();
    root_cache cache(K);
    if (r.m_min > 0) cache.put_theorem(big_int(r.m_min), M.u_star);
    return asymptotic_fields(r, K, p, cache, M, v, round);
  }, opt.stop);
  return r;
}

pair_report prove_pair_values(const resonant_pair<big_int>& p, unsigned digits, const big_rational& qdot0,
                              stop_token stop) {
  return prove_pair(p, {.digits = digits, .qdot0 = qdot0, .asymptotics = false, .enclosures = true, .stop = std::move(stop)});
}

paper_lobe_detail prove_paper_lobe(const resonant_pair<big_int>& p, const big_int& k, unsigned digits) {
  check_report_digits(digits);
  const big_int a = p.order(), b = big_int(p.delta());
  const auto ks = 2 * b < a ? fast_nodes(a, b) : std::vector<big_int>{};
  if (std::find(ks.begin(), ks.end(), k) == ks.end())
    throw compute_error("pair " + p.str() + " has no asymptotic lobe k = " + k.str());
  const big_int m = a - 2 * k * b;
  paper_lobe_detail d;
  round_refined(p, digits, true, false, start_bits(p, digits, true), [&](unsigned bits, rounder& round) {
    theorem_constants K(bits, p);
    root_cache cache(K);
    lobe_enclosures L(bits);
    GYRORES_TRY_PROOF(prove_lobe(L, K, cache, k, m));
    iv w(bits), q(bits), c(bits), t(bits);
    // q'(theta_asy) = (-1)^k cos u cos w (tan w - w), w = x tan u_asy (pair_report.hpp).
    mpfi_mul(w, K.x, L.Ta);
    mpfi_tan(t, w);
    mpfi_sub(q, t, w);
    mpfi_cos(c, w);
    mpfi_mul(q, q, c);
    mpfi_cos(c, L.u_asy);
    mpfi_mul(q, q, c);
    if (k % 2 != 0) mpfi_neg(q, q);
    round(d.qdot_asy, q, "qdot_asy");
    mpfi_mul(c, q, K.a);  // q'/rho0, rho0 = sqrt(tau sigma)/a
    mpfi_div(c, c, K.sqrt_ts);
    round(d.qdot_asy_over_rho0, c, "qdot_asy/rho0");
    round(d.u_asy, L.u_asy, "u_asy");
    round(d.theta_asy, L.theta_asy, "theta_asy");
    round(d.error, L.error, "the asymptotic error");
    round(d.bound, L.bound, "the asymptotic bound");
    round(d.theta_c, L.theta_c, "theta_c");
    theorem_radius(c, K, L.Tc);  // sqrt(G) is even in u: tan of u_c's sign does not matter
    round(d.r_c, c, "r_c");
    return proof_status::proved();
  });
  return d;
}

}  // namespace gyrores
