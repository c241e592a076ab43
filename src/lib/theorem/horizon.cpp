// include/gyrores/theorem/horizon.hpp; the argument is proofs/horizon-theorem.md.
#include <gyrores/theorem/horizon.hpp>

#include <arb.h>

#include "../core/ball.hpp"
#include "lobe_balls.hpp"

#include <algorithm>
#include <functional>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/model/rotation.hpp>

namespace gyrores {
namespace {

using namespace arb_support;

// The precision a proof may reach before it gives up (compute_error): 64 times its start, and
// at least 2^16 bits. Only a tie (the end point R(T) equal to a lobe's minimum, a level equal
// to one) needs more, and a tie is never decided.
slong precision_cap(slong prec0) { return std::max<slong>(prec0 << 6, slong(1) << 16); }
std::string bits_text(slong prec0) { return std::to_string(precision_cap(prec0)) + " bits"; }

// The coupling at one precision: x, s = sqrt(n^2 + 4), |n|, sqrt(1 - x^2), pi.
struct coupling_balls {
  slong prec;
  ball x, s, n, c, pi;
  coupling_balls(const coupling_spec& spec, const quadratic_number& xq, slong p) : prec(p) {
    set_quadratic(x, xq, prec);
    set_rational(n, spec.n2, prec);
    arb_sqrt(n, n, prec);
    set_rational(s, spec.n2 + 4, prec);
    arb_sqrt(s, s, prec);
    ball x2;
    arb_mul(x2, x, x, prec);
    arb_sub_si(c, x2, 1, prec);
    arb_neg(c, c);
    arb_sqrt(c, c, prec);
    arb_const_pi(pi, prec);
  }

