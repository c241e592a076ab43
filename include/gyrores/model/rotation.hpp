// The rotation by x on the circle R/Z, in exact arithmetic: the smallest fractional part
// {k alpha + beta} over 0 <= k <= K, the first k at which it falls to a level, and the same for
// the distance ||k x - 1/2|| that orders a coupling's lobes (theorem/horizon.hpp).
//
// Each is a Euclid-like recursion (proofs/horizon-theorem.md, "Rotation minima"): the sequence
// y_k = k alpha + beta splits into runs between integer crossings; the candidates of a run (its
// first element when alpha <= 1/2, its last when alpha > 1/2) form again a rotation,
// by alpha1 = {-1/alpha} or {1/(1 - alpha)}, over at most K/2 indices. So each call costs
// O(log K) field operations, exactly (core/quadratic.hpp); K can have hundreds of digits.
// Ties (possible only for rational alpha) give the smallest k. The recursion runs as a loop with
// its levels on the heap (no stack depth grows with K), and looks at `stop` once per level
// (throwing `interrupted`).
#pragma once
#include <optional>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/quadratic.hpp>
#include <gyrores/core/stop.hpp>

namespace gyrores {

struct rotation_minimum {
  quadratic_number value;  // the minimum
  big_int k;               // the smallest k attaining it
};

// min over 0 <= k <= K of {k alpha + beta}; alpha, beta in [0, 1), K >= 0 (usage_error otherwise).
rotation_minimum min_fractional_part(const quadratic_number& alpha, const quadratic_number& beta, const big_int& K,
                                     stop_token stop = {});

// The smallest k in [0, K] with {k alpha + beta} <= w (w >= 0), or none.
std::optional<big_int> first_fractional_part_at_most(const quadratic_number& alpha, const quadratic_number& beta,
                                                     const quadratic_number& w, const big_int& K, stop_token stop = {});

// nu_k = ||k x - 1/2|| (distance to the nearest integer), x in (0, 1):
// min over 0 <= k <= K, with the smallest k attaining it.
rotation_minimum min_distance_to_half(const quadratic_number& x, const big_int& K, stop_token stop = {});

// The smallest k in [0, K] with ||k x - 1/2|| <= delta (delta >= 0), or none.
std::optional<big_int> first_distance_to_half_at_most(const quadratic_number& x, const quadratic_number& delta,
                                                      const big_int& K, stop_token stop = {});

// ||k x - 1/2|| itself, and the sign of mu_k = pi (1/2 - {k x}) (+1, 0 or -1): the side of its
// lobe on which the minimiser lies.
quadratic_number distance_to_half(const quadratic_number& x, const big_int& k);
int lobe_offset_sign(const quadratic_number& x, const big_int& k);

}  // namespace gyrores
