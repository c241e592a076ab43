// The plain theorem-aware peer in double (method peer_newton): what someone who has read
// proofs/lattice-theorem.md would write in an afternoon, without gyrores. Integers in I (int64 for
// pairs of order below 2^62, __int128 above: the largest product formed is below a), the root
// by Newton's method in double, no heap allocation.
//
//   m_min = 0, 1, 2 as a = 0 mod 4, odd, 2 mod 4; a = tau + sigma, b = tau - sigma, x = b/a.
//   The minimiser lobes k (0 <= k < a) are those with a - 2 k b = +-m_min (mod 2a). With P = a,
//   B = 2b (m_min = 1) or P = a/2, B = b (m_min = 2) the + lobes are k = -B^{-1} mod P (and, for
//   m_min = 2, k + P), the - lobes their mirrors -k mod a. So theta_first = 2 (k pi + u*)/a when
//   k = 0 or 2k < P, else 2 ((P - k) pi - u*)/a: one modular inverse.
//   u* in (0, pi/2) solves H(u) = x u + atan(x tan u) = mu = pi m_min/(2a). H is increasing and
//   convex on [0, pi/2) (H'' = 2 x (1-x^2) sin u cos u/E^2 >= 0, E = cos^2 u + x^2 sin^2 u), so
//   mu/(1+x) <= u* <= mu/(2x) = pi m_min/(4b) <= pi/4 (the chord and the tangent at 0), and
//   Newton from the upper end decreases monotonically onto u*: no bracketing solver needed, the
//   lower end only guards against rounding.
//   r_res = x sqrt(1-x^2) t^2/sqrt((1+t^2)(1+x^2 t^2)), t = tan u*, sqrt(1-x^2) = 2 sqrt(tau
//   sigma)/a; t_first = sqrt(tau sigma) theta_first.
#pragma once
#include <cmath>
#include <cstdint>
#include <numbers>

namespace gyrores::bench {

struct peer_point {
  double r_res = 0, theta_first = 0, t_first = 0, u_star = 0;
  int iterations = 0;  // Newton steps
};

// x^{-1} mod n for gcd(x, n) = 1, 0 <= x < n (extended Euclid; the cofactors stay below n).
template <class I> I peer_inverse_mod(I x, I n) {
  I r0 = n, r1 = x, s0 = 0, s1 = 1;
  while (r1 != 0) {
    const I q = r0 / r1, r2 = r0 - q * r1, s2 = s0 - q * s1;
    r0 = r1, r1 = r2, s0 = s1, s1 = s2;
  }
  return s0 < 0 ? s0 + n : s0;
}

// u* = H^{-1}(mu) for 0 < x < 1 by Newton from mu/(2x) (see above); `steps` receives the count.
inline double peer_root(double x, double mu, int& steps) {
  const double lo = mu / (1 + x);
  double u = mu / (2 * x);
  steps = 0;
  for (int i = 0; i < 60; ++i) {
    const double t = std::tan(u), xt = x * t;
    const double f = x * u + std::atan(xt) - mu, df = x + x * (1 + t * t) / (1 + xt * xt);
    const double du = f / df;
    ++steps;
    if (!(du > 0)) break;  // at (or a rounding below) the root: monotone descent is over
    u = std::fmax(u - du, lo);
    if (du <= 0x1p-26 * u) {  // quadratic convergence: the step just made is accurate to ~ulp
      break;
    }
  }
  return u;
}

// The minimum of the coprime pair tau > sigma >= 1 (amplitude 1).
template <class I> peer_point peer_newton_minimum(I tau, I sigma) {
  constexpr double pi = std::numbers::pi;
  const I a = tau + sigma, b = tau - sigma;
  const int a4 = int(a % 4), m_min = a4 == 0 ? 0 : (a4 == 2 ? 2 : 1);
  const double ad = double(a), sqrt_ts = std::sqrt(double(tau) * double(sigma));
  peer_point out;
  if (m_min == 0) {  // r_res = 0 at theta = pi/2 (and 3 pi/2)
    out.theta_first = pi / 2;
    out.t_first = sqrt_ts * out.theta_first;
    return out;
  }
  const I P = m_min == 1 ? a : a / 2, B = (m_min == 1 ? 2 * b : b) % P;
  const I inv = peer_inverse_mod(B, P), k = inv == 0 ? I(0) : P - inv;
  const double x = double(b) / ad;
  out.u_star = peer_root(x, pi * m_min / (2 * ad), out.iterations);
  const double t = std::tan(out.u_star), t2 = t * t;
  out.r_res = x * (2 * sqrt_ts / ad) * t2 / std::sqrt((1 + t2) * (1 + x * x * t2));
  const bool plus = k == 0 || 2 * k < P;
  out.theta_first = 2 * (double(plus ? k : P - k) * pi + (plus ? out.u_star : -out.u_star)) / ad;
  out.t_first = sqrt_ts * out.theta_first;
  return out;
}

}  // namespace gyrores::bench
