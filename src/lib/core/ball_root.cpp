// src/lib/core/ball_root.hpp: the proved root in Arb.
#include "ball_root.hpp"

#include <gyrores/core/real.hpp>

namespace gyrores::arb_support {

namespace {

// out = 2^(-prec + shift) max(1, |u|): the scale of a convergence test and of the bracket.
void scale_of(arb_t out, const arb_t u, slong prec, slong shift) {
  arb_abs(out, u);
  if (arf_cmpabs_2exp_si(arb_midref(out), 0) < 0) arb_one(out);
  arb_mul_2exp_si(out, out, -prec + shift);
  arb_get_mid_arb(out, out);
}

// Safeguarded Newton on exact midpoints inside [lo, hi] (g(lo) < 0 < g(hi)), from the middle,
// until a step is below 2^(-prec + 8) max(1, |u|), or g(u) holds 0: u is then as close to the
// root as g's own precision can tell (a steep or ill-conditioned g: the crossing of a tiny
// coupling moves R by only about x per unit of u), and the bracket's slack takes that in.
void newton_point(const ball_fn& g, const ball_fn& dg, ball& lo, ball& hi, slong prec, ball& u) {
  ball gu, du, step, next, scale;
  const auto bisect = [&] {  // u = the middle of [lo, hi]; true when that is narrow enough
    arb_sub(step, hi, lo, prec);
    arb_add(u, lo, hi, prec);
    arb_mul_2exp_si(u, u, -1);
    arb_get_mid_arb(u, u);
    scale_of(scale, u, prec, 8);
    return arb_lt(step, scale);
  };
  bisect();
  for (int it = 0; it < 4 * int(prec) + 200; ++it) {
    g(gu, u);
    if (arb_is_negative(gu)) arb_set(lo, u);
    else if (arb_is_positive(gu)) arb_set(hi, u);
    else return;  // g(u) holds 0
    dg(du, u);
    if (arb_is_finite(du) && !arb_contains_zero(du)) {  // Newton, when it stays inside [lo, hi]
      arb_get_mid_arb(step, gu);
      arb_get_mid_arb(next, du);
      arb_div(step, step, next, prec);
      arb_sub(next, u, step, prec);
      arb_get_mid_arb(next, next);
      if (arb_gt(next, lo) && arb_lt(next, hi)) {
        scale_of(scale, u, prec, 8);
        arb_abs(step, step);
        arb_get_mid_arb(step, step);
        arb_set(u, next);
        if (arb_lt(step, scale)) return;
        continue;
      }
    }
    if (bisect()) return;
  }
}

// 4 rad(g(u))/|g'(u)|, an upper bound as an exact point: the uncertainty of g itself (e.g. of a
// target given as a ball) moved to u.
void slack_of(const ball_fn& g, const ball_fn& dg, const arb_t u, slong prec, ball& slack) {
  ball gu, du;
  g(gu, u);
  dg(du, u);
  arb_zero(slack);
  if (!arb_is_finite(du) || arb_contains_zero(du)) return;
  arb_get_rad_arb(slack, gu);
  arb_get_mid_arb(du, du);
  arb_abs(du, du);
  arb_div(slack, slack, du, prec);
  arb_mul_2exp_si(slack, slack, 2);
  arb_get_ubound_arf(arb_midref(slack.get()), slack, prec);
  mag_zero(arb_radref(slack.get()));
}

// g(a) < 0 < g(b), decided in balls (a, b exact points).
bool signs_at(const ball_fn& g, const arb_t a, const arb_t b) {
  ball ga, gb;
  g(ga, a);
  g(gb, b);
  return arb_is_negative(ga) && arb_is_positive(gb);
}

}  // namespace

void decimal_unit(arb_t out, const arf_t a, const arf_t b, unsigned decimal_digits) {
  const slong k = slong(digits10_to_bits(decimal_digits - 1)) - 1;
  fmpz_holder ea, eb;  // (Arb leaves the bound of 0 undefined: a zero end takes the other's)
  if (!arf_is_zero(a)) arf_abs_bound_lt_2exp_fmpz(ea, a);
  if (!arf_is_zero(b)) arf_abs_bound_lt_2exp_fmpz(eb, b);
  if (arf_is_zero(a) || (!arf_is_zero(b) && fmpz_cmp(ea, eb) < 0)) fmpz_set(ea, eb);
  fmpz_sub_si(ea, ea, k);
  arb_one(out);
  arb_mul_2exp_fmpz(out, out, ea);
}

proof_status prove_ball_root(const ball_fn& g, const ball_fn& dg, const arb_t lo_in, const arb_t hi_in, slong prec,
                             unsigned decimal_digits, ball_root& out) {
  ball lo, hi, u, slack, eps, a, b, e;
  arb_get_mid_arb(lo, lo_in);
  arb_get_mid_arb(hi, hi_in);
  const ball region_lo = lo, region_hi = hi;
  g(a, lo);
  g(b, hi);
  if (arb_gt(lo, hi) || arb_is_positive(a) || arb_is_negative(b))
    return proof_status::undecided("the search bracket's ends do not show the root's sign change at this precision");
  newton_point(g, dg, lo, hi, prec, u);
  // The bracket: u -+ eps, eps = 2^(-prec + shift) max(1, |u|) plus the slack of g itself.
  slack_of(g, dg, u, prec, slack);
  for (slong shift = 12; shift <= 60; shift += 16) {
    scale_of(eps, u, prec, shift);
    arb_add(eps, eps, slack, prec);
    arb_get_mid_arb(eps, eps);
    arb_sub(a, u, eps, prec);
    arb_add(b, u, eps, prec);
    arb_get_mid_arb(a, a);
    arb_get_mid_arb(b, b);
    if (!signs_at(g, a, b)) continue;
    arf_struct *a_end = arb_midref(a.get()), *b_end = arb_midref(b.get());
    out.bracket = enclosure(binary_of(a_end), binary_of(b_end));
    arb_set_interval_arf(out.value, a_end, b_end, prec);
    out.decimals = 0;
    if (decimal_digits == 0) return proof_status::proved();
    // Their decimals lie in [a - e, a] and [b, b + e]; inside [lo, hi] they are on the root's
    // sides, where g has the sign the callers prove for all of [lo, hi] (a < root < b is proved).
    decimal_unit(e, a_end, b_end, decimal_digits);
    arf_sub(a_end, a_end, arb_midref(e.get()), ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_add(b_end, b_end, arb_midref(e.get()), ARF_PREC_EXACT, ARF_RND_DOWN);
    if (arb_ge(a, region_lo) && arb_le(b, region_hi)) {
      arb_set_interval_arf(out.value, a_end, b_end, prec);
      out.decimals = decimal_digits;
    }
    return proof_status::proved();
  }
  return proof_status::undecided("the ends of the root's bracket were not decided at this precision");
}

}  // namespace gyrores::arb_support
