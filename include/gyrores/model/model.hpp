// The model q'' + n z' + q = 0, z'' - n q' + z = 0 for any real coupling n (docs/mathematics.md §1).
//
// Impulse (q, q', z, z')(0) = (0, v, 0, 0). All functions are templates on the real type T and
// use only +, -, *, /, sqrt, sin and cos, so they also run on interval types (mpfi_real).
#pragma once
#include <cmath>

#include <gyrores/core/real.hpp>

namespace gyrores {

template <class T> struct modal_frequencies {
  T omega1, omega2;  // W1 = (sqrt(n^2+4)+n)/2, W2 = (sqrt(n^2+4)-n)/2, W1 W2 = 1
};

// For n >= 0, W2 is formed as 2/(sqrt(n^2+4)+n) = 1/W1 (no cancellation for large n); the
// formulas swap roles for n < 0 so that W1 - W2 = n always.
template <class T> modal_frequencies<T> modal_frequencies_of(const T& n) {
  using std::sqrt;
  T s = sqrt(n * n + 4);
  if (n >= 0) {
    T w1 = (s + n) / 2;
    return {w1, 2 / (s + n)};
  }
  T w2 = (s - n) / 2;
  return {2 / (s - n), w2};
}

// rho0 = v / sqrt(n^2 + 4) (paper eq. rho0).
template <class T> T impulse_rho0(const T& n, const T& v) {
  using std::sqrt;
  return v / sqrt(n * n + 4);
}

template <class T> struct phase_state {
  T q, qdot, z, zdot;
};

// Impulse response at time t (paper eq. impulseResp-explicit). Accuracy: the phases W1 t and
// W2 t are formed in T, so the absolute phase error grows like |t| * eps; for long times on a
// resonant pair use the resonant parametrisation (resonant.hpp) instead.
template <class T> phase_state<T> impulse_response(const T& n, const T& v, const T& t) {
  using std::cos;
  using std::sin;
  auto w = modal_frequencies_of(n);
  T r0 = impulse_rho0(n, v);
  T p1 = w.omega1 * t, p2 = w.omega2 * t;
  T s1 = sin(p1), c1 = cos(p1), s2 = sin(p2), c2 = cos(p2);
  return {r0 * (s1 + s2), r0 * (w.omega1 * c1 + w.omega2 * c2), r0 * (c2 - c1), r0 * (w.omega1 * s1 - w.omega2 * s2)};
}

template <class T> T energy_q(const phase_state<T>& s) { return (s.q * s.q + s.qdot * s.qdot) / 2; }
template <class T> T energy_z(const phase_state<T>& s) { return (s.z * s.z + s.zdot * s.zdot) / 2; }

// Boundary of the convex envelope of the (q, q') projection at support direction phi (paper
// Prop. convexEnvelope, eq. boundary): a point of rho0 (E_W1 (+) E_W2).
template <class T> struct plane_point {
  T x, y;
};
// What the boundary and the support function share at direction phi: rho0, cos phi, sin phi,
// omega_i^2 and d_i = sqrt(cos^2 phi + omega_i^2 sin^2 phi).
template <class T> struct envelope_direction {
  T r0, c, s, w1sq, w2sq, d1, d2;
};
template <class T> envelope_direction<T> envelope_direction_of(const T& n, const T& v, const T& phi) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  auto w = modal_frequencies_of(n);
  envelope_direction<T> e{impulse_rho0(n, v), cos(phi), sin(phi), w.omega1 * w.omega1, w.omega2 * w.omega2, T(0), T(0)};
  e.d1 = sqrt(e.c * e.c + e.w1sq * e.s * e.s);
  e.d2 = sqrt(e.c * e.c + e.w2sq * e.s * e.s);
  return e;
}

template <class T> plane_point<T> envelope_boundary(const T& n, const T& v, const T& phi) {
  const auto e = envelope_direction_of(n, v, phi);
  return {e.r0 * (e.c / e.d1 + e.c / e.d2), e.r0 * (e.w1sq * e.s / e.d1 + e.w2sq * e.s / e.d2)};
}

}  // namespace gyrores
