// The minimum of H_q over a finite horizon by scanning every critical point: O(T), the tests'
// independent reference of the horizon theorem (theorem/horizon.hpp; the product's figures mark
// the theorem's minimum). (The coupling itself, exactly: model/coupling.hpp.)
//
// Minimum of H_q over [0, T] for any real n > 0 (horizon_minimum): dH_q/dt = -n q' z', so the
// minimum is at t = T, or at a root of q' or z' in [0, T]. Both are bracketed exactly:
//  - q'/rho0 = W1 cos W1 t + W2 cos W2 t has the sign (-1)^i at t = i pi/W1 (W1 > 1 > W2), and
//    exactly one root in each [i pi/W1, (i+1) pi/W1]: at a root sin^2 W1 t = 1 - W2^4 cos^2 W2 t,
//    so W1^4 sin^2 W1 t = W1^4 - cos^2 W2 t > 1 - cos^2 W2 t >= W2^4 sin^2 W2 t, hence the
//    derivative -(W1^2 sin W1 t + W2^2 sin W2 t) has the sign of -sin W1 t, constant inside the
//    interval: every root crosses the same way, so there is only one.
//  - z'/rho0 = W1 sin W1 t - W2 sin W2 t has the sign (-1)^i at t = (i + 1/2) pi/W1 and, by the
//    same argument with sin and cos exchanged, exactly one root in each
//    [(i - 1/2) pi/W1, (i + 1/2) pi/W1]; for i = 0 it is t = 0 (H_q(0) = v^2/2, the maximum).
// Each root is solved by TOMS 748 (roots.hpp) in T; H_q is q^2/2 at a q' root (q' = 0 there;
// R is stationary, see resonant.hpp) and (q^2 + q'^2)/2 at a z' root. Cost: about 2 W1 T/pi
// root solves. Accuracy: the phases W1 t are formed in T, so the absolute phase error grows
// like T * eps(T): at 200 bits it is the tests' reference.
// Infimum over all time: for non-resonant n the line (W1 t, W2 t) is dense on the torus and
// passes arbitrarily close to P+ = (pi/2, -pi/2), where q = q' = 0 (docs/mathematics.md §3): inf H_q = 0,
// not attained. For resonant n it is the pair's H_min = r_res^2/2, first attained at t_first.
#pragma once
#include <boost/multiprecision/gmp.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/core/roots.hpp>
#include <gyrores/model/model.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// Result of horizon_minimum: min of H_q over [0, T] and the first time it is attained.
template <class T> struct horizon_min_result {
  T h_min;               // min_{t in [0, T]} H_q(t)
  T t_min;               // the first t in [0, T] where it is attained (ties: relative 2^(-3 bits/4))
  T q, qdot;             // the state (q, q') there
  bool at_horizon_end = false;  // the minimum is at t = T (H_q still decreasing there)
  std::size_t critical_points = 0;  // roots of q' and z' examined (t = 0 included)
  std::uintmax_t evaluations = 0;
};

// Largest number of critical points horizon_minimum accepts (about 2 W1 T/pi); beyond it throws
// usage_error (asks for a shorter horizon).
inline constexpr std::size_t horizon_max_critical_points = 4000000;

namespace detail {

// q/rho0, q'/rho0 and z'/rho0 of the impulse response (model.hpp) at t.
template <class T> struct horizon_motion {
  T W1, W2;
  T qdot(const T& t) const {
    using std::cos;
    return T(W1 * cos(W1 * t) + W2 * cos(W2 * t));
  }
  T zdot(const T& t) const {
    using std::sin;
    return T(W1 * sin(W1 * t) - W2 * sin(W2 * t));
  }
  T qpos(const T& t) const {
    using std::sin;
    return T(sin(W1 * t) + sin(W2 * t));
  }
};

// q'/rho0 or z'/rho0 as one function type, so that the root solver is compiled once per T.
template <class T> struct horizon_derivative {
  const horizon_motion<T>* m;
  bool of_z;  // z' (else q')
  T operator()(const T& t) const { return of_z ? m->zdot(t) : m->qdot(t); }
};

// The running minimum of H_q over the critical points examined. Every candidate within a
// relative tie band of the running minimum is kept; at the end the earliest of them is the first
// time the minimum is attained.
template <class T> class horizon_min_tracker {
 public:
  explicit horizon_min_tracker(const T& tie_rel) : tie_rel_(tie_rel) {}
  void consider(const T& t, const T& h, const T& q, const T& qdot, bool end) {
    ++count_;
    if (!have_ || h < best_) {
      best_ = h;
      have_ = true;
      std::erase_if(near_, [&](const candidate& c) { return c.h > best_ * (1 + tie_rel_); });
    }
    if (h <= best_ * (1 + tie_rel_)) near_.push_back({t, h, q, qdot, end});
  }
  // Precondition: consider() was called at least once.
  void finish(horizon_min_result<T>& r) const {
    const candidate* first = &near_.front();
    for (const auto& c : near_)
      if (c.t < first->t) first = &c;
    r.h_min = best_;
    r.t_min = first->t;
    r.q = first->q;
    r.qdot = first->qdot;
    r.at_horizon_end = first->end;
    r.critical_points = count_;
  }

 private:
  struct candidate {
    T t, h, q, qdot;
    bool end;
  };
  T tie_rel_;
  T best_ = 0;
  bool have_ = false;
  std::size_t count_ = 0;
  std::vector<candidate> near_;
};

// The root of f in [lo, min(hi, horizon)], or nullopt for an interval clipped by the horizon in
// which f does not change sign (an unclipped interval always holds exactly one root: header
// comment). Adds the evaluations of f.
template <class T, class F>
std::optional<T> horizon_root(const F& f, const T& lo, T hi, const T& horizon, const T& tol_floor, const char* what,
                              std::uintmax_t& evaluations) {
  const bool clipped = hi > horizon;
  if (clipped) hi = horizon;
  const T flo = f(lo), fhi = f(hi);
  if (clipped && (flo < 0) == (fhi < 0) && fhi != 0) return std::nullopt;
  evaluations += 2;
  auto root = root_bracketed(f, lo, hi, flo, fhi, default_root_tolerance<T>(tol_floor), what);
  evaluations += root.evaluations;
  return root.root;
}

// A large count for a message: "about N" while N fits comfortably in long long, else in
// scientific notation (a cast of 1e308 to long long overflows), "more than 1.8e+308" beyond double.
inline std::string approximate_count_text(double count) {
  if (count < 1e18) return "about " + std::to_string(static_cast<long long>(count));
  if (!std::isfinite(count)) return "more than 1.8e+308";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", count);
  return std::string("about ") + buf;
}

}  // namespace detail

