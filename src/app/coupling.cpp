// include/gyrores/app/coupling.hpp
#include <gyrores/app/coupling.hpp>

#include <limits>

#include <gyrores/app/plant.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/model/inputs.hpp>

namespace gyrores::app {

coupling_result run_coupling(const coupling_request& request) {
  coupling_report_options opt = request.options;
  if (opt.convergents > coupling_convergents_max)
    throw usage_error("convergents must be in [0, " + std::to_string(coupling_convergents_max) + "], got " +
                      std::to_string(opt.convergents));
  // The envelope of the inputs (model/limits.hpp), before any work (the CLI's parsers name
  // the flags; this is for every other caller).
  check_coupling_limits(request.spec.n2, "the coupling's n^2");
  check_horizon_limits(opt.horizon, "the horizon");
  if (opt.below) check_level_limits(*opt.below, "the level");
  if (request.certificate) check_certificate_horizon(opt.horizon);
  if (!(request.qdot0 > 0)) throw usage_error("qdot0 must be > 0, got " + rational_str(request.qdot0));
  if (request.plant && request.qdot0 != 1) throw usage_error("give a plant's velocity or qdot0, not both");
  if (request.certificate && (request.qdot0 != 1 || request.plant))
    throw usage_error("a coupling certificate states the unit impulse in model units (qdot0 = 1): drop the plant or qdot0, or the certificate");
  if (request.plant) {
    if (request.plant->n2() != request.spec.n2)
      throw usage_error("the coupling's n^2 is not the plant's g^2/(m k) = " + rational_str(request.plant->n2()));
    opt.scales = plant_scales(*request.plant);
  } else if (request.qdot0 != 1) {
    opt.scales = report_scales::of_qdot0(request.qdot0);
    opt.pair_qdot0 = request.qdot0;
  }
  opt.use = request.certificate ? proof_use::certificate : proof_use::report;
  coupling_result out{analyse_coupling(request.spec, opt), std::nullopt};
  if (!request.certificate) return out;
  const coupling_report& r = out.report;
  out.certificate = horizon_certificate_of(request.spec, r.horizon.proof, opt.digits);
  if (r.below) out.certificate->below = below_certificate_of(request.spec, r.below->proof, opt.digits);
  return out;
}

namespace {

// The nearest double of e into `out`; undecided (the proof's precision rises) while it is not.
proof_status double_into(double& out, const enclosure& e) {
  const auto d = e.nearest_double();
  if (!d) return proof_status::undecided("the nearest double");
  out = *d;
  return proof_status::proved();
}

}  // namespace

coupling_doubles run_coupling_doubles(const coupling_spec& spec, const horizon_time& horizon,
                                      const std::optional<big_rational>& level, stop_token stop) {
  constexpr unsigned digits = 17;  // the precision to start from: a double's digits
  check_coupling_limits(spec.n2, "the coupling's n^2");
  check_horizon_limits(horizon, "the horizon");
  if (level) check_level_limits(*level, "the level");
  coupling_doubles out;
  out.resonant = coupling_resonant_pair(spec).has_value();
  const auto m = prove_horizon_minimum(spec, horizon, {digits, [&](const horizon_minimum_proof& p) {
                                                          GYRORES_TRY_PROOF(double_into(out.h_min, p.h_min));
                                                          return double_into(out.t_min, p.t_min);
                                                        }}, proof_use::report, stop);
  out.at_end = m.at_horizon_end;
  out.t_below = std::numeric_limits<double>::quiet_NaN();
  if (level)
    prove_first_below(spec, *level, {digits, [&](const first_below_proof& p) {
                                       if (p.kase == below_case::never) return proof_status::proved();
                                       return double_into(out.t_below, p.t_below);
                                     }}, proof_use::report, stop);
  return out;
}

}  // namespace gyrores::app
