// The equation kernels of the lattice and horizon theorems in Arb ball arithmetic, written once
// (proofs/lattice-theorem.md, Statement; proofs/horizon-theorem.md, Notation), with x itself a
// ball: a point for one coupling (theorem/horizon.cpp), an interval for a box of couplings
// (theorem/band.cpp). Private to src/lib/theorem. The solvers: theorem/root.hpp for H(u) = mu,
// core/ball_root.hpp for G(u) = 2E and R = 2E. (The MPFI kernels are theorem/root.cpp's tangent
// forms and theorem_radius; the double ones theorem/root_refined.hpp and minimum.cpp.)
#pragma once
#include <arb.h>

#include <optional>

#include <gyrores/core/integer.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>

namespace gyrores::kernels_arb {

// H(u) = x u + phi(u), phi the continuous angle of (cos u, x sin u), for |u| <= pi/2.
void H(arb_t out, const arb_t x, const arb_t u, slong p);

// G(u) = (1 - x^2) x^2 sin^4 u / E(u), E = cos^2 u + x^2 sin^2 u: R at a zero of q'
// (lattice-theorem.md Step C).
void G(arb_t out, const arb_t x, const arb_t u, slong p);

// G'(u) = (1 - x^2) x^2 sin^3 u cos u (4 E + 2 (1 - x^2) sin^2 u)/E^2 (for Newton only).
void dG(arb_t out, const arb_t x, const arb_t u, slong p);

// R = q^2 + q'^2 (qdot0 = 1) at alpha = S t/2, beta = x alpha, c = sqrt(1 - x^2):
// (c sin alpha cos beta)^2 + (cos alpha cos beta - x sin alpha sin beta)^2 (horizon-theorem.md
// Step 1), and dR/dalpha = -4 x q' z' (for Newton only).
void R(arb_t out, const arb_t x, const arb_t c, const arb_t alpha, slong p);
void dR(arb_t out, const arb_t x, const arb_t alpha, slong p);

// alpha_T = S T/2 (S = sqrt(n^2 + 4) and pi balls).
void alpha_T(arb_t out, const arb_t S, const horizon_time& T, const arb_t pi, slong p);

// k_c = floor(alpha_T/pi + 1/2), the lobe holding t = T, exactly. For T = value pi it is
// floor(S value/2 + 1/2) with S = sqrt(Q (P + 4Q))/Q in Q(sqrt d); for a rational T > 0 the
// argument is transcendental (pi), so it is never an integer and a fine enough ball decides the
// floor: none when the balls at p do not.
std::optional<big_int> cut_lobe(const coupling_spec& spec, const horizon_time& T, slong p);

}  // namespace gyrores::kernels_arb
