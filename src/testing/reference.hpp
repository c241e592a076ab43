// An independent reference for the inscribed radius, used by the tests.
//
// Independence (the point of this file): it shares nothing with the library's numerical code (no
// lobe frames, no local coordinates, no TOMS 748, no integer shortcut for degenerate pairs). It
// evaluates the paper's naive resonant forms (naive_forms.hpp, docs/mathematics.md §1)
//   q(theta)  = rho0 (sin tau theta + sin sigma theta),
//   q'(theta) = rho0 (sqrt(tau/sigma) cos tau theta + sqrt(sigma/tau) cos sigma theta),
//   R(theta)  = q^2 + q'^2,  rho0 = v/(sqrt(tau/sigma) + sqrt(sigma/tau)),
// forming tau*theta directly in the working type, and finds the global minimum of R by brute
// force:
//   1. scan dR/dtheta in double on a uniform grid of `points_per_order * (tau + sigma)` points
//      (>= 16 points per fast half-period pi/tau), offset by half a step so that theta = pi/2
//      and theta = pi are never grid points;
//   2. every grid interval where dR/dtheta changes sign from - to + holds a local minimum:
//      locate it in double (Illinois false position) and evaluate R there;
//   3. every local minimum whose double value lies within a generous slack of the smallest
//      one is re-bisected from its grid interval in the working type T (mpfr_real at high
//      precision, or any other real type) down to ~2^-bits, and R is evaluated there in T;
//   4. the global minimisers are those refined minima within a tie threshold of the smallest.
// Cost: O((tau + sigma) * points_per_order) double evaluations plus O(bits) evaluations in T per
// candidate. Blind spot (accepted for a reference, documented): a local minimum whose basin is
// narrower than one grid step may be missed; with 32 points per unit of order the grid step is
// below pi/(16 tau), far smaller than the spacing of critical points observed for orders <= 1000.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "testing/naive_forms.hpp"

