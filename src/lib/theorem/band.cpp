// include/gyrores/theorem/band.hpp; the argument is proofs/horizon-theorem.md, Step 12.
#include <gyrores/theorem/band.hpp>

#include <arb.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <set>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/rotation.hpp>

#include "../core/ball.hpp"
#include "band_envelope.hpp"
#include "kernels_arb.hpp"

namespace gyrores {
namespace {

using namespace arb_support;
using namespace kernels_arb;
using band_detail::envelope_bound;
using band_detail::envelope_max;

constexpr slong lip_prec = 128;
// Lobe centres listed per box at most (more: the box is split first, with a one-lobe bound).
constexpr std::size_t max_centres = std::size_t(1) << 20;

// sin and cos of a ball, each clipped to [-1, 1] (Arb may return wider balls for wide arguments).
void sin_cos_clipped(arb_t s, arb_t c, const arb_t a, slong p) {
  arb_sin_cos(s, c, a, p);
  ball unit;
  arb_zero_pm_one(unit);
  if (!arb_is_finite(s) || !arb_contains(unit, s)) arb_set(s, unit);
  if (!arb_is_finite(c) || !arb_contains(unit, c)) arb_set(c, unit);
}


big_int floor_int(const arb_t v, bool upper, slong p) {
  arf_t b;
  arf_init(b);
  if (upper) arb_get_ubound_arf(b, v, p);
  else arb_get_lbound_arf(b, v, p);
  fmpz_holder z;
  arf_get_fmpz(z, b, ARF_RND_FLOOR);
  arf_clear(b);
  return z.value();
}

double H_double(double x, double u) { return x * u + std::atan2(x * std::sin(u), std::cos(u)); }

// An enclosure [a, b] of the u in [-pi/2, pi/2] with H_x(u) = c, for a point (or very thin) x
// in (0, 1) and every c in the ball |c| <= (1 + x) pi/2: H_x is strictly increasing (H' >= 2x),
// so H(a) < c < H(b) proves a < u < b. False when the ends cannot be decided.
bool H_inverse(arb_t out, const arb_t x, const arb_t c, slong p) {
  const double xd = arf_get_d(arb_midref(x), ARF_RND_NEAR), cd = arf_get_d(arb_midref(c), ARF_RND_NEAR);
  double lo = -M_PI / 2, hi = M_PI / 2;
  for (int i = 0; i < 80; ++i) {
    const double m = (lo + hi) / 2;
    (H_double(xd, m) < cd ? lo : hi) = m;
  }
  ball u, h, d, step, half_pi;
  arb_const_pi(half_pi, p);
  arb_mul_2exp_si(half_pi, half_pi, -1);
  arb_set_d(u, (lo + hi) / 2);
  for (int i = 0; i < 6; ++i) {  // Newton on midpoints: 53 bits doubles each step
    H(h, x, u, p);
    arb_sub(h, h, c, p);
    dH(d, x, u, p);
    arb_get_mid_arb(h, h);
    arb_get_mid_arb(d, d);
    arb_div(step, h, d, p);
    arb_sub(u, u, step, p);
    arb_get_mid_arb(u, u);
  }
  // eps: the rounding left, plus the width of c over the slope (>= 2x).
  ball eps, slope;
  arb_get_rad_arb(eps, c);
  dH(slope, x, u, p);
  arb_get_mid_arb(slope, slope);
  arb_div(eps, eps, slope, p);
  arb_mul_2exp_si(eps, eps, 1);
  ball floor_eps;
  arb_one(floor_eps);
  arb_mul_2exp_si(floor_eps, floor_eps, -(p - 24));
  arb_add(eps, eps, floor_eps, p);
  arb_get_ubound_arf(arb_midref(eps.get()), eps, p);
  mag_zero(arb_radref(eps.get()));
  for (int tries = 0; tries < 5; ++tries, arb_mul_2exp_si(eps, eps, 12)) {
    ball a, b, ha, hb, neg_half_pi;
    arb_sub(a, u, eps, p);
    arb_add(b, u, eps, p);
    arb_get_mid_arb(a, a);
    arb_get_mid_arb(b, b);
    arb_neg(neg_half_pi, half_pi);
    if (arb_lt(a, neg_half_pi)) arb_set(a, neg_half_pi);
    if (arb_gt(b, half_pi)) arb_set(b, half_pi);
    H(ha, x, a, p);
    H(hb, x, b, p);
    if (arb_lt(ha, c) && arb_gt(hb, c)) {
      arb_union(out, a, b, p);
      return true;
    }
  }
  return false;
}

// ---- The band's arithmetic context ----

struct band_ctx {
  horizon_time T;
  slong prec;
  ball pi, t;  // pi and the horizon T as balls
  stop_token stop;

