// The producer of certificates (certificate.hpp): certify_pair.
//
// Fast floating point finds the answer (the lattice method in MPFR), interval arithmetic (MPFI)
// proves it, step by step (proof_steps.hpp, cover.hpp; proofs/global-minimality.md):
// local-root, basin, symmetry, and the cover R > r_hi^2 outside the basins, by bisection over
// every fast lobe ("all-lobes", orders up to max_lobes), or, for x < 1/2, by the Rayleigh bound
// away from the slow nodes plus bisection over the few lobes at each node ("slow-nodes", up to
// max_nodes nodes, any order: (10^30+1, 10^30) has one node).
// Precision is adaptive: enclosures start at start_bits and double until r_res, theta_first and
// t_first all have relative width <= 10^-digits (absolute for 0). The cover runs once, at
// cover_bits (64 bits plus the bits of the order, at least start_bits), against that level's
// r_hi. Degenerate pairs (delta = 2 mod 4) are certified by integer arithmetic.
// If the cover cannot be completed (order too high, or an undecided box), the certificate says
// "not proved" and claims only r_res <= r_hi (a point of the trajectory attains it).
#pragma once
#include "reference/certificate.hpp"
#include <gyrores/model/pair.hpp>

namespace gyrores {

// A certificate for p with at least `digits` correct digits in every claim. Throws usage_error
// when digits is outside [1, 10000]; compute_error when a step cannot be proved (interval
// Newton, the basin, separated minimiser images) or opt.max_bits is reached first.
certificate certify_pair(const resonant_pair<big_int>& p, unsigned digits, const certify_options& opt = {});

}  // namespace gyrores
