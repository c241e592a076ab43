// The theorem's minimum (theorem/minimum.hpp) in balls of double-doubles (core/dd_ball.hpp): the
// one proved solver of H(u) = mu in this arithmetic, and the minimum's values over its ball,
// every step an exact statement about balls, about 2^-95 wide. The certified sweep rounds these
// balls to its rows' doubles and falls back to the MPFI proof where a rounding is not decided
// (src/lib/sweep/certified_filter.cpp); the paper's error in balls is theorem/paper.hpp's.
//
// For one pair (amplitude v = 1, orders below 2^31: a, b, k and 2b exact doubles):
//  1. u*: interval Newton on F(u) = x sin u cos w - cos u sin w, w = mu - x u (zero on (0, pi/2)
//     only at u*: F has the sign of H(u) - mu, theorem/root.hpp) about the double root u0: u* lies
//     in u0 - F(u0)/F'(X), X = u0 +- rho, if that lies inside X (F' over X from F'(u0) and a
//     bound on F''): a ball U. Degenerate pairs (m_min = 0): u* = 0.
//  2. Over U: r_res = x sqrt(1-x^2) sin^2 u/sqrt(cos^2 u + x^2 sin^2 u) (the theorem's sqrt(G)
//     with t = tan u); theta_first = 2 (k pi + sign(m) u)/a of the first lobe, t_first =
//     sqrt(tau sigma) theta_first, t_first/t_min_paper = theta_first b/pi; t_min_paper =
//     pi sqrt(tau sigma)/b.
#pragma once
#include <cstdint>

#include <gyrores/core/dd_ball.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/core/status.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

// n/d for integers 0 <= n < 2^53, 0 < d < 2^53, as a ball (dd::quotient, within 2^-104).
dd_ball dd_ball_quotient(double n, double d);

// A pair's constants as balls.
struct dd_ball_constants {
  double a = 0, b = 0;                          // exact (orders below 2^31)
  dd_ball x, x2, pi, sqrt_ts, inv_a, inv_b;  // b/a, x^2, pi, sqrt(tau sigma), 1/a, 1/b
};
// False for orders from 2^31 on (or if a ball operation cannot decide, which does not happen).
bool dd_ball_constants_of(dd_ball_constants& K, const resonant_pair<std::int64_t>& p);

// A double-double point u and the balls of its sine and cosine.
struct dd_trig_point {
  double_double u;
  dd_ball s, c;
};
dd_trig_point dd_trig_at(const double_double& u);
// sin and cos over the ball U from their balls at the point P.u (for U near P.u: the first-order
// Taylor terms, and t^2/2 for the rest, t over U - P.u): a third of a ball sin_cos's cost.
void dd_sin_cos_near(const dd_trig_point& P, const dd_ball& U, dd_ball& s, dd_ball& c);

// Interval Newton: the root z of f in u0 +- rho lies in `out` = u0 - fv/dfX (fv: f(u0), dfX:
// f' over u0 +- rho), and exists there, if `out` lies inside u0 +- rho; false otherwise.
bool dd_newton_enclosure(dd_ball& out, double u0, double rho, const dd_ball& fv, const dd_ball& dfX);

// Step 1: F at P for mu (a ball of pi m/(2a)); slope, if not null, receives the ball of F' there.
dd_ball theorem_F_dd_ball(const dd_ball_constants& K, const dd_ball& mu, const dd_trig_point& P, dd_ball* slope);
// A ball holding u* for m_min = 1, 2, proved; not proved (undecided) otherwise.
proof_status theorem_root_dd_ball(dd_ball& U, const dd_ball_constants& K, int m_min);

// Step 2's balls (r_res = 0 exactly for degenerate pairs).
struct minimum_dd_ball {
  dd_ball r_res, theta_first, t_first, t_min_paper, t_ratio;
};
// The minimum of the pair of K with m_min = theorem_m_min(a) and the first minimiser lobe `first`
// (theorem/lobes.hpp, k reduced); not proved when u* or r_res is not decided in balls.
proof_status prove_minimum_dd_ball(minimum_dd_ball& M, const dd_ball_constants& K, int m_min,
                                   const lobe_frame<int128>& first);

}  // namespace gyrores
