// Any coupling n: exact resonance detection, the minimum of H_q over a finite horizon, and the
// best resonant approximations (docs/mathematics.md §1; paper Prop. resonance).
//
// Resonance (exact, rational arithmetic on n^2). With r = n^2 = P/Q in lowest terms and
// s = sqrt(n^2 + 4), the frequency ratio is W1/W2 = (s + n)^2/4 = (r + 2 + n s)/2, so it is
// rational iff n s = sqrt(r (r + 4)) is, i.e. iff r (r + 4) = P (P + 4Q)/Q^2 is a rational square,
// i.e. iff the integer D = P (P + 4Q) is a perfect square. Then
//     W1/W2 = (P + 2Q + sqrt(D)) / (2Q)   (reduced: the pair (tau, sigma)).
// Examples: n^2 = 1/12: D = 49, W1/W2 = 32/24 = 4/3; n^2 = 4/99: D = 1600, W1/W2 = 11/9;
// n = 2: D = 32, not a square, so n = 2 is not resonant; n = 3/2: D = 225, W1/W2 = 4.
// A decimal close to a resonant value (0.2886751345948 for 1/sqrt(12)) is an exact rational
// whose D is not a square: not resonant. Only n^2 matters (the sign of n mirrors the motion).
//
// Continued fraction of W1/W2 = (m + sqrt(D))/d with m = P + 2Q, d = 2Q: d divides D - m^2 =
// -4Q^2, so the classical recurrence for quadratic irrationals runs in exact integers
// (a = floor((m + isqrt(D))/d), m' = a d - m, d' = (D - m'^2)/d). The convergents p_k/q_k are
// the best rational approximations of W1/W2; each (p_k, q_k) with p_k > q_k is a resonant pair.
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
// like T * eps(T); the CLI proves its digits by recomputing at higher precision.
// Infimum over all time: for non-resonant n the line (W1 t, W2 t) is dense on the torus and
// passes arbitrarily close to P+ = (pi/2, -pi/2), where q = q' = 0 (docs/mathematics.md §3): inf H_q = 0,
// not attained. For resonant n it is the pair's H_min = r_res^2/2, first attained at t_first.
#pragma once
#include <boost/multiprecision/gmp.hpp>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/model/model.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/core/roots.hpp>

namespace gyrores {

// A coupling given exactly: n^2 (always rational here) and, when known, n itself (rational).
// n = 0 is rejected (no coupling: H_q is constant). The sign of n is kept for messages only.
struct coupling_spec {
  big_rational n2;                 // n^2 > 0, exact
  std::optional<big_rational> n;   // n when given as a rational (its sign as given)

  static coupling_spec from_n(const big_rational& n) {
    if (n == 0) throw usage_error("n = 0 means no coupling: H_q = qdot0^2/2 for all t (nothing to analyse)");
    return {n * n, n};
  }
  static coupling_spec from_n2(const big_rational& n2) {
    if (n2 < 0) throw usage_error("n^2 must be > 0, got " + rational_str(n2));
    if (n2 == 0) throw usage_error("n^2 = 0 means no coupling: H_q = qdot0^2/2 for all t (nothing to analyse)");
    return {n2, std::nullopt};
  }
  big_int P() const { return boost::multiprecision::numerator(n2); }
  big_int Q() const { return boost::multiprecision::denominator(n2); }
  // D = P (P + 4Q): W1/W2 is rational iff D is a perfect square.
  big_int discriminant() const { return P() * (P() + 4 * Q()); }

