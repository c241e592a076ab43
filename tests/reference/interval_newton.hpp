// The one interval Newton of gyrores: proves that a function has exactly one root near a point
// guess and encloses it (MPFI, outward rounding). Used by the proof programs (proofs/lobe_roots.hpp,
// and the roots of q' of tests/reference/lobe_intervals.hpp).
//
// The method (the interval Newton of arb_calc): for an interval X and its midpoint m,
//   N(X) = m - f(m)/f'(X).
// If f'(X) excludes 0 and N(X) lies in the interior of X, then f has exactly one root in X and
// that root lies in N(X) (mean value theorem: a root is a fixed point of the Newton operator,
// and f is strictly monotone on X). A step is accepted only then; N(X) is inside X, so it
// shrinks X. Before the first accepted step, a failed step widens X around the guess (radius
// times 4) and retries; after it, the first failed step, or an accepted step that no longer
// shrinks X at the working precision, ends the iteration with the last accepted enclosure.
#pragma once
#include <functional>
#include <optional>

#include <gyrores/core/real.hpp>

namespace gyrores {

// A function of one interval variable returning an enclosure of its range (f or f').
using interval_function = std::function<mpfi_real(const mpfi_real&)>;

// Encloses the root of f near `guess`, at Boost's default precision of mpfi_real and mpfr_real,
// which guess and scale must have (core/real.hpp: the callers, the proof programs, set it and
// run single-threaded; proved code of the library uses
// core/fixed_precision.hpp and Arb instead).
//   f, df        enclosures of f and f' on an interval (df is evaluated on the whole X, f on
//                its midpoint as a point interval);
//   guess        a point near the root, e.g. a floating-point root polished to the working
//                precision;
//   scale        > 0, the size of the root (typically |guess|, or a floor where the root may
//                be 0): the first X is guess +- scale * 2^(12 - bits), and each failed step
//                before a proof widens the radius 4 times;
//   max_steps    the iteration budget, widening steps included (40 for q' roots, 60 for
//                u + tan u = s in gyrores). Newton needs a handful of steps once X holds the
//                root; k widenings reach a radius scale * 2^(12 + 2k - bits), so the guess must
//                be about that close: with a guess at the working precision the budget is
//                ample, a double-precision guess needs bits - 65 <= 2 (max_steps - 6) or so.
// Returns N(X) for the last accepted X: f has exactly one root in that X, and it lies in the
// returned enclosure. nullopt when no step was accepted: f'(X) contained 0, or the budget ran
// out while widening. Preconditions, not checked: f and df are enclosures of a
// function and its derivative (a wrong df proves nothing); scale > 0. The caller must still
// check whatever else it needs (that the root lies in a given domain, or is the one sought).
std::optional<mpfi_real> interval_newton(const interval_function& f, const interval_function& df,
                                         const mpfr_real& guess, const mpfr_real& scale, int max_steps);

}  // namespace gyrores
