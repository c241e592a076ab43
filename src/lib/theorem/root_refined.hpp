// The double-double root of theorem/root.hpp (theorem_root_refined) as always-inline functions,
// so that theorem/minimum.cpp's double path gets them in its own code (no call, no result in
// memory) and root.cpp defines the public function from the same text. Private to src/lib.
#pragma once
#include <algorithm>
#include <cmath>

#include <gyrores/core/double_double.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores::detail {

// compute_error: the steps did not settle (out of line: the hot path carries no string).
[[noreturn, gnu::cold]] void root_refined_failed();

// sin and cos of 0 <= v <= 3/2 to about 2^-50 from the high parts of core/double_double.hpp's
// table and Taylor polynomials of d = v - i/128 to d^5 (the double steps' values: they need no
// more, the double-double step below decides).
struct sin_cos_pair {
  double s, c;
};
GYRORES_DD_INLINE sin_cos_pair sin_cos_rough(const sin_cos_table& t, double v) {
  const int i = int(v * 128);
  const double d = v - i * 0x1p-7, e = d * d;
  const double cd = 1 - e * (0.5 - e * (1.0 / 24)), sd = d - d * e * (1.0 / 6 - e * (1.0 / 120));
  const double S = t.s[std::size_t(i)].hi, C = t.c[std::size_t(i)].hi;
  return {S * cd + C * sd, C * cd - S * sd};
}

// The start of theorem_root_refined's Newton steps, with v = mu/(2x) = pi m/(4b) (> 1/2 only for
// b = 1: m = 1 for b odd, b = 2 is degenerate, b >= 3 gives v <= pi/8). Only the speed depends on
// it (the double-double step decides). Two expansions, each within 2^-37 u* where `close` says
// so (measured against MPFR roots: the O(v^6) and O(x^6) remainders are about v^6/2 and x^6/3):
//  - H(u)/(2x) = u + alpha u^3 + beta u^5 + O(u^7), alpha = (1 - x^2)/6, beta = (1 - x^2)(2 -
//    3x^2)/30 (the series of tan and arctan), inverted: u* = v - alpha v^3 + (3 alpha^2 - beta) v^5
//    + O(v^7); close for v <= 2^-5 (b >= 25: most pairs of a large sweep);
//  - b = 1 (mu/x = pi/2, x = 1/a): H(u)/x = u + tan u - x^2 tan^3 u/3 + x^4 tan^5 u/5 - ..., so
//    u* = u0 + c1 x^2 + c2 x^4 + O(x^6) with u0 + tan u0 = pi/2 (the x -> 0 limit), t = tan u0,
//    c1 = t^3/(3 (2 + t^2)), c2 = (t^2 (1 + t^2) c1 - t (1 + t^2) c1^2 - t^5/5)/(2 + t^2) (the
//    constants to double precision, from mpmath at 40 digits); close for x <= 2^-5.
struct root_start {
  double u;
  bool close;
};
GYRORES_DD_INLINE root_start theorem_root_start(double x, double v) {
  if (v > 0.5) {
    constexpr double u0 = 0x1.6bc1c59f8b810p-1, c1 = 0x1.3d4b245548d38p-4, c2 = -0x1.4c7d8a66b6b0fp-10;
    const double x2 = x * x;
    return {u0 + x2 * (c1 + x2 * c2), x <= 0x1p-5};
  }
  const double y = 1 - x * x, alpha = y * (1.0 / 6), beta = y * (2 - 3 * x * x) * (1.0 / 30), v2 = v * v;
  return {v * (1 - v2 * (alpha - v2 * (3 * alpha * alpha - beta))), v <= 0x1p-5};
}

// Newton steps in double on G(u) = tan(H(u) - mu) = F/D (F as in theorem/root.hpp, D = cos u cos w
// + x sin u sin w > 0 for w > 0), which has the root of H and needs no arctangent: G' = (1 + G^2)
// H', H' = x (E + 1)/E, F^2 + D^2 = E = cos^2 u + x^2 sin^2 u, so the step G/G' is F D/(x (E + 1)).
// Until a step is below 2^-18 u: H''/(2H') = (1 - x^2) sin u cos u/(E (E + 1)) <= 2/3 (E >= 1/2
// for u <= pi/4), so the error left is about 2^-36 u^2 <= 2^-36.3 u, below the 2^-35 u the
// double-double step accepts. Kept in [lo, hi] (the root's bracket: w >= mu/2 > 0 there).
GYRORES_DD_INLINE double theorem_root_double_steps(const sin_cos_table& t, double x, double mu, double u, double lo,
                                                  double hi) {
  for (int i = 0; i < 8; ++i) {
    const sin_cos_pair su = sin_cos_rough(t, u), sw = sin_cos_rough(t, mu - x * u);
    const double F = x * su.s * sw.c - su.c * sw.s, D = su.c * sw.c + x * su.s * sw.s;
    const double E = su.c * su.c + x * x * su.s * su.s;
    const double du = F * D / (x * (E + 1));
    u = std::clamp(u - du, lo, hi);
    if (std::fabs(du) <= 0x1p-18 * u) break;
  }
  return u;
}