  // |n| in T: |num|/den for a rational n, else sqrt(P/Q) (correctly rounded parts).
  template <class T> T abs_n() const {
    using std::sqrt;
    if (n) {
      big_int num = boost::multiprecision::numerator(*n), den = boost::multiprecision::denominator(*n);
      if (num < 0) num = -num;
      return real_from_int<T>(num) / real_from_int<T>(den);
    }
    return sqrt(real_from_int<T>(P()) / real_from_int<T>(Q()));
  }
};

// The resonant pair of a coupling, decided exactly; std::nullopt when W1/W2 is irrational.
inline std::optional<resonant_pair<big_int>> coupling_resonant_pair(const coupling_spec& c) {
  big_int root;
  if (!int_is_square(c.discriminant(), root)) return std::nullopt;
  return pair_from_ratio(c.P() + 2 * c.Q() + root, 2 * c.Q());
}

// One convergent p/q of W1/W2 with its resonant pair (p > q) and the partial quotient a_k.
struct ratio_convergent {
  big_int partial_quotient;
  big_int p, q;  // the convergent p/q (coprime)
};

// The first `max_terms` convergents of W1/W2 (all of them when the ratio is rational, i.e. the
// coupling is resonant: the last is then W1/W2 itself). Exact integer arithmetic throughout.
inline std::vector<ratio_convergent> coupling_convergents(const coupling_spec& c, std::size_t max_terms) {
  std::vector<ratio_convergent> out;
  big_int P = c.P(), Q = c.Q(), D = c.discriminant();
  big_int m = P + 2 * Q, d = 2 * Q;  // W1/W2 = (m + sqrt D)/d
  big_int sq;
  bool rational = int_is_square(D, sq);
  big_int p_prev = 1, p_prev2 = 0, q_prev = 0, q_prev2 = 1;  // p_{-1}, p_{-2}, q_{-1}, q_{-2}
  if (rational) {
    // Plain Euclid on the reduced fraction (m + sq)/d.
    big_int num = m + sq, den = d;
    big_int g = int_gcd(num, den);
    num /= g;
    den /= g;
    while (den != 0 && out.size() < max_terms) {
      big_int a = num / den;  // num, den > 0
      big_int r = num - a * den;
      big_int p = a * p_prev + p_prev2, q = a * q_prev + q_prev2;
      out.push_back({a, p, q});
      p_prev2 = p_prev; p_prev = p; q_prev2 = q_prev; q_prev = q;
      num = den;
      den = r;
    }
    return out;
  }
  // Quadratic irrational (m + sqrt D)/d with d | D - m^2 (here D - m^2 = -4 Q^2 and d = 2Q).
  while (out.size() < max_terms) {
    // a = floor((m + sqrt D)/d); with D non-square, floor((m + isqrt D)/d) for d > 0 and
    // floor((m + isqrt D + 1)/d) - ... for d < 0; handle both signs exactly.
    big_int a;
    if (d > 0) {
      a = (m + sq);
      a = a >= 0 ? big_int(a / d) : big_int(-((-a + d - 1) / d));
    } else {
      // (m + sqrt D)/d with d < 0: floor = floor((-(m) - sqrt D)/(-d)); -(m + sqrt D) lies in
      // (-(m + sq + 1), -(m + sq)), so floor((-(m + sq + 1))/(-d)) rounded as below.
      big_int num = -(m + sq + 1), den = -d;
      a = num >= 0 ? big_int(num / den) : big_int(-((-num + den - 1) / den));
    }
    big_int p = a * p_prev + p_prev2, q = a * q_prev + q_prev2;
    out.push_back({a, p, q});
    p_prev2 = p_prev; p_prev = p; q_prev2 = q_prev; q_prev = q;
    big_int m_next = a * d - m;
    big_int d_next = (D - m_next * m_next) / d;
    m = m_next;
    d = d_next;
  }
  return out;
}

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

// min of H_q = (q^2 + q'^2)/2 over [0, horizon] for coupling n != 0 (|n| is used) and impulse
// v > 0, by the exact bracketing of the critical points described in the header comment.
// Preconditions (checked, usage_error): v > 0, horizon >= 0, n != 0.
template <class T> horizon_min_result<T> horizon_minimum(const T& n_in, const T& v, const T& horizon) {
  using std::cos;
  using std::fabs;
  using std::floor;
  using std::ldexp;
  using std::sin;
  if (!(v > 0)) throw usage_error("the impulse amplitude qdot0 must be > 0");
  if (!(horizon >= 0)) throw usage_error("the horizon must be >= 0");
  if (n_in == 0) throw usage_error("n = 0 means no coupling: H_q is constant");
  const T n = fabs(n_in);
  const auto w = modal_frequencies_of(n);
  const T W1 = w.omega1, W2 = w.omega2, rho0 = impulse_rho0(n, v), pi = real_pi<T>();
  const T step = pi / W1;
  {
    T count = 2 * horizon / step;
    if (count > T(double(horizon_max_critical_points)))
      throw usage_error("the horizon is too long: about " + std::to_string(static_cast<long long>(static_cast<double>(count))) +
                        " critical points (limit " + std::to_string(horizon_max_critical_points) + ")");
  }
  auto qdot = [&](const T& t) { return T(W1 * cos(W1 * t) + W2 * cos(W2 * t)); };  // / rho0
  auto zdot = [&](const T& t) { return T(W1 * sin(W1 * t) - W2 * sin(W2 * t)); };
  auto qpos = [&](const T& t) { return T(sin(W1 * t) + sin(W2 * t)); };

  horizon_min_result<T> r;
  // Keep every candidate within a relative 2^(-3 bits/4) of the running minimum (the tie band);
  // at the end the earliest of them is the first time the minimum is attained.
  const T tie_rel = ldexp(T(1), -int(3 * real_bits<T>() / 4));
  struct candidate {
    T t, h, q, qdot;
    bool end;
  };
  std::vector<candidate> near;
  T best = 0;
  bool have = false;
  auto consider = [&](const T& t, const T& h, const T& qv, const T& qd, bool end) {
    ++r.critical_points;
    if (!have || h < best) {
      best = h;
      have = true;
      std::erase_if(near, [&](const candidate& c) { return c.h > best * (1 + tie_rel); });
    }
    if (h <= best * (1 + tie_rel)) near.push_back({t, h, qv, qd, end});
  };
  // t = 0: the z' root of the first interval (H_q(0) = v^2/2).
  consider(T(0), v * v / 2, T(0), v, false);
  const T tol_floor = step / 1024;
  auto solve = [&](auto&& f, const T& lo, const T& hi, const char* what) {
    T flo = f(lo), fhi = f(hi);
    r.evaluations += 2;
    auto root = root_bracketed(f, lo, hi, flo, fhi, default_root_tolerance<T>(tol_floor), what);
    r.evaluations += root.evaluations;
    return root.root;
  };
  // Roots of q' in [i step, (i+1) step] and of z' in [(i+1/2) step, (i+3/2) step], clipped to T.
  const long long intervals = static_cast<long long>(static_cast<double>(floor(horizon / step))) + 1;
  for (long long i = 0; i < intervals; ++i) {
    T lo = step * T(i), hi = step * T(i + 1);
    if (lo > horizon) break;
    bool clipped = hi > horizon;
    if (clipped) hi = horizon;
    T flo = qdot(lo), fhi = qdot(hi);
    if (!clipped || (flo < 0) != (fhi < 0) || fhi == 0) {
      T t = solve(qdot, lo, hi, "horizon minimum (q' = 0)");
      T qv = rho0 * qpos(t);
      consider(t, qv * qv / 2, qv, T(0), false);
    }
    T zlo = step * (T(i) + T(0.5)), zhi = step * (T(i) + T(1.5));
    if (zlo <= horizon) {
      bool zclipped = zhi > horizon;
      if (zclipped) zhi = horizon;
      T glo = zdot(zlo), ghi = zdot(zhi);
      if (!zclipped || (glo < 0) != (ghi < 0) || ghi == 0) {
        T t = solve(zdot, zlo, zhi, "horizon minimum (z' = 0)");
        T qv = rho0 * qpos(t), qd = rho0 * qdot(t);
        consider(t, (qv * qv + qd * qd) / 2, qv, qd, false);
      }
    }
  }
  // The end point t = T (counted among the critical points).
  {
    T qv = rho0 * qpos(horizon), qd = rho0 * qdot(horizon);
    consider(horizon, (qv * qv + qd * qd) / 2, qv, qd, true);
  }
  const candidate* first = &near.front();
  for (const auto& c : near)
    if (c.t < first->t) first = &c;
  r.h_min = best;
  r.t_min = first->t;
  r.q = first->q;
  r.qdot = first->qdot;
  r.at_horizon_end = first->end;
  return r;
}

}  // namespace gyrores
