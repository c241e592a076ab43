// The sweep's internal steps that the tests call one by one (tests/test_sweep.cpp,
// tests/test_certified_filter.cpp): the decisions a wrong row could hide behind, each tested
// against an independent reference and mutated (tests/mutants/CMakeLists.txt). Not for use
// outside the tests (names and signatures change with the sweep).
#pragma once
#include <cstdint>

#include <gyrores/core/dd_ball.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/evaluate.hpp>

namespace gyrores::sweep_testing {

// The double nearest (upward, downward) to every v in the ball X (v > 0), if there is one such
// double; false otherwise. The certified filter's rows print these.
bool round_nearest(const dd_ball& X, double& out);
bool round_up(const dd_ball& X, double& out);
bool round_down(const dd_ball& X, double& out);

// The certified double row of p from the double-double balls alone (cfg.certified): true with
// r the row sweep_evaluate gives, or false (r fresh) where the MPFI fallback would run.
bool certified_filter_row(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg);

// P3's r_res^2 <= R(pi/2) for a non-degenerate pair p of a double row, given r_res within one
// ulp and N = 4 a^2 R(pi/2) (sweep_quarter_R_scaled): in double where decided beyond its
// rounding error, else by the proved enclosure (false if not proved).
bool r_below_quarter_R(const resonant_pair<std::int64_t>& p, double r_res, int128 N);

// The sweeps without rows (src/lib/sweep/fast.cpp). True: r_res^2 <= R(pi/2) proved for the
// non-degenerate pair (tau, sigma) with m_min = m and N = 4 a^2 R(pi/2); false: not decided.
bool fast_r_below_quarter_R(std::int64_t tau, std::int64_t sigma, int m, std::int64_t N);
// Whether a pair whose asy constant is at most `bound` (paper_constant_bound, theorem/paper.hpp)
// may be skipped because its computed constant and ratio are certainly below those of a pair
// already computed, whose constant is `known` (0: none).
bool fast_asy_below(double bound, double known);

}  // namespace gyrores::sweep_testing
