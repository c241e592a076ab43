// The horizon theorem's proofs (theorem/horizon.hpp) as `gyrores coupling` prints them: every
// enclosure correctly rounded, to nearest with `digits` significant digits, with the enclosure
// rounded outward to digits + 3 (core/enclosure.hpp, report()); exact values (the horizon end T,
// an exact zero, t = 0) are rounded once from their rational. The precision of the proof rises
// until every rounding is decided, and the report keeps the proof it rounded: a certificate is
// written from that same proof (certify/horizon_certificate.hpp), never from a second one.
// The proofs are at the impulse qdot0 = 1 (H_q(0) = 1/2); with `scales` (report/scales.hpp) the
// energies, radius and times are rounded in those units (the share of H_q(0) does not change).
#pragma once
#include <optional>
#include <string>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/report/scales.hpp>
#include <gyrores/theorem/horizon.hpp>

namespace gyrores {

struct horizon_minimum_report {
  unsigned digits = 0;
  horizon_minimum_proof proof;       // what the numbers below round (x, cut lobe, decisions, roots)
  std::optional<horizon_lobe> lobe;  // the lobe of the minimum (none when at the horizon's end)
  proved_real h_min, t_min;          // min of H_q over [0, T] and the first time it is attained
  proved_real r_min;                 // the radius sqrt(2 h_min) = sqrt(q^2 + q'^2) there
  proved_real h_min_share;           // h_min as a percentage of H_q(0) (report/scales.hpp)
};

// With proof_use::certificate the proof is one a certificate can be written from
// (theorem/horizon.hpp). usage_error for T < 0 or digits outside [1, report_digits_max];
// compute_error when the end point ties a lobe value (not decided within tie_bits_cap);
// interrupted when `stop` is set.
horizon_minimum_report report_horizon_minimum(const coupling_spec& c, const horizon_time& horizon, unsigned digits,
                                              stop_token stop = {}, proof_use use = proof_use::report,
                                              const report_scales& scales = {});

struct first_below_report {
  unsigned digits = 0;
  first_below_proof proof;
  bool never = false;                // H_q stays above E for all time
  std::string reason;                // one line: why never, or where the crossing is
  std::optional<horizon_lobe> lobe;  // the first lobe whose minimum is <= E (none: t = 0 or never)
  proved_real t_below;               // the first t with H_q(t) <= E (when not never)
};

// The first time H_q <= E (E >= 0, at the unit impulse). Throws as report_horizon_minimum.
first_below_report report_first_below(const coupling_spec& c, const big_rational& level, unsigned digits,
                                      stop_token stop = {}, proof_use use = proof_use::report,
                                      const report_scales& scales = {});

}  // namespace gyrores
