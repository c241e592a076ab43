// include/gyrores/theorem/minimum_dd_ball.hpp: u* and the minimum in double-double balls.
#include <gyrores/theorem/minimum_dd_ball.hpp>

#include <cmath>

#include <gyrores/core/error.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

using ddb::add;
using ddb::exact;
using ddb::mul;
using ddb::scale;
using ddb::sub;

// dd::quotient is within 2^-104 of n/d relatively (core/double_double.hpp), and n/d <= q.hi (1 +
// 2^-52). Half the divisions of ddb::div.
dd_ball dd_ball_quotient(double n, double d) {
  const double_double q = dd::quotient(n, d);
  return {q, ddb::up(0x1.0001p-104 * q.hi)};
}

bool dd_ball_constants_of(dd_ball_constants& K, const resonant_pair<std::int64_t>& p) {
  if (p.order() >= (int128(1) << 31)) return false;
  K.a = double(std::int64_t(p.order()));
  K.b = double(p.delta());
  K.pi = ddb::pi();
  K.x = dd_ball_quotient(K.b, K.a);
  K.x2 = mul(K.x, K.x);
  K.inv_a = dd_ball_quotient(1.0, K.a);
  K.inv_b = dd_ball_quotient(1.0, K.b);
  return ddb::sqrt(K.sqrt_ts, exact(dd::of_int(p.tau() * p.sigma())));  // tau sigma < 2^62: exact
}

dd_trig_point dd_trig_at(const double_double& u) {
  dd_trig_point t{u, {}, {}};
  ddb::sin_cos(exact(u), t.s, t.c);
  return t;
}

// For v = u + t (u = P.u, t in the ball U - u) Taylor's theorem gives |sin v - (sin u + t cos u)|
// <= t^2/2 and |cos v - (cos u - t sin u)| <= t^2/2 (|sin''|, |cos''| <= 1). sin u and cos u lie
// in P's balls, so the ball operations hold sin u + t cos u and cos u - t sin u for every such t,
// and the radii add upper_abs(t)^2/2 (rounded up by `up`).
void dd_sin_cos_near(const dd_trig_point& P, const dd_ball& U, dd_ball& s, dd_ball& c) {
  const dd_ball t = sub(U, exact(P.u));
  const double ta = ddb::upper_abs(t), remainder = ta * ta * 0.5;
  s = add(P.s, mul(P.c, t));
  c = sub(P.c, mul(P.s, t));
  s.r = ddb::up(s.r + remainder);
  c.r = ddb::up(c.r + remainder);
}

// For f with one root z in the ball X = u0 +- rho, f(u0) in the ball fv and f' over X in the ball
// dfX (excluding 0): by the mean value theorem f(u0) = f'(xi) (u0 - z) with xi in X, so z lies in
// N = u0 - fv/dfX; and if N lies inside X, X holds a root (Moore's theorem), so z lies in N.
bool dd_newton_enclosure(dd_ball& out, double u0, double rho, const dd_ball& fv, const dd_ball& dfX) {
  dd_ball q;
  if (!ddb::div(q, fv, dfX)) return false;
  out = sub(exact(u0), q);
  return std::fabs(out.m.hi - u0) * (1 + 0x1p-50) + std::fabs(out.m.lo) + out.r < rho * (1 - 0x1p-50);
}

// F(u) = x sin u cos w - cos u sin w, w = mu - x u; sign(F) = sign(H(u) - mu) on (0, pi/2), and
// F = 0 only at u*. F' = 2x cos u cos w + (1 + x^2) sin u sin w; |F''| <= 2x (1 + x) +
// (1 + x^2)(1 + x) < 8 (x < 1, dw/du = -x), so F' over u0 +- rho lies within 8 rho of F'(u0).
dd_ball theorem_F_dd_ball(const dd_ball_constants& K, const dd_ball& mu, const dd_trig_point& P, dd_ball* slope) {
  dd_ball sw, cw;
  ddb::sin_cos(sub(mu, mul(K.x, exact(P.u))), sw, cw);
  if (slope) *slope = add(mul(scale(K.x, 2), mul(P.c, cw)), mul(add(exact(1.0), K.x2), mul(P.s, sw)));
  return sub(mul(K.x, mul(P.s, cw)), mul(P.c, sw));
}