  // H, H' and G of theorem/lobe_balls.hpp at this coupling's x (|u| <= pi/2 here).
  void H(arb_t out, const arb_t u) const { lobe_balls::H_of(out, x, u, prec); }
  void dH(arb_t out, const arb_t u) const { lobe_balls::dH_of(out, x, u, prec); }
  void G(arb_t out, const arb_t u) const { lobe_balls::G_of(out, x, u, prec); }
  // dG/du = (1 - x^2) x^2 sin^3 u cos u (4 E - 2 sin^2 u (x^2 - 1)) / E^2, for Newton only.
  void dG(arb_t out, const arb_t u) const {
    ball sn, cs, xs, e, t, w;
    arb_sin_cos(sn, cs, u, prec);
    arb_mul(xs, x, sn, prec);
    arb_mul(xs, xs, xs, prec);
    arb_mul(t, cs, cs, prec);
    arb_add(e, t, xs, prec);
    arb_mul(t, sn, sn, prec);                 // sin^2
    arb_mul(w, c, c, prec);                   // 1 - x^2
    arb_mul(out, t, w, prec);                 // (1 - x^2) sin^2
    arb_mul_2exp_si(out, out, 1);             // 2 (1 - x^2) sin^2 = -2 sin^2 (x^2 - 1)
    arb_mul_2exp_si(e, e, 2);
    arb_add(out, out, e, prec);               // 4E + 2 (1 - x^2) sin^2
    arb_mul_2exp_si(e, e, -2);
    arb_mul(out, out, w, prec);
    arb_mul(w, x, x, prec);
    arb_mul(out, out, w, prec);
    arb_mul(out, out, t, prec);
    arb_mul(out, out, sn, prec);
    arb_mul(out, out, cs, prec);
    arb_mul(e, e, e, prec);
    arb_div(out, out, e, prec);
  }
  // R = q^2 + q'^2 (qdot0 = 1) at alpha = s t/2, beta = x alpha, and dR/dalpha = -4 n q' z'/s.
  void R(arb_t out, const arb_t alpha) const {
    ball sa, ca, sb, cb, b, q, qd, t;
    arb_mul(b, x, alpha, prec);
    arb_sin_cos(sa, ca, alpha, prec);
    arb_sin_cos(sb, cb, b, prec);
    arb_mul(q, sa, cb, prec);
    arb_mul(q, q, c, prec);
    arb_mul(qd, ca, cb, prec);
    arb_mul(t, sa, sb, prec);
    arb_mul(t, t, x, prec);
    arb_sub(qd, qd, t, prec);
    arb_mul(q, q, q, prec);
    arb_mul(qd, qd, qd, prec);
    arb_add(out, q, qd, prec);
  }
  void dR(arb_t out, const arb_t alpha) const {
    ball sa, ca, sb, cb, b, qd, zd, t;
    arb_mul(b, x, alpha, prec);
    arb_sin_cos(sa, ca, alpha, prec);
    arb_sin_cos(sb, cb, b, prec);
    arb_mul(qd, ca, cb, prec);
    arb_mul(t, sa, sb, prec);
    arb_mul(t, t, x, prec);
    arb_sub(qd, qd, t, prec);
    arb_mul(zd, sa, cb, prec);
    arb_mul(zd, zd, x, prec);
    arb_mul(t, ca, sb, prec);
    arb_add(zd, zd, t, prec);
    arb_mul(out, qd, zd, prec);
    arb_mul(out, out, n, prec);
    arb_mul_2exp_si(out, out, 2);
    arb_div(out, out, s, prec);
    arb_neg(out, out);
  }
};

using ball_fn = std::function<void(arb_t, const arb_t)>;

// out = max(1, |u|): the scale of a convergence test.
void unit_floor(arb_t out, const arb_t u) {
  arb_abs(out, u);
  ball one;
  arb_one(one);
  if (arb_lt(out, one)) arb_one(out);
}

// The root of g in (lo, hi) where g < 0 before the root and g > 0 after it (g need not be
// monotone elsewhere, only this sign pattern holds: the callers prove it), enclosed in a ball:
// safeguarded Newton on exact midpoints, then the ends of a tiny bracket [a, b] are decided:
// g(a) < 0 < g(b) proves a < root < b. False when this precision cannot decide (raise it).
// A bracket whose ends (midpoints at this precision) are in the wrong order or where g has the
// wrong sign is refused at once (false, and the caller raises the precision): it happens when
// the ends are closer than the precision can tell, or where g is steep (for a tiny x, H rises
// from about 0 to pi/2 within x of pi/2).
bool prove_root(const ball_fn& g, const ball_fn& dg, const arb_t lo_in, const arb_t hi_in, slong prec, arb_t out) {
  ball lo, hi, u, gu, du, step, next, width;
  arb_get_mid_arb(lo, lo_in);
  arb_get_mid_arb(hi, hi_in);
  g(gu, lo);
  g(du, hi);
  if (arb_gt(lo, hi) || arb_is_positive(gu) || arb_is_negative(du)) return false;
  arb_add(u, lo, hi, prec);
  arb_mul_2exp_si(u, u, -1);
  arb_get_mid_arb(u, u);
  bool converged = false;
  for (int it = 0; it < 4 * int(prec) + 200 && !converged; ++it) {
    g(gu, u);
    if (arb_is_negative(gu)) arb_set(lo, u);
    else if (arb_is_positive(gu)) arb_set(hi, u);
    dg(du, u);
    bool newton = false;
    if (arb_is_finite(du) && !arb_contains_zero(du)) {
      arb_get_mid_arb(step, gu);
      arb_get_mid_arb(next, du);
      arb_div(step, step, next, prec);
      arb_sub(next, u, step, prec);
      arb_get_mid_arb(next, next);
      newton = arb_gt(next, lo) && arb_lt(next, hi);
      // Converged: the Newton step is below 2^(-prec + 8) relative to max(1, |u|).
      arb_abs(step, step);
      arb_get_mid_arb(step, step);
      ball scale;
      unit_floor(scale, u);
      arb_mul_2exp_si(scale, scale, -prec + 8);
      if (newton && arb_lt(step, scale)) converged = true;
    }
    if (newton) arb_set(u, next);
    else {
      arb_sub(width, hi, lo, prec);
      arb_add(u, lo, hi, prec);
      arb_mul_2exp_si(u, u, -1);
      arb_get_mid_arb(u, u);
      ball scale;
      unit_floor(scale, u);
      arb_mul_2exp_si(scale, scale, -prec + 8);
      if (arb_lt(width, scale)) converged = true;
    }
  }
  // The bracket: u -+ eps, eps = 2^(-prec + shift) max(1, |u|) plus 4 rad(g(u))/|g'(u)| (the
  // uncertainty of g itself, e.g. of a target given as a ball).
  ball slack;
  g(gu, u);
  dg(du, u);
  arb_zero(slack);
  if (arb_is_finite(du) && !arb_contains_zero(du)) {
    arb_get_rad_arb(slack, gu);
    ball slope;
    arb_get_mid_arb(slope, du);
    arb_abs(slope, slope);
    arb_div(slack, slack, slope, prec);
    arb_mul_2exp_si(slack, slack, 2);
    arb_get_ubound_arf(arb_midref(slack.get()), slack, prec);
    mag_zero(arb_radref(slack.get()));
  }
  for (slong shift = 12; shift <= 60; shift += 16) {
    ball eps, a, b, ga, gb;
    unit_floor(eps, u);
    arb_mul_2exp_si(eps, eps, -prec + shift);
    arb_add(eps, eps, slack, prec);
    arb_get_mid_arb(eps, eps);
    arb_sub(a, u, eps, prec);
    arb_add(b, u, eps, prec);
    arb_get_mid_arb(a, a);
    arb_get_mid_arb(b, b);
    g(ga, a);
    g(gb, b);
    if (arb_is_negative(ga) && arb_is_positive(gb)) {
      arb_set_interval_arf(out, arb_midref(a.get()), arb_midref(b.get()), prec);
      return true;
    }
  }
  return false;
}

ball_fn constant_minus(const ball_fn& f, const arb_t target, slong prec) {
  return [f, target, prec](arb_t out, const arb_t u) {
    f(out, u);
    arb_sub(out, out, target, prec);
  };
}

// u0 = H^{-1}(pi nu) in [0, pi/2) for nu in [0, 1/2] (exactly 0 for nu = 0).
bool prove_lobe_root(const coupling_balls& cb, const quadratic_number& nu, arb_t out) {
  if (nu.sign() == 0) {
    arb_zero(out);
    return true;
  }
  ball target, lo, hi;
  set_quadratic(target, nu, cb.prec);
  arb_mul(target, target, cb.pi, cb.prec);
  arb_zero(lo);
  arb_set(hi, cb.pi);
  arb_mul_2exp_si(hi, hi, -1);  // H(pi/2) = (1 + x) pi/2 > pi nu
  auto H = [&cb](arb_t o, const arb_t u) { cb.H(o, u); };
  auto dH = [&cb](arb_t o, const arb_t u) { cb.dH(o, u); };
  return prove_root(constant_minus(H, target, cb.prec), dH, lo, hi, cb.prec, out);
}

// The lobe's minimiser alpha = k pi + side u0, the minimum value R = G(u0) and the time 2 alpha/s.
struct lobe_point {
  ball u0, alpha, value, t;
};

bool prove_lobe_point(const coupling_balls& cb, const horizon_lobe& lobe, lobe_point& p) {
  if (!prove_lobe_root(cb, lobe.nu, p.u0)) return false;
  cb.G(p.value, p.u0);
  set_int(p.alpha, lobe.k);
  arb_mul(p.alpha, p.alpha, cb.pi, cb.prec);
  ball su;
  arb_mul_si(su, p.u0, lobe.side, cb.prec);
  arb_add(p.alpha, p.alpha, su, cb.prec);
  arb_mul_2exp_si(p.t, p.alpha, 1);
  arb_div(p.t, p.t, cb.s, cb.prec);
  return true;
}

// The correct rounding of a ball to `digits` digits, with its enclosure (digits + 3, outward).
bool round_ball(const arb_t v, unsigned digits, slong prec, proved_real& out) {
  if (!arb_is_finite(v)) return false;
  fixed_mpfr lo(prec + 64), hi(prec + 64);
  arb_get_interval_mpfr(lo, hi, v);
  if (!enclosure_rounding(lo, hi, digits, out.value)) return false;
  out.enclosure = {format_scientific(static_cast<mpfr_srcptr>(lo), digits + 3, MPFR_RNDD),
                   format_scientific(static_cast<mpfr_srcptr>(hi), digits + 3, MPFR_RNDU)};
  return true;
}

proved_real exact_rational_value(const big_rational& v, unsigned digits) {
  proved_real out;
  out.value = format_rational_scientific(v, digits);
  const std::string e = format_rational_scientific(v, digits + 3);
  out.enclosure = {e, e};
  if (v != parse_rational(e, "enclosure")) {
    // Outward: the (digits + 3)-digit text is not exact; widen by one unit of its last place.
    fixed_mpfr lo(64 + 4 * (digits + 3)), hi(64 + 4 * (digits + 3));
    mpfr_set_q(lo, v.backend().data(), MPFR_RNDD);
    mpfr_set_q(hi, v.backend().data(), MPFR_RNDU);
    out.enclosure = {format_scientific(static_cast<mpfr_srcptr>(lo), digits + 3, MPFR_RNDD),
                     format_scientific(static_cast<mpfr_srcptr>(hi), digits + 3, MPFR_RNDU)};
  }
  return out;
}

horizon_lobe lobe_of(const quadratic_number& x, const big_int& k) {
  horizon_lobe l{k, distance_to_half(x, k), lobe_offset_sign(x, k)};
  // |mu| = pi/2 in a lobe k >= 1 (k x an integer): both -+H^{-1}(pi/2) minimise; the first is -.
  if (k >= 1 && l.nu == quadratic_number(1, 2)) l.side = -1;
  return l;
}

// log2 |v| rounded up, for v != 0 (0 for v = 0).
slong magnitude_bits(const big_rational& v) {
  const auto bits = [](big_int w) { return w == 0 ? slong(0) : slong(boost::multiprecision::msb(w < 0 ? big_int(-w) : w)) + 1; };
  return v == 0 ? 0 : bits(boost::multiprecision::numerator(v)) - bits(boost::multiprecision::denominator(v)) + 1;
}

// The starting precision: the digits asked, plus twice the bits of the integer part of `scale`
// (the phases reach about scale and must keep the digits after their integer part), plus
// log2(1/x) for a small coupling (H rises steeply within x of pi/2, and x pi/2 must show).
slong start_bits(unsigned digits, const big_rational& scale, const coupling_spec& spec) {
  return slong(digits * 3.33) + 64 + 2 * std::max<slong>(0, magnitude_bits(scale)) +
         std::max<slong>(0, -magnitude_bits(spec.n2) / 2);
}

// alpha_T = s T/2 as a ball.
void set_alpha_T(arb_t out, const coupling_balls& cb, const horizon_time& T) {
  set_rational(out, T.value, cb.prec);
  arb_mul(out, out, cb.s, cb.prec);
  arb_mul_2exp_si(out, out, -1);
  if (T.times_pi) arb_mul(out, out, cb.pi, cb.prec);
}

// k_c = floor(alpha_T/pi + 1/2), exactly. For T = value pi it is floor(s value/2 + 1/2) with
// s = sqrt(Q (P + 4Q))/Q in Q(sqrt d); for a rational T > 0 the argument is transcendental (pi), so
// it is never an integer and a fine enough ball decides the floor.
big_int cut_lobe_of(const coupling_spec& spec, const quadratic_number& x, const horizon_time& T, slong prec,
                    const stop_token& stop) {
  if (T.value == 0) return 0;
  if (T.times_pi) {
    const big_int P = spec.P(), Q = spec.Q(), d = Q * (P + 4 * Q);
    big_int root;
    const quadratic_number s = int_is_square(d, root) ? quadratic_number(root, Q) : quadratic_number(0, 1, Q, d);
    return (s * quadratic_number(T.value / 2) + quadratic_number(1, 2)).floor();
  }
  const slong prec0 = prec;
  for (; prec <= precision_cap(prec0); prec *= 2) {
    stop.throw_if_requested();
    coupling_balls cb(spec, x, prec);
    ball a, f, half;
    set_alpha_T(a, cb, T);
    arb_div(a, a, cb.pi, prec);
    arb_set_d(half, 0.5);
    arb_add(a, a, half, prec);
    arb_floor(f, a, prec);
    fmpz_holder z;
    if (arb_get_unique_fmpz(z, f)) return z.value();
  }
  throw compute_error("horizon: the lobe holding t = T was not decided within " + bits_text(prec0));
}

}  // namespace

horizon_minimum_report prove_horizon_minimum(const coupling_spec& spec, const horizon_time& T, unsigned digits,
                                             stop_token stop) {
  check_report_digits(digits);
  if (T.value < 0) throw usage_error("the horizon must be >= 0, got " + T.str());
  horizon_minimum_report r;
  r.digits = digits;
  r.horizon = T;
  r.x = coupling_rotation_number(spec);
  const slong prec0 = start_bits(digits, T.times_pi ? big_rational(T.value * 4) : T.value, spec);
  r.cut_lobe = cut_lobe_of(spec, r.x, T, prec0, stop);
  // The best full lobe (exact), and the cut lobe.
  std::optional<horizon_lobe> full;
  if (r.cut_lobe >= 1) full = lobe_of(r.x, min_distance_to_half(r.x, big_int(r.cut_lobe - 1)).k);
  const horizon_lobe cut = lobe_of(r.x, r.cut_lobe);
  for (slong prec = prec0; prec <= precision_cap(prec0); prec *= 2) {
    stop.throw_if_requested();
    coupling_balls cb(spec, r.x, prec);
    ball alpha_T;
    set_alpha_T(alpha_T, cb, T);
    lobe_point cut_point;
    if (!prove_lobe_point(cb, cut, cut_point)) continue;
    if (arb_le(cut_point.alpha, alpha_T)) r.cut_lobe_reached = true;
    else if (arb_gt(cut_point.alpha, alpha_T)) r.cut_lobe_reached = false;
    else continue;  // not decided at this precision
    // The winner among lobes: the smaller nu, ties to the earlier lobe (exact comparison).
    std::optional<horizon_lobe> best = full;
    if (r.cut_lobe_reached && (!best || cut.nu < best->nu)) best = cut;
    if (!r.cut_lobe_reached) {
      // Against the end point R(T): decided by balls (V(nu) and R(T) differ unless T is a minimiser).
      ball end;
      cb.R(end, alpha_T);
      lobe_point bp;
      if (best && !prove_lobe_point(cb, *best, bp)) continue;
      if (!best || arb_lt(end, bp.value)) {
        r.at_horizon_end = true;
        r.lobe.reset();
        ball radius;
        arb_sqrtpos(radius, end, prec);
        arb_mul_2exp_si(end, end, -1);
        if (!round_ball(end, digits, prec, r.h_min) || !round_ball(radius, digits, prec, r.r_min)) continue;
        if (!T.times_pi) r.t_min = exact_rational_value(T.value, digits);
        else {
          ball t;
          set_rational(t, T.value, prec);
          arb_mul(t, t, cb.pi, prec);
          if (!round_ball(t, digits, prec, r.t_min)) continue;
        }
        return r;
      }
      if (!arb_gt(end, bp.value)) continue;
    }
    r.at_horizon_end = false;
    r.lobe = best;
    lobe_point p;
    if (!prove_lobe_point(cb, *best, p)) continue;
    ball radius;
    arb_sqrtpos(radius, p.value, prec);
    arb_mul_2exp_si(p.value, p.value, -1);
    if (best->nu.sign() == 0) {
      r.h_min = r.r_min = exact_rational_value(0, digits);
      if (!round_ball(p.t, digits, prec, r.t_min)) continue;
      return r;
    }
    if (!round_ball(p.value, digits, prec, r.h_min) || !round_ball(p.t, digits, prec, r.t_min) ||
        !round_ball(radius, digits, prec, r.r_min))
      continue;
    return r;
  }
  throw compute_error("horizon: the minimum over [0, " + T.str() +
                      "] was not decided within " + bits_text(prec0) + " (the end point ties a lobe's minimum)");
}

namespace {

// The first lobe k with ||k x - 1/2|| <= delta: within one period for rational x (then none
// means never), else by K = 2^10, 2^26, ... (irrational x: some k hits every delta > 0).
std::optional<big_int> first_lobe_at_most(const quadratic_number& x, const quadratic_number& delta, const stop_token& stop) {
  if (x.is_rational()) return first_distance_to_half_at_most(x, delta, x.r());
  if (delta.sign() == 0) return std::nullopt;
  for (big_int K = 1024;; K <<= 16) {
    stop.throw_if_requested();
    if (auto k = first_distance_to_half_at_most(x, delta, K)) return k;
  }
}

}  // namespace

first_below_report prove_first_below(const coupling_spec& spec, const big_rational& E, unsigned digits,
                                     stop_token stop) {
  check_report_digits(digits);
  if (E < 0) throw usage_error("the level E must be >= 0, got " + rational_str(E));
  first_below_report r;
  r.digits = digits;
  r.level = E;
  const quadratic_number x = coupling_rotation_number(spec);
  if (2 * E >= 1) {
    r.t_below = exact_rational_value(0, digits);
    r.reason = "H_q(0) = qdot0^2/2 = 1/2 is already <= E";
    return r;
  }
  if (E == 0) {
    // R = 0 only at a lobe with nu = 0, at its centre (q = q' = 0): x = (2j+1)/(2k), a degenerate pair.
    auto k = first_lobe_at_most(x, quadratic_number(0), stop);
    if (!k) {
      r.never = true;
      r.reason = x.is_rational() ? "resonant and not degenerate (delta != 2 mod 4): H_q >= H_min > 0 for all time"
                                 : "W1/W2 is irrational: H_q comes arbitrarily close to 0 but never reaches it";
      return r;
    }
    r.lobe = lobe_of(x, *k);
    const slong zero_prec0 = start_bits(digits, big_rational(*k), spec);
    for (slong prec = zero_prec0; prec <= precision_cap(zero_prec0); prec *= 2) {
      coupling_balls cb(spec, x, prec);
      lobe_point p;
      if (prove_lobe_point(cb, *r.lobe, p) && round_ball(p.t, digits, prec, r.t_below)) {
        r.reason = "the first exact zero of H_q (a degenerate pair), at the centre of lobe " + k->str();
        return r;
      }
    }
    throw compute_error("first time below: not decided within " + bits_text(zero_prec0));
  }
  const slong prec0 = start_bits(digits, 1, spec);
  for (slong prec = prec0; prec <= precision_cap(prec0); prec *= 2) {
    stop.throw_if_requested();
    coupling_balls cb(spec, x, prec);
    ball level;
    set_rational(level, 2 * E, prec);
    // delta = H(G^{-1}(2E))/pi, or >= 1/2 when 2E >= G(pi/2) = 1 - x^2 (then lobe 0 reaches it).
    ball gmax, half_pi;
    arb_mul_2exp_si(half_pi, cb.pi, -1);
    cb.G(gmax, half_pi);
    quadratic_number delta_lo, delta_hi;
    if (arb_ge(level, gmax)) delta_lo = delta_hi = quadratic_number(1, 2);
    else if (arb_lt(level, gmax)) {
      ball u, zero, d;
      arb_zero(zero);
      auto G = [&cb](arb_t o, const arb_t v) { cb.G(o, v); };
      auto dG = [&cb](arb_t o, const arb_t v) { cb.dG(o, v); };
      if (!prove_root(constant_minus(G, level, prec), dG, zero, half_pi, prec, u)) continue;
      cb.H(d, u);
      arb_div(d, d, cb.pi, prec);
      arf_t lo, hi;
      arf_init(lo);
      arf_init(hi);
      arb_get_lbound_arf(lo, d, prec);
      arb_get_ubound_arf(hi, d, prec);
      const big_rational l = arf_rational(lo), h = arf_rational(hi);
      arf_clear(lo);
      arf_clear(hi);
      if (l < 0) continue;
      delta_lo = quadratic_number(l);
      delta_hi = quadratic_number(h);
    } else continue;
    const auto k_hi = first_lobe_at_most(x, delta_hi, stop);
    const auto k_lo = first_lobe_at_most(x, delta_lo, stop);
    if (k_hi != k_lo) continue;  // delta is too close to some lobe's ||k x - 1/2||
    if (!k_hi) {
      r.never = true;
      r.reason = "resonant: H_q >= H_min > E for all time (the motion is periodic and no lobe's minimum reaches E)";
      return r;
    }
    r.lobe = lobe_of(x, *k_hi);
    // The crossing on the descending branch [k pi - pi/2 (0 for k = 0), k pi + side u0]: before it
    // R > 2E, after it R <= 2E (proofs/horizon-theorem.md), so g = 2E - R has the sign pattern of prove_root.
    const slong p2 = prec + slong(boost::multiprecision::msb(big_int(*k_hi + 1)));
    coupling_balls cb2(spec, x, p2);
    ball level2;
    set_rational(level2, 2 * E, p2);
    lobe_point p;
    if (!prove_lobe_point(cb2, *r.lobe, p)) continue;
    ball lo;
    if (*k_hi == 0) arb_zero(lo);
    else {
      set_int(lo, *k_hi);
      arb_mul(lo, lo, cb2.pi, p2);
      ball hp;
      arb_mul_2exp_si(hp, cb2.pi, -1);
      arb_sub(lo, lo, hp, p2);
    }
    auto g = [&cb2, &level2, p2](arb_t o, const arb_t a) {
      cb2.R(o, a);
      arb_sub(o, level2, o, p2);
    };
    auto dg = [&cb2](arb_t o, const arb_t a) {
      cb2.dR(o, a);
      arb_neg(o, o);
    };
    ball hi, alpha;
    arb_set(hi, p.alpha);
    if (!prove_root(g, dg, lo, hi, p2, alpha)) continue;
    ball t;
    arb_mul_2exp_si(t, alpha, 1);
    arb_div(t, t, cb2.s, p2);
    if (!round_ball(t, digits, p2, r.t_below)) continue;
    r.reason = "lobe " + k_hi->str() + " is the first whose minimum reaches E; H_q crosses E once on its descending branch";
    return r;
  }
  throw compute_error("first time below: not decided within " + bits_text(prec0) + " (E equals a lobe's minimum?)");
}

}  // namespace gyrores
