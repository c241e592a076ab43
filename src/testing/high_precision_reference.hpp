// An independent high-precision reference for r_res, theta_first and t_first of any pair.
//
// Independence (the point of this file; it is the truth the tests and the benchmark measure the
// library against): nothing here uses the library's numerical code (no lobe frames, no local
// coordinates, no TOMS 748 wrapper, no lattice, no degenerate shortcut). From gyrores it takes
// only the types (big_int, mpfr_real), scoped_digits and integer -> mpfr conversion. It evaluates
// the paper's naive resonant forms (naive_forms.hpp, docs/mathematics.md §1), forming tau*theta
// directly:
//   q(theta)  = rho0 (sin tau theta + sin sigma theta),
//   q'(theta) = rho0 (W1 cos tau theta + W2 cos sigma theta),  W1 = sqrt(tau/sigma), W2 = 1/W1,
//   z'(theta) = rho0 (W1 sin tau theta - W2 sin sigma theta),  rho0 = v/(W1 + W2),
// and makes that safe for huge pairs by brute precision instead of by clever coordinates: the
// working precision is
//   P = bits_wanted + 2 log2(tau + sigma) + 96 bits,
// one log2(a) because tau*theta is rounded relative to its size (an absolute phase error of
// a 2^-P), one more because q = sin(tau theta) + sin(sigma theta) cancels down to r_res, which
// is as small as ~x = b/a ~ 1/a for delta = 1 (an absolute error of 2^-(bits_wanted + log2 a)
// in q is then still a relative 2^-bits_wanted in r_res).
//
// Critical points. dR/dt = -2 n q' z' (docs/mathematics.md §1): the minima of R = q^2 + q'^2 are
// roots of q' or of z'. At theta = i pi/tau, cos(tau theta) = (-1)^i and W1 > W2, so q' has the sign
// (-1)^i there: each interval I_i = [i pi/tau, (i+1) pi/tau] holds a root of q' (exactly one:
// q' is a trigonometric polynomial of degree tau). Likewise z' has the sign (-1)^i at
// (i + 1/2) pi/tau, so each J_i = [(i - 1/2) pi/tau, (i + 1/2) pi/tau] holds a root of z'.
// A root is solved by bisection at a base precision, then Newton steps with precision doubling
// (safeguarded by the bracket), then one confirming step at full precision. At a q' root, q is
// stationary (q' = dq/dt), so R = q^2 there is insensitive to the root's error while q'^2 is
// not (q'^2 would only add rounding noise): R is taken as q^2 at q' roots and as q^2 + q'^2 at
// z' roots (where R itself is stationary).
//
// Global minimality, two modes:
//  - global (small pairs, order <= hp_scan_max_order): every one of the 4 tau critical points is
//    located in double (naive formulation; Illinois false position on the sign-change
//    brackets above), R evaluated there, and every candidate within a slack of the smallest
//    (the slack covers the double phase error ~ a eps) is refined at full precision. This finds
//    the minimum whether it sits at a q' root or at a z' root.
//  - local (large pairs): the caller supplies a starting guess (e.g. the library's
//    theta_first: a guess only, it is not trusted). The reference examines the q' roots in the
//    2K+1 intervals I_i around the guess and around its mirror 2 pi - guess, and the z' roots
//    in the intervals J_i around them; the reference minimum is the smallest R among them.
//    Blind spot (stated): a minimum farther than K fast half-periods from the guess is not
//    seen; global minimality there rests on the global mode for the smaller pairs and on the
//    structure (docs/mathematics.md §3) the library relies on. The local mode still catches a
//    wrong value of r_res and a minimiser in the wrong lobe nearby.
// theta_first is the smallest theta in [0, 2 pi) among the minimisers (ties: R within a relative
// 2^-(bits_wanted/2) of the minimum). t_first = sqrt(tau sigma) theta_first.
// Degenerate pairs are not special-cased: the reference finds a q' root with q ~ 0 (|q| below
// 2^-(bits_wanted + log2 a)); `zero` reports that, and r_res is then the tiny computed value.
#pragma once
#include <cstdint>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/real.hpp>
#include "testing/test_support.hpp"

namespace gyrores::test::hp {

using gyrores::big_int;
using gyrores::mpfr_real;

// Orders up to which the reference enumerates every critical point (in double: ~4 tau root
// solves of ~6 evaluations each; order 2e6 takes about a second at -O2).
inline constexpr std::int64_t hp_scan_max_order = 2100000;

struct hp_result {
  mpfr_real r_res, radius_sq;        // min sqrt(R), min R (amplitude v = 1)
  mpfr_real theta_first, t_first;    // smallest minimiser in [0, 2 pi), sqrt(tau sigma) theta_first
  std::vector<mpfr_real> minimisers; // every (tied) minimiser found, ascending
  big_int first_half_period;         // i with theta_first in I_i = [i pi/tau, (i+1) pi/tau]
  bool zero = false;                 // r_res below the resolution: a zero of R (degenerate pair)
  bool global = false;               // global mode (all critical points) or local mode
  bool at_qdot_root = true;          // the minimum is at a q' root (false: at a z' root)
  unsigned bits = 0;                 // working precision P
  std::size_t candidates = 0;        // critical points refined at full precision
  std::size_t critical_points = 0;   // critical points examined (double scan or local)
};

// The reference for the pair (tau, sigma), amplitude v = 1, accurate to `digits` decimal digits
// (relative, in r_res, theta_first and t_first). `guess` (any precision, in [0, 2 pi)) is used
// only in local mode (order > hp_scan_max_order, or force_local); `neighbours` = K.
// The result is at precision P (see the header); compare inside a scoped_digits of at least
// `digits` + a few. Throws std::invalid_argument unless tau > sigma >= 1, std::logic_error if
// the reference cannot vouch for its result (a bracket without a sign change, Newton not
// converging, r_res below the precision budget).
hp_result hp_reference(const big_int& tau, const big_int& sigma, unsigned digits, const mpfr_real& guess,
                       bool force_local = false, int neighbours = 4);

// Convenience: global mode (no guess needed); requires tau + sigma <= hp_scan_max_order
// (std::invalid_argument otherwise).
hp_result hp_reference(const big_int& tau, const big_int& sigma, unsigned digits);

// The root of q' inside the paper's lobe |a theta/2 - k pi| < pi/2 (a = tau + sigma; the paper's
// theta_c, docs/mathematics.md §2, for k = round(a/(2b)) and x = b/a < 1/2), to `digits` decimal
// digits. The lobe is covered by the fast half-periods I_i, i in [floor((2k-1) tau/a),
// floor((2k+1) tau/a)], each holding one root of q'; each is solved independently at a low
// precision and the one inside the lobe is refined at P = digits + 2 log2(a) + 96 bits (`bits`;
// convert theta to text inside a scoped_digits of that many bits). Precondition (not checked):
// tau > sigma >= 1, k >= 1. Throws std::logic_error unless exactly one root lies in the lobe.
struct hp_lobe_root_result {
  mpfr_real theta;
  unsigned bits = 0;
};
hp_lobe_root_result hp_lobe_root(const big_int& tau, const big_int& sigma, const big_int& k, unsigned digits);

}  // namespace gyrores::test::hp