namespace {

// theorem_root_dd_ball, and in P the point u0 about which U was proved (the minimum's sines come
// from it).
proof_status theorem_root_at(dd_ball& U, dd_trig_point& P, const dd_ball_constants& K, int m_min) {
  const dd_ball mu = mul(scale(K.pi, 0.5), dd_ball_quotient(m_min, K.a));  // pi m/(2a)
  double u0;
  try {
    u0 = theorem_root_double(K.x.m.hi, mu.m.hi);
  } catch (const compute_error&) {
    return proof_status::no_convergence("u*: the double root did not converge");
  }
  if (!(u0 > 0x1p-40 && u0 < 1.5)) return proof_status::out_of_domain("u*: the double root is out of range");
  const double rho = 0x1p-44 * u0;
  dd_ball slope;
  P = dd_trig_at(double_double(u0));
  const dd_ball f0 = theorem_F_dd_ball(K, mu, P, &slope);
  slope.r = ddb::up(slope.r + 8 * rho);
  if (dd_newton_enclosure(U, u0, rho, f0, slope) && U.m.hi - U.r > 0 && U.m.hi + U.r < 1.5) return proof_status::proved();
  return proof_status::undecided("u*: interval Newton");
}

// 1/pi, formed once.
const dd_ball& inverse_pi() {
  static const dd_ball v = [] {
    dd_ball q;
    ddb::div(q, exact(1.0), ddb::pi());
    return q;
  }();
  return v;
}

// r(u) = x sqrt(1-x^2) sin^2 u/sqrt(cos^2 u + x^2 sin^2 u), x sqrt(1-x^2) = 2 b sqrt(tau sigma)/a^2,
// over a ball U given the balls s, c of its sine and cosine.
bool radius_over(dd_ball& r, const dd_ball_constants& K, const dd_ball& s, const dd_ball& c) {
  dd_ball root;
  const dd_ball s2 = mul(s, s);
  if (!ddb::sqrt(root, add(mul(c, c), mul(K.x2, s2)))) return false;
  const dd_ball coefficient = mul(mul(scale(K.sqrt_ts, 2), K.x), K.inv_a);  // 2 sqrt(tau sigma) (b/a)/a
  return ddb::div(r, mul(coefficient, s2), root);
}

}  // namespace

proof_status theorem_root_dd_ball(dd_ball& U, const dd_ball_constants& K, int m_min) {
  dd_trig_point P;
  return theorem_root_at(U, P, K, m_min);
}

proof_status prove_minimum_dd_ball(minimum_dd_ball& M, const dd_ball_constants& K, int m_min,
                                   const lobe_frame<int128>& first) {
  const double key = double(lobe_order_key(first, int128(std::int64_t(K.a))));
  M.t_min_paper = mul(mul(K.pi, K.sqrt_ts), K.inv_b);  // pi sqrt(tau sigma)/b
  M.r_res = exact(0.0);
  dd_ball U = exact(0.0);  // degenerate: u* = 0 exactly, r_res = 0 (the theorem's m_min = 0 lobes)
  if (m_min != 0) {
    dd_ball s, c;
    dd_trig_point P;
    GYRORES_TRY_PROOF(theorem_root_at(U, P, K, m_min));
    dd_sin_cos_near(P, U, s, c);
    if (!radius_over(M.r_res, K, s, c)) return proof_status::undecided("r_res: a divisor's ball holds 0");
    if (first.m < 0) U = ddb::neg(U);  // the lobe's minimiser is sign(m) u*
  }
  M.theta_first = mul(scale(add(mul(K.pi, exact(key)), U), 2), K.inv_a);  // 2 (k pi + u)/a
  M.t_first = mul(K.sqrt_ts, M.theta_first);
  M.t_ratio = mul(mul(M.theta_first, exact(K.b)), inverse_pi());  // theta b/pi
  return proof_status::proved();
}

}  // namespace gyrores