// min of H_q = (q^2 + q'^2)/2 over [0, horizon] for coupling n != 0 (|n| is used) and impulse
// v > 0, by the exact bracketing of the critical points described in the header comment.
// Preconditions (checked, usage_error): v > 0, horizon >= 0, n != 0, at most
// horizon_max_critical_points critical points. mpfr_real works at Boost's default precision,
// which every argument must have (else Boost's operators change that process-wide default
// during the call: core/real.hpp); mpfr_fixed<D> carries its own (the tests' reference runs there).
template <class T> horizon_min_result<T> horizon_minimum(const T& n_in, const T& v, const T& horizon) {
  using std::fabs;
  using std::floor;
  using std::ldexp;
  if (!(v > 0)) throw usage_error("the impulse amplitude qdot0 must be > 0");
  if (!(horizon >= 0)) throw usage_error("the horizon must be >= 0");
  if (n_in == 0) throw usage_error("n = 0 means no coupling: H_q is constant");
  const T n = fabs(n_in);
  const auto w = modal_frequencies_of(n);
  const detail::horizon_motion<T> m{w.omega1, w.omega2};
  const T rho0 = impulse_rho0(n, v), pi = real_pi<T>();
  const T step = pi / m.W1;
  if (T count = 2 * horizon / step; count > T(double(horizon_max_critical_points)))
    throw usage_error("the horizon is too long: " + detail::approximate_count_text(static_cast<double>(count)) +
                      " critical points (limit " + std::to_string(horizon_max_critical_points) + ")");
  const detail::horizon_derivative<T> qdot{&m, false}, zdot{&m, true};
  horizon_min_result<T> r;
  detail::horizon_min_tracker<T> best(ldexp(T(1), -int(3 * real_bits<T>() / 4)));
  best.consider(T(0), v * v / 2, T(0), v, false);  // t = 0: the z' root of the first interval
  const T tol_floor = step / 1024;
  // Roots of q' in [i step, (i+1) step] and of z' in [(i+1/2) step, (i+3/2) step], clipped to T.
  const long long intervals = static_cast<long long>(static_cast<double>(floor(horizon / step))) + 1;
  for (long long i = 0; i < intervals; ++i) {
    const T lo = step * T(i);
    if (lo > horizon) break;
    if (auto t = detail::horizon_root(qdot, lo, T(step * T(i + 1)), horizon, tol_floor, "horizon minimum (q' = 0)",
                                      r.evaluations)) {
      T qv = rho0 * m.qpos(*t);
      best.consider(*t, qv * qv / 2, qv, T(0), false);
    }
    const T zlo = step * (T(i) + T(0.5));
    if (zlo > horizon) continue;
    if (auto t = detail::horizon_root(zdot, zlo, T(step * (T(i) + T(1.5))), horizon, tol_floor,
                                      "horizon minimum (z' = 0)", r.evaluations)) {
      T qv = rho0 * m.qpos(*t), qd = rho0 * m.qdot(*t);
      best.consider(*t, (qv * qv + qd * qd) / 2, qv, qd, false);
    }
  }
  // The end point t = T (counted among the critical points).
  const T qv = rho0 * m.qpos(horizon), qd = rho0 * m.qdot(horizon);
  best.consider(horizon, (qv * qv + qd * qd) / 2, qv, qd, true);
  best.finish(r);
  return r;
}


}  // namespace gyrores
