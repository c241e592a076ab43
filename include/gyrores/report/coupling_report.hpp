// What gyrores reports about any coupling n (`gyrores coupling`): the exact resonance test, the
// pair analysis when resonant, the minimum of H_q over a horizon [0, T] and its first time, the
// first time H_q falls to a level, the infimum over all time, and the continued-fraction
// convergents of W1/W2 as resonant pairs (model/coupling.hpp, report/horizon_report.hpp).
//
// Every number is proved: the correct rounding of an enclosure (the horizon theorem for the
// minimum over [0, T] and the first time below a level, the lattice theorem for the pair).
// Impulse qdot0 = 1 (H_q(0) = 1/2) unless the options scale it (report/scales.hpp). The horizon reports keep the proofs they
// rounded: `gyrores coupling --certificate` writes its certificate from them (app/coupling.hpp).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/report/horizon_report.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores {

struct coupling_report_options {
  unsigned digits = 12;                  // [1, report_digits_max]
  horizon_time horizon{big_rational(100)};  // T >= 0
  std::optional<big_rational> below;     // a level E: the first time H_q <= E
  std::size_t convergents = 8;           // how many convergents of W1/W2
  stop_token stop;                       // Ctrl-C
  proof_use use = proof_use::report;     // certificate: the horizon proofs made to be certified too
  report_scales scales;                  // the units of the horizon values and of pi/|n| (below: a unit-impulse level)
  big_rational pair_qdot0 = 1;           // the impulse of the pair's and the convergents' values
};

// One convergent p/q of W1/W2: the resonant pair (p, q) when p > q, with its proved values.
struct coupling_convergent {
  ratio_convergent convergent;
  std::optional<resonant_pair<big_int>> pair;  // none for the ratio 1 (p = q)
  std::optional<pair_report> values;           // proved (report/pair_report.hpp)
};

struct coupling_report {
  coupling_spec spec;
  bool n_negative = false;                      // n was given < 0 (it mirrors the motion; |n| is used)
  std::string abs_n, t_min_paper;               // |n| and the paper's proxy pi/|n| (proved)
  std::optional<resonant_pair<big_int>> pair;   // when resonant
  std::optional<pair_report> pair_values;       // its analysis, proved
  horizon_minimum_report horizon;               // min of H_q over [0, T] and its first time
  std::optional<first_below_report> below;      // when a level was given
  // inf of H_q over all time: the pair's H_min (attained) or 0 (not attained, dense torus line).
  std::string inf_all_time;
  bool inf_attained = false;
  std::string inf_reason;                       // one line saying why
  std::vector<coupling_convergent> convergents;
};

// Throws usage_error for digits outside [1, report_digits_max], a negative horizon or level;
// compute_error when some number cannot be decided; interrupted when opt.stop is set.
coupling_report analyse_coupling(const coupling_spec& spec, const coupling_report_options& opt = {});

}  // namespace gyrores
