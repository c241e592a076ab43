// include/gyrores/report/horizon_report.hpp: the horizon theorem's proofs, rounded.
#include <gyrores/report/horizon_report.hpp>

#include <algorithm>

#include <gyrores/report/share.hpp>

namespace gyrores {

namespace {

// Rounds `e` into `out`; undecided (the proof's precision then rises) while it straddles.
proof_status round_into(proved_real& out, const enclosure& e, unsigned digits) {
  auto r = e.report(digits);
  if (!r) return proof_status::undecided("a rounding of the report");
  out = std::move(*r);
  return proof_status::proved();
}

std::string below_reason(const first_below_proof& p) {
  switch (p.kase) {
    case below_case::start: return "H_q(0) = qdot0^2/2 = 1/2 is already <= E";
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

}  // namespace

horizon_minimum_report report_horizon_minimum(const coupling_spec& c, const horizon_time& horizon, unsigned digits,
                                              stop_token stop, proof_use use) {
  horizon_minimum_report r;
  r.digits = digits;
  r.proof = prove_horizon_minimum(c, horizon, {digits, [&](const horizon_minimum_proof& p) {
                                                 GYRORES_TRY_PROOF(round_into(r.h_min, p.h_min, digits));
                                                 GYRORES_TRY_PROOF(round_into(r.h_min_share, scaled(p.h_min, share_factor()),
                                                                              std::min(digits, share_digits)));
                                                 GYRORES_TRY_PROOF(round_into(r.t_min, p.t_min, digits));
                                                 return round_into(r.r_min, p.r_min, digits);
                                               }}, use, stop);
  if (!r.proof.at_horizon_end && r.proof.best) r.lobe = r.proof.best->lobe;
  return r;
}

first_below_report report_first_below(const coupling_spec& c, const big_rational& level, unsigned digits,
                                      stop_token stop, proof_use use) {
  first_below_report r;
  r.digits = digits;
  r.proof = prove_first_below(c, level, {digits, [&](const first_below_proof& p) {
                                           if (p.kase == below_case::never) return proof_status::proved();
                                           return round_into(r.t_below, p.t_below, digits);
                                         }}, use, stop);
  r.never = r.proof.kase == below_case::never;
  r.reason = below_reason(r.proof);
  if (r.proof.lobe) r.lobe = r.proof.lobe->lobe;
  return r;
}

}  // namespace gyrores