  band_ctx(const horizon_time& horizon, const stop_token& s) : T(horizon), stop(s) {
    // The phases reach about T and must keep 128 bits after their integer part.
    const auto bits = [](const big_int& v) { return v == 0 ? slong(0) : slong(boost::multiprecision::msb(v < 0 ? big_int(-v) : v)) + 1; };
    const slong mag = std::max<slong>(0, bits(boost::multiprecision::numerator(T.value)) - bits(boost::multiprecision::denominator(T.value)) + 2);
    prec = 160 + 2 * mag;
    arb_const_pi(pi, prec);
    set_rational(t, T.value, prec);
    if (T.times_pi) arb_mul(t, t, pi, prec);
  }

  // x = n/sqrt(n^2 + 4) as a ball (n a ball).
  void x_of_n(arb_t out, const arb_t n) const {
    ball s;
    arb_mul(s, n, n, prec);
    arb_add_si(s, s, 4, prec);
    arb_sqrt(s, s, prec);
    arb_div(out, n, s, prec);
  }
  // An outward rational enclosure [lo, hi] of x(n) over n in [na, nb].
  std::pair<big_rational, big_rational> x_interval(const big_rational& na, const big_rational& nb) const {
    ball n, x;
    set_rational(n, na, prec);
    x_of_n(x, n);
    const big_rational lo = lower_rational(x, prec);
    set_rational(n, nb, prec);
    x_of_n(x, n);
    return {lo, upper_rational(x, prec)};
  }
  // alpha_T/pi + 1/2 = T/(pi sqrt(1 - x^2)) + 1/2, whose floor is the lobe k_c holding t = T.
  void cut_argument(arb_t out, const arb_t x) const {
    ball w;
    arb_mul(w, x, x, prec);
    arb_sub_si(w, w, 1, prec);
    arb_neg(w, w);
    arb_sqrt(w, w, prec);
    if (T.times_pi) set_rational(out, T.value, prec);
    else arb_div(out, t, pi, prec);
    arb_div(out, out, w, prec);
    ball h;
    arb_set_d(h, 0.5);
    arb_add(out, out, h, prec);
  }
  // A lower bound of k_c over x >= xa and an upper bound over x <= xb (k_c increases with x).
  big_int cut_lobe_at_least(const big_rational& xa) const {
    ball x, a;
    set_rational(x, xa, prec);
    cut_argument(a, x);
    return floor_int(a, false, prec);
  }
  big_int cut_lobe_at_most(const big_rational& xb) const {
    ball x, a;
    set_rational(x, xb, prec);
    cut_argument(a, x);
    return floor_int(a, true, prec);
  }
  // alpha_T = T/sqrt(1 - x^2) at x.
  void alpha_T(arb_t out, const big_rational& xv) const {
    ball x, w;
    set_rational(x, xv, prec);
    arb_mul(w, x, x, prec);
    arb_sub_si(w, w, 1, prec);
    arb_neg(w, w);
    arb_sqrt(w, w, prec);
    arb_div(out, t, w, prec);
  }

