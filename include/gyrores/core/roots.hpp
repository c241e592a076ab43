// The one place where gyrores calls Boost.Math's TOMS 748 bracketing solver.
//
// Contract (Boost's, kept): f(lo) and f(hi) must differ in sign (or one be 0); the solver
// returns a bracket [r.first, r.second] with a sign change of f. On top of Boost we
//  - check the sign change first and throw compute_error naming `what`, the type and the bracket;
//  - count evaluations, and throw compute_error if the budget runs out before the tolerance
//    is met (Boost would return the last bracket, which looks like an answer);
//  - use a relative tolerance with an absolute floor, so a root at or near 0 terminates.
// Only point types (double, long double, float128, mpfr_real): TOMS 748 compares values, which
// on mpfi_real would terminate the process on overlapping intervals.
#pragma once
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>

#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores {

// Stops when |hi - lo| <= eps * max(min(|lo|, |hi|), floor): relative, floored at `floor`.
template <class T> struct root_tolerance {
  T eps, floor;
  bool operator()(const T& lo, const T& hi) const {
    using std::fabs;
    T m = fabs(lo) < fabs(hi) ? fabs(lo) : fabs(hi);
    if (m < floor) m = floor;
    return fabs(hi - lo) <= eps * m;
  }
};

// Default tolerance for T at its current precision: 4 ulp relative, floored at `scale`
// (roots of size below `scale` are located to 4 ulp of `scale`, absolutely).
template <class T> root_tolerance<T> default_root_tolerance(const T& scale) {
  return {4 * real_epsilon<T>(), scale};
}

template <class T> struct root_result {
  T root;                    // the midpoint of the final bracket (or the exact zero)
  T lo, hi;                  // final bracket
  std::uintmax_t evaluations;
};

template <class T> std::string root_describe(const T& v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

// Solve f(u) = 0 on [lo, hi] given f(lo), f(hi). Throws compute_error on a missing sign change
// or an exhausted budget (typical budget: 200; TOMS 748 needs ~10 calls in double, ~3 log2(bits)).
template <class T, class F>
root_result<T> root_bracketed(F&& f, const T& lo, const T& hi, const T& flo, const T& fhi,
                              const root_tolerance<T>& tol, const char* what, std::uintmax_t budget = 400) {
  if (flo == 0) return {lo, lo, lo, 0};
  if (fhi == 0) return {hi, hi, hi, 0};
  if ((flo < 0) == (fhi < 0))
    throw compute_error(std::string(what) + ": bracket has no sign change in " + real_type_name<T>() + ": f(" +
                        root_describe(lo) + ")=" + root_describe(flo) + ", f(" + root_describe(hi) +
                        ")=" + root_describe(fhi));
  std::uintmax_t iters = budget;
  auto tol_copy = tol;
  std::pair<T, T> r = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, tol_copy, iters);
  if (iters >= budget && !tol(r.first, r.second))
    throw compute_error(std::string(what) + ": TOMS748 did not converge in " + std::to_string(budget) +
                        " evaluations (" + real_type_name<T>() + ", bracket [" + root_describe(r.first) +
                        ", " + root_describe(r.second) + "])");
  T mid = (r.first + r.second) / 2;
  return {mid, r.first, r.second, iters};
}

// Safeguarded Newton (rtsafe): fdf(u) returns {f, f'}; [lo, hi] brackets a sign change with
// sign(f(lo)) = sign_lo. Newton steps that leave the bracket are replaced by bisection; the
// bracket shrinks with every evaluation. Stops after the first step below 2^(-3 bits/4) of the
// scale (quadratic convergence then leaves an error far below one ulp) and returns the new
// point together with the last evaluation point (where f was evaluated). Returns false if it
// has not converged within max_iter (the caller falls back to TOMS 748).
template <class T> struct newton_result {
  T root, last_point;
  std::uintmax_t evaluations;
};
template <class T, class FDF>
bool root_newton_safeguarded(FDF&& fdf, T lo, T hi, int sign_lo, const T& u0, const T& floor, newton_result<T>& out,
                             int max_iter = 40) {
  using std::fabs;
  using std::ldexp;
  const T tol = ldexp(T(1), -int(3 * real_bits<T>() / 4));
  T u = u0;
  if (!(u > lo && u < hi)) u = (lo + hi) / 2;
  for (int it = 1; it <= max_iter; ++it) {
    auto [f, df] = fdf(u);
    if (f == 0) {
      out = {u, u, std::uintmax_t(it)};
      return true;
    }
    if ((f > 0) == (sign_lo > 0)) lo = u;
    else hi = u;
    T next = u - f / df;
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;  // also catches df = 0 and NaN
    T step = fabs(next - u);
    T scale = fabs(next) > floor ? fabs(next) : floor;
    T prev = u;
    u = next;
    if (step <= tol * scale) {
      out = {u, prev, std::uintmax_t(it)};
      return true;
    }
  }
  return false;
}

}  // namespace gyrores
