// Lobe evaluation in a real type T, for the references from before the lattice theorem
// (tests/reference/lattice.hpp, global_search.hpp, asymptotic.hpp), their tests and the
// benchmark's pre-theorem rows. The product never evaluates a lobe in T this way (the theorem
// works with H(u) = mu, include/gyrores/theorem/), so these live beside the tests.
#pragma once
#include <cmath>

#include <gyrores/core/real.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

// The impulse amplitude v = qdot0 must be > 0 (usage_error otherwise; NaN is rejected too).
template <class T> void check_amplitude(const T& v) {
  if (!(v > 0)) throw usage_error("the impulse amplitude qdot0 must be > 0");
}

// The frame in T: mu = pi m/(2a) and the sign (-1)^(k+j).
template <class T> struct lobe_frame_real {
  T mu;
  int sign;
};

template <class T, class L> lobe_frame_real<T> lobe_frame_real_of(const resonant_constants<T>& c, const lobe_frame<L>& f,
                                                                   const L& a) {
  T mu = c.pi * real_from_int<T>(f.m) / (2 * real_from_int<T>(a));
  bool odd = ((f.k + f.j) & 1) != 0;
  return {mu, odd ? -1 : 1};
}

// theta = 2 (k pi + u)/a reduced to [0, 2 pi): k is reduced mod a exactly first.
template <class T, class L> T lobe_theta(const resonant_constants<T>& c, const lobe_frame<L>& f, const L& a, const T& u) {
  L kr = int_mod(f.k, a);
  T at = real_from_int<T>(a);
  T th = 2 * (c.pi * real_from_int<T>(kr) + u) / at;  // one division (at 10000 digits a division costs 2 products)
  T two_pi = 2 * c.pi;
  if (th < 0) th += two_pi;
  if (th >= two_pi) th -= two_pi;
  return th;
}

// q, q', z, z' at u in a frame.
template <class T> lobe_values<T> lobe_eval(const resonant_constants<T>& c, const lobe_frame_real<T>& f, const T& u) {
  T w = f.mu - c.x * u;
  auto [su, cu] = real_sin_cos(u);
  auto [sw, cw] = real_sin_cos(w);
  T sv = f.sign > 0 ? c.v : T(-c.v);
  T amp = sv * c.s1mx2;
  return {amp * su * sw, sv * (cu * sw - c.x * su * cw), amp * su * cw, sv * (c.x * su * sw + cu * cw)};
}

// Scale below which a root u of q' or z' in this frame is located absolutely, not relatively:
// |mu|/1024, at most 1/1024. The q' roots that matter sit at |u| ~ |mu|/x or larger (e.g.
// |u| ~ 1e-9 for (10^9, 1)), so they keep full relative accuracy; mu = 0 only for degenerate
// pairs, which never reach a root solver.
template <class T> T lobe_root_floor(const lobe_frame_real<T>& f) {
  using std::fabs;
  T m = fabs(f.mu);
  if (m > 1) m = 1;
  return m / 1024;
}

// At a root of q' (q' = dq/dt = 0), q is stationary in u, so R = q^2 there is insensitive to
// the error of the root, whereas q'^2 is not: for (10^9, 1) a root error of one ulp makes
// q'^2 exceed q^2. The radius at a q' root is therefore taken as |q| alone.

// q'(u)/(s v) and its u-derivative, sharing the four trig values (for Newton polishing).
template <class T> struct qdot_with_derivative {
  T f, df;
  T su, cu, sw, cw;
};
template <class T> qdot_with_derivative<T> lobe_qdot_newton(const resonant_constants<T>& c, const T& mu, const T& u) {
  T w = mu - c.x * u;
  auto [su, cu] = real_sin_cos(u);
  auto [sw, cw] = real_sin_cos(w);
  T f = cu * sw - c.x * su * cw;
  T df = -(1 + c.x * c.x) * su * sw - 2 * c.x * cu * cw;
  return {f, df, su, cu, sw, cw};
}

// The frame nearest theta0 = pi * num/den (den > 0): k = round(a num/(2 den)),
// j = floor(b num/(2 den)); and u at theta = pi * num2/den in that frame, as the exact
// fraction pi * (a num2 - 2 k den) / (2 den).
template <class L> lobe_frame<L> lobe_frame_near(const L& a, const L& b, const L& num, const L& den) {
  L twice = 2 * den;
  L k = int_floor_div(L(2 * a * num + twice), L(2 * twice));  // round(a num / (2 den))
  L j = int_floor_div(L(b * num), twice);
  return lobe_frame_of(a, b, k, j);
}
template <class T, class L> T lobe_u_at(const resonant_constants<T>& c, const lobe_frame<L>& f, const L& a, const L& num,
                                        const L& den) {
  L top = a * num - 2 * f.k * den;
  return c.pi * real_from_int<T>(top) / (2 * real_from_int<T>(den));
}

}  // namespace gyrores