namespace gyrores::ref {

// The naive forms of one coprime pair given by its integers (kept for the messages).
template <class T> struct naive_model : test::naive_forms<T> {
  std::int64_t itau, isigma;

  naive_model(std::int64_t t, std::int64_t s, const T& amplitude = T(1))
      : test::naive_forms<T>(T(t), T(s), amplitude), itau(t), isigma(s) {}
};

// One local minimum found by the double scan: its grid interval (indices i, i+1) and the
// double estimate.
struct scan_minimum {
  std::int64_t index;  // the interval is [theta_i, theta_{i+1}] on the offset grid
  double theta, radius_sq;
};

struct scan_result {
  std::int64_t grid_points;
  std::vector<scan_minimum> minima;  // every local minimum detected, by theta
  double min_radius_sq;              // smallest double estimate
};

// theta_i = 2 pi (i + 1/2)/N in T.
template <class T> T grid_theta(std::int64_t i, std::int64_t n) {
  T two_pi = 2 * boost::math::constants::pi<T>();
  return two_pi * (T(2 * i + 1) / T(2 * n));
}

// Steps 1-2: every local minimum of R on [0, 2 pi), located in double. Throws std::logic_error
// if there is none (impossible for a pair).
scan_result scan_minima(std::int64_t tau, std::int64_t sigma, int points_per_order = 32);

template <class T> struct ref_result {
  T r_res, radius_sq;          // min sqrt(R), min R
  std::vector<T> minimisers;   // global minimisers in [0, 2 pi), ascending
  T theta_first;               // minimisers.front()
  T next_radius_sq;            // smallest refined local-minimum value that is not a global minimum (0 if none)
  double other_min_radius_sq;  // smallest double-scan local minimum farther than 1e-7 from every
                               // global minimiser (1 if none): how far R stays from its minimum elsewhere
  std::size_t local_minima;    // local minima seen by the scan
  std::size_t refined;         // candidates refined in T
};

// The local minimiser of R in T to about 2^-bits (absolute; theta = O(1)).
// Fast path: Newton steps on dR from the double estimate `guess`, accepted only if dR changes sign
// from - to + across [theta - w, theta + w], w = 2^(16 - bits) (a certificate that a minimiser lies
// within w). Otherwise bisection on a bracket: the grid interval [theta_i, theta_{i+1}], widened by
// one grid step on each side (at most twice) if rounding in T disagrees with the double scan at an
// end point. No - to + sign change at all: throws.
template <class T>
T refine_minimum(const naive_model<T>& m, std::int64_t i, std::int64_t n, int bits, double guess = -1) {
  using std::fabs;
  using std::ldexp;
  const T width = ldexp(T(1), -bits);
  if (guess >= 0) {
    T th = T(guess);
    for (int it = 0; it < 12; ++it) {
      T d2 = m.d2R(th);
      if (!(d2 > 0)) break;
      T step = m.dR(th) / d2;
      th -= step;
      if (fabs(step) <= width) break;
    }
    const T w = ldexp(T(1), 16 - bits);
    if (m.dR(T(th - w)) < 0 && m.dR(T(th + w)) >= 0) return th;
  }
  T lo, hi, dlo, dhi;
  bool ok = false;
  std::int64_t lo_i = i, hi_i = i + 1;
  for (int widen = 0; widen < 3 && !ok; ++widen) {
    lo = grid_theta<T>(lo_i, n);
    hi = grid_theta<T>(hi_i, n);
    dlo = m.dR(lo);
    dhi = m.dR(hi);
    ok = dlo < 0 && dhi >= 0;
    --lo_i;
    ++hi_i;
  }
  if (!ok) {
    std::ostringstream os;
    os << "reference: no sign change of dR for (" << m.itau << ", " << m.isigma << ") near grid index " << i;
    throw std::logic_error(os.str());
  }
  for (int it = 0; it < bits + 64 && hi - lo > width; ++it) {
    T mid = (lo + hi) / 2;
    if (m.dR(mid) < 0) lo = mid; else hi = mid;
  }
  return (lo + hi) / 2;
}

// The reference inscribed radius of (tau, sigma) in T. `bits`: target accuracy of theta
// (use the precision of T minus a few bits). tie_rel, tie_abs: a refined minimum R_i is a
// global minimiser iff R_i <= R_min (1 + tie_rel) + tie_abs * v^2.
// `slack_rel`, `slack_abs`: double candidates kept for refinement (generous; see step 3).
template <class T>
ref_result<T> reference_inscribed(std::int64_t tau, std::int64_t sigma, int bits, const T& tie_rel, const T& tie_abs,
                                  const T& v = T(1), int points_per_order = 32) {
  using std::sqrt;
  if (!(tau > sigma && sigma >= 1)) throw std::invalid_argument("reference_inscribed: need tau > sigma >= 1");
  scan_result sc = scan_minima(tau, sigma, points_per_order);
  // R is homogeneous of degree 2 in v; the double scan runs at v = 1.
  const double slack = 1e-9 + 1e-6 * sc.min_radius_sq;
  naive_model<T> m(tau, sigma, v);
  const T two_pi = 2 * boost::math::constants::pi<T>();
  std::vector<std::pair<T, T>> cand;  // (theta, R)
  for (const auto& mn : sc.minima) {
    if (mn.radius_sq > sc.min_radius_sq + slack) continue;
    T th = refine_minimum(m, mn.index, sc.grid_points, bits, mn.theta);
    if (th >= two_pi) th -= two_pi;
    cand.push_back({th, m.R(th)});
  }
  T rmin = cand.front().second;
  for (const auto& c : cand)
    if (c.second < rmin) rmin = c.second;
  const T tie = rmin * (1 + tie_rel) + tie_abs * v * v;
  ref_result<T> out;
  out.radius_sq = rmin;
  out.r_res = sqrt(rmin);
  out.next_radius_sq = T(0);
  bool have_next = false;
  for (const auto& c : cand) {
    if (c.second <= tie) {
      out.minimisers.push_back(c.first);
    } else if (!have_next || c.second < out.next_radius_sq) {
      out.next_radius_sq = c.second;
      have_next = true;
    }
  }
  std::sort(out.minimisers.begin(), out.minimisers.end());
  out.other_min_radius_sq = 1;
  for (const auto& mn : sc.minima) {
    bool near = false;
    for (const auto& g : out.minimisers) {
      double dg = std::fabs(mn.theta - static_cast<double>(g));
      near = near || dg < 1e-7 || std::fabs(dg - 2 * boost::math::constants::pi<double>()) < 1e-7;
    }
    if (!near && mn.radius_sq < out.other_min_radius_sq) out.other_min_radius_sq = mn.radius_sq;
  }
  out.theta_first = out.minimisers.front();
  out.local_minima = sc.minima.size();
  out.refined = cand.size();
  return out;
}

// Root of f on [lo, hi] by bisection in T (f(lo), f(hi) of opposite signs; throws otherwise).
template <class T, class F> T bisect_root(F&& f, T lo, T hi, int bits) {
  using std::ldexp;
  T flo = f(lo), fhi = f(hi);
  if ((flo < 0) == (fhi < 0)) throw std::logic_error("reference bisect_root: no sign change");
  const T width = ldexp(T(1), -bits);
  for (int it = 0; it < bits + 64 && hi - lo > width; ++it) {
    T mid = (lo + hi) / 2;
    T fm = f(mid);
    if ((fm < 0) == (flo < 0)) { lo = mid; flo = fm; } else { hi = mid; }
  }
  return (lo + hi) / 2;
}

}  // namespace gyrores::ref
