// The sweep's fast path: a pair's contribution to the summary without its row, for sweeps that
// write no rows (no --out), in double, not --certified.
//
// Without rows, what a pair's values feed is the summary (sweep/summary.hpp): the checks'
// verdicts, which must stay exact, and three computed (not proved) values: t_first/(pi/|n|)
// for the quantiles, and the asy ratio and constant, whose largest values are printed. So:
//  - every verdict is decided by a proof that is cheaper than the row's value: exact integers
//    (the lobes, paper-node, structure, R(pi/2)) and proved inequalities (P3, asy-bound) that
//    are far from tight for the pairs taken here (src/lib/sweep/fast.cpp argues each); the
//    row's double path decides the same (paper-node from the same integers, so its failures,
//    the common case, are counted here too);
//  - t_first/(pi/|n|) is formed from u* by its series in mu/(2x) (pairs with delta >=
//    sweep_fast_min_delta, where u* <= pi/(2 delta) is small), as theta_first within about an
//    ulp of the exact value: the same bound as the row's theorem_minimum_double
//    (theorem/minimum.hpp), so the quantiles agree with a run that writes rows except, rarely,
//    in their last digit (a value within an ulp of a rounding boundary);
//  - the asy ratio and constant are computed (by the row's own function, bit for bit) only for
//    the pairs whose proved upper bound on them reaches the largest constant already computed
//    in this run: the others cannot change either maximum.
// A pair that is not decided this way (small delta, a failure of P3 or structure, a bound that
// does not decide)
// goes the row's way (sweep_evaluate_to, sweep_record_fill, sweep_accumulator::add), so its
// contribution, failures and notes included, is exactly the row path's.
#pragma once
#include <atomic>
#include <cstdint>
#include <vector>

#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/summary.hpp>

namespace gyrores {
namespace detail {

// Non-degenerate pairs with a smaller delta go the row's way (u* is not small there).
inline constexpr std::int64_t sweep_fast_min_delta = 64;

// u* = H^{-1}(pi m/(2a)) with H(u) = x u + arctan(x tan u), x = b/a, for b >= 64 and m = 1, 2:
// within a few ulps (fast.cpp).
double sweep_fast_root(std::int64_t a, std::int64_t b, int m);
// theta = 2 (k pi + su)/a (k >= 1, |su| < pi/2) within half an ulp and a few units of 2^-60.
double sweep_fast_theta(std::int64_t a, std::int64_t k, double su);
// sweep_quarter_R_scaled(a, b) (sweep/certified.hpp), 4 a^2 R(pi/2), in int64 for 0 < b < a < 2^28
// (it is below 2^62 there).
std::int64_t sweep_fast_quarter_R_scaled(std::int64_t a, std::int64_t b);
// Proved: r_res^2 <= R(pi/2) for the non-degenerate pair (tau, sigma) with m_min = m and
// N = 4 a^2 R(pi/2) (sweep_quarter_R_scaled). False: not decided this way (not: it fails).
bool sweep_fast_r_below_quarter_R(std::int64_t tau, std::int64_t sigma, int m, std::int64_t N);
// A proved upper bound, up to a relative 2^-47, of the asy constant |theta_c - theta_asy| a/x^2
// of a pair with x = b/a < 1/2 and the paper's lobe offset |m| = am <= b.
double sweep_fast_asy_bound(std::int64_t a, std::int64_t b, std::int64_t am);
// Whether a pair whose asy constant is at most `bound` (sweep_fast_asy_bound) may be skipped
// because its computed constant and ratio are certainly below those of a pair already
// computed, whose constant is `known` (0: none).
bool sweep_fast_asy_below(double bound, double known);

// The k of the pass frame (theorem/lobes.hpp, pass_frame: (2j+1) a - 2 k b = m_min, 0 < k <
// ah) of each pair of a block, by Montgomery's batch inversion over each run of one order: with
// ah = a (m_min = 1) or a/2 (m_min = 2), b = -2 sigma mod ah gives k = (4 sigma)^-1 or
// (2 sigma)^-1 mod ah (fast.cpp); 0 for degenerate pairs and orders from 2^31 on. ks[i] is
// pairs[i]'s. The lobes built from it are checked by the structure check, whose failure sends a
// pair the row's way: a wrong k costs time, never a wrong summary.
void sweep_fast_pass_ks(const std::vector<resonant_pair<std::int64_t>>& pairs, std::vector<std::int64_t>& ks);

// Adds p's contribution to acc if the fast path decides it (true); false: nothing was added.
// `asy_known` is the largest asy constant computed so far by this caller (updated); pass_k is
// p's from sweep_fast_pass_ks.
bool sweep_fast_add(sweep_accumulator& acc, const resonant_pair<std::int64_t>& p, const sweep_config& cfg,
                    double& asy_known, std::int64_t pass_k);

// Whether a sweep with this configuration may take the fast path (double rows, no rows
// written, not certified).
inline bool sweep_fast_config(const sweep_config& cfg) { return !cfg.certified; }

// The largest asy constant computed by any worker of one run (a hint: any value a pair of the
// run has given is a valid one; relaxed order suffices).
void sweep_fast_publish(std::atomic<double>& shared, double known);

}  // namespace detail
}  // namespace gyrores
