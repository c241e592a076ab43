// The obvious implementation a user without gyrores would write: plain Boost TOMS 748 on the
// naive q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) (docs/mathematics.md §1, tau*theta
// formed directly in T) over one fast half-period, then r = rho0 |sin tau theta + sin sigma theta|.
// The benchmark's peer "naive_toms748" and the hard-case test that shows it failing on huge pairs
// use it; it shares nothing with the library's numerics (from gyrores only the conversions of
// integers and pi into T).
#pragma once
#include <cmath>
#include <cstdint>

#include <boost/math/tools/toms748_solve.hpp>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores::test {

template <class T> struct naive_toms748_result {
  T theta, r;
  std::uintmax_t evaluations;
};

// The root of the naive q' in the fast half-period [i pi/tau, (i+1) pi/tau] (q' has the sign
// (-1)^i at its ends when the phases are exact), by boost::math::tools::toms748_solve with
// eps_tolerance(bits - 2) and at most 1000 evaluations; theta is the final bracket's midpoint.
// Throws what toms748_solve throws when rounding in T has destroyed the sign change.
template <class T> naive_toms748_result<T> naive_toms748(const big_int& tau_i, const big_int& sigma_i, const big_int& i) {
  using std::cos;
  using std::fabs;
  using std::sin;
  using std::sqrt;
  const T tau = real_from_int<T>(tau_i), sigma = real_from_int<T>(sigma_i), pi = real_pi<T>();
  const T w1 = sqrt(tau / sigma), w2 = sqrt(sigma / tau), rho0 = 1 / (w1 + w2);
  auto qdot = [&](const T& th) { return T(w1 * cos(tau * th) + w2 * cos(sigma * th)); };
  const T lo = pi * real_from_int<T>(i) / tau, hi = pi * real_from_int<T>(big_int(i + 1)) / tau;
  boost::uintmax_t iters = 1000;
  auto br = boost::math::tools::toms748_solve(qdot, lo, hi,
                                              boost::math::tools::eps_tolerance<T>(real_bits<T>() - 2), iters);
  const T th = (br.first + br.second) / 2;
  return {th, rho0 * fabs(sin(tau * th) + sin(sigma * th)), iters};
}

}  // namespace gyrores::test