// The accepted double-double step of theorem/root.hpp (either kind below): its start u (a
// double in the bracket [lo, hi], so w = mu - x u >= mu/2 > 0), its correction delta (u* = u +
// delta within 2^-61 u through the table, 2^-63 u by the small step), and the sines and cosines
// at u and at w(u): sin within 2^-63 relative (small step: 2^-66.4), cos within 2^-63.
struct root_step {
  double u, delta;
  double_double sin_u, cos_u, sin_w, cos_w;
};

// The step through the table (any u <= pi/4, w <= pi/6), into s; true if its correction is below
// 2^-35 u. F = x sin u cos w - cos u sin w with the sines and cosines of core/double_double.hpp
// (dd_sin_cos_first_quadrant: sin within 2^-63 relative, cos within 2^-63, so within 2^-62.5
// relative as cos u >= cos(pi/4), cos w >= cos(pi/6)) and two double-double products (7u^2
// each): T1 = x sin u cos w and T2 = cos u sin w within 2^-61.7 of theirs; T1 - T2 by an exact
// two_sum of the high parts and the low parts in double.
GYRORES_DD_INLINE bool table_step_at(const sin_cos_table& table, const double_double& x, const double_double& mu,
                                     double u, root_step& s) {
  double_double su, cu, sw, cw;
  dd_sin_cos_first_quadrant(table, u, su, cu);
  dd_sin_cos_first_quadrant(table, dd::sub(mu, dd::mul(x, u)), sw, cw);
  const double_double T1 = dd::mul(dd::mul(x, su), cw), T2 = dd::mul(cu, sw);
  const double_double f = dd::two_sum(T1.hi, -T2.hi);
  const double F = f.hi + (f.lo + (T1.lo - T2.lo));
  const double dF = 2 * x.hi * cu.hi * cw.hi + (1 + x.hi * x.hi) * su.hi * sw.hi;
  const double delta = -F / dF;
  s = {u, delta, su, cu, sw, cw};
  return std::fabs(delta) <= 0x1p-35 * u;
}

// The same step for u, w < 2^-7 (v < 2^-7 and mu < 2^-7: b >= 101 m and a >= 201 m), by the
// Taylor polynomials alone: sin v = v (1 + p(v)), cos v = 1 - g(v), p and g those of
// dd_sin_cos_first_quadrant (|p| < 2^-16.5, |g| < 2^-15, within 2^-67.3 and 2^-65.9 in double).
// Then F = (x u - w) + x u A - w B, A = p(u) - g(w) - p(u) g(w), B = p(w) - g(u) - p(w) g(u),
// and x u - w = 2 x u - mu = L. L from the exact product 2 x.hi u = P: 2 P.hi - mu.hi is exact
// when it is below mu.hi/2 (Sterbenz's lemma), the low parts in double. p(w) and g(w) are taken
// at wr = RN(RN(mu.hi - x.hi u) + RN(mu.lo - x.lo u)) (one fma and an addition, without waiting
// for w's double-double), within 2^-51.9 w of w, so within 2^-65 of theirs (their slopes are
// below w < 2^-7); with their evaluation errors and the roundings of A and B (|A|, |B| <
// 2^-14.4) A and B are within 2^-64.2, and with x u A, w B and their sum in double (and wr for w
// in w B) F is within 2^-63.5 (x u + w) <= 2^-62.5 x u near the root (w <= x u (1 + 2^-13)), so
// the step within 2^-63.5 u (F' >= 2x cos u cos w > 1.99 x).
// A step is accepted when its correction delta is below 2^-30 u (not the table step's 2^-35: u <
// 2^-7 here): Newton's quadratic term is then below (1 + x^2) tan u 2^-60 u^2 <= 2^-65.9 u, the
// step's own rounding (dF in double) below 2^-49 |delta| <= 2^-79 u, so u + delta is within
// 2^-63 u of u*; and |L| <= |F| + |x u A| + |w B| <= 2^-14.3 mu, as Sterbenz needs.
GYRORES_DD_INLINE bool small_step_at(const double_double& x, const double_double& mu, double u, root_step& s) {
  const double_double P = dd::two_prod(x.hi, u);
  const double c = mu.lo - x.lo * u;
  const double wr = __builtin_fma(-x.hi, u, mu.hi) + c;
  // w = mu - x u within 2^-104 w (the fast_two_sum of the high parts is exact: x.hi u <= mu.hi/2
  // (1 + 2^-50) in the bracket).
  const double_double d = dd::fast_two_sum(mu.hi, -P.hi);
  const double_double w = dd::fast_two_sum(d.hi, d.lo + (mu.lo - P.lo - x.lo * u));
  const double eu = u * u, ew = wr * wr;
  const double gu = eu * (0.5 - eu * (1.0 / 24 - eu * (1.0 / 720)));
  const double gw = ew * (0.5 - ew * (1.0 / 24 - ew * (1.0 / 720)));
  const double pu = eu * (-1.0 / 6 + eu * (1.0 / 120 - eu * (1.0 / 5040)));
  const double pw = ew * (-1.0 / 6 + ew * (1.0 / 120 - ew * (1.0 / 5040)));
  const double A = pu - gw - pu * gw, B = pw - gu - pw * gu;
  const double F = (2 * P.hi - mu.hi) + ((2 * P.lo + 2 * x.lo * u - mu.lo) + (P.hi * A - wr * B));
  const double dF = 2 * x.hi * (1 - gu) * (1 - gw) + (1 + x.hi * x.hi) * u * wr;
  const double delta = -F / dF;
  // sin u = u + u p(u) within 2^-67 u; sin w = w + w p(w) within 2^-66.4 w (p at wr: 2^-67.5).
  s = {u, delta, dd::fast_two_sum(u, u * pu), dd::fast_two_sum(1, -gu), dd::fast_two_sum(w.hi, w.lo + w.hi * pw),
       dd::fast_two_sum(1, -gw)};
  return std::fabs(delta) <= 0x1p-30 * u;
}

