// include/gyrores/theorem/horizon.hpp; the argument is proofs/horizon-theorem.md.
#include <gyrores/theorem/horizon.hpp>

#include <arb.h>

#include <algorithm>

#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/refine.hpp>
#include <gyrores/model/limits.hpp>
#include <gyrores/model/rotation.hpp>
#include <gyrores/theorem/root.hpp>

#include "../core/ball.hpp"
#include "../core/ball_root.hpp"
#include "kernels_arb.hpp"

namespace gyrores {
namespace {

using namespace arb_support;

// The coupling at one precision: x, S = sqrt(n^2 + 4), sqrt(1 - x^2) and pi as balls, and x as
// the interval of the solver of H(u) = mu (theorem/root.hpp).
struct coupling_balls {
  slong prec;
  ball x, s, c, pi;
  theorem_constants K;
  coupling_balls(const coupling_spec& spec, const quadratic_number& xq, slong p) : prec(p), K(p) {
    set_quadratic(x, xq, prec);
    set_rational(s, spec.n2 + 4, prec);
    arb_sqrt(s, s, prec);
    ball x2;
    arb_mul(x2, x, x, prec);
    arb_sub_si(c, x2, 1, prec);
    arb_neg(c, c);
    arb_sqrt(c, c, prec);
    arb_const_pi(pi, prec);
    fixed_mpfi xi(p);
    interval_of(xi, x);
    set_theorem_constants(K, xi);
  }
};

// The enclosure of a ball (its ends at 64 bits more, outward); undecided when not finite.
proof_status enclosure_from(const arb_t v, slong prec, enclosure& out) {
  if (!arb_is_finite(v)) return proof_status::undecided("an enclosure is not finite at this precision");
  out = enclosure_of(v, prec + 64);
  return proof_status::proved();
}

// h_min = R/2 and r_min = sqrt(R) from a ball of the minimum R.
proof_status set_minimum(const arb_t R, slong prec, horizon_minimum_proof& r) {
  ball h, radius;
  arb_sqrtpos(radius, R, prec);
  arb_mul_2exp_si(h, R, -1);
  GYRORES_TRY_PROOF(enclosure_from(h, prec, r.h_min));
  return enclosure_from(radius, prec, r.r_min);
}

// A certificate's decimals (horizon.hpp) that cannot be: compute_error at once.
[[noreturn]] void no_decimals(const std::string& what, unsigned decimals) {
  throw compute_error("coupling certificate: " + what + " within 10^-" + std::to_string(decimals) +
                      ", where the certificate's decimals cannot decide it");
}

// The root u0 = H^{-1}(pi nu) of a lobe (exactly 0 for nu = 0) by the one solver, for a
// certificate (decimals > 0) with its bracket's decimals to `decimals` digits; u0 as a ball.
proof_status prove_root_of(const coupling_balls& cb, const horizon_lobe& lobe, unsigned decimals, lobe_root& out,
                           arb_t u0) {
  out.lobe = lobe;
  if (lobe.nu.sign() == 0) {
    out.bracket = {enclosure(), decimals};
    out.u = enclosure();
    arb_zero(u0);
    return proof_status::proved();
  }
  ball mu;
  set_quadratic(mu, lobe.nu, cb.prec);
  arb_mul(mu, mu, cb.pi, cb.prec);
  root_enclosure r(cb.prec);
  interval_of(r.mu, mu);
  GYRORES_TRY_PROOF(prove_theorem_root(r, cb.K, decimals));
  if (r.decimals < decimals) no_decimals("a lobe's root lies next to pi/2", decimals);
  out.bracket = {enclosure(r.lo, r.hi), r.decimals};
  out.u = enclosure(r.U);
  set_ball(u0, r.U, cb.prec);
  return proof_status::proved();
}

// A lobe's minimiser alpha = k pi + side u0, the minimum value R = G(u0) and the time 2 alpha/S.
struct lobe_point {
  lobe_root root;
  ball u0, alpha, value, t;
};

proof_status prove_lobe_point(const coupling_balls& cb, const horizon_lobe& lobe, unsigned decimals, lobe_point& p) {
  GYRORES_TRY_PROOF(prove_root_of(cb, lobe, decimals, p.root, p.u0));
  kernels_arb::G(p.value, cb.x, p.u0, cb.prec);
  set_int(p.alpha, lobe.k);
  arb_mul(p.alpha, p.alpha, cb.pi, cb.prec);
  ball su;
  arb_mul_si(su, p.u0, lobe.side, cb.prec);
  arb_add(p.alpha, p.alpha, su, cb.prec);
  arb_mul_2exp_si(p.t, p.alpha, 1);
  arb_div(p.t, p.t, cb.s, cb.prec);
  return proof_status::proved();
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

// The starting precision: the digits asked and 64 guard bits, plus twice the bits of the integer
// part of `scale` (the phases reach about scale and must keep the digits after their integer
// part), plus log2(1/x) for a small coupling (H rises steeply within x of pi/2, and x pi/2 must
// show).
mpfr_prec_t start_bits(unsigned digits, const big_rational& scale, const coupling_spec& spec) {
  return mpfr_prec_t(digits10_to_bits(digits)) + 64 + 2 * std::max<slong>(0, magnitude_bits(scale)) +
         std::max<slong>(0, -magnitude_bits(spec.n2) / 2);
}

precision_plan plan_of(mpfr_prec_t start) { return {start, tie_bits_cap(start)}; }

// k_c (kernels_arb::cut_lobe), at the precision that decides it.
big_int cut_lobe_of(const coupling_spec& spec, const horizon_time& T, mpfr_prec_t start, const stop_token& stop) {
  return refine(plan_of(start), stop, "horizon: the lobe holding t = T", [&](mpfr_prec_t prec, proof_status& status) {
    std::optional<big_int> k = kernels_arb::cut_lobe(spec, T, slong(prec));
    if (!k) status = proof_status::undecided("the floor of S T/(2 pi) + 1/2");
    return k;
  });
}

// The exact half of the minimum's proof: the cut lobe and the best full lobe.
struct horizon_setup {
  const coupling_spec& spec;
  horizon_time T;
  quadratic_number x;
  big_int cut_lobe;
  std::optional<horizon_lobe> full;  // the best of the lobes 0..k_c - 1
  horizon_lobe cut;
  unsigned decimals;
};

// The minimum over [0, T] at one precision (proofs/horizon-theorem.md, items 2-3).
proof_status minimum_at(const horizon_setup& h, slong prec, horizon_minimum_proof& r) {
  coupling_balls cb(h.spec, h.x, prec);
  ball alpha_T;
  kernels_arb::alpha_T(alpha_T, cb.s, h.T, cb.pi, prec);
  lobe_point cut;
  GYRORES_TRY_PROOF(prove_lobe_point(cb, h.cut, h.decimals, cut));
  r.cut = cut.root;
  if (arb_le(cut.alpha, alpha_T)) r.cut_lobe_reached = true;
  else if (arb_gt(cut.alpha, alpha_T)) r.cut_lobe_reached = false;
  else return proof_status::undecided("whether the cut lobe's minimiser lies before T");
  // The winner among lobes: the smaller nu, ties to the earlier lobe (exact comparison).
  std::optional<horizon_lobe> best = h.full;
  if (r.cut_lobe_reached && (!best || h.cut.nu < best->nu)) best = h.cut;
  lobe_point bp;
  if (best && best->k == h.cut_lobe) bp = cut;
  else if (best) GYRORES_TRY_PROOF(prove_lobe_point(cb, *best, h.decimals, bp));
  if (best) r.best = bp.root;
  if (!r.cut_lobe_reached) {
    // Against the end point R(T): decided by balls (V(nu) and R(T) differ unless T is a minimiser).
    ball end;
    kernels_arb::R(end, cb.x, cb.c, alpha_T, prec);
    if (!best || arb_lt(end, bp.value)) {
      r.at_horizon_end = true;
      r.t_min = enclosure::exact(h.T.value);
      if (h.T.times_pi) {
        ball t;
        set_rational(t, h.T.value, prec);
        arb_mul(t, t, cb.pi, prec);
        GYRORES_TRY_PROOF(enclosure_from(t, prec, r.t_min));
      }
      return set_minimum(end, prec, r);
    }
    if (!arb_gt(end, bp.value)) return proof_status::undecided("the end point R(T) against the best lobe's minimum");
  }
  r.at_horizon_end = false;
  GYRORES_TRY_PROOF(enclosure_from(bp.t, prec, r.t_min));
  if (best->nu.sign() != 0) return set_minimum(bp.value, prec, r);
  r.h_min = r.r_min = enclosure::exact(0);  // a degenerate pair's zero
  return proof_status::proved();
}

}  // namespace

horizon_minimum_proof prove_horizon_minimum(const coupling_spec& spec, const horizon_time& T,
                                            const refine_goal<horizon_minimum_proof>& goal, proof_use use,
                                            stop_token stop) {
  check_report_digits(goal.digits);
  if (T.value < 0) throw usage_error("the horizon must be >= 0, got " + T.str());
  const quadratic_number x = coupling_rotation_number(spec);
  const mpfr_prec_t start = start_bits(goal.digits, T.times_pi ? big_rational(T.value * 4) : T.value, spec);
  const unsigned decimals = use == proof_use::certificate ? certificate_digits(goal.digits) : 0;
  horizon_setup h{spec, T, x, cut_lobe_of(spec, T, start, stop), std::nullopt, {}, decimals};
  // The best full lobe (exact), and the cut lobe.
  if (h.cut_lobe >= 1) h.full = lobe_of(x, min_distance_to_half(x, big_int(h.cut_lobe - 1), stop).k);
  h.cut = lobe_of(x, h.cut_lobe);
  return refine(plan_of(start), stop, "horizon: the minimum over [0, " + T.str() + "]", [&](mpfr_prec_t bits, proof_status& status) {
    horizon_minimum_proof r;
    r.horizon = T;
    r.x = x;
    r.cut_lobe = h.cut_lobe;
    r.bits = bits;
    status = minimum_at(h, slong(bits), r);
    if (status) status = goal.accepts(r);
    return status ? std::optional<horizon_minimum_proof>(std::move(r)) : std::nullopt;
  });
}

lobe_root certified_lobe_root(const coupling_spec& spec, const big_int& k, unsigned digits) {
  if (k < 0) throw usage_error("a lobe index must be >= 0, got " + k.str());
  check_report_digits(digits);
  const quadratic_number x = coupling_rotation_number(spec);
  horizon_lobe lobe = lobe_of(x, k);
  if (k == 0) lobe.side = 1;  // lobe 0: only u >= 0 is in [0, T]
  const mpfr_prec_t start = start_bits(digits, 1, spec);  // (the root depends on nu alone)
  return refine(plan_of(start), {}, "horizon: the root of lobe " + k.str(), [&](mpfr_prec_t bits, proof_status& status) {
    coupling_balls cb(spec, x, slong(bits));
    lobe_root out;
    ball u0;
    status = prove_root_of(cb, lobe, certificate_digits(digits), out, u0);
    return status ? std::optional<lobe_root>(std::move(out)) : std::nullopt;
  });
}

namespace {

// The first lobe k with ||k x - 1/2|| <= delta: within one period for rational x (then none
// means never), else by K = 2^10, 2^26, ... (irrational x: some k hits every delta > 0) up to
// the lobes of limits::lobe_digits digits, beyond which the proof stops with the reason (only a
// coupling very close to a resonant one, a tiny delta, goes that far).
std::optional<big_int> first_lobe_at_most(const quadratic_number& x, const quadratic_number& delta, const stop_token& stop) {
  if (x.is_rational()) return first_distance_to_half_at_most(x, delta, x.r(), stop);
  if (delta.sign() == 0) return std::nullopt;
  const big_int last = boost::multiprecision::pow(big_int(10), unsigned(limits::lobe_digits)) - 1;
  for (big_int K = 1024;; K <<= 16) {
    stop.throw_if_requested();
    const bool final_try = K >= last;
    if (auto k = first_distance_to_half_at_most(x, delta, final_try ? last : K, stop)) return k;
    if (final_try)
      throw compute_error("horizon: the first lobe below the level lies beyond lobe 10^" +
                          std::to_string(limits::lobe_digits) + " (the limit of the coupling inputs)");
  }
}

// The first lobe k with nu_k <= delta, for every delta in [lo, hi]: undecided when the ends differ.
proof_status first_lobe_within(const quadratic_number& x, const big_rational& lo, const big_rational& hi,
                               const stop_token& stop, std::optional<big_int>& k) {
  if (lo < 0) return proof_status::undecided("delta's lower end is not positive at this precision");
  k = first_lobe_at_most(x, quadratic_number(hi), stop);
  if (k != first_lobe_at_most(x, quadratic_number(lo), stop))
    return proof_status::undecided("delta is too close to some lobe's ||k x - 1/2||");
  return proof_status::proved();
}

// The first lobe whose minimum reaches 2E (none: never), from delta = H(G^{-1}(2E))/pi
// (horizon-theorem item 5) when 2E < G(pi/2) = 1 - x^2, with the level root's bracket and
// delta's enclosure in r. For a certificate (decimals > 0) delta is H over the level root's
// decimal bracket, and the lobe must be the same for every value within 2 units of the last of
// delta's decimals about it (every decimal a certificate may write for delta lies there), or no
// certificate can state it. Otherwise delta >= 1/2: lobe 0 reaches the level.
// The level is compared with the supremum G(pi/2) = 1 - x^2 = 4Q/(P + 4Q) exactly (a rational),
// before any root: at equality no precision would decide it.
proof_status first_lobe_at_level(const coupling_balls& cb, const quadratic_number& x, const arb_t level,
                                 bool at_or_above_sup, unsigned decimals, const stop_token& stop, first_below_proof& r,
                                 std::optional<big_int>& k) {
  const slong prec = cb.prec;
  ball half_pi;
  arb_mul_2exp_si(half_pi, cb.pi, -1);
  if (at_or_above_sup) return first_lobe_within(x, big_rational(1, 2), big_rational(1, 2), stop, k);
  ball zero, d, plain;
  arb_zero(zero);
  auto g = [&cb, level](arb_t o, const arb_t v) {
    kernels_arb::G(o, cb.x, v, cb.prec);
    arb_sub(o, o, level, cb.prec);
  };
  auto dg = [&cb](arb_t o, const arb_t v) { kernels_arb::dG(o, cb.x, v, cb.prec); };
  ball_root u;
  GYRORES_TRY_PROOF(prove_ball_root(g, dg, zero, half_pi, prec, decimals, u));
  if (u.decimals < decimals) no_decimals("the level's root G^{-1}(2E) lies next to pi/2", decimals);
  r.level_root = proved_bracket{u.bracket, u.decimals};
  // delta over the plain bracket decides the lobe (as precise as the precision allows).
  set_enclosure(plain, u.bracket, prec);
  kernels_arb::H(d, cb.x, plain, prec);
  arb_div(d, d, cb.pi, prec);
  if (!arb_is_finite(d)) return proof_status::undecided("delta is not finite at this precision");
  r.delta = proved_bracket{enclosure_of(d, prec), 0};
  GYRORES_TRY_PROOF(first_lobe_within(x, r.delta->ends.lo_rational(), r.delta->ends.hi_rational(), stop, k));
  if (decimals == 0) return proof_status::proved();
  // For the certificate: over the decimals, and a unit of delta's last decimal digit on each side.
  kernels_arb::H(d, cb.x, u.value, prec);
  arb_div(d, d, cb.pi, prec);
  r.delta = proved_bracket{enclosure_of(d, prec), decimals};
  ball e;
  decimal_unit(e, arb_midref(d.get()), arb_midref(d.get()), decimals);
  arb_mul_2exp_si(e, e, 1);  // above the ends' own units too (d's radius is far below e)
  const big_rational unit = lower_rational(e, prec);
  std::optional<big_int> k_decimals;
  if (!first_lobe_within(x, r.delta->ends.lo_rational() - unit, r.delta->ends.hi_rational() + unit, stop, k_decimals) ||
      k_decimals != k)
    no_decimals("delta lies next to a lobe's ||k x - 1/2||", decimals);
  return proof_status::proved();
}

// The crossing R = 2E on lobe k's descending branch: u in [k pi - pi/2 (0 for k = 0), k pi +
// side u0], where R > 2E before it and R <= 2E after it (proofs/horizon-theorem.md), so
// g = 2E - R has the sign pattern of prove_ball_root; R at k pi + u with the bits of k more.
proof_status crossing_at(const coupling_spec& spec, const quadratic_number& x, const big_rational& E, slong prec,
                         unsigned decimals, first_below_proof& r) {
  const big_int& k = r.lobe->lobe.k;
  const slong p2 = prec + slong(boost::multiprecision::msb(big_int(k + 1)));
  coupling_balls cb(spec, x, p2);
  lobe_point p;
  GYRORES_TRY_PROOF(prove_lobe_point(cb, r.lobe->lobe, decimals, p));
  r.lobe = p.root;
  ball level, kpi, lo, hi, c, t;
  set_rational(level, 2 * E, p2);
  set_int(kpi, k);
  arb_mul(kpi, kpi, cb.pi, p2);
  if (k == 0) arb_zero(lo);
  else {
    arb_mul_2exp_si(lo, cb.pi, -1);
    arb_neg(lo, lo);
  }
  arb_mul_si(hi, p.u0, r.lobe->lobe.side, p2);
  auto g = [&cb, &level, &kpi, p2](arb_t o, const arb_t u) {
    ball a;
    arb_add(a, kpi, u, p2);
    kernels_arb::R(o, cb.x, cb.c, a, p2);
    arb_sub(o, level, o, p2);
  };
  auto dg = [&cb, &kpi, p2](arb_t o, const arb_t u) {
    ball a;
    arb_add(a, kpi, u, p2);
    kernels_arb::dR(o, cb.x, a, p2);
    arb_neg(o, o);
  };
  ball_root u;
  GYRORES_TRY_PROOF(prove_ball_root(g, dg, lo, hi, prec, decimals, u));
  if (u.decimals < decimals) no_decimals("the crossing lies next to the lobe's minimiser", decimals);
  r.crossing = proved_bracket{u.bracket, u.decimals};
  arb_add(t, kpi, u.value, p2);
  arb_mul_2exp_si(t, t, 1);
  arb_div(t, t, cb.s, p2);
  return enclosure_from(t, p2, r.t_below);
}

// The first zero of a degenerate coupling: the centre of lobe k (nu = 0, u0 = 0), t = 2 k pi/S.
proof_status zero_at(const coupling_spec& spec, const quadratic_number& x, slong prec, first_below_proof& r) {
  coupling_balls cb(spec, x, prec);
  lobe_point p;
  GYRORES_TRY_PROOF(prove_lobe_point(cb, r.lobe->lobe, 0, p));
  r.lobe = p.root;
  return enclosure_from(p.t, prec, r.t_below);
}

}  // namespace

first_below_proof prove_first_below(const coupling_spec& spec, const big_rational& E,
                                    const refine_goal<first_below_proof>& goal, proof_use use, stop_token stop) {
  check_report_digits(goal.digits);
  if (E < 0) throw usage_error("the level E must be >= 0, got " + rational_str(E));
  const quadratic_number x = coupling_rotation_number(spec);
  const unsigned decimals = use == proof_use::certificate ? certificate_digits(goal.digits) : 0;
  first_below_proof base;
  base.level = E;
  base.resonant = x.is_rational();
  // The cases without a real to prove (their values are exact).
  const auto exact_case = [&](below_case kase) {
    base.kase = kase;
    if (!goal.accepts(base)) throw compute_error("first time below: an exact answer was refused by its goal");
    return base;
  };
  if (2 * E >= 1) {
    base.t_below = enclosure::exact(0);
    return exact_case(below_case::start);
  }
  std::optional<big_int> zero_lobe;
  if (E == 0) {
    // R = 0 only at a lobe with nu = 0, at its centre (q = q' = 0): x = (2j+1)/(2k), a degenerate pair.
    zero_lobe = first_lobe_at_most(x, quadratic_number(0), stop);
    if (!zero_lobe) return exact_case(below_case::never);
  }
  // 2E against the supremum of the lobe values, G(pi/2) = 1 - x^2 = 4Q/(P + 4Q), exactly.
  const bool at_or_above_sup = 2 * E >= big_rational(4 * spec.Q(), big_int(spec.P() + 4 * spec.Q()));
  const mpfr_prec_t start = start_bits(goal.digits, zero_lobe ? big_rational(*zero_lobe) : big_rational(1), spec);
  return refine(plan_of(start), stop, "first time below", [&](mpfr_prec_t bits, proof_status& status) {
    first_below_proof r = base;
    r.bits = bits;
    const slong prec = slong(bits);
    if (zero_lobe) {
      r.kase = below_case::zero;
      r.lobe = lobe_root{lobe_of(x, *zero_lobe), {}, enclosure()};
      status = zero_at(spec, x, prec, r);
    } else {
      coupling_balls cb(spec, x, prec);
      ball level;
      set_rational(level, 2 * E, prec);
      std::optional<big_int> k;
      status = first_lobe_at_level(cb, x, level, at_or_above_sup, decimals, stop, r, k);
      if (status && !k) r.kase = below_case::never;
      else if (status) {
        r.kase = below_case::lobe;
        r.lobe = lobe_root{lobe_of(x, *k), {}, enclosure()};
        status = crossing_at(spec, x, E, prec, decimals, r);
      }
    }
    if (status) status = goal.accepts(r);
    return status ? std::optional<first_below_proof>(std::move(r)) : std::nullopt;
  });
}

}  // namespace gyrores
