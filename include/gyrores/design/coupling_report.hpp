// What gyrores reports about any coupling n (`gyrores coupling`): the exact
// resonance test, the pair analysis when resonant, the minimum of H_q over a horizon [0, T] and
// its first time, the infimum over all time, and the continued-fraction convergents of W1/W2 as
// resonant pairs (coupling.hpp has the mathematics).
//
// Digits: the resonant pair's values (and the convergents' pairs) are proved: correct roundings of
// enclosures (theorem/pair_report.hpp). The minimum over a horizon of a coupling that is not
// resonant, or whose first hit lies beyond the horizon, is a D-digit string accepted by the
// two-run test of core/verified_digits.hpp (a strong consistency check, not a proof; the report
// says so). Impulse qdot0 = 1 throughout.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/rational.hpp>
#include <gyrores/design/coupling.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/theorem/pair_report.hpp>

namespace gyrores {

// A horizon T >= 0 given exactly: T = value, or T = value * pi (formed in each real type).
struct exact_horizon {
  big_rational value = 0;
  bool times_pi = false;
};

// min of H_q over [0, T] for |n| (horizon_minimum), verified to D digits.
struct verified_horizon_min {
  std::string h_min, t_min, r_min;  // the minimum, its first time, and the radius sqrt(2 h_min)
  bool at_horizon_end = false;      // the minimum is at t = T
  std::size_t critical_points = 0;  // roots of q' and z' examined (in the higher-precision run)
};

// Throws usage_error for digits outside [1, 10000], a negative horizon or one too long for
// horizon_minimum; compute_error when the digits cannot be settled.
verified_horizon_min verify_horizon_minimum(const coupling_spec& c, const exact_horizon& horizon, unsigned digits);

struct coupling_report_options {
  unsigned digits = 12;           // [1, 10000]
  big_rational horizon = 100;     // T >= 0
  std::size_t convergents = 8;    // how many convergents of W1/W2
};

// One convergent p/q of W1/W2: the resonant pair (p, q) when p > q, with its verified values.
struct coupling_convergent {
  ratio_convergent convergent;
  std::optional<resonant_pair<big_int>> pair;   // none for the ratio 1 (p = q)
  std::optional<pair_report> values;          // proved (theorem/pair_report.hpp)
};

struct coupling_report {
  coupling_spec spec;
  bool n_negative = false;       // n was given < 0 (it mirrors the motion; |n| is used)
  std::string abs_n, t_min_paper;  // |n| and the paper's proxy pi/|n| (proved)
  std::optional<resonant_pair<big_int>> pair;        // when resonant
  std::optional<pair_report> pair_values;   // its analysis, proved
  // min of H_q over [0, T] and its first time: the pair's H_min and t_first when the horizon
  // contains t_first (decided at 256 bits), else from horizon_minimum.
  std::string h_min_horizon, t_min_horizon;
  bool horizon_proved = true;    // from the pair analysis (proved); false: verified digits, not proved
  bool min_at_horizon_end = false;
  std::string horizon_source;    // one line saying which of the two, and how
  // inf of H_q over all time: the pair's H_min (attained) or 0 (not attained, dense torus line).
  std::string inf_all_time;
  bool inf_attained = false;
  std::string inf_reason;        // one line saying why
  std::vector<coupling_convergent> convergents;
};

// Throws usage_error for digits outside [1, 10000], a negative horizon or one too long for
// horizon_minimum; compute_error when some digits cannot be settled.
coupling_report analyse_coupling(const coupling_spec& spec, const coupling_report_options& opt = {});

}  // namespace gyrores
