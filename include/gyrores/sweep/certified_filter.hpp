// The certified sweep's fast filter: a double row of `gyrores sweep --certified` proved in
// double-double ball arithmetic (core/dd_ball.hpp) instead of MPFI, with the existing proof
// (sweep_prove_pair, sweep/certified.hpp) as the fallback whenever the filter cannot decide.
//
// What it proves for one pair (amplitude v = 1), every step an exact statement about balls:
//  1. u*: interval Newton on F(u) = x sin u cos w - cos u sin w, w = mu - x u (zero on (0, pi/2)
//     only at u*: F has the sign of H(u) - mu, theorem/root.hpp) about the double root u0: u* lies
//     in u0 - F(u0)/F'(X), X = u0 +- rho, if that lies inside X (F' over X from F'(u0) and a
//     bound on F''): a ball U. Degenerate pairs (m_min = 0): u* = 0.
//  2. Over U: r_res = x sqrt(1-x^2) sin^2 u/sqrt(cos^2 u + x^2 sin^2 u) (the theorem's sqrt(G)
//     with t = tan u); theta_first = 2 (k pi + sign(m) u)/a of the first lobe, t_first =
//     sqrt(tau sigma) theta_first, t_first/t_min_paper = theta_first b/pi; t_min_paper =
//     pi sqrt(tau sigma)/b.
//     The degeneracy check's r_res > 0 and r_res^2 4 a^2 < 4 a^2 R(pi/2) (the exact integer).
//  3. (asy-bound, x < 1/2, s = pi |m|/(2b) > 0) u_a: interval Newton on q(u) = (u - s) cos u +
//     sin u = cos u (u + tan u - s), as in 1. Then d = u_c - u_a without cancellation: for
//     u = u_a + d, y = x (t - d), t = s - u_a = tan u_a and T = tan u - tan u_a =
//     sin d/(cos u_a cos u),
//       sigma(d) = (sin y - y cos y) - x (T + d) cos y = cos y (tan(x (s - u)) - x tan u),
//     whose sign is that of u_c - u (H increasing; |y|, |x (s - u)| < pi/2). sin y - y cos y is
//     the alternating series sum_{n>=1} (-1)^(n+1) 2n y^(2n+1)/(2n+1)! (terms decreasing for
//     |y| < 1, so the first omitted one bounds the rest). sigma is evaluated with u_a a ball
//     holding u_a's bracket, so its sign at two points d_lo < d_hi brackets d. Then error = 2d/a,
//     bound = pi^3 x^2/a, ratio = error/bound, constant = 2d/x^2, and ratio <= 1.
// Printed values: the row's rule (sweep_prove_pair's): each real is the exact value rounded to
// double, to nearest (the asy columns upward, asy_bound downward). The filter returns a value
// only if every point of its enclosure rounds to the same double, so the row is byte for byte
// the one the fallback prints; anything undecided (a rounding, a sign, a check that does not
// pass) returns false and the caller runs the fallback.
// Range: orders below 2^31 (a, b, k and 2b exact in double, a^2 and 4 a^2 exact double-doubles).
#pragma once
#include <cstdint>

#include <gyrores/core/dd_ball.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/checks.hpp>

namespace gyrores {
template <class T> struct sweep_row;  // sweep/evaluate.hpp, which calls the filter
}

namespace gyrores::detail {

// The row of pair p for a certified double sweep, if the filter proves all of it (fields as
// sweep_evaluate_into fills them); false, with r untouched, if the fallback must run.
// Precondition: cfg.certified.
bool sweep_certified_filter(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg);

// The double estimate of u_c - u_asy >= 0 of src/lib/sweep/evaluate.cpp (x < 1/2, 0 < s <= pi/2).
double sweep_asy_difference(double x, double s);

}  // namespace gyrores::detail

// The filter's steps, for the tests (tests/test_certified_filter.cpp) and their mutants.
namespace gyrores::detail::filter {

// The double nearest (upward, downward) to every v in [A.m - A.r, B.m + B.r] (v > 0), if there
// is one such double; false otherwise.
bool round_nearest(const dd_ball& A, const dd_ball& B, double& out);
bool round_up(const dd_ball& A, const dd_ball& B, double& out);
bool round_down(const dd_ball& A, const dd_ball& B, double& out);

struct constants {
  double a = 0, b = 0;           // exact (orders below 2^31)
  dd_ball x, x2, pi, sqrt_ts;  // b/a, x^2, pi, sqrt(tau sigma)
};
bool constants_of(constants& K, const resonant_pair<std::int64_t>& p);

// A double-double point u and the balls of its sine and cosine.
struct trig_point {
  double_double u;
  dd_ball s, c;
};
trig_point trig_at(const double_double& u);
// sin and cos over the ball U from their balls at the point P.u (for U near P.u: the first-order
// Taylor terms, and t^2/2 for the rest, t over U - P.u).
void sin_cos_near(const trig_point& P, const dd_ball& U, dd_ball& s, dd_ball& c);

// Interval Newton: the root z of f in u0 +- rho lies in `out` = u0 - fv/dfX (fv: f(u0), dfX:
// f' over u0 +- rho), and exists there, if `out` lies inside u0 +- rho; false otherwise.
bool newton_enclosure(dd_ball& out, double u0, double rho, const dd_ball& fv, const dd_ball& dfX);

// Step 1: F at P (mu = pi m_min/(2a)); slope, if not null, receives the ball of F' there.
dd_ball theorem_F(const constants& K, const dd_ball& mu, const trig_point& P, dd_ball* slope);
// A ball holding u* (m_min = 1, 2), proved; false if not decided.
bool theorem_root(dd_ball& U, const constants& K, int m_min);

// Step 3: q(u) = (u - s) cos u + sin u at P (and q' there); sin y - y cos y over the ball y
// (|y| < 1/2); sigma(d) (and sigma'(d)) with u_a in the ball ua (cua its cosine) and t = s - ua.
dd_ball paper_q(const dd_ball& s, const trig_point& P, dd_ball* slope);
bool sin_minus_y_cos(dd_ball& out, const dd_ball& y);
bool paper_sigma(dd_ball& out, const constants& K, const dd_ball& t, const dd_ball& ua, const dd_ball& cua,
                 const double_double& d, dd_ball* slope);
// A ball holding d = u_c - u_a > 0 for s = pi |m|/(2b) > 0 (x < 1/2), proved; false if not decided.
bool asy_difference(dd_ball& D, const constants& K, const dd_ball& s);

}  // namespace gyrores::detail::filter
