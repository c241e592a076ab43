// The paper's lobe asymptotics (Thm. theta_asy, Thm. error_bound; docs/mathematics.md §2, P6, P7), computed
// exactly as stated, beside the exact lobe root they approximate, and the x -> 0 limit form
// of r_res (docs/mathematics.md §3).
//
// Notation (docs/mathematics.md §1, §2): a = tau + sigma, b = tau - sigma, x = b/a. The paper picks the fast
// node k = round(1/(2x)) = round(a/(2b)), sets mu = pi/2 - k pi x and s = mu/x, and in the lobe
// alpha = a theta/2 = k pi + u (|u| < pi/2) replaces the exact condition q' = 0,
//     x tan u = tan(mu - x u)                                   (exact, "lobe equation")
// by u + tan u = s (root u_asy), giving theta_asy = pi/b + (2/a)(u_asy - s). It claims
//     |theta_c - theta_asy| <= pi^3 x^2 / a                      (P7, to be checked, not assumed)
// for the root theta_c of q' = 0 in that lobe.
//
// Exact forms used here (no cancellation, no tau * theta):
//  - k, m = a - 2 k b are exact integers (|m| <= b); mu = pi m/(2a), s = pi m/(2b); the
//    difference pi/2 - k pi x is never formed in floating point.
//  - theta_asy = 2 (k pi + u_asy)/a. This equals the paper's pi/b + (2/a)(u_asy - s) exactly,
//    since pi/b - 2s/a = pi (a - m)/(a b) = 2 k pi/a; both forms are returned.
//  - u_asy is the root of phi(u) = u - atan(s - u) on [-pi/2, pi/2]: same root as u + tan u = s
//    (tan u = s - u with |u| < pi/2), phi(-pi/2) < 0 < phi(pi/2) for every real s (also in
//    floating point, as |atan| <= pi/2), and 1 < phi' <= 2, so the root is well conditioned.
//  - u_c is the root of psi(u) = u - atan(tan(mu - x u)/x) on [-pi/2, pi/2]: the same root as
//    the lobe equation and as f(u) = cos u sin(mu - x u) - x sin u cos(mu - x u) (docs/mathematics.md §3,
//    j = 0), with psi(-pi/2) <= 0 <= psi(pi/2) for x < 1/2 (|mu - x u| <= pi x < pi/2) and
//    1 < psi' <= 1 + sec^2(mu - x u).
//  - The error theta_c - theta_asy = 2 (u_c - u_asy)/a is O(x^2/a), far below the rounding of
//    theta itself when a is large, so it is NOT formed as a difference. With d = u_c - u_asy,
//    y = s - u_asy (= tan u_asy) and w = x (y - d), the lobe equation minus u + tan u = s is
//    exactly
//        d + sin d / (cos u_asy cos(u_asy + d)) = x^2 (y - d)^3 S(w),   S(w) = (tan w - w)/w^3,
//    solved for e = d/x^2 (safeguarded Newton, asymptotic_error_scaled), with S from its
//    alternating series. Then
//    error = 2 |e| x^2/a and ratio = error/bound = 2 |e|/pi^3 keep full relative accuracy for
//    pairs of any size (error and bound may underflow to 0 in double for a > ~1e100; the ratio
//    does not). As x -> 0, e -> tan^3 u/(3 (1 + sec^2 u)), so |theta_c - theta_asy| ~ C(s) x^2/a
//    with C(s) = 2 |tan u|^3/(3 (1 + sec^2 u)) (docs/mathematics.md §3, "C(s)"). Since |m| <= b,
//    |s| <= pi/2 and C(s) <= C(pi/2) = 0.1549, i.e. ratio -> at most 0.0049967 (approached as
//    b = 1, a -> oo; the largest ratio of a sweep is at its largest pair with b = 1). P7 itself
//    is proved with a sharper constant in proofs/README.md (Lemma 7.1); the sweeps
//    (`gyrores sweep`, check asy-bound) measure how sharp it is.
//    u_c from psi and u_asy + d are compared (compute_error if they disagree).
//
// Applicability: the lobe equation has exactly one root in |u| < pi/2 when x < 1/2 (2b < a).
// For x >= 1/2 the lobe frame (k, j = 0) need not bracket a root and the slow-node reduction
// (mu, x u small) does not apply: the report says so (applicable = false) and computes nothing.
// Ties: a/(2b) is a half-integer iff b divides a with odd quotient; gcd(a, b) = gcd(2 tau, b)
// is 1 or 2, and b = 2 forces a = 0 mod 4, so ties happen exactly when b = 1. Then both
// k = (a-1)/2 and k = (a+1)/2 are reported; they are mirror images (theta -> 2 pi - theta).
// Degenerate pairs (delta = 2 mod 4) are computed too: the lobe root exists, but r_res = 0 is
// attained at theta = pi/2 (degenerate.hpp), inside this lobe only when b = 2 (then m = 0, s = 0,
// u_asy = u_c = 0 and theta_asy = theta_c = pi/2). The report says so in `reason`.
#pragma once
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "reference/lattice.hpp"
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/model/resonant.hpp>
#include "reference/inscribed_result.hpp"
#include <gyrores/core/roots.hpp>
#include "testing/test_support.hpp"

