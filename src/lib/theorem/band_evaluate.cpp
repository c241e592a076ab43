// src/lib/theorem/band_evaluate.hpp
#include "band_evaluate.hpp"

#include <cmath>

#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/theorem/horizon.hpp>
#include <gyrores/theorem/root.hpp>

#include "kernels_arb.hpp"

namespace gyrores::band_detail {

using arb_support::ball;
using arb_support::lower_rational;
using arb_support::set_int;
using arb_support::set_quadratic;
using arb_support::set_rational;
using arb_support::upper_rational;

namespace {

slong bits_of(const big_int& v) { return v == 0 ? 0 : slong(boost::multiprecision::msb(v < 0 ? big_int(-v) : v)) + 1; }

// sin and cos of a ball, each clipped to [-1, 1] (Arb may return wider balls for wide arguments).
void sin_cos_clipped(arb_t s, arb_t c, const arb_t a, slong p) {
  arb_sin_cos(s, c, a, p);
  ball unit;
  arb_zero_pm_one(unit);
  if (!arb_is_finite(s) || !arb_contains(unit, s)) arb_set(s, unit);
  if (!arb_is_finite(c) || !arb_contains(unit, c)) arb_set(c, unit);
}

// s = sqrt(n^2 + 4), x = n/s, c = 2/s, dx/dn = 4/s^3 and dc/dn = -2n/s^3 over a ball of n > 0. Each is
// monotone in n except dc/dn, whose size 2n/s^3 peaks at n = sqrt 2: enclosed from the ball's ends,
// since evaluating them on a wide ball directly can divide by a ball that holds 0.
void coefficients(arb_t s, arb_t x, arb_t c, arb_t dx, arb_t dc, const arb_t n, slong p) {
  const auto at = [p](arb_t s1, arb_t x1, arb_t c1, arb_t dx1, arb_t dc1, const arb_t n1) {
    ball s3;
    arb_mul(s1, n1, n1, p);
    arb_add_si(s1, s1, 4, p);
    arb_sqrt(s1, s1, p);
    arb_div(x1, n1, s1, p);
    arb_set_si(c1, 2);
    arb_div(c1, c1, s1, p);
    arb_mul(s3, s1, s1, p);
    arb_mul(s3, s3, s1, p);
    arb_set_si(dx1, 4);
    arb_div(dx1, dx1, s3, p);
    arb_mul_si(dc1, n1, -2, p);
    arb_div(dc1, dc1, s3, p);
  };
  if (arb_is_exact(n)) {
    at(s, x, c, dx, dc, n);
    return;
  }
  ball lo, hi, s2, x2, c2, dx2, dc2;
  arf_t b;
  arf_init(b);
  arb_get_lbound_arf(b, n, p);
  arb_set_arf(lo, b);
  arb_get_ubound_arf(b, n, p);
  arb_set_arf(hi, b);
  arf_clear(b);
  at(s, x, c, dx, dc, lo);
  at(s2, x2, c2, dx2, dc2, hi);
  arb_union(s, s, s2, p);
  arb_union(x, x, x2, p);
  arb_union(c, c, c2, p);
  arb_union(dx, dx, dx2, p);
  arb_union(dc, dc, dc2, p);
  ball root2;
  arb_sqrt_ui(root2, 2, p);
  if (arb_overlaps(n, root2)) {
    at(s2, x2, c2, dx2, dc2, root2);
    arb_union(dc, dc, dc2, p);
  }
}
// R(n, T) = q^2 + q'^2 and dR/dn at t = T (qdot0 = 1): with alpha = s t/2, beta = n t/2,
// q = c sin(alpha) cos(beta), q' = cos(alpha) cos(beta) - x sin(alpha) sin(beta); d alpha/dn = x t/2,
// d beta/dn = t/2 (horizon-theorem.md Step 12 (d)).
void R_and_slope(arb_t R, arb_t dR, const arb_t n, const arb_t tt, slong p) {
  ball s, x, c, dx, dc, a, b, da, db, sa, ca, sb, cb, q, qd, dq, dqd, tmp, tmp2;
  coefficients(s, x, c, dx, dc, n, p);
  arb_mul(a, s, tt, p);
  arb_mul_2exp_si(a, a, -1);
  arb_mul(b, n, tt, p);
  arb_mul_2exp_si(b, b, -1);
  arb_mul(da, x, tt, p);
  arb_mul_2exp_si(da, da, -1);
  arb_mul_2exp_si(db, tt, -1);
  sin_cos_clipped(sa, ca, a, p);
  sin_cos_clipped(sb, cb, b, p);
  arb_mul(q, sa, cb, p);
  arb_mul(q, q, c, p);
  arb_mul(dq, sa, cb, p);
  arb_mul(dq, dq, dc, p);
  arb_mul(tmp, ca, cb, p);
  arb_mul(tmp, tmp, da, p);
  arb_mul(tmp2, sa, sb, p);
  arb_mul(tmp2, tmp2, db, p);
  arb_sub(tmp, tmp, tmp2, p);
  arb_mul(tmp, tmp, c, p);
  arb_add(dq, dq, tmp, p);
  arb_mul(qd, ca, cb, p);
  arb_mul(tmp, sa, sb, p);
  arb_mul(tmp, tmp, x, p);
  arb_sub(qd, qd, tmp, p);
  arb_mul(dqd, sa, cb, p);
  arb_mul(dqd, dqd, da, p);
  arb_mul(tmp, ca, sb, p);
  arb_mul(tmp, tmp, db, p);
  arb_add(dqd, dqd, tmp, p);
  arb_neg(dqd, dqd);
  arb_mul(tmp, sa, sb, p);
  arb_mul(tmp, tmp, dx, p);
  arb_sub(dqd, dqd, tmp, p);
  arb_mul(tmp, ca, sb, p);
  arb_mul(tmp, tmp, da, p);
  arb_mul(tmp2, sa, cb, p);
  arb_mul(tmp2, tmp2, db, p);
  arb_add(tmp, tmp, tmp2, p);
  arb_mul(tmp, tmp, x, p);
  arb_sub(dqd, dqd, tmp, p);
  arb_mul(R, q, q, p);
  arb_mul(tmp, qd, qd, p);
  arb_add(R, R, tmp, p);
  arb_mul(dR, q, dq, p);
  arb_mul(tmp, qd, dqd, p);
  arb_add(dR, dR, tmp, p);
  arb_mul_2exp_si(dR, dR, 1);
}

}  // namespace

enclosure enclosure_of_rationals(const big_rational& lo, const big_rational& hi) {
  const auto size = [](const big_rational& v) {
    return bits_of(boost::multiprecision::numerator(v)) + bits_of(boost::multiprecision::denominator(v));
  };
  const mpfr_prec_t bits = std::min<mpfr_prec_t>(mpfr_prec_t(1) << 20, 64 + std::max(size(lo), size(hi)));
  return enclosure(enclosure::exact(lo, bits).lo(), enclosure::exact(hi, bits).hi());  // outward, not exact
}

band_arith::band_arith(const horizon_time& T, slong prec) : T_(T), prec_(prec) { arb_const_pi(pi_, prec_); }

void band_arith::alpha_T(arb_t out, const band_coupling& c) const {
  ball s;
  set_rational(s, c.spec.n2 + 4, prec_);
  arb_sqrt(s, s, prec_);
  kernels_arb::alpha_T(out, s, T_, pi_, prec_);
}

big_int band_arith::cut_lobe(const band_coupling& c) const {
  if (std::optional<big_int> k = kernels_arb::cut_lobe(c.spec, T_, prec_)) return *k;
  throw precision_shortfall("the lobe holding t = T was not decided");
}

// H_x^{-1}(target), target a ball in [0, pi/2] (x = c.x, a point), by the one solver of
// H(u) = mu (theorem/root.hpp), with x and mu as intervals; its failure at this precision is a
// precision_shortfall (the band's loop raises the precision).
void band_arith::lobe_root(arb_t out, const band_coupling& c, const arb_t target) const {
  if (arb_is_zero(target)) {
    arb_zero(out);
    return;
  }
  ball x;
  set_quadratic(x, c.x, prec_);
  fixed_mpfi xi(prec_);
  arb_support::interval_of(xi, x);
  theorem_constants K(prec_);
  set_theorem_constants(K, xi);
  root_enclosure r(prec_);
  arb_support::interval_of(r.mu, target);
  const proof_status proved = prove_theorem_root(r, K);
  if (!proved) throw precision_shortfall(proved.reason());
  arb_support::set_ball(out, r.U, prec_);
}

void band_arith::signed_root(arb_t out, const band_coupling& c, const quadratic_number& signed_nu) const {
  ball target;
  set_quadratic(target, signed_nu.sign() < 0 ? -signed_nu : signed_nu, prec_);
  arb_mul(target, target, pi_, prec_);
  lobe_root(out, c, target);
  if (signed_nu.sign() < 0) arb_neg(out, out);
}

void band_arith::V(arb_t out, const band_coupling& c, const quadratic_number& nu) const {
  if (nu.sign() == 0) {
    arb_zero(out);
    return;
  }
  ball u, x;
  signed_root(u, c, nu);
  set_quadratic(x, c.x, prec_);
  kernels_arb::G(out, x, u, prec_);
  if (!arb_is_finite(out)) throw precision_shortfall("a lobe value V_x(nu) was not enclosed");
}

big_rational band_arith::V_upper(const band_coupling& c, const quadratic_number& nu) const {
  ball v;
  V(v, c, nu);
  return upper_rational(v, prec_);
}

big_rational band_arith::V_lower(const band_coupling& c, const quadratic_number& nu) const {
  ball v;
  V(v, c, nu);
  const big_rational r = lower_rational(v, prec_);
  return r > 0 ? r : big_rational(0);
}

// alpha_T increases with x: reached needs the minimiser's largest alpha on [a, b] at or below
// alpha_T(a), the least; not reached its least alpha above alpha_T(b), the largest.
bool band_arith::reached_on(const big_int& k, const band_coupling& a, const band_coupling& b, bool reached) const {
  const band_coupling &near = reached ? a : b, &far = reached ? b : a;
  ball u, top, at;
  alpha_T(at, near);
  if (k < 0) return false;
  if (k == 0) {  // u*_0 = H^{-1}(pi/2), largest at a (horizon Step 12 (b))
    signed_root(u, near, quadratic_number(1, 2));
    return reached ? arb_le(u, at) : arb_gt(u, at);
  }
  const quadratic_number ka = quadratic_number(k) * a.x, kb = quadratic_number(k) * b.x;
  if (ka.floor() != kb.floor()) return false;  // k x passes an integer: mu_k takes every value
  // mu_k(a)/pi, the largest on [a, b] (reached), or mu_k(b)/pi, the least
  const quadratic_number nu = quadratic_number(1, 2) - (reached ? ka : kb).frac();
  signed_root(u, nu.sign() >= 0 ? near : far, nu);
  set_int(top, k);
  arb_mul(top, top, pi_, prec_);
  arb_add(top, top, u, prec_);
  return reached ? arb_le(top, at) : arb_gt(top, at);
}

// g = (pi k - u)(1 - x^2) - x^2 tan u over [a, b] (band-theorem.md item 2, Step 4): at least its
// value at (x, u) = (b, u+), at most its value at (a, u-), with u+ >= every u of the interval,
// u- <= every one (u = H_x^{-1}(pi nu_k) rises with nu_k and falls with x). g_signed is g at the
// coupling `at` and one end of the ball u = H^{-1}(nu) at `root_at` (1 - x^2 = 4/(n^2 + 4)
// exactly): true when it is > 0 (upper end) or < 0 (lower end).
bool band_arith::g_signed(const big_int& k, const band_coupling& root_at, const quadratic_number& nu,
                          const band_coupling& at, bool upper_end) const {
  ball u, g, t, w;
  signed_root(u, root_at, nu);
  if (upper_end) arb_get_ubound_arf(arb_midref(u.get()), u, prec_);
  else arb_get_lbound_arf(arb_midref(u.get()), u, prec_);
  mag_zero(arb_radref(u.get()));
  set_int(g, k);
  arb_mul(g, g, pi_, prec_);
  arb_sub(g, g, u, prec_);
  set_rational(w, big_rational(4) / (at.spec.n2 + 4), prec_);
  arb_mul(g, g, w, prec_);
  arb_tan(t, u, prec_);
  set_rational(w, at.spec.n2 / (at.spec.n2 + 4), prec_);
  arb_mul(t, t, w, prec_);
  arb_sub(g, g, t, prec_);
  return upper_end ? arb_is_positive(g) : arb_is_negative(g);
}

std::pair<big_rational, big_rational> band_arith::end_point_range(const band_coupling& a, const band_coupling& b) const {
  // n over [a, b] as a ball from its ends' outward bounds; the mean value form about a rational
  // middle, intersected with the direct enclosure.
  ball na, nb, N, mid, R, dR, Rm, dRm, r, unit, spread, t;
  set_rational(na, a.spec.n2, prec_);
  arb_sqrt(na, na, prec_);
  set_rational(nb, b.spec.n2, prec_);
  arb_sqrt(nb, nb, prec_);
  const big_rational lo = lower_rational(na, prec_), hi = upper_rational(nb, prec_);
  arb_support::set_interval(N, lo, hi, prec_);
  set_rational(t, T_.value, prec_);
  if (T_.times_pi) arb_mul(t, t, pi_, prec_);
  R_and_slope(R, dR, N, t, prec_);
  set_rational(mid, (lo + hi) / 2, prec_);
  R_and_slope(Rm, dRm, mid, t, prec_);
  set_rational(r, (hi - lo) / 2, prec_);
  arb_zero_pm_one(unit);
  arb_mul(spread, dR, r, prec_);
  arb_mul(spread, spread, unit, prec_);
  arb_add(Rm, Rm, spread, prec_);
  std::optional<big_rational> inf, sup;
  for (const arb_srcptr v : {R.get(), Rm.get()}) {
    if (!arb_is_finite(v)) continue;
    const big_rational l = lower_rational(v, prec_), h = upper_rational(v, prec_);
    if (!inf || l > *inf) inf = l;
    if (!sup || h < *sup) sup = h;
  }
  if (!inf) throw precision_shortfall("the end point R(T) over an interval was not enclosed");
  if (*inf < 0) inf = big_rational(0);
  return {*inf, *sup};
}

// The proofs of the horizon theorem at one coupling, at this precision's digits: their enclosures'
// exact ends (2 h_min = the minimum of R).
std::pair<big_rational, big_rational> band_arith::minimum_at(const band_coupling& c, const stop_token& stop) const {
  const unsigned digits = std::clamp<unsigned>(unsigned(prec_ / 4), 12, report_digits_max - 3);
  const horizon_minimum_proof h = prove_horizon_minimum(c.spec, T_, {digits, {}}, proof_use::report, stop);
  return {h.h_min.lo_rational() * 2, h.h_min.hi_rational() * 2};
}

std::optional<std::pair<big_rational, big_rational>> band_arith::first_below_at(const band_coupling& c,
                                                                                const big_rational& E,
                                                                                const stop_token& stop) const {
  const unsigned digits = std::clamp<unsigned>(unsigned(prec_ / 4), 12, report_digits_max - 3);
  const first_below_proof f = prove_first_below(c.spec, E, {digits, {}}, proof_use::report, stop);
  if (f.kase == below_case::never) return std::nullopt;
  return std::pair{f.t_below.lo_rational(), f.t_below.hi_rational()};
}

std::pair<big_rational, big_rational> band_arith::middle_third(const band_coupling& a, const band_coupling& b) const {
  ball xa, xb, w, p, q;
  set_quadratic(xa, a.x, prec_);
  set_quadratic(xb, b.x, prec_);
  arb_sub(w, xb, xa, prec_);
  arb_div_ui(w, w, 3, prec_);
  arb_add(p, xa, w, prec_);
  arb_sub(q, xb, w, prec_);
  const big_rational lo = arb_support::arf_rational(arb_midref(p.get())), hi = arb_support::arf_rational(arb_midref(q.get()));
  if (!(lo < hi)) throw precision_shortfall("an interval narrower than the precision");
  return {lo, hi};
}

}  // namespace gyrores::band_detail
