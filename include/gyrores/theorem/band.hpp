// A band of couplings [n1, n2] (a designer's tolerance): over every n in it, the largest and the
// smallest minimum of H_q over [0, T], and the degenerate pairs whose exact zero of H_q comes
// before T (proofs/horizon-theorem.md, item 6 and Step 12).
//
// M(n) = min over [0, T] of H_q is min(V(nu*), R(T)) (the horizon theorem): the best lobe's value
// V_x(nu*), nu* = min over the lobes k <= K_T of ||k x - 1/2||, x = n/sqrt(n^2 + 4), against the
// end point. A branch and bound over boxes N of n bounds M on each box from that structure, not
// from a Lipschitz constant: from above by the end point R(T) over N (a mean-value enclosure) and
// by the peaks of nu* over the box's x-interval for the lobes admissible on all of N (listed
// exactly: between two neighbouring centres (2j+1)/(2k) nu* lies under two tents), through
// V_x's monotonicity in nu and in x; from below by R(T) over N and by the smallest nu* over the
// box (its value at the two ends, or 0 where a lobe's centre lies inside), for the lobes
// admissible somewhere on N. These bounds tighten with the box, not with the horizon. Each
// proved M(n) at an exact rational n (the horizon theorem) closes the other side: the worst case
// lies between the best proved M(n) and the largest box bound. The best case is exactly 0 when
// the band holds a degenerate pair (x = (2j+1)/(2k)) whose zero, at t = 2 k pi/sqrt(n^2 + 4),
// lies in [0, T]: found exactly, by the smallest such k.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/theorem/horizon.hpp>

namespace gyrores {

// Where a band proof stands (for a progress display): which extreme, the work done on it so far
// and its enclosure (H_q; hi may be +infinity before the first box bound).
struct band_progress {
  bool worst = true;
  std::size_t evaluations = 0, boxes = 0;  // proved horizon minima and box bounds, this extreme
  double lo = 0, hi = 0;
};

struct band_options {
  unsigned digits = 6;                 // the relative width asked of each enclosure: 10^-digits
  std::size_t max_evaluations = 4000;  // box bounds plus proved horizon minima per extreme (then the enclosure reached is reported)
  bool want_worst = true, want_best = true;  // which extremes to prove (the other is left 0, unconverged)
  stop_token stop;
  std::function<void(const band_progress&)> progress;  // called after each step of the search (optional)
};

// One extreme of M over the band: a proved enclosure, and where it is attained.
struct band_extreme {
  big_rational lo, hi;            // lo <= the extreme <= hi (exact rationals)
  std::string value;              // the correct rounding to `digits` digits when lo and hi share it, else ""
  big_rational n_at;              // a coupling where M(n_at) lies within [lo, hi]
  big_rational n_box_lo, n_box_hi;  // the box of n being refined when n_at was found (it holds n_at)
  bool converged = false;         // hi - lo reached the asked width
};

struct band_degenerate {
  big_rational n2;                      // the coupling's n^2, exactly
  resonant_pair<big_int> pair;
  proved_real t_zero;                   // its first zero of H_q
};

struct band_report {
  big_rational n1, n2;
  horizon_time horizon;
  unsigned digits = 6;
  std::string lipschitz;                // a bound L on |dH_q/dn| over the band and [0, T], so |M(n) - M(n')| <= L |n - n'|
                                        // (upper end, 6 digits; for sampling M: the enclosures do not use it)
  band_extreme worst;                   // max over n of M(n)
  band_extreme best;                    // min over n of M(n)
  std::optional<band_degenerate> zero;  // a degenerate pair whose zero lies in [0, T] (then best = 0)
  std::size_t evaluations = 0;          // proved horizon minima computed
  std::size_t boxes = 0;                // box bounds computed
};

// Throws usage_error unless 0 < n1 < n2 and T >= 0; interrupted when opt.stop is set.
band_report prove_band(const big_rational& n1, const big_rational& n2, const horizon_time& horizon,
                       const band_options& opt = {});

}  // namespace gyrores
