// The resonant parametrisation of a pair (tau, sigma) and its exact local coordinates.
//
// With a = tau + sigma, b = tau - sigma, x = b/a, alpha = a theta/2, beta = b theta/2 = x alpha:
//   q  = 2 rho0 sin(alpha) cos(beta),            q' = v (cos alpha cos beta - x sin alpha sin beta),
//   z  = 2 rho0 sin(alpha) sin(beta),            z' = v (x sin alpha cos beta + cos alpha sin beta),
// with 2 rho0 = v sqrt(1 - x^2) = 2 v sqrt(tau sigma)/a (docs/mathematics.md §1).
//
// Local coordinates (a "lobe frame", docs/mathematics.md §3): integers k, j fix a fast node alpha = k pi and
// a slow node beta = pi/2 + j pi; with alpha = k pi + u and w = mu - x u,
// mu = pi m / (2a), m = (2j+1) a - 2 k b (an integer), and s = (-1)^(k+j):
//   q  = s v sqrt(1-x^2) sin u sin w,      q' = s v (cos u sin w - x sin u cos w),
//   z  = s v sqrt(1-x^2) sin u cos w,      z' = s v (x sin u sin w + cos u cos w).
// Everything here is an integer or an O(1) angle: tau * theta is never formed, so the
// evaluation keeps full relative accuracy for pairs of any size (e.g. (10^30+1, 10^30)).
#pragma once
#include <cmath>
#include <type_traits>

#include <gyrores/model/pair.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores {

// Per-pair constants in T, computed once (each from exact integers, one or two roundings).
template <class T> struct resonant_constants {
  T v;        // impulse amplitude qdot0 > 0
  T x;        // b/a
  T s1mx2;    // sqrt(1 - x^2) = 2 sqrt(tau sigma)/a
  T sqrt_ts;  // sqrt(tau sigma): t = sqrt(tau sigma) theta
  T pi;
  T n;        // resonant coupling b / sqrt(tau sigma) (> 0 by convention)
  T omega1, omega2;  // sqrt(tau/sigma), sqrt(sigma/tau)
  T rho0;     // v sqrt(tau sigma)/a
};

// Which members resonant_constants_from computes: all, or only those the lobe-frame functions
// of this header use (v, x, s1mx2, sqrt_ts, pi; n, omega1, omega2 and
// rho0 are then left at 0). At 10000 digits the four divisions and square roots saved cost
// about a third of one sine-cosine pair.
enum class constants_scope { all, lobe };

// From the pair's integers in any integer type J (int64, int128, big_int): a = tau + sigma,
// b = tau - sigma. Callers pass them as int128 when they fit, so that a pair held as big_int
// (e.g. (10^30+1, 10^30)) costs no GMP arithmetic here.
template <class T, class J>
resonant_constants<T> resonant_constants_from(const J& a_i, const J& b_i, const J& tau_i, const J& sigma_i, const T& v,
                                              constants_scope scope = constants_scope::all) {
  using std::sqrt;
  resonant_constants<T> c;
  c.v = v;
  T a = real_from_int<T>(a_i);
  T b = real_from_int<T>(b_i);
  T tau = real_from_int<T>(tau_i), sigma = real_from_int<T>(sigma_i);
  c.x = b / a;
  bool ts_done = false;
  if constexpr (is_mpfr_v<T>) {
    // One correctly rounded square root when tau*sigma is exact at this precision (always, for
    // pairs below 2^(bits/2)): more accurate than the two roots and a product below, and cheaper.
    T ts;
    if (mpfr_mul(ts.backend().data(), tau.backend().data(), sigma.backend().data(), MPFR_RNDN) == 0) {
      c.sqrt_ts = sqrt(ts);
      ts_done = true;
    }
  }
  if (!ts_done) c.sqrt_ts = sqrt(tau) * sqrt(sigma);  // no product: tau*sigma may exceed T's exact range
  c.s1mx2 = 2 * c.sqrt_ts / a;
  c.pi = real_pi<T>();
  if (scope == constants_scope::lobe) return c;
  c.n = b / c.sqrt_ts;
  c.omega1 = sqrt(tau / sigma);
  c.omega2 = sqrt(sigma / tau);
  c.rho0 = v * c.sqrt_ts / a;
  return c;
}

template <class T, pair_integer I> resonant_constants<T> resonant_constants_of(const resonant_pair<I>& p, const T& v) {
  using W = wide_int<I>;
  return resonant_constants_from<T>(p.order(), W(p.delta()), W(p.tau()), W(p.sigma()), v);
}

// A lobe frame: exact integers (L is int128 or big_int). m = (2j+1) a - 2 k b.
template <class L> struct lobe_frame {
  L k, j, m;
};

template <class L> lobe_frame<L> lobe_frame_of(const L& a, const L& b, const L& k, const L& j) {
  return {k, j, L((2 * j + 1) * a - 2 * k * b)};
}

template <class T> struct lobe_values {
  T q, qdot, z, zdot;
  T radius_sq() const { return q * q + qdot * qdot; }
};

// Exact symmetries of R (docs/mathematics.md §1, §3), as maps of frames (u is kept or negated):
//  mirror theta -> 2 pi - theta: (k, j, u) -> (a - k, b - 1 - j, -u), m -> -m.
//  shift  theta -> theta + pi (tau, sigma both odd): (k, j, u) -> (k + a/2, j + b/2, u), m -> m.
template <class L> lobe_frame<L> lobe_mirror(const lobe_frame<L>& f, const L& a, const L& b) {
  return {L(a - f.k), L(b - 1 - f.j), L(-f.m)};
}
template <class L> lobe_frame<L> lobe_shift(const lobe_frame<L>& f, const L& a, const L& b) {
  return {L(f.k + a / 2), L(f.j + b / 2), f.m};
}

// Plain evaluation at a real theta (for plots and references at moderate order): alpha and
// beta are formed in T, so the phase error grows like a * |theta| * eps.
template <class T> lobe_values<T> resonant_state_at(const resonant_constants<T>& c, const T& a, const T& b, const T& theta) {
  using std::cos;
  using std::sin;
  T al = a * theta / 2, be = b * theta / 2;
  T sa = sin(al), ca = cos(al), sb = sin(be), cb = cos(be);
  T amp = c.v * c.s1mx2;
  return {amp * sa * cb, c.v * (ca * cb - c.x * sa * sb), amp * sa * sb, c.v * (c.x * sa * cb + ca * sb)};
}

}  // namespace gyrores
