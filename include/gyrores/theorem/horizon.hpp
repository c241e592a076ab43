// The horizon theorem (proofs/horizon-theorem.md, id "horizon-theorem/1"): for ANY coupling n,
// the minimum of H_q over [0, T] and the first time H_q falls to a level, proved, in O(log T).
//
// The lattice theorem's lobe argument never uses that x = n/sqrt(n^2 + 4) is rational. Lobe k
// (alpha = sqrt(n^2 + 4) t/2 in [k pi - pi/2, k pi + pi/2]) has offset |mu_k| = pi ||k x - 1/2||
// and minimum R = G(H^{-1}(|mu_k|)), increasing in ||k x - 1/2||. So the minimum over [0, T] is
// decided by integers: the lobe k <= k_c - 1 with the smallest ||k x - 1/2|| (model/rotation.hpp,
// exact), against the lobe k_c cut by T (its minimiser inside [0, T] or not) and the end point
// R(T). The first time below a level is the first lobe whose minimum reaches it, then one
// crossing on that lobe's descending branch. Only the final roots are real numbers: each is
// proved by a bracket whose ends are decided in Arb ball arithmetic, and printed as the correct
// rounding of its enclosure (impulse qdot0 = 1: H_q = R/2).
#pragma once
#include <optional>
#include <string>

#include <gyrores/core/quadratic.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/theorem/pair_report.hpp>

namespace gyrores {

inline constexpr const char* horizon_theorem_id = "horizon-theorem/1";

// Which lobe the minimum over [0, T] comes from (the integers a certificate carries).
struct horizon_lobe {
  big_int k;                 // the lobe
  quadratic_number nu;       // ||k x - 1/2||, exactly
  int side = 1;              // the minimiser is at u = side * H^{-1}(pi nu) in the lobe (-1, 0, +1)
};

struct horizon_minimum_report {
  unsigned digits = 0;
  horizon_time horizon;          // T
  quadratic_number x;            // n/sqrt(n^2 + 4), exactly
  big_int cut_lobe;              // k_c = floor(sqrt(n^2 + 4) T/(2 pi) + 1/2): the lobe holding t = T
  bool cut_lobe_reached = false; // k_c's minimiser lies in [0, T]
  bool at_horizon_end = false;   // the minimum is R(T), at t = T (H_q still decreasing there)
  std::optional<horizon_lobe> lobe;  // the lobe of the minimum (none when at the horizon's end)
  proved_real h_min, t_min;      // min of H_q over [0, T] and the first time it is attained
  proved_real r_min;             // the radius sqrt(2 h_min) = sqrt(q^2 + q'^2) there
};

// Throws usage_error for T < 0 or digits outside [1, report_digits_max]; compute_error when the
// end point ties a lobe value within 64 times the starting precision (at least 2^16 bits);
// interrupted when `stop` is set.
horizon_minimum_report prove_horizon_minimum(const coupling_spec& c, const horizon_time& horizon, unsigned digits,
                                             stop_token stop = {});

struct first_below_report {
  unsigned digits = 0;
  big_rational level;            // E (an energy; qdot0 = 1, so the initial H_q is 1/2)
  bool never = false;            // H_q stays above E for all time
  std::string reason;            // one line: why never, or where the crossing is
  std::optional<horizon_lobe> lobe;  // the first lobe whose minimum is <= E (none: t = 0 or never)
  proved_real t_below;           // the first t with H_q(t) <= E (when not never)
};

// The first time H_q <= E (E >= 0). Never only for a resonant coupling whose H_min exceeds E,
// or E = 0 for a coupling with no exact zero. Throws as prove_horizon_minimum.
first_below_report prove_first_below(const coupling_spec& c, const big_rational& level, unsigned digits,
                                     stop_token stop = {});

}  // namespace gyrores
