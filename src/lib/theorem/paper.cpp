// include/gyrores/theorem/paper.hpp: the paper's error in its lobe, in double, in MPFI and in
// double-double balls, and the proved upper bound of its constant.
#include <gyrores/theorem/paper.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include <gyrores/core/error.hpp>

namespace gyrores {

// ---- double ----

// With s = pi |m|/(2b) > 0, x < 1/2: f(u) = u + arctan(x tan u)/x - s has the root u_c and
// f' = 1 + (1 + tan^2 u)/(1 + x^2 tan^2 u) >= 2; with t = tan u_a = s - u_a, f(u_a) = -D,
// D = t - arctan(x t)/x = x^2 t^3 sum_n (-1)^n (x t)^(2n)/(2n + 3) (x t < 0.44: prove_paper_error
// below). Newton's method on g(d) = f(u_a + d) = d + arctan(x Dt/(1 + x^2 t t'))/x - D, with
// t' = tan(u_a + d) and Dt = t' - t = sin d/(cos u_a cos(u_a + d)) (no difference of tangents
// is formed), from d = D/f'(u_a); g' = f'(u_a + d), |g''| < 4. Once a step is below 2^-26 d the
// next error is below 2^-52 d.
double paper_difference_double(double x, double s) {
  // u_a to about an ulp: paper_root_double's 4 ulps, then one Newton step on u + tan u - s (its
  // residual is accurate to an ulp of s, and 1/(2 + t^2) < 1/2 of it moves u).
  double ua = paper_root_double(s);
  const double tan_a = std::tan(ua);
  ua -= (ua + tan_a - s) / (2 + tan_a * tan_a);
  // The series' coefficients 1/(2n + 3), once; y2 < 0.2 needs fewer than 30 terms.
  static const std::array<double, 64> inverse_odd = [] {
    std::array<double, 64> c{};
    for (std::size_t n = 0; n < c.size(); ++n) c[n] = 1.0 / double(2 * n + 3);
    return c;
  }();
  const double t = s - ua, y2 = (x * t) * (x * t);
  double sum = 0, power = 1;
  for (std::size_t n = 0; n < inverse_odd.size(); ++n) {
    const double term = power * inverse_odd[n];
    sum += n % 2 ? -term : term;
    if (term <= 0x1p-56 * sum) break;
    power *= y2;
  }
  const double D = x * x * t * t * t * sum, cu = std::cos(ua);
  auto fprime = [x](double tan_u) { return 1 + (1 + tan_u * tan_u) / (1 + x * x * tan_u * tan_u); };
  double d = D / fprime(t);
  for (int it = 0; it < 40; ++it) {
    const double u = ua + d, tu = std::tan(u);
    const double dt = std::sin(d) / (cu * std::cos(u));
    const double g = d + std::atan(x * dt / (1 + x * x * t * tu)) / x - D;
    const double step = g / fprime(tu);
    d -= step;
    if (std::fabs(step) <= 0x1p-26 * d) return d;
  }
  throw compute_error("paper: Newton's method for u_c - u_asy did not converge (x = " + std::to_string(x) +
                      ", s = " + std::to_string(s) + ")");
}

paper_error_double paper_error_of(std::int64_t a, std::int64_t b, std::int64_t am) {
  constexpr double pi = std::numbers::pi;
  const double x = double(b) / double(a), x2 = x * x, pi3 = pi * pi * pi;
  const double d = am == 0 ? 0.0 : paper_difference_double(x, pi * double(am) / double(2 * b));
  paper_error_double v;
  v.constant = 2 * (d / x2);
  v.error = v.constant * x2 / double(a);
  v.bound = pi3 * x2 / double(a);
  v.ratio = v.constant / pi3;
  return v;
}

// paper_constant_bound (theorem/paper.hpp): the constant c = 2 d/x^2 (paper_difference_double),
// d = D/f'(xi) for some xi in [u_a, u_c] with D = x^2 t^3 sum_n (-1)^n (x t)^(2n)/(2n + 3) <=
// x^2 t^3/3 (alternating, decreasing: x t < 1), t = tan u_a, and f'(u) = 1 + (1 + tan^2 u)/(1 +
// x^2 tan^2 u) increasing in u (x < 1), so f'(xi) >= f'(u_a) and, with y = x t,
//   c <= (2 t^3/3) (1 + y^2)/(2 + t^2 + y^2),
// increasing in t (its logarithmic derivative is >= 3/t - 2/t). And t <= t_hi = t_max s/(pi/2)
// = t_max |m|/b: t(s) = s - u_a(s) has t(0) = 0 and dt/ds = (1 + t^2)/(2 + t^2) increasing in t,
// hence in s, so t is convex and below its chord to s = pi/2 (s <= pi/2 as |m| <= b), where
// t_max = tan u_a(pi/2) (tests/test_sweep.cpp checks the rounded-up constant against the
// paper's root). The result: a few roundings (x and |m|/b from reciprocals included), within
// 2^-47 of the bound.

// ---- enclosures ----

// Why 2 log2(a) + 8 extra bits suffice (d = u_c - u_a, both for |m| >= 1, s = pi |m|/(2b),
// x < 1/2): with f, f' and D as in paper_difference_double, f' in [2, 2 + tan^2 u] and D's terms
// alternating and decreasing. As s <= pi/2: u_a < 0.72, t < 0.87, x t < 0.44, so D >= 0.29 x^2 t^3
// and D < 0.06; d = D/f'(xi) for some xi in [u_a, u_c] (mean value theorem), u_c <= u_a + D/2 <
// 0.75, f'(xi) < 2.87, so d >= x^2 t^3/10. With u_a <= t and t >= s/2 >= pi/(4b): d/u_a >=
// x^2 t^2/10 >= pi^2/(160 a^2) > 1/(17 a^2). The two brackets are 2^-(prec - 16) relative about
// u_a ~ u_c, so the difference is 68 a^2 2^-(prec - 16) relative to d: 2 log2(a) + 7 bits lost at
// most.
proof_status prove_paper_error(paper_error_enclosure& E, const theorem_constants& K, std::int64_t am, int narrow_bits) {
  fixed_mpfi d(K.prec);
  if (am == 0) {
    mpfi_set_ui(d, 0);  // s = 0: u_a = u_c = 0 exactly
  } else {
    root_enclosure uc(K.prec), ua(K.prec);
    if (!prove_theorem_root(uc, K, big_int(am))) return proof_status::undecided("u_c: the theorem's root");
    if (!prove_paper_root(ua, K, big_int(am))) return proof_status::undecided("u_a: the paper's root");
    mpfi_sub(d, uc.U, ua.U);
    mpfi_abs(d, d);
    if (!fixed_narrow(d, narrow_bits)) return proof_status::undecided("u_c - u_a: too wide at this precision");
  }
  paper_error_bound(E.error, E.bound, K, d);
  mpfi_div(E.ratio, E.error, E.bound);
  mpfi_mul_2ui(E.constant, d, 1);
  mpfi_div(E.constant, E.constant, K.x2);
  return proof_status::proved();
}

// ---- double-double balls ----

using ddb::add;
using ddb::exact;
using ddb::mul;
using ddb::scale;
using ddb::sub;

namespace {

// q(u) = (u - s) cos u + sin u = cos u (u + tan u - s), zero only at u_a on (-pi/2, pi/2).
// q' = 2 cos u + (s - u) sin u; |q''| = |-3 sin u + (s - u) cos u| <= 3 + |s - u| < 7 for
// u in (0, 1.5), s <= pi/2.
dd_ball paper_q(const dd_ball& s, const dd_trig_point& P, dd_ball* slope) {
  const dd_ball us = sub(exact(P.u), s);
  if (slope) *slope = sub(scale(P.c, 2), mul(us, P.s));
  return add(mul(us, P.c), P.s);
}

// 1/D_n = 2n/(2n+1)!, the coefficients of sin y - y cos y = y^3 sum_{n>=1} (-1)^(n+1) y^(2n-2)/D_n,
// as balls (D_n exact integers; D_10 only bounds the remainder).
constexpr int series_terms = 10;
const std::array<dd_ball, series_terms + 1>& series_coefficients() {
  static const std::array<dd_ball, series_terms + 1> c = [] {
    const std::int64_t D[series_terms + 1] = {0,          3,           30,           840,
                                              45360,      3991680,     518918400,    93405312000,
                                              22230464256000, 6758061133824000, 2554547108585472000};
    std::array<dd_ball, series_terms + 1> out{};
    for (int n = 1; n <= series_terms; ++n) ddb::div(out[std::size_t(n)], exact(1.0), exact(dd::of_int(D[n])));
    return out;
  }();
  return c;
}

// sigma(d) = (sin y - y cos y) - x (T + d) cos y = cos y (tan(x (s - u)) - x tan u) for
// u = u_a + d, y = x (t - d), t = s - u_a = tan u_a and T = tan u - tan u_a = sin d/(cos u_a cos u),
// whose sign is that of u_c - u (H increasing; |y|, |x (s - u)| < pi/2); at the point d, with
// u_a the ball ua (its cosine cua) and t = s - ua. With u = ua + d,
//   sigma' = -x (y sin y + (sec^2 u + 1) cos y + x (T + d) sin y)
// (P'(y) = y sin y, dy/dd = -x, d(T + d)/dd = sec^2 u + 1), and for u <= 1.2 (sec^2 u < 7.7,
// tan u < 2.6), |y| < 1/2, x < 1/2 the bracket's derivative in d is at most 1 (y sin y) +
// 2 sec^2 u tan u + (sec^2 u + 1) x |y| (the second term) + x (sec^2 u + 1) |y| + x^2 |T + d| (the
// third) < 1 + 40 + 2.2 + 2.2 + 1: |sigma''| < 50 x.
bool paper_sigma(dd_ball& out, const dd_ball_constants& K, const dd_ball& t, const dd_ball& ua, const dd_ball& cua,
                 const double_double& d, dd_ball* slope) {
  const dd_ball y = mul(K.x, sub(t, exact(d)));
  dd_ball P;
  if (!sin_minus_y_cos(P, y)) return false;
  dd_ball sd, cd, su, cu, sy, cy;
  ddb::sin_cos(exact(d), sd, cd);
  const dd_ball u = add(ua, exact(d));
  if (!(ddb::upper_abs(u) < 1.19)) return false;  // 1.2 over d0 +- rho_d (paper_difference_dd_ball)
  ddb::sin_cos(u, su, cu);
  ddb::sin_cos(y, sy, cy);
  dd_ball inv;  // 1/(cos u_a cos u)
  if (!ddb::div(inv, exact(1.0), mul(cua, cu))) return false;
  const dd_ball Td = add(mul(sd, inv), exact(d));  // T + d
  if (slope) {
    const dd_ball sec = mul(inv, cua), sec2 = mul(sec, sec);  // 1/cos u, its square
    const dd_ball B = add(add(mul(y, sy), mul(add(sec2, exact(1.0)), cy)), mul(mul(K.x, Td), sy));
    *slope = ddb::neg(mul(K.x, B));
  }
  out = sub(P, mul(mul(K.x, Td), cy));
  return true;
}

}  // namespace

// Horner over the first N terms, N the fewest whose first omitted term is below 2^-75 of the
// first, plus that term's bound on the rest (the terms decrease for |y| < 1, so the first
// omitted one bounds the rest).
bool sin_minus_y_cos(dd_ball& out, const dd_ball& y) {
  const double ya = ddb::upper_abs(y);
  if (!(ya < 0.5)) return false;
  const auto& c = series_coefficients();
  const double y2a = ya * ya;
  int N = 1;
  double power = y2a;  // about y^(2N)
  while (N < series_terms - 1 && power * c[std::size_t(N + 1)].m.hi > 0x1p-77) {
    ++N;
    power *= y2a;
  }
  // The remainder bound c_(N+1) |y|^(2N+3), rounded up step by step.
  double rest = c[std::size_t(N + 1)].m.hi * (1 + 0x1p-50);
  for (int i = 0; i < 2 * N + 3; ++i) rest = ddb::up(rest * ya);
  const dd_ball y2 = mul(y, y);
  dd_ball S = c[std::size_t(N)];
  for (int n = N - 1; n >= 1; --n) S = sub(c[std::size_t(n)], mul(y2, S));
  out = mul(mul(y2, y), S);
  out.r = ddb::up(out.r + rest);
  return true;
}

// u_a by interval Newton on q about the double root; then d by interval Newton on sigma(., u_a)
// about the double estimate, sigma evaluated with u_a a ball holding u_a's bracket.
proof_status paper_difference_dd_ball(dd_ball& D, const dd_ball_constants& K, const dd_ball& s) {
  const auto undecided = proof_status::undecided("u_c - u_a: interval Newton");
  double u0;
  try {
    u0 = paper_root_double(s.m.hi);
  } catch (const compute_error&) {
    return proof_status::no_convergence("u_a: the double root did not converge");
  }
  if (!(u0 > 0x1p-40 && u0 < 1.5)) return proof_status::out_of_domain("u_a: the double root is out of range");
  const double rho = 0x1p-44 * u0;
  dd_ball slope, ua;
  const dd_trig_point P = dd_trig_at(double_double(u0));
  const dd_ball q0 = paper_q(s, P, &slope);
  slope.r = ddb::up(slope.r + 7 * rho);
  if (!dd_newton_enclosure(ua, u0, rho, q0, slope)) return undecided;
  const dd_ball t = sub(s, ua);
  dd_ball sua, cua;
  dd_sin_cos_near(P, ua, sua, cua);
  const double d0 = paper_difference_double(K.x.m.hi, s.m.hi);
  if (!(d0 > 0)) return undecided;
  const double rho_d = 0x1p-30 * d0;
  dd_ball g0;
  if (!paper_sigma(g0, K, t, ua, cua, double_double(d0), &slope)) return undecided;
  // u <= 1.2 over d0 +- rho_d too (paper_sigma checked d0 with u_a's ball; rho_d < 2^-30).
  slope.r = ddb::up(slope.r + 50 * ddb::upper_abs(K.x) * rho_d);
  if (dd_newton_enclosure(D, d0, rho_d, g0, slope) && ddb::positive(D)) return proof_status::proved();
  return undecided;
}

proof_status prove_paper_error_dd_ball(paper_error_dd_ball& E, const dd_ball_constants& K, std::int64_t am) {
  static const dd_ball inverse_pi_cubed = [] {
    dd_ball q;
    ddb::div(q, exact(1.0), mul(mul(ddb::pi(), ddb::pi()), ddb::pi()));
    return q;
  }();
  E.bound = mul(mul(mul(mul(K.pi, K.pi), K.pi), K.x2), K.inv_a);  // pi^3 x^2/a
  dd_ball D = exact(0.0);  // am = 0: s = 0, u_c = u_a = 0
  if (am != 0) {
    const dd_ball s = scale(mul(mul(K.pi, exact(double(am))), K.inv_b), 0.5);  // pi |m|/(2b)
    GYRORES_TRY_PROOF(paper_difference_dd_ball(D, K, s));
  }
  const dd_ball D2 = scale(D, 2), inverse_x = dd_ball_quotient(K.a, K.b);
  E.constant = mul(D2, mul(inverse_x, inverse_x));       // 2d/x^2
  E.error = mul(D2, K.inv_a);                            // 2d/a
  E.ratio = mul(E.constant, inverse_pi_cubed);           // 2d/(pi^3 x^2)
  return proof_status::proved();
}

}  // namespace gyrores
