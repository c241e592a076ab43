// Degenerate pairs (delta = 2 mod 4): r_res = 0 exactly, decided by integer arithmetic.
//
// Argument (paper Thm. degenerate, completed in proofs/): delta = 2 mod 4 forces tau, sigma odd
// with tau = -sigma mod 4, so at theta = pi/2: cos(tau pi/2) = cos(sigma pi/2) = 0 and
// sin(tau pi/2) = -sin(sigma pi/2), hence q = q' = 0. R = 0 only where the closed line
// (tau theta, sigma theta) meets P+ or P- (docs/mathematics.md §3); its offset there is (pi/2)|a - 4N|
// with a = 0 mod 4, met for the single N = a/4, once at P+ and once at P-: the zeros in
// [0, 2 pi) are exactly pi/2 and 3 pi/2, and pi/2 is the first.
#pragma once
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>

#include "reference/inscribed_result.hpp"

namespace gyrores {

template <class T, pair_integer I> inscribed_result<T> inscribed_degenerate(const resonant_pair<I>& p, const T& v) {
  if (!p.degenerate()) throw usage_error("inscribed_degenerate: pair " + p.str() + " has delta != 2 mod 4");
  auto c = resonant_constants_of<T>(p, v);
  inscribed_result<T> r;
  r.r_res = 0;
  r.h_min = 0;
  r.h_z_max = v * v / 2;
  r.minimisers = {c.pi / 2, 3 * c.pi / 2};
  r.theta_first = c.pi / 2;
  r.t_first = c.sqrt_ts * c.pi / 2;
  r.degenerate = true;
  r.method = inscribed_method::degenerate_exact;
  r.first = {0, 0, 0, T(0)};
  r.critical_points = 0;
  r.evaluations = 0;
  return r;
}

// Compiled once in tests/reference/instances_*.cpp for double, long double, float128 and mpfr_real.
#define GYRORES_DEGENERATE_INSTANCES(PREFIX, T) \
  PREFIX template inscribed_result<T> inscribed_degenerate<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&); \
  PREFIX template inscribed_result<T> inscribed_degenerate<T, big_int>(const resonant_pair<big_int>&, const T&);
GYRORES_FOR_COMPILED_REALS(GYRORES_DEGENERATE_INSTANCES, extern)

}  // namespace gyrores
