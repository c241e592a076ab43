// include/gyrores/report/horizon_report.hpp: the horizon theorem's proofs, rounded.
#include <gyrores/report/horizon_report.hpp>

#include <algorithm>

#include <gyrores/report/scales.hpp>

namespace gyrores {

namespace {

// Rounds `e` into `out`; undecided (the proof's precision then rises) while it straddles.
proof_status round_into(proved_real& out, const enclosure& e, unsigned digits) {
  auto r = e.report(digits);
  if (!r) return proof_status::undecided("a rounding of the report");
  out = std::move(*r);
  return proof_status::proved();
}

std::string below_reason(const first_below_proof& p, bool unit) {
  switch (p.kase) {
    case below_case::start: return unit ? "H_q(0) = qdot0^2/2 = 1/2 is already <= E" : "H_q(0) is already <= E";
    case below_case::zero:
      return "the first exact zero of H_q (a degenerate pair), at the centre of lobe " + p.lobe->lobe.k.str();
    case below_case::lobe:
      return "lobe " + p.lobe->lobe.k.str() + " is the first whose minimum reaches E; H_q crosses E once on its descending branch";
    case below_case::never: break;
  }
  if (p.level > 0) return "resonant: H_q >= H_min > E for all time (the motion is periodic and no lobe's minimum reaches E)";
  return p.resonant ? "resonant and not degenerate (delta != 2 mod 4): H_q >= H_min > 0 for all time"
                    : "W1/W2 is irrational: H_q comes arbitrarily close to 0 but never reaches it";
}

// An enclosure in the units of `scales`: `k` times it (exact), or times sqrt(k2).
enclosure in_units(const enclosure& e, const big_rational& k) { return k == 1 ? e : scaled(e, k); }
enclosure in_units_sqrt(const enclosure& e, const big_rational& k2, unsigned digits) {
  return k2 == 1 ? e : scaled_sqrt(e, k2, mpfr_prec_t(digits10_to_bits(digits) + 32));
}

}  // namespace

horizon_minimum_report report_horizon_minimum(const coupling_spec& c, const horizon_time& horizon, unsigned digits,
                                              stop_token stop, proof_use use, const report_scales& scales) {
  horizon_minimum_report r;
  r.digits = digits;
  r.proof = prove_horizon_minimum(c, horizon, {digits, [&](const horizon_minimum_proof& p) {
                                                 GYRORES_TRY_PROOF(round_into(r.h_min, in_units(p.h_min, scales.energy), digits));
                                                 GYRORES_TRY_PROOF(round_into(r.h_min_share, scaled(p.h_min, share_factor()),
                                                                              std::min(digits, share_digits)));
                                                 GYRORES_TRY_PROOF(round_into(r.t_min, in_units_sqrt(p.t_min, scales.time2, digits), digits));
                                                 return round_into(r.r_min, in_units_sqrt(p.r_min, scales.radius2, digits), digits);
                                               }}, use, stop);
  if (!r.proof.at_horizon_end && r.proof.best) r.lobe = r.proof.best->lobe;
  return r;
}

first_below_report report_first_below(const coupling_spec& c, const big_rational& level, unsigned digits,
                                      stop_token stop, proof_use use, const report_scales& scales) {
  first_below_report r;
  r.digits = digits;
  r.proof = prove_first_below(c, level, {digits, [&](const first_below_proof& p) {
                                           if (p.kase == below_case::never) return proof_status::proved();
                                           return round_into(r.t_below, in_units_sqrt(p.t_below, scales.time2, digits), digits);
                                         }}, use, stop);
  r.never = r.proof.kase == below_case::never;
  r.reason = below_reason(r.proof, scales.unit());
  if (r.proof.lobe) r.lobe = r.proof.lobe->lobe;
  return r;
}

}  // namespace gyrores