  // Bounds of the lobe minimiser u*_k(x) = H_x^{-1}(mu_k(x)), mu_k = pi (1/2 - {k x}), over
  // x in [xa, xb] (Step 12): increasing in mu; for mu > 0 decreasing in x, for mu < 0 increasing.
  // Returns false when a root could not be enclosed.
  bool lobe_minimiser_bounds(const big_int& k, const big_rational& xa, const big_rational& xb, arb_t lo, arb_t hi) const {
    const big_rational fa = xa * big_rational(k), fb = xb * big_rational(k);
    const auto floor_of = [](const big_rational& v) {
      return int_floor_div(big_int(boost::multiprecision::numerator(v)), big_int(boost::multiprecision::denominator(v)));
    };
    const big_int fl = floor_of(fa);
    big_rational t_min(-1, 2), t_max(1, 2);  // mu = pi t
    if (floor_of(fb) == fl) {
      // {k x} runs from {k xa} to {k xb} without wrapping: mu decreases from mu(xa) to mu(xb).
      t_max = big_rational(1, 2) - (fa - big_rational(fl));
      t_min = big_rational(1, 2) - (fb - big_rational(fl));
    }
    ball x, c;
    set_rational(x, t_max >= 0 ? xa : xb, prec);
    set_rational(c, t_max, prec);
    arb_mul(c, c, pi, prec);
    ball r;
    if (!H_inverse(r, x, c, prec)) return false;
    arf_t b;
    arf_init(b);
    arb_get_ubound_arf(b, r, prec);
    arb_set_arf(hi, b);
    set_rational(x, t_min >= 0 ? xb : xa, prec);
    set_rational(c, t_min, prec);
    arb_mul(c, c, pi, prec);
    if (!H_inverse(r, x, c, prec)) {
      arf_clear(b);
      return false;
    }
    arb_get_lbound_arf(b, r, prec);
    arb_set_arf(lo, b);
    arf_clear(b);
    return true;
  }
  // Lobe k's minimiser lies in [0, T] for every x in [xa, xb] whose cut lobe is k:
  // k pi + sup u*_k <= alpha_T(xa) <= alpha_T(x).
  bool lobe_reached_on(const big_int& k, const big_rational& xa, const big_rational& xb) const {
    ball lo, hi, a, kp;
    if (!lobe_minimiser_bounds(k, xa, xb, lo, hi)) return false;
    set_int(kp, k);
    arb_mul(kp, kp, pi, prec);
    arb_add(kp, kp, hi, prec);
    alpha_T(a, xa);
    return arb_le(kp, a);
  }
  // Lobe k's minimiser lies after T for every x in [xa, xb]: k pi + inf u*_k > alpha_T(xb).
  bool lobe_unreached_on(const big_int& k, const big_rational& xa, const big_rational& xb) const {
    ball lo, hi, a, kp;
    if (!lobe_minimiser_bounds(k, xa, xb, lo, hi)) return false;
    set_int(kp, k);
    arb_mul(kp, kp, pi, prec);
    arb_add(kp, kp, lo, prec);
    alpha_T(a, xb);
    return arb_gt(kp, a);
  }

  // sup over x in [ylo, yhi] of V_x(h) = G_x(H_x^{-1}(pi h)), h in [0, 1/2] (an upper bound):
  // H_x^{-1}(c) decreases in x for c > 0, so u <= H_{ylo}^{-1}(pi h); G_x increases in u on
  // [0, pi/2]. +infinity (an empty optional) when the root is not enclosed.
  std::optional<big_rational> V_upper(const big_rational& ylo, const big_rational& yhi, const big_rational& h) const {
    if (h <= 0) return big_rational(0);
    ball x, c, u, g, xs;
    set_rational(x, ylo, prec);
    set_rational(c, h, prec);
    arb_mul(c, c, pi, prec);
    if (!H_inverse(u, x, c, prec)) return std::nullopt;
    arf_t b;
    arf_init(b);
    arb_get_ubound_arf(b, u, prec);
    arb_set_arf(u, b);
    arf_clear(b);
    ball half_pi;
    arb_mul_2exp_si(half_pi, pi, -1);
    if (arb_gt(u, half_pi)) arb_set(u, half_pi);
    set_interval(xs, ylo, yhi, prec);
    G(g, xs, u, prec);
    if (!arb_is_finite(g)) return std::nullopt;
    return upper_rational(g, prec);
  }
  // inf over x in [ylo, yhi] of V_x(m), m in [0, 1/2] (a lower bound, >= 0).
  big_rational V_lower(const big_rational& ylo, const big_rational& yhi, const big_rational& m) const {
    if (m <= 0) return 0;
    ball x, c, u, g, xs;
    set_rational(x, yhi, prec);
    set_rational(c, m, prec);
    arb_mul(c, c, pi, prec);
    if (!H_inverse(u, x, c, prec)) return 0;
    arf_t b;
    arf_init(b);
    arb_get_lbound_arf(b, u, prec);
    arb_set_arf(u, b);
    arf_clear(b);
    if (!arb_is_positive(u)) return 0;
    set_interval(xs, ylo, yhi, prec);
    G(g, xs, u, prec);
    if (!arb_is_finite(g)) return 0;
    const big_rational r = lower_rational(g, prec);
    return r > 0 ? r : big_rational(0);
  }