// True where the small step applies (v ~ mu/(2x) bounds u in the bracket, mu bounds w).
GYRORES_DD_INLINE bool small_root_applies(const double_double& mu, double v) { return v < 0x1p-7 && mu.hi < 0x1p-7; }

// The steps of theorem_root_refined up to the accepted one, with x_rough and v = mu/(2x) to a few
// ulps as the start's inputs and the bracket's upper end (only the speed depends on them: a caller
// holding the pair's integers forms them from those, off the path through x and mu).
//  - Small steps (u, w < 2^-7) from theorem_root_start's series to v^3 (its v^5 coefficient 3
//    alpha^2 - beta = y/30 - y^2/60, y = 1 - x^2, lies in [0, 1/60], so the start is within
//    2^-33.8 u* for v < 2^-7, inside the accepted 2^-30: one step; it is below v, in the bracket).
//  - Otherwise theorem_root_start, double steps where it is not close, then table steps.
GYRORES_DD_INLINE root_step root_step_of(const double_double& x, const double_double& mu, double x_rough, double v) {
  // The root's bracket, widened below (u* >= mu/(1 + x) > mu/2; no division): the steps stay in
  // it, so w = mu - x u >= mu/2 > 0 (to an ulp or two of v).
  const double lo = 0.5 * mu.hi, hi = v;
  root_step s;
  if (small_root_applies(mu, v)) {
    double u = v * (1 - (v * v) * ((1 - x_rough * x_rough) * (1.0 / 6)));
    for (int step = 0; step < 4; ++step, u = std::clamp(u + s.delta, lo, hi))
      if (small_step_at(x, mu, u, s)) return s;
  } else {
    const root_start start = theorem_root_start(x_rough, hi);
    double u = std::clamp(start.u, lo, hi);
    const sin_cos_table& table = dd_sin_cos_table();
    if (!start.close) u = theorem_root_double_steps(table, x.hi, mu.hi, u, lo, hi);
    for (int step = 0; step < 4; ++step, u = std::clamp(u + s.delta, lo, hi))
      if (table_step_at(table, x, mu, u, s)) return s;
  }
  root_refined_failed();
}

// theorem_root_refined (theorem/root.hpp): the accepted step's u + delta, and the sines and
// cosines there by their first-order terms (the second are below 2^-70 of them through the
// table, |x delta| <= 2^-35 x u <= 2^-35 w as x u <= mu/2 <= w, and 2^-60 u^2 <= 2^-74 of them
// by the small step).
GYRORES_DD_INLINE root_double_double root_refined(const double_double& x, const double_double& mu, double x_rough,
                                                  double v) {
  const root_step s = root_step_of(x, mu, x_rough, v);
  return {dd::two_sum(s.u, s.delta), dd::add(s.sin_u, s.delta * s.cos_u.hi), dd::add(s.cos_u, -s.delta * s.sin_u.hi),
          dd::add(s.sin_w, -(x.hi * s.delta) * s.cos_w.hi)};
}

}  // namespace gyrores::detail