namespace gyrores {

// One lobe of the paper's asymptotics. All angles in radians; theta in [0, 2 pi).
template <class T> struct asymptotic_lobe {
  big_int k;             // fast node alpha = k pi: round(a/(2b)) (on a tie: one of the two)
  big_int m;             // a - 2 k b, exact, |m| <= b
  T mu;                  // pi m/(2a)  (= pi/2 - k pi x)
  T s;                   // pi m/(2b)  (= mu/x)
  T u_asy;               // root of u + tan u = s in (-pi/2, pi/2)
  T theta_asy;           // 2 (k pi + u_asy)/a
  T theta_asy_paper;     // pi/b + (2/a)(u_asy - s): the paper's form, equal in exact arithmetic
  T qdot_asy;            // q'(theta_asy) = dq/dt at the exact theta_asy, amplitude v (paper: "validated as"),
                         // = (-1)^k v cos u cos w (tan w - w), w = x (s - u_asy): no cancellation
  T u_c;                 // exact lobe root: x tan u = tan(mu - x u), |u| < pi/2
  T theta_c;             // 2 (k pi + u_c)/a, the root of q' = 0 in this lobe
  T r_c;                 // sqrt(q^2 + q'^2) = |q| at theta_c (the lobe's candidate for r_res)
  T error;               // |theta_c - theta_asy| = 2 |u_c - u_asy|/a, formed without cancellation
  T bound;               // pi^3 x^2/a (paper eq. errorBound)
  T ratio;               // error/bound = 2 |u_c - u_asy|/(pi^3 x^2); P7 claims ratio <= 1
  bool holds_global_min = false;  // theta_c is a global minimiser of R (checked against inscribed_lattice)
};

// The paper's asymptotics for one pair.
template <class T> struct asymptotic_report {
  bool applicable = false;
  // !applicable: why. applicable: remarks (tie, degenerate pair), possibly empty.
  std::string reason;
  T x{};                                 // b/a
  bool tie = false;                      // a/(2b) is a half-integer (b = 1): two lobes
  std::vector<asymptotic_lobe<T>> lobes; // one, or two on a tie (ascending k); empty if !applicable
  // Observed closed form (docs/mathematics.md §3, *observed*, not a theorem): r_res ~ v x |sin u* tan u*|,
  // u* + tan u* = s* = pi m_min/(2b). Filled only when applicable.
  int m_min = 0;                         // strand_offset_min(): 0, 1 or 2
  T s_star{}, u_star{};
  T r_res_asy{};                         // v x |sin u* tan u*| (no sqrt(1 - x^2) factor, as stated)
  T r_res{};                             // exact r_res (inscribed_lattice)
  T r_res_asy_rel_error{};               // |r_res_asy - r_res|/r_res (absolute |r_res_asy| if r_res = 0)
};

namespace detail {

// Refuses pairs beyond T's exponent range (mpfr_real has none in practice).
template <class T, pair_integer I> void asy_check_range(const resonant_pair<I>& p, const char* what) {
  if constexpr (!is_variable_precision_v<T>) {
    if (boost::multiprecision::msb(to_big(p.order())) + 16 >= unsigned(std::numeric_limits<T>::max_exponent))
      throw compute_error(std::string(what) + ": pair " + p.str() + " exceeds the exponent range of " +
                          real_type_name<T>() + "; use mpfr_real");
  }
}

template <class T> std::uintmax_t asy_budget() { return std::uintmax_t(4 * real_bits<T>() + 200); }

// (tan w - w)/w^3 for |w| < pi/2 without cancellation: tan w - w = (sin w - w cos w)/cos w and
// (sin w - w cos w)/w^3 = sum_{n>=1} (-1)^(n+1) 2n w^(2n-2)/(2n+1)! (alternating, terms decrease).
template <class T> T tan_minus_id_over_cube(const T& w) {
  using std::cos;
  using std::fabs;
  const T eps = real_epsilon<T>();
  T w2 = w * w, term = T(1) / 3, sum = term;
  for (int n = 1; n < 100000; ++n) {
    term *= -w2 / T((2 * n) * (2 * n + 3));
    sum += term;
    if (fabs(term) <= eps * fabs(sum)) break;
  }
  return sum / cos(w);
}

// Tolerance for roots u of size >= ~|s|/4: relative 4 ulp, floored at min(1, |s|/8), so that a
// tiny root (|s| ~ pi/(2b) tiny when b is huge) is still found to full relative accuracy.
template <class T> root_tolerance<T> asy_u_tolerance(const T& s) {
  using std::fabs;
  T fl = fabs(s) / 8;
  if (fl > 1) fl = 1;
  return {4 * real_epsilon<T>(), fl};
}

}  // namespace detail

// The exact lobe root u_c: the root of psi(u) = u - atan(tan(mu - x u)/x) on [-pi/2, pi/2], i.e.
// of the lobe equation x tan u = tan(mu - x u) (precondition, not checked: 0 < x < 1/2, so that
// |mu - x u| < pi/2 and the root is unique; mu = pi m/(2a) with |m| <= b). s = mu/x only sets the
// tolerance floor (the root is ~ s/2 when s is small). To ~4 ulp; compute_error if TOMS 748 fails.
template <class T> T lobe_equation_root(const T& x, const T& mu, const T& s, const T& pi) {
  using std::atan;
  using std::tan;
  if (mu == 0) return T(0);  // exact: psi is odd when mu = 0
  auto psi = [&](const T& u) { return T(u - atan(tan(mu - x * u) / x)); };
  T h = pi / 2, lo = -h;
  return root_bracketed(psi, lo, h, psi(lo), psi(h), detail::asy_u_tolerance(s),
                        "asymptotic: lobe root of x tan u = tan(mu - x u)", detail::asy_budget<T>())
      .root;
}

namespace detail {

// G(e) of asymptotic_error_scaled (the lobe equation minus u + tan u = s, divided by x^2; see
// the header comment) and its derivative, from the values one evaluation forms anyway:
//   G(e)  = e (1 + sinc(d)/(cos u cos(u + d))) - y^3 S(w),   d = e x^2, y = y0 - d, w = x y,
//   G'(e) = 1 + sec^2(u + d) + tan^2 w                          (>= 2 on the whole domain),
//   G''(e) = 2 x^2 (sec^2(u + d) tan(u + d) - x tan w sec^2 w),
// (e sinc(d) = sin(d)/x^2 has the derivative cos(d); cos d cos(u + d) + sin d sin(u + d) = cos u;
// d/dy (y^3 S(x y)) = tan^2(x y)/x^2.) tan w = w + w^3 S(w) has no cancellation. curv bounds
// |G''|/(2 x^2) at e: |tan| <= |sec|, so sec^3(u + d) + x |tan w| sec^2 w.
template <class T> struct asy_error_eval {
  T g, dg, curv;
};
template <class T> struct asy_error_equation {
  T x, x2, y0, u, cu;
  asy_error_eval<T> operator()(const T& e) const {
    using std::cos;
    using std::fabs;
    using std::sin;
    using std::sqrt;
    const T d = e * x2;
    const T sinc = d == 0 ? T(1) : T(sin(d) / d);
    const T cud = cos(u + d);
    const T y = y0 - d, w = x * y;
    const T sw = tan_minus_id_over_cube(w);
    const T g = e * (1 + sinc / (cu * cud)) - y * y * y * sw;
    const T sec2 = 1 / (cud * cud), tw = w + w * w * w * sw, sec2w = 1 + tw * tw;
    return {g, T(1 + sec2 + tw * tw), T(sec2 * sqrt(sec2) + x * fabs(tw) * sec2w)};
  }
};

// The fallback of asymptotic_error_scaled: a sign bracket expanded away from e0 (steps |e0|/4,
// doubling, clipped to the domain |u + e x^2| < pi/2 where G runs from -oo to +oo), then TOMS 748
// to 4 ulp relative. compute_error if no bracket is found or TOMS 748 fails.
template <class T> T asy_error_bracketed(const asy_error_equation<T>& eq, const T& e0, const T& g0, const T& s,
                                         const T& pi) {
  using std::fabs;
  auto G = [&](const T& e) { return eq(e).g; };
  const bool bounded = eq.x2 > 0;
  const T lim_hi = bounded ? T((pi / 2 - eq.u) / eq.x2) : T(0), lim_lo = bounded ? T((-pi / 2 - eq.u) / eq.x2) : T(0);
  const int dir = g0 < 0 ? 1 : -1;
  T near = e0, gnear = g0;
  T step = (fabs(e0) > 0 ? fabs(e0) : T(1)) / 4;
  T far = e0, gfar = g0;
  bool found = false;
  for (int it = 0; it < int(2 * real_bits<T>() + 200); ++it) {
    far = near + dir * step;
    if (bounded && dir > 0 && far >= lim_hi) far = (near + lim_hi) / 2;
    if (bounded && dir < 0 && far <= lim_lo) far = (near + lim_lo) / 2;
    gfar = G(far);
    if (gfar == 0) return far;
    if ((gfar > 0) == (dir > 0)) {
      found = true;
      break;
    }
    near = far;
    gnear = gfar;
    step *= 2;
  }
  if (!found)
    throw compute_error("asymptotic: no bracket for (u_c - u_asy)/x^2 in " + real_type_name<T>() + " (s = " +
                        root_describe(s) + ")");
  T lo = dir > 0 ? near : far, hi = dir > 0 ? far : near;
  T glo = dir > 0 ? gnear : gfar, ghi = dir > 0 ? gfar : gnear;
  root_tolerance<T> tol{4 * real_epsilon<T>(), fabs(e0) > 0 ? T(fabs(e0) / 16) : T(1)};
  return root_bracketed(G, lo, hi, glo, ghi, tol, "asymptotic: (u_c - u_asy)/x^2", asy_budget<T>()).root;
}

}  // namespace detail

// e = (u_c - u_asy)/x^2 from the cancellation-free equation G(e) = 0 in the header comment, so
// that |theta_c - theta_asy| = 2 |e| x^2/a keeps full relative accuracy for pairs of any size
// (x < 1/2; s = pi m/(2b); u_asy = u_plus_tan_u_root(s)).
// Method: Newton's method on G from the first-order guess e0 (exact as x -> 0), safeguarded by
// the sign bracket of the points evaluated so far (inside the domain |u_asy + e x^2| < pi/2).
// G is increasing with G' >= 2 and |G''| = O(x^2) (detail::asy_error_equation), so from e0
// Newton converges quadratically at once: about 3 evaluations of G for x near 1/2 and 1 as
// x -> 0, where the bracketing search and TOMS 748 of the fallback took about 10. A step
// h = G/G' is accepted when the Newton error bound after it, |G''| G' h^2/8 (G' >= 2 bounds the
// distance to the root by |G|/2), with |G''| <= 4 x^2 curv (twice the bound at the current
// point), is at most eps/8 of the result: the result is then as accurate as G's rounding
// allows (tests/test_asymptotic.cpp measures it against a 50-digit reference). A step that
// leaves the bracket, a NaN or no convergence within 2 log2(bits) + 10 steps falls back to the
// bracketing search and TOMS 748 (detail::asy_error_bracketed), which throws compute_error if
// it fails: no unverified number is returned.
template <class T> T asymptotic_error_scaled(const T& x, const T& s, const T& u_asy, const T& pi) {
  using std::cos;
  using std::fabs;
  const T x2 = x * x, y0 = s - u_asy, ca = cos(u_asy);
  const detail::asy_error_equation<T> eq{x, x2, y0, u_asy, ca};
  const T e0 = y0 * y0 * y0 * detail::tan_minus_id_over_cube(T(x * y0)) / (1 + 1 / (ca * ca));
  auto ev = eq(e0);
  if (ev.g == 0) return e0;
  const T g0 = ev.g;
  // Open sign bracket (lo: G < 0, hi: G > 0), first the domain's ends.
  const bool bounded = x2 > 0;
  T lo = bounded ? T((-pi / 2 - u_asy) / x2) : T(-std::numeric_limits<double>::infinity());
  T hi = bounded ? T((pi / 2 - u_asy) / x2) : T(std::numeric_limits<double>::infinity());
  const T eps = real_epsilon<T>();
  const int max_steps = 2 * int(std::bit_width(real_bits<T>())) + 10;
  T e = e0;
  for (int it = 0; it < max_steps; ++it) {
    if (!(e > lo && e < hi)) break;
    if (it > 0) {
      ev = eq(e);
      if (ev.g == 0) return e;
    }
    if (ev.g < 0) lo = e;
    else hi = e;
    const T h = ev.g / ev.dg, next = e - h;
    if (!(next > lo && next < hi)) break;  // also NaN
    if (x2 * ev.curv * ev.dg * h * h <= eps * fabs(next) / 4) return next;
    e = next;
  }
  return detail::asy_error_bracketed(eq, e0, g0, s, pi);
}

namespace detail {

// 2 (k pi + u)/a with k/a formed as one exact-integer ratio.
template <class T, class L> T asy_theta(const L& k, const L& a, const T& u, const T& pi) {
  T at = real_from_int<T>(a);
  return 2 * pi * real_from_ratio<T>(k, a) + 2 * u / at;
}

// Does the lobe (k, u_c) carry a global minimiser of the exact result lr? Compared as lobe
// frames: same k mod a (exact) and |u - u_c| <= 2^(-bits/2), since theta itself cannot
// separate neighbouring lobes once 2 pi/a is below its rounding. The minimiser frames are
// lr.first and its images under theta -> 2 pi - theta and (m_min = 2) theta -> theta + pi
// (lattice.hpp); degenerate pairs: theta = pi/2, 3 pi/2, i.e. (a/4, 0), (3a/4, 0).
template <class T>
bool asy_holds_global_min(const inscribed_result<T>& lr, const big_int& A, const big_int& k, const T& u_c,
                          bool degenerate, int m_min) {
  using std::fabs;
  using std::ldexp;
  std::vector<std::pair<big_int, T>> frames;
  if (degenerate) {
    frames = {{big_int(A / 4), T(0)}, {big_int(3 * A / 4), T(0)}};
  } else {
    const big_int& k1 = lr.first.k;
    const T& u1 = lr.first.u;
    frames.push_back({int_mod(k1, A), u1});
    frames.push_back({int_mod(big_int(A - k1), A), T(-u1)});
    if (m_min == 2) {
      big_int ks = k1 + A / 2;
      frames.push_back({int_mod(ks, A), u1});
      frames.push_back({int_mod(big_int(A - ks), A), T(-u1)});
    }
  }
  if (frames.size() != lr.minimisers.size())
    throw compute_error("asymptotic: inscribed_lattice returned " + std::to_string(lr.minimisers.size()) +
                        " minimisers, expected " + std::to_string(frames.size()));
  const T tol = ldexp(T(1), -int(real_bits<T>() / 2));
  const big_int kr = int_mod(k, A);
  for (const auto& f : frames)
    if (f.first == kr && fabs(f.second - u_c) <= tol) return true;
  return false;
}

}  // namespace detail

// The root u of u + tan u = s in (-pi/2, pi/2), for any real s, in T, with the solver's record
// (final bracket, evaluations). Solved as u - atan(s - u) = 0 on [-pi/2, pi/2] with
// root_bracketed (TOMS 748; the sign change holds for every s, and the derivative lies in
// (1, 2]). Accuracy: a few ulp relative to max(|u|, min(1, |s|/8)), i.e. full relative accuracy
// also for tiny s. Throws compute_error if the solver fails (it never returns an unverified number).
template <class T> root_result<T> u_plus_tan_u_solve(const T& s) {
  using std::atan;
  if (s == 0) return {T(0), T(0), T(0), 0};  // exact: the root is odd in s
  auto phi = [&](const T& u) { return T(u - atan(s - u)); };
  T h = real_pi<T>() / 2, lo = -h;
  auto r = root_bracketed(phi, lo, h, phi(lo), phi(h), detail::asy_u_tolerance(s), "asymptotic: u + tan u = s",
                          detail::asy_budget<T>());
  r.evaluations += 2;  // phi(lo), phi(hi)
  return r;
}
template <class T> T u_plus_tan_u_root(const T& s) { return u_plus_tan_u_solve(s).root; }

// The paper's fast-node indices k = round(a/(2b)) (exact integer arithmetic): one k, or the two
// k = (a-1)/2, (a+1)/2 when a/(2b) is a half-integer (exactly when b = 1). Defined for every
// pair; meaningful for the asymptotics only when x < 1/2.
template <pair_integer I> std::vector<big_int> paper_lobe_indices(const resonant_pair<I>& p) {
  big_int a = to_big(p.order()), b = to_big(p.delta());
  auto [k, tie] = paper_fast_node(a, b);
  if (tie) return {k, big_int(k + 1)};
  return {k};
}

// theta_asy = 2 (k pi + u_asy)/a for the lobe k (paper eq. uasy, with u + tan u = s,
// s = pi (a - 2 k b)/(2b)); cheap: one bracketed root of u + tan u = s, no exact lobe solver.
// Preconditions: x = b/a < 1/2 (usage_error otherwise); k any integer (the paper's k is
// paper_lobe_indices(p)); a within T's exponent range (compute_error otherwise).
// The result is the paper's heuristic approximation to the root theta_c, not theta_c.
// It is not reduced mod 2 pi (for the paper's k it lies in (0, 2 pi)).
template <class T, pair_integer I> T theta_asy_only(const resonant_pair<I>& p, const big_int& k) {
  using L = wide_int<I>;
  const L a = p.order(), b = L(p.delta());
  if (2 * b >= a) throw usage_error("theta_asy_only: x = b/a >= 1/2 for " + p.str() + ": the lobe asymptotics do not apply");
  detail::asy_check_range<T>(p, "theta_asy_only");
  big_int A = to_big(a), B = to_big(b);
  big_int m = A - 2 * k * B;
  T pi = real_pi<T>();
  T s = pi * real_from_ratio<T>(m, big_int(2 * B));
  T u = u_plus_tan_u_root(s);
  return detail::asy_theta(k, A, u, pi);
}

// theta_asy for the paper's k (the smaller one on a tie); same contract as above. For
// int64 pairs the integer work stays in int128.
template <class T, pair_integer I> T theta_asy_only(const resonant_pair<I>& p) {
  using L = wide_int<I>;
  const L a = p.order(), b = L(p.delta());
  if (2 * b >= a) throw usage_error("theta_asy_only: x = b/a >= 1/2 for " + p.str() + ": the lobe asymptotics do not apply");
  detail::asy_check_range<T>(p, "theta_asy_only");
  const L k = paper_fast_node(a, b).k;
  const L m = a - 2 * k * b;
  T pi = real_pi<T>();
  T s = pi * real_from_ratio<T>(m, L(2 * b));
  T u = u_plus_tan_u_root(s);
  return detail::asy_theta(k, a, u, pi);
}

namespace detail {

// One lobe k of paper_asymptotics (below): u_asy and theta_asy, q'(theta_asy), the exact lobe
// root, the error against the paper's bound, and whether the lobe holds a global minimiser of
// the lattice result lr.
template <class T, class L, pair_integer I>
asymptotic_lobe<T> asy_lobe(const resonant_pair<I>& p, const resonant_constants<T>& c, const T& v, const L& a,
                            const L& b, const L& k, const inscribed_result<T>& lr, int m_min) {
  using std::fabs;
  using std::ldexp;
  const T pi = c.pi, x = c.x;
  const T at = real_from_int<T>(a);
  asymptotic_lobe<T> lo;
  const L m = a - 2 * k * b;
  lo.k = to_big(k);
  lo.m = to_big(m);
  lobe_frame<L> fr{k, L(0), m};
  auto frr = lobe_frame_real_of(c, fr, a);
  lo.mu = frr.mu;
  lo.s = pi * real_from_ratio<T>(m, L(2 * b));
  lo.u_asy = u_plus_tan_u_root(lo.s);
  lo.theta_asy = asy_theta(k, a, lo.u_asy, pi);
  lo.theta_asy_paper = pi / real_from_int<T>(b) + 2 * (lo.u_asy - lo.s) / at;
  {
    // q' at the exact theta_asy: with w = mu - x u_asy = x (s - u_asy) = x tan u_asy,
    // q' = (-1)^k v cos u cos w (tan w - x tan u) = (-1)^k v cos u cos w (tan w - w); the last
    // form drops the rounding residual of u_asy (which would otherwise dominate for large a).
    using std::cos;
    const T w = x * (lo.s - lo.u_asy);
    lo.qdot_asy = T(frr.sign) * v * cos(lo.u_asy) * cos(w) * w * w * w * tan_minus_id_over_cube(w);
  }
  lo.u_c = lobe_equation_root(x, lo.mu, lo.s, pi);
  lo.theta_c = asy_theta(k, a, lo.u_c, pi);
  // R = q^2 at the root of q'; |q| keeps full relative accuracy where q' (which vanishes only up
  // to the root's rounding) would not (tiny s: q ~ x u^2 while the q' residual is ~ eps x u).
  lo.r_c = fabs(lobe_eval(c, frr, lo.u_c).q);
  const T e = asymptotic_error_scaled(x, lo.s, lo.u_asy, pi);
  const T x2 = x * x;
  // Cross-check: the two routes to u_c (psi root; u_asy + e x^2) must agree to rounding.
  const T gap = fabs(lo.u_c - (lo.u_asy + e * x2));
  if (!(gap <= ldexp(T(1), 10 - int(real_bits<T>()))))
    throw compute_error("asymptotic: lobe root and u_asy + (u_c - u_asy) disagree by " + root_describe(gap) +
                        " for " + p.str() + " in " + real_type_name<T>());
  lo.error = 2 * fabs(e) * x2 / at;
  lo.bound = pi * pi * pi * x2 / at;
  lo.ratio = 2 * fabs(e) / (pi * pi * pi);
  lo.holds_global_min = asy_holds_global_min(lr, to_big(a), to_big(k), lo.u_c, p.degenerate(), m_min);
  return lo;
}

}  // namespace detail

// The paper's asymptotics for pair p and impulse amplitude v > 0 (usage_error otherwise):
// every lobe k = round(1/(2x)) (two on a tie) with u_asy, theta_asy (both forms), q'(theta_asy),
// the exact lobe root theta_c, error = |theta_c - theta_asy| (cancellation-free), the paper's
// bound pi^3 x^2/a and the ratio error/bound; whether theta_c is a global minimiser (exact
// comparison with inscribed_lattice, O(log tau)); and the x -> 0 limit form r_res_asy with its
// relative error against the exact r_res.
// x >= 1/2: applicable = false, `reason` says why, nothing else is computed.
// Heuristic (not proved) parts: theta_asy and r_res_asy are approximations; the bound is the
// paper's claim P7, reported, not enforced; holds_global_min relies on inscribed_lattice, whose
// minimiser location is *observed* (lattice.hpp STATUS). Exact parts: k, m (integers), u_asy,
// u_c, theta_c (roots to ~4 ulp), error/ratio (to a few ulp relative).
// Throws compute_error if a root cannot be bracketed, the two routes to u_c disagree, or the
// pair exceeds T's exponent range.
template <class T, pair_integer I> asymptotic_report<T> paper_asymptotics(const resonant_pair<I>& p, const T& v) {
  using std::fabs;
  using std::sin;
  using std::tan;
  using L = wide_int<I>;
  check_amplitude(v);
  asymptotic_report<T> rep;
  const L a = p.order(), b = L(p.delta());
  rep.m_min = p.strand_offset_min();
  if (2 * b >= a) {
    detail::asy_check_range<T>(p, "paper_asymptotics");
    rep.x = real_from_ratio<T>(b, a);
    rep.applicable = false;
    rep.reason = "x = b/a = " + to_decimal(b) + "/" + to_decimal(a) +
                 " >= 1/2: the lobe equation x tan u = tan(mu - x u) need not have a unique root in "
                 "|u| < pi/2 and the slow-node reduction (mu and x u small) does not apply";
    return rep;
  }
  detail::asy_check_range<T>(p, "paper_asymptotics");
  rep.applicable = true;
  auto c = resonant_constants_of<T>(p, v);
  const T pi = c.pi, x = c.x;
  rep.x = x;
  auto [k0, tie] = paper_fast_node(a, b);
  rep.tie = tie;
  if (tie) rep.reason = "a/(2b) is a half-integer (b = 1): both lobes k = (a-1)/2 and (a+1)/2 are reported (mirror images)";
  if (p.degenerate()) {
    if (!rep.reason.empty()) rep.reason += "; ";
    rep.reason += "degenerate pair (delta = 2 mod 4): r_res = 0 exactly at theta = pi/2 (integer arithmetic); the "
                  "lobe root near pi/b is still reported, and it is that zero only when b = 2";
  }
  auto lr = inscribed_lattice<T>(p, v);
  std::vector<L> ks{k0};
  if (tie) ks.push_back(L(k0 + 1));
  for (const L& k : ks) rep.lobes.push_back(detail::asy_lobe(p, c, v, a, b, k, lr, rep.m_min));
  rep.s_star = pi * real_from_ratio<T>(L(rep.m_min), L(2 * b));
  rep.u_star = u_plus_tan_u_root(rep.s_star);
  rep.r_res_asy = v * x * fabs(sin(rep.u_star) * tan(rep.u_star));
  rep.r_res = lr.r_res;
  rep.r_res_asy_rel_error = lr.r_res > 0 ? T(fabs(rep.r_res_asy - lr.r_res) / lr.r_res) : T(fabs(rep.r_res_asy));
  return rep;
}

// Compiled once in tests/reference/ for double, long double, float128 and mpfr_real.
#define GYRORES_ASYMPTOTIC_INSTANCES(PREFIX, T) \
  PREFIX template root_result<T> u_plus_tan_u_solve<T>(const T&); \
  PREFIX template T lobe_equation_root<T>(const T&, const T&, const T&, const T&); \
  PREFIX template T asymptotic_error_scaled<T>(const T&, const T&, const T&, const T&); \
  PREFIX template T theta_asy_only<T, std::int64_t>(const resonant_pair<std::int64_t>&); \
  PREFIX template T theta_asy_only<T, big_int>(const resonant_pair<big_int>&); \
  PREFIX template T theta_asy_only<T, std::int64_t>(const resonant_pair<std::int64_t>&, const big_int&); \
  PREFIX template T theta_asy_only<T, big_int>(const resonant_pair<big_int>&, const big_int&); \
  PREFIX template asymptotic_report<T> paper_asymptotics<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&); \
  PREFIX template asymptotic_report<T> paper_asymptotics<T, big_int>(const resonant_pair<big_int>&, const T&);
GYRORES_FOR_COMPILED_REALS(GYRORES_ASYMPTOTIC_INSTANCES, extern)

}  // namespace gyrores