  // R(n, T) = q^2 + q'^2 and dR/dn at t = T, n a ball (qdot0 = 1). With s = sqrt(n^2 + 4),
  // x = n/s, c = 2/s, alpha = s t/2, beta = n t/2: q = c sin(alpha) cos(beta),
  // q' = cos(alpha) cos(beta) - x sin(alpha) sin(beta); d alpha/dn = x t/2, d beta/dn = t/2,
  // dx/dn = 4/s^3, dc/dn = -2n/s^3 (Step 12).
  // s, x, c = 2/s, dx/dn = 4/s^3 and dc/dn = -2n/s^3 over a ball of n > 0. Each is monotone in n
  // except dc/dn, whose size 2n/s^3 peaks at n = sqrt 2: enclosed from the ball's ends, since
  // evaluating them on a wide ball directly can divide by a ball that holds 0 (s^3 from s s s).
  static void coefficients(arb_t s, arb_t x, arb_t c, arb_t dx, arb_t dc, const arb_t n, slong p) {
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
  void R_and_slope(arb_t R, arb_t dR, const arb_t n, const arb_t tt, slong p) const {
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
  // [inf, sup] of R(n, T) over n in [na, nb]: the mean-value form R(mid) + R'(N) [-r, r]
  // intersected with the direct enclosure.
  std::pair<big_rational, big_rational> R_range(const big_rational& na, const big_rational& nb) const {
    ball n, R, dR, Rm, dRm, mid, r;
    set_interval(n, na, nb, prec);
    R_and_slope(R, dR, n, t, prec);
    set_rational(mid, (na + nb) / 2, prec);
    R_and_slope(Rm, dRm, mid, t, prec);
    set_rational(r, (nb - na) / 2, prec);
    ball spread, unit;
    arb_zero_pm_one(unit);
    arb_mul(spread, dR, r, prec);
    arb_mul(spread, spread, unit, prec);
    arb_add(Rm, Rm, spread, prec);
    // Both contain every R(n, T), n in [na, nb]: keep the tighter end of each.
    std::optional<big_rational> lo, hi;
    for (const arb_srcptr v : {R.get(), Rm.get()}) {
      if (!arb_is_finite(v)) continue;
      const big_rational l = lower_rational(v, prec), h = upper_rational(v, prec);
      if (!lo || l > *lo) lo = l;
      if (!hi || h < *hi) hi = h;
    }
    if (!lo || !hi) throw compute_error("band: no finite enclosure of R(T) over a box");
    if (*lo < 0) lo = big_rational(0);
    return {*lo, *hi};
  }
};

// ---- Point evaluations and degenerate pairs ----

// A degenerate pair in the band whose zero t = pi sqrt(4k^2 - o^2)/2 (x = o/(2k), o odd) lies in
// [0, T]: the smallest k with such an o, taking the largest o (the earliest zero for that k).
// The zero of lobe k is at t = pi k sqrt(1 - x^2) >= pi k sqrt(1 - x2^2), so no k beyond
// T/(pi sqrt(1 - x2^2)) can have one; the scan ends there, or earlier at the first hit: when that
// bound is large, some k <= 1/(x2 - x1) + 1 holds an odd o in [2k x1, 2k x2] and its zero is early.
// The first zero of H_q of a degenerate coupling, as reported at 12 digits (the horizon theorem's
// first time below 0: the pair's t_first).
proved_real first_zero(const coupling_spec& c) {
  proved_real t;
  prove_first_below(c, 0, {12, [&t](const first_below_proof& p) {
                             auto r = p.t_below.report(12);
                             if (!r) return proof_status::undecided("the rounding of the first zero");
                             t = std::move(*r);
                             return proof_status::proved();
                           }});
  return t;
}

std::optional<band_degenerate> find_degenerate(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                               const stop_token& stop) {
  const quadratic_number x1 = coupling_rotation_number(coupling_spec::from_n(n1)),
                         x2 = coupling_rotation_number(coupling_spec::from_n(n2));
  const double T_d = T.value.convert_to<double>() * (T.times_pi ? M_PI : 1.0);
  const double sqrt1mx2 = std::sqrt(std::max(0.0, 1 - x2.approx() * x2.approx()));
  // t ~ pi k sqrt(1 - x^2) >= pi k sqrt(1 - x2^2) (rounded generously).
  const double k_last = sqrt1mx2 > 0 ? T_d / (M_PI * sqrt1mx2 * (1 - 1e-9)) + 2 : 1e300;
  for (long k = 1; double(k) <= k_last; ++k) {
    if (k % 4096 == 0) stop.throw_if_requested();
    big_int o = (quadratic_number(2 * k) * x2).floor();
    if (o % 2 == 0) o -= 1;
    if (o < 1 || quadratic_number(o, 2 * k) < x1) continue;
    // The zero's time pi sqrt(4k^2 - o^2)/2 against T, in Arb.
    const big_int r2 = big_int(4) * k * k - o * o;
    for (slong p = 128; p <= (slong(1) << 16); p *= 2) {
      ball t, hT, pi;
      set_int(t, r2);
      arb_sqrt(t, t, p);
      arb_mul_2exp_si(t, t, -1);
      arb_const_pi(pi, p);
      set_rational(hT, T.value, p);
      if (T.times_pi) arb_mul(hT, hT, pi, p);
      arb_mul(t, t, pi, p);
      if (arb_gt(t, hT)) break;
      if (arb_le(t, hT)) {
        const big_rational n2_exact(4 * o * o, r2);
        const auto pair = coupling_resonant_pair(coupling_spec::from_n2(n2_exact));
        if (!pair) throw compute_error("band: x = " + o.str() + "/" + std::to_string(2 * k) + " gave no pair");
        return band_degenerate{n2_exact, *pair, first_zero(coupling_spec::from_n2(n2_exact))};
      }
    }
  }
  return std::nullopt;
}

// An upper bound of |dH_q/dn| for t in [0, T] and n in [n1, n2] (reported; M is L-Lipschitz).
big_rational lipschitz_bound(const band_ctx& ctx, const big_rational& n1, const big_rational& n2) {
  const slong p = lip_prec;
  ball n, t, zero, R, dR;
  set_interval(n, n1, n2, p);
  arb_zero(zero);
  arb_union(t, zero, ctx.t, p);
  ctx.R_and_slope(R, dR, n, t, p);
  if (!arb_is_finite(dR)) throw compute_error("band: no finite bound of dH_q/dn");
  arb_mul_2exp_si(dR, dR, -1);  // dH_q/dn = (dR/dn)/2
  arb_abs(dR, dR);
  return upper_rational(dR, p);
}

// M(n) as a proved enclosure of R = 2 H_q (the horizon theorem at an exact rational n).
std::pair<big_rational, big_rational> minimum_at(const big_rational& n, const horizon_time& T, const stop_token& stop) {
  // (Proved until its minimum, first time and radius round to 17 digits, and its ends rounded
  // outward to 20 digits: the band's search, and so its outputs, as before the one-core refactor.)
  const auto decided = [](const horizon_minimum_proof& p) {
    return p.h_min.rounded(17) && p.t_min.rounded(17) && p.r_min.rounded(17) ? proof_status::proved()
                                                                              : proof_status::undecided("a rounding");
  };
  const auto [lo, hi] = prove_horizon_minimum(coupling_spec::from_n(n), T, {17, decided}, proof_use::report, stop).h_min.outward_rationals(20);
  return {lo * 2, hi * 2};
}

// A rational n in [na, nb] near n(x) = 2x/sqrt(1 - x^2).
big_rational n_near(const band_ctx& ctx, const big_rational& x, const big_rational& na, const big_rational& nb) {
  ball xb, w, n;
  set_rational(xb, x, ctx.prec);
  arb_mul(w, xb, xb, ctx.prec);
  arb_sub_si(w, w, 1, ctx.prec);
  arb_neg(w, w);
  arb_sqrt(w, w, ctx.prec);
  arb_div(n, xb, w, ctx.prec);
  arb_mul_2exp_si(n, n, 1);
  if (!arb_is_finite(n)) return (na + nb) / 2;
  const big_rational v = arf_rational(arb_midref(n.get()));
  return v < na ? na : (v > nb ? nb : v);
}

std::string rounding_of(const big_rational& lo, const big_rational& hi, unsigned digits) {
  const std::string a = format_rational_scientific(lo, digits), b = format_rational_scientific(hi, digits);
  return a == b ? a : std::string();
}

// ---- The branch and bound (Step 12) ----

struct box {
  big_rational a, b;   // the box of n
  big_rational bound;  // U(N) (worst) or L(N) (best), in R = 2 H_q
  big_rational cap;    // worst: an upper bound of nu* over the box for its lobes (the parent's)
  std::optional<big_rational> hint;  // where to evaluate M next
};

struct search {
  const band_ctx& ctx;
  big_rational n1, n2;
  quadratic_number x1, x2;  // x at the band's ends, exactly
  const band_options& opt;
  bool worst;
  std::size_t evaluations = 0, boxes = 0;
  std::set<big_rational> evaluated;
  // The cached nu*_K at the band's ends (best case).
  std::map<big_int, quadratic_number> end_nu[2];

  search(const band_ctx& c, const big_rational& a, const big_rational& b, const band_options& o, bool w)
      : ctx(c), n1(a), n2(b), x1(coupling_rotation_number(coupling_spec::from_n(a))),
        x2(coupling_rotation_number(coupling_spec::from_n(b))), opt(o), worst(w) {}

  // U(N): the worst case's upper bound over the box [a, b].
  box upper(const big_rational& a, const big_rational& b, const big_rational& cap) {
    ++boxes;
    box out{a, b, 0, cap, std::nullopt};
    const auto [xa, xb] = ctx.x_interval(a, b);
    const auto [r_lo, r_hi] = ctx.R_range(a, b);
    (void)r_lo;
    out.bound = r_hi;
    // Lobes 0..k_c^- - 1 are admissible on all of N, and lobe k_c^- too when its minimiser is
    // reached wherever it is the cut lobe.
    const big_int kc = ctx.cut_lobe_at_least(xa);
    big_int K = kc - 1;
    if (kc >= 0 && ctx.lobe_reached_on(kc, xa, xb)) K = kc;
    if (K < 0) {
      out.hint = (a + b) / 2;
      return out;
    }
    const envelope_bound env = envelope_max(xa, xb, K, cap, max_centres, 3, ctx.stop);
    out.cap = env.value;
    // V_x(nu*(x)) <= V_x(height of the piece holding x) <= sup over the piece of V(height).
    std::optional<big_rational> uv = big_rational(0);
    for (const auto& pc : env.top) {
      const auto v = ctx.V_upper(pc.lo, pc.hi, pc.height);
      if (!v) uv.reset();
      else if (uv && *v > *uv) uv = v;
      if (!uv) break;
    }
    if (uv && (env.top.empty() || env.rest > 0)) {
      const auto v = ctx.V_upper(xa, xb, env.top.empty() ? env.value : env.rest);
      if (!v) uv.reset();
      else if (*v > *uv) uv = v;
    }
    if (env.enumerated && env.centres <= 64) {
      // Also the one lobe best at the middle (its bound tends to nu* there as the box shrinks,
      // whichever tents the pieces used).
      const big_int k = min_distance_to_half(quadratic_number(big_rational((xa + xb) / 2)), K).k;
      const big_rational one = band_detail::lobe_distance_max(xa, xb, k);
      if (one < env.value) {
        const auto v = ctx.V_upper(xa, xb, one);
        if (v && (!uv || *v < *uv)) uv = v;
      }
    }
    if (uv && *uv < out.bound) {
      out.bound = *uv;
      // Where the highest peak is (a one-lobe bound says little about where M is largest).
      if (env.enumerated && !env.top.empty()) out.hint = n_near(ctx, env.top.front().at, a, b);
    } else out.hint = (a + b) / 2;
    return out;
  }

  const quadratic_number& end_distance(int side, const big_int& K) {
    auto& cache = end_nu[side];
    auto it = cache.find(K);
    if (it == cache.end()) it = cache.emplace(K, min_distance_to_half(side == 0 ? x1 : x2, K).value).first;
    return it->second;
  }

  // L(N): the best case's lower bound over the box [a, b].
  box lower(const big_rational& a, const big_rational& b) {
    ++boxes;
    box out{a, b, 0, 0, std::nullopt};
    const auto [xa, xb] = ctx.x_interval(a, b);
    const auto [r_lo, r_hi] = ctx.R_range(a, b);
    (void)r_hi;
    out.bound = r_lo;
    // Lobes up to k_c^+ may be admissible somewhere on N; lobe k_c^+ is not if its minimiser lies
    // after T on all of N.
    const big_int kc_hi = ctx.cut_lobe_at_most(xb), kc_lo = ctx.cut_lobe_at_least(xa);
    big_int K = kc_hi;
    if (ctx.lobe_unreached_on(kc_hi, xa, xb)) K = kc_hi - 1;
    if (K < 0) {
      out.hint = (a + b) / 2;
      return out;
    }
    // The box's x-interval inside the band, with the band's own ends exact: no lobe k < k_c^- has
    // a centre in it (that would be a degenerate pair of the band with its zero before T).
    const quadratic_number ya = a == n1 ? x1 : std::max(x1, quadratic_number(xa));
    const quadratic_number yb = b == n2 ? x2 : std::min(x2, quadratic_number(xb));
    bool centre = false;
    const big_int k_first = kc_lo < 1 ? big_int(1) : kc_lo;
    if (K - k_first >= 64) centre = true;
    else
      for (big_int k = k_first; k <= K && !centre; ++k) {
        // A centre (2j+1)/(2k) in [ya, yb]: an integer in [k ya - 1/2, k yb - 1/2].
        const quadratic_number lo = quadratic_number(k) * ya - quadratic_number(1, 2);
        const big_int c = lo.ceil();
        if (quadratic_number(c) <= quadratic_number(k) * yb - quadratic_number(1, 2)) centre = true;
      }
    big_rational m = 0;
    std::optional<big_rational> hint;
    if (!centre) {
      const quadratic_number va = a == n1 ? end_distance(0, K) : min_distance_to_half(ya, K).value;
      const quadratic_number vb = b == n2 ? end_distance(1, K) : min_distance_to_half(yb, K).value;
      // Exact rationals, except at a band end (an irrational x): there a rational lower bound.
      const auto low = [this](const quadratic_number& v) {
        if (v.is_rational()) return big_rational(v.p(), v.r());
        ball vb_ball;
        set_quadratic(vb_ball, v, ctx.prec);
        const big_rational l = lower_rational(vb_ball, ctx.prec);
        return l > 0 ? l : big_rational(0);
      };
      const big_rational ma = low(va), mb = low(vb);
      m = ma <= mb ? ma : mb;
      hint = ma <= mb ? a : b;
    }
    const big_rational lv = ctx.V_lower(xa, xb, m);
    if (lv < out.bound) {
      out.bound = lv;
      out.hint = hint ? *hint : big_rational((a + b) / 2);
    } else out.hint = (a + b) / 2;
    return out;
  }

  band_extreme run(std::size_t& total_evaluations, std::size_t& total_boxes) {
    band_extreme e;
    const big_rational rel = big_rational(1, boost::multiprecision::pow(big_int(10), opt.digits));
    big_rational best_lo, best_hi;  // the best proved point value (max of lo / min of hi), R units
    bool have = false;
    auto evaluate = [&](const big_rational& n, const big_rational& a, const big_rational& b) {
      if (!evaluated.insert(n).second) return;
      const auto [lo, hi] = minimum_at(n, ctx.T, opt.stop);
      ++evaluations;
      if (!have || (worst ? lo > best_lo : hi < best_hi)) {
        have = true;
        best_lo = lo;
        best_hi = hi;
        e.n_at = n;
        e.n_box_lo = a;
        e.n_box_hi = b;
      }
    };
    auto cmp = [this](const box& x, const box& y) { return worst ? x.bound < y.bound : x.bound > y.bound; };
    std::priority_queue<box, std::vector<box>, decltype(cmp)> open(cmp);
    evaluate(n1, n1, n1);
    evaluate(n2, n2, n2);
    const big_rational half(1, 2);
    open.push(worst ? upper(n1, n2, half) : lower(n1, n2));
    auto report = [&](const big_rational& lo, const big_rational& hi) {
      if (!opt.progress) return;
      band_progress p;
      p.worst = worst;
      p.evaluations = evaluations;
      p.boxes = boxes;
      p.lo = lo.convert_to<double>() / 2;
      p.hi = hi.convert_to<double>() / 2;
      opt.progress(p);
    };
    for (;;) {
      opt.stop.throw_if_requested();
      // The extreme lies between the best proved value and the best remaining bound.
      const big_rational top = open.empty() ? (worst ? best_lo : best_hi) : open.top().bound;
      e.lo = worst ? best_lo : (top < best_hi ? top : best_hi);
      e.hi = worst ? (top > best_lo ? top : best_lo) : best_hi;
      report(e.lo, e.hi);
      if (e.hi - e.lo <= rel * e.hi) {
        // Narrow enough; a little more work usually settles the last digit's rounding too.
        e.converged = true;
        if (!rounding_of(e.lo / 2, e.hi / 2, opt.digits).empty() || e.hi - e.lo <= rel * e.hi / 1000) break;
      }
      if (evaluations + boxes + 3 > opt.max_evaluations) break;
      box bx = open.top();
      open.pop();
      if (bx.hint && !evaluated.count(*bx.hint)) {
        evaluate(*bx.hint, bx.a, bx.b);
        bx.hint.reset();
        // The box stays as it is (its bound still holds); it is split when it is on top again.
        if (worst ? bx.bound > best_lo : bx.bound < best_hi) open.push(bx);
        continue;
      }
      const big_rational mid = (bx.a + bx.b) / 2;
      for (const auto& [a, b] : {std::pair{bx.a, mid}, std::pair{mid, bx.b}}) {
        box child = worst ? upper(a, b, bx.cap) : lower(a, b);
        // A box that cannot beat the best proved value is dropped.
        if (worst ? child.bound > best_lo : child.bound < best_hi) open.push(std::move(child));
      }
    }
    // The smallest box still open around n_at, if any, says where the extreme is found.
    for (; !open.empty(); open.pop()) {
      const box& bx = open.top();
      if (bx.a <= e.n_at && e.n_at <= bx.b && bx.b - bx.a < e.n_box_hi - e.n_box_lo) {
        e.n_box_lo = bx.a;
        e.n_box_hi = bx.b;
      }
    }
    total_evaluations += evaluations;
    total_boxes += boxes;
    // R = 2 H_q: the report is in H_q.
    e.lo /= 2;
    e.hi /= 2;
    if (e.lo < 0) e.lo = 0;
    e.value = rounding_of(e.lo, e.hi, opt.digits);
    return e;
  }
};

}  // namespace

band_report prove_band(const big_rational& n1, const big_rational& n2, const horizon_time& T, const band_options& opt) {
  check_band(n1, n2, "a band");
  if (T.value < 0) throw usage_error("the horizon must be >= 0, got " + T.str());
  if (opt.digits < 1 || opt.digits > 12) throw usage_error("band digits must be in [1, 12], got " + std::to_string(opt.digits));
  band_report r;
  r.n1 = n1;
  r.n2 = n2;
  r.horizon = T;
  r.digits = opt.digits;
  const band_ctx ctx(T, opt.stop);
  r.lipschitz = format_rational_scientific(lipschitz_bound(ctx, n1, n2), 6);
  if (opt.want_worst) r.worst = search(ctx, n1, n2, opt, true).run(r.evaluations, r.boxes);
  if (!opt.want_best) return r;
  r.zero = find_degenerate(n1, n2, T, opt.stop);
  if (r.zero) {
    r.best.lo = r.best.hi = 0;
    r.best.value = format_rational_scientific(big_rational(0), opt.digits);
    r.best.n_at = 0;
    r.best.converged = true;
  } else r.best = search(ctx, n1, n2, opt, false).run(r.evaluations, r.boxes);
  return r;
}

}  // namespace gyrores
