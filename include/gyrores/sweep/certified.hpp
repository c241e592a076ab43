// The proofs of a certified sweep (`gyrores sweep --certified`): per pair, the paper's claims
// decided by exact integers and interval arithmetic, never by floating point.
//
// sweep_prove_pair(p) establishes, for one pair (amplitude v = 1):
//  - R(pi/2) exactly: at theta = pi/2 the phases a pi/4 and b pi/4 are multiples of pi/4, so
//    4 a^2 R(pi/2) is an integer (`quarter_R_scaled`), and its vanishing is decided exactly
//    (P3 in docs/mathematics.md);
//  - the minimisers' lobes by the lattice theorem (proofs/lattice-theorem.md, exact integers:
//    inscribed/lattice_theorem.hpp) and their count, 2 (delta odd) or 4 (delta = 0 mod 4);
//  - enclosures of r_res and theta_first: u* is bracketed by proving H(lo) < mu_min < H(hi) in
//    MPFI (H increases), then r_res = sqrt(G([lo, hi])), theta_first = 2 (k pi + sign(m) u*)/a;
//  - for x < 1/2, an enclosure of the paper's error |theta_c - theta_asy| in the lobe
//    k = round(a/(2b)) (the smaller on a tie), without cancellation: with f(u) = u +
//    arctan(x tan u)/x - s and u_a + tan u_a = s (s = pi |m|/(2b)), f(u_a) = -D with
//    D = t - arctan(x t)/x >= 0, t = tan u_a, and f' = 1 + (1 + t^2)/(1 + x^2 t^2) >= 2, so
//    u_c - u_a = D/f'(xi) with xi in [u_a, u_a + D/2] (mean value theorem). D is evaluated by
//    its alternating series when x t is small.
// Every bound is outward: the doubles returned are rounded down (lo) and up (hi) from MPFI
// intervals. Precision starts at 64 bits and doubles (to 512) when a decision or an enclosure is
// too wide. Nothing here uses the global MPFR precision, so it is safe on the sweep's threads.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

struct sweep_proof {
  int128 quarter_R_scaled = 0;            // 4 a^2 R(pi/2), exact
  int m_min = 0;                          // min |a - 4N|
  std::vector<lobe_frame<int128>> lobes;  // the minimisers' lobes (theorem), theta order
  bool enclosed = false;                  // r_res/theta_first enclosures below were proved
  double r_lo = 0, r_hi = 0;              // r_res (0, 0 for degenerate pairs: exact)
  double theta_lo = 0, theta_hi = 0;      // theta_first
  bool r_below_R_half_pi = false;         // r_hi^2 <= R(pi/2), proved (non-degenerate pairs)
  bool has_asy = false;                   // asked for and x < 1/2
  bool asy_enclosed = false;              // the error's enclosure was proved
  double asy_error_hi = 0, asy_bound_lo = 0, asy_ratio_lo = 0, asy_ratio_hi = 0, asy_constant_hi = 0;
  std::string note;                       // why something could not be proved (resource limits)
};

// 4 a^2 R(pi/2) (v = 1) for a pair with order a and delta b (a > b >= 1, a = b mod 2): exact.
int128 sweep_quarter_R_scaled(std::int64_t a, std::int64_t b);

// The proofs above for pair p (order <= 2^40); `asy`: also the paper's error bound (x < 1/2).
sweep_proof sweep_prove_pair(const resonant_pair<std::int64_t>& p, bool asy);

}  // namespace gyrores
