// A band of couplings [n1, n2] (a designer's tolerance) over a horizon [0, T]: the band theorem
// (proofs/band-theorem.md, id "band-theorem/1"). With M(n) the minimum of R = 2 H_q over [0, T] at
// the coupling n (the horizon theorem, theorem/horizon.hpp):
//   absorption guarantee  W = max over the band of M: every coupling drains q at least to W/2;
//   containment guarantee B = min over the band of M: every coupling keeps at least B/2 in q;
//   band-wide first time below E: the latest first time H_q <= E over the band
//                                  (= the least T whose absorption guarantee is <= E).
// Each is proved by a branch and bound over intervals of x = n/sqrt(n^2 + 4): every interval gets
// an upper (W) or lower (B) bound from the lobes' structure (the peak lemma: the least odd or even
// denominator fraction of the interval, exact; the lobe value at the interval's ends, monotone in
// x) and from the end point R(T); every split point is a coupling with rational n^2, whose minimum
// the horizon theorem proves. The search stops when the best proved value and the best remaining
// bound round alike to the digits asked: the extreme is then settled, attained at that coupling
// (a resonant pair when x is rational). Everything here is in H_q units (R/2), qdot0 = 1, but for
// the extremes' reported values when options.energy_scale = qdot0^2 is given.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/quadratic.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>

namespace gyrores {

inline constexpr const char* band_theorem_id = "band-theorem/1";

// A coupling of the band, exactly: its n^2 and its x (rational iff resonant).
struct band_coupling {
  coupling_spec spec;
  quadratic_number x;
  static band_coupling of_n(const big_rational& n);             // a band's end, n > 0
  static band_coupling of_x(const big_int& p, const big_int& q);  // x = p/q in (0, 1): n^2 = 4p^2/(q^2 - p^2)
};

// Where a proof stands (for a progress display), in H_q units; hi may be +infinity at first.
struct band_progress {
  const char* what = "";  // "absorption", "containment", "first time below"
  std::size_t intervals = 0, couplings = 0;
  double lo = 0, hi = 0;
};

struct band_options {
  unsigned digits = 6;                 // the extremes are settled to this many digits, [1, report_digits_max]
  std::size_t max_intervals = 100000;  // a cap on the intervals of one branch and bound (then: not settled)
  std::optional<big_rational> versus;  // H_q: stop as soon as the extreme is proved on one side of it
  big_rational energy_scale = 1;       // the extremes are reported and settled as H_q times this (qdot0^2), exactly
  bool record_cover = false;           // keep the final covering of the band (for a certificate)
  stop_token stop;                     // Ctrl-C: the search returns the bracket so far (interrupted)
  std::function<void(const band_progress&)> progress;  // called as the search goes (optional)
};

// One interval of the covering a search ends with (what a certificate states, band-theorem.md
// item 4): its ends, which bound of item 4 it took and that bound (R units, upper for the
// absorption guarantee, lower for the containment one).
enum class band_bound_kind {
  lobes,          // V_a(max F_K) over J (absorption), min(V_a(F_K(a)), V_b(F_K(b))) or 0 (containment)
  line_falling,   // J clean for K, one falling line nu_k: V_a(f(a))
  line_rising,    // J clean, one rising line nu_k with g > 0 proved: V_b(f(b))
  line_turning,   // J clean, one rising line nu_k with g < 0 proved: V_a(nu_k(a))
  line_unproved,  // J clean, one rising line: V_a(f(b))
  end_point,      // the end point's range over J (absorption: its sup; containment: min with K - 1's lobes)
};
struct band_cover_interval {
  band_coupling a, b;
  band_bound_kind kind = band_bound_kind::lobes;
  big_int K;                // the lobes 0..K the bound uses (absorption: K- of item 4; containment: K+)
  big_int k;                // the line's lobe, for the line kinds
  bool reached = false;     // absorption: K = k_c(a) because lobe k_c(a) is reached on J
  bool unreached = false;   // containment: lobe k_c(b) not reached on J (K = k_c(b) - 1 and the end point)
  big_rational bound;       // R units
};

// One extreme, W or B, in H_q units.
struct band_extreme {
  enclosure value;               // proved: the extreme lies in it
  bool settled = false;          // value.rounded(digits) is defined: the correct rounding
  bool decided = false;          // options.versus was given and value lies on one side of it
  bool interrupted = false;      // stopped by the stop token: value is the bracket reached
  std::string unsettled_reason;  // why not settled (a cap), when neither settled nor interrupted
  band_coupling at;              // the coupling whose own minimum is the attained end of `value`
  enclosure at_value;            // that minimum (H_q)
  std::size_t intervals = 0, couplings = 0;
  std::vector<band_cover_interval> cover;  // with options.record_cover: the intervals that bound the rest, in order
};

// W and B over the band [n1, n2] and the horizon T > 0. usage_error unless 0 < n1 < n2 and T > 0.
band_extreme prove_band_absorption(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                   const band_options& opt = {});
band_extreme prove_band_containment(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                    const band_options& opt = {});

// The bound of band-theorem item 4 over one interval [a, b] (a < b, R = 2 H_q units): an upper
// bound of M on it (absorption) or a lower bound (containment), and which bound it took. What the
// searches compute for every interval; public for the tests of each proof step and for checkers.
band_cover_interval band_interval_bound(const band_coupling& a, const band_coupling& b, const horizon_time& T,
                                        bool absorption, unsigned digits = 6);

// The latest first time H_q <= E over the band, in time units.
struct band_first_below {
  big_rational level;            // E
  bool never = false;            // some coupling of the band never reaches E
  std::string reason;            // why never (the pair), or where the latest time is approached
  enclosure time;                // proved (when not never): the latest first time lies in it
  bool settled = false, interrupted = false;
  std::string unsettled_reason;
  band_coupling at;              // a coupling whose own first time below E is the lower end
  enclosure at_time;             // that time
  std::size_t intervals = 0, couplings = 0;
};
band_first_below prove_band_first_below(const big_rational& n1, const big_rational& n2, const big_rational& level,
                                        const band_options& opt = {});

}  // namespace gyrores
