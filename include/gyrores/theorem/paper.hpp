// The paper's asymptotics against the theorem (docs/mathematics.md §2, P7), in its lobe
// k = round(a/(2b)) (paper_fast_node, theorem/lobes.hpp; the smaller k on a tie, the other is
// its mirror image), offset m = a - 2 k b, |m| <= b, s = pi |m|/(2b): the paper's root u_a of
// u + tan u = s (theta_asy = 2 (k pi + u_a)/a; paper_root_double and prove_paper_root in
// theorem/root.hpp, which share the theorem's Newton ladder) against the theorem's
// u_c = H^{-1}(pi |m|/(2a)). For x = b/a < 1/2, d = u_c - u_a >= 0 (the signs of u_c, u_a follow
// m's, so |u_c - u_a| is the same for m < 0) and
//   error = |theta_c - theta_asy| = 2 d/a,  bound = pi^3 x^2/a (the paper's),
//   ratio = error/bound,  constant = error a/x^2 = 2 d/x^2 (its sup over pairs estimates the
//   sharp constant); the sweep checks ratio <= 1 for every pair (P7).
// d is O(x^2 u^3) against u, so it is never formed as a difference of two roots in floating
// point: in double by Newton's method on an equation without cancellation; in double-double
// balls by interval Newton on the same; in MPFI from two proved brackets at enough more bits.
// The pair report's Case B quantities (theta_asy, q'(theta_asy)) are theorem/pair_report.hpp's.
#pragma once
#include <cstdint>

#include <gyrores/core/dd_ball.hpp>
#include <gyrores/core/double_double.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/core/status.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum_dd_ball.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

// |m| of the paper's lobe of the pair with order a and delta b (a > b >= 1), from its node if
// the caller has it.
inline std::int64_t paper_offset(std::int64_t a, std::int64_t b, const paper_node<std::int64_t>& node) {
  const std::int64_t m = a - 2 * node.k * b;  // the smaller k on a tie
  return m < 0 ? -m : m;
}
inline std::int64_t paper_offset(std::int64_t a, std::int64_t b) { return paper_offset(a, b, paper_fast_node(a, b)); }

// ---- double ----

// d = u_c - u_a >= 0 for x < 1/2, 0 < s <= pi/2, within about 2^-50 relative (Newton's method,
// paper.cpp); compute_error if it does not converge (never seen).
double paper_difference_double(double x, double s);

struct paper_error_double {
  double error = 0, bound = 0, ratio = 0, constant = 0;
};
// The columns above in double for the pair (a, b) with x < 1/2 and its offset am = paper_offset.
paper_error_double paper_error_of(std::int64_t a, std::int64_t b, std::int64_t am);

// A proved upper bound of the constant 2 d/x^2 for x < 1/2 and am/b = |m|/b in (0, 1], as num/den
// (den in [2, 3.5]: callers compare products, without the division), within 2^-47 of
//   (2 t^3/3) (1 + y^2)/(2 + t^2 + y^2),  t = t_max |m|/b,  y = x t,
// t_max = tan u_a(pi/2) = 0.86033358901937976... (rounded up); the argument is in paper.cpp.
struct paper_bound_fraction {
  double num, den;
};
GYRORES_DD_INLINE paper_bound_fraction paper_constant_bound(double x, double am_over_b) {
  constexpr double t_max_up = 0.860333589019381;  // 1.2e-15 above t_max
  const double t = t_max_up * am_over_b;
  const double t2 = t * t, y2 = x * x * t2;
  return {(2.0 / 3) * (t2 * t) * (1 + y2), 2 + t2 + y2};
}

// ---- enclosures at K's precision ----

struct paper_error_enclosure {
  explicit paper_error_enclosure(mpfr_prec_t p) : prec(p), error(p), bound(p), ratio(p), constant(p) {}
  mpfr_prec_t prec;
  fixed_mpfi error, bound, ratio, constant;
};
// The columns for the pair of K with x < 1/2 and offset am = paper_offset (am = 0: d = 0 exactly):
// u_c by prove_theorem_root, u_a by prove_paper_root, d narrower than 2^-narrow_bits relative
// before its quotients are formed. K's precision needs 2 log2(a) + 8 bits beyond narrow_bits
// (paper.cpp); not proved (the caller doubles it) if a root or the width is not reached.
proof_status prove_paper_error(paper_error_enclosure& E, const theorem_constants& K, std::int64_t am, int narrow_bits);

// ---- double-double balls (theorem/minimum_dd_ball.hpp) ----

// sin y - y cos y over the ball y (|y| < 1/2) by its alternating series; false outside.
bool sin_minus_y_cos(dd_ball& out, const dd_ball& y);
// A ball holding d = u_c - u_a > 0 for s = pi |m|/(2b) > 0 (a ball; x < 1/2), proved; not proved
// when a Newton enclosure is not decided.
proof_status paper_difference_dd_ball(dd_ball& D, const dd_ball_constants& K, const dd_ball& s);

struct paper_error_dd_ball {
  dd_ball error, bound, ratio, constant;
};
// The columns in balls for the pair of K (x < 1/2) and offset am > 0.
proof_status prove_paper_error_dd_ball(paper_error_dd_ball& E, const dd_ball_constants& K, std::int64_t am);

}  // namespace gyrores
