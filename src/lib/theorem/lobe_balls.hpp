// The lobe functions of the horizon theorem (proofs/horizon-theorem.md, Notation) in Arb ball
// arithmetic with x itself a ball (a point for one coupling, theorem/horizon.cpp; an interval
// for a box of couplings, theorem/band.cpp). Private to src/lib/theorem.
#pragma once
#include <arb.h>

namespace gyrores::lobe_balls {

// out = v^2 from the ends of v (a plain product v v of a wide ball can reach below 0).
void square(arb_t out, const arb_t v, slong p);

// H_x(u) = x u + phi(u), phi the continuous angle of (cos u, x sin u), for |u| <= pi/2.
void H_of(arb_t out, const arb_t x, const arb_t u, slong p);

// H'(u) = x + x/E(u), E = cos^2 u + x^2 sin^2 u.
void dH_of(arb_t out, const arb_t x, const arb_t u, slong p);

// G_x(u) = (1 - x^2) x^2 sin^4 u / E(u): R at a zero of q' (lattice-theorem.md Step C).
void G_of(arb_t out, const arb_t x, const arb_t u, slong p);

}  // namespace gyrores::lobe_balls
