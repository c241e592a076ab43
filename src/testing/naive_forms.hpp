// The paper's naive resonant forms, shared by the two independent references (reference.hpp,
// high_precision_reference.hpp) and by tests that evaluate the model "by hand".
//
// Independence (the point of this file): nothing here uses the library's numerical code (no
// lobe frames, no local coordinates, no root solver of the library). The forms are evaluated as
// printed in the paper (docs/mathematics.md §1), forming tau*theta directly in the working type:
//   q(theta)  = rho0 (sin tau theta + sin sigma theta),
//   q'(theta) = rho0 (W1 cos tau theta + W2 cos sigma theta),  W1 = sqrt(tau/sigma), W2 = sqrt(sigma/tau),
//   z(theta)  = rho0 (cos sigma theta - cos tau theta),
//   z'(theta) = rho0 (W1 sin tau theta - W2 sin sigma theta),  rho0 = v/(W1 + W2),
//   R(theta)  = q^2 + q'^2.
// A test that compares the library with these forms therefore compares two different
// formulations of the same quantity.
#pragma once
#include <cmath>

namespace gyrores::test {

// sin and cos of the two phases tau theta (1) and sigma theta (2).
template <class T> struct naive_phases {
  T s1, c1, s2, c2;
};

// q, q' and their first two theta-derivatives (d = d/dtheta).
template <class T> struct naive_jet {
  T q, dq, ddq, qd, dqd, ddqd;
};

// The naive forms of one pair in the real type T (constants from tau, sigma and the amplitude v
// as given in T; for mpfr_real at the default precision when constructed).
template <class T> struct naive_forms {
  T tau, sigma, w1, w2, rho0, v;

  naive_forms(const T& tau_in, const T& sigma_in, const T& amplitude = T(1))
      : tau(tau_in), sigma(sigma_in), v(amplitude) {
    using std::sqrt;
    w1 = sqrt(tau / sigma);
    w2 = sqrt(sigma / tau);
    rho0 = v / (w1 + w2);
  }

  naive_phases<T> phases(const T& th) const {
    using std::cos;
    using std::sin;
    T p1 = tau * th, p2 = sigma * th;
    return {sin(p1), cos(p1), sin(p2), cos(p2)};
  }
  T q(const T& th) const {
    using std::sin;
    return rho0 * (sin(tau * th) + sin(sigma * th));
  }
  T qdot(const T& th) const {
    using std::cos;
    return rho0 * (w1 * cos(tau * th) + w2 * cos(sigma * th));
  }
  T R(const T& th) const {
    T a = q(th), b = qdot(th);
    return a * a + b * b;
  }
  naive_jet<T> jet(const T& th) const {
    const auto [s1, c1, s2, c2] = phases(th);
    return {rho0 * (s1 + s2),
            rho0 * (tau * c1 + sigma * c2),
            -rho0 * (tau * tau * s1 + sigma * sigma * s2),
            rho0 * (w1 * c1 + w2 * c2),
            -rho0 * (w1 * tau * s1 + w2 * sigma * s2),
            -rho0 * (w1 * tau * tau * c1 + w2 * sigma * sigma * c2)};
  }
  // dR/dtheta = 2 (q dq/dtheta + q' dq'/dtheta).
  T dR(const T& th) const {
    const naive_jet<T> j = jet(th);
    return 2 * (j.q * j.dq + j.qd * j.dqd);
  }
  // d^2R/dtheta^2 = 2 (q_th^2 + q q_thth + q'_th^2 + q' q'_thth), for Newton steps on dR.
  T d2R(const T& th) const {
    const naive_jet<T> j = jet(th);
    return 2 * (j.dq * j.dq + j.q * j.ddq + j.dqd * j.dqd + j.qd * j.ddqd);
  }
  // (q, q', z, z') at resonant time theta: the paper's impulse response with t = sqrt(tau sigma)
  // theta, written with the resonant harmonics W1 t = tau theta, W2 t = sigma theta.
  struct state {
    T q, qdot, z, zdot;
  };
  state full_state(const T& th) const {
    const auto [s1, c1, s2, c2] = phases(th);
    return {rho0 * (s1 + s2), rho0 * (w1 * c1 + w2 * c2), rho0 * (c2 - c1), rho0 * (w1 * s1 - w2 * s2)};
  }
};

// Illinois false position in double (a secant kept inside a sign-change bracket; the value at
// the end that stayed twice in a row is halved, which keeps the convergence superlinear). The
// caller evaluates f and decides when to stop:
//   for (...) { double c = br.next(); br.update(c, f(c)); }
// Precondition (not checked): flo and fhi do not have the same strict sign.
struct illinois_bracket {
  double lo, hi, flo, fhi;
  int side = 0;  // -1: lo moved last, +1: hi moved last, 0: neither yet

  // The secant point of the bracket, or its midpoint when that is not strictly inside.
  double next() const;
  // c replaces the end whose value has the sign of fc (fc = 0 counts as the sign of hi's side
  // when flo < 0, of lo's side otherwise).
  void update(double c, double fc);
};

}  // namespace gyrores::test
