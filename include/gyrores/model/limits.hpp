// The envelope of the coupling inputs: the one set of limits that the parsers (model/inputs.hpp,
// model/coupling.hpp) enforce and that the coupling certificate checker reads up to
// (src/checker/horizon_checker.hpp holds its own copy of these numbers; tests/test_limits.cpp
// checks that they agree and that certificates at every edge are written and accepted).
// docs/formats.md, "Limits of the coupling inputs", documents them.
//
// Why these numbers: every proof's cost grows with the digits of its integers (the lobe k_c of
// t = T has about log10(S T) digits, S = sqrt(n^2 + 4)) and of its rationals; within the envelope
// a coupling, its minimum over [0, T] and its first time below a level take well under a second
// and their certificates are checked in about as long.
#pragma once
#include <cstddef>

namespace gyrores::limits {

// Horizons: T = 0, or 10^-horizon_exponent <= T <= 10^horizon_exponent (T = a pi: a within them).
inline constexpr long horizon_exponent = 1000;
// Couplings: 10^-n2_exponent <= n^2 <= 10^n2_exponent (so |n| within 10^-+150).
inline constexpr long n2_exponent = 300;
// Levels: E = 0, or E >= 10^-level_exponent (any E >= 1/2 is reached at t = 0). The first time
// below 10^-900 took 18 s, and its crossing lies within about sqrt(E) of a lobe's minimiser, so a
// certificate needs about -log10(E)/2 digits: 10^-100 answers in 0.1 s, certified at 40 digits.
inline constexpr long level_exponent = 100;
// n^2, T and E as exact rationals written reduced, "p/q": at most this many characters.
inline constexpr std::size_t rational_chars = 2000;
// The lobe integers of a proof or certificate (k_c, k*): at most this many digits. k_c < 10^1151
// within the bounds above; the first lobe below a level may lie further for a coupling very close
// to a resonant one: then the proof stops with the reason (compute_error, exit 3).
inline constexpr std::size_t lobe_digits = 1200;

}  // namespace gyrores::limits
