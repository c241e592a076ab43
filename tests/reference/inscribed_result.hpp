// The one result type of the reference inscribed-radius solvers (the global search, the lattice
// method).
#pragma once
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <gyrores/core/integer.hpp>

namespace gyrores {

enum class inscribed_method { degenerate_exact, global_search, lattice };

// A point in lobe-frame coordinates (resonant.hpp): theta = 2 (k pi + u)/a, exact integers
// k, j, m and the real u.
template <class T> struct lobe_point {
  big_int k, j, m;
  T u;
};

// r_res = min over theta in [0, 2 pi) of sqrt(q^2 + q'^2); h_min = r_res^2/2 (min of H_q);
// h_z_max = v^2/2 - h_min (max of H_z, since H = v^2/2 is conserved). minimisers: every
// global minimiser theta in [0, 2 pi), ascending; theta_first = minimisers.front(),
// t_first = sqrt(tau sigma) theta_first. For degenerate pairs r_res = 0 exactly.
template <class T> struct inscribed_result {
  T r_res, h_min, h_z_max;
  std::vector<T> minimisers;
  T theta_first, t_first;
  bool degenerate = false;
  inscribed_method method = inscribed_method::global_search;
  lobe_point<T> first;             // the first minimiser in local coordinates (not for degenerate pairs)
  std::size_t critical_points = 0;  // critical points of R examined
  std::uintmax_t evaluations = 0;   // evaluations of q' or z' by the root solvers
  // Global search only: the smallest R = q^2 + q'^2 among critical points that are not global
  // minimisers (the gap to the minimum shows how clearly the minimum is separated); 0 otherwise.
  T next_radius_sq = 0;
};

// What follows from the minimum R = radius_sq of q^2 + q'^2 (amplitude v) and its minimisers
// (ascending): r_res, h_min, h_z_max, the minimisers, theta_first and t_first = sqrt_ts theta_first.
template <class T>
void set_minimum(inscribed_result<T>& r, const T& radius_sq, const T& v, const T& sqrt_ts,
                 std::vector<T> ascending_minimisers) {
  using std::sqrt;
  r.r_res = sqrt(radius_sq);
  r.h_min = radius_sq / 2;
  r.h_z_max = v * v / 2 - r.h_min;
  r.minimisers = std::move(ascending_minimisers);
  r.theta_first = r.minimisers.front();
  r.t_first = sqrt_ts * r.theta_first;
}

}  // namespace gyrores
