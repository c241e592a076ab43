// include/gyrores/sweep/certified_filter.hpp: a certified double row in double-double balls.
#include <gyrores/sweep/certified_filter.hpp>

#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>

#include <gyrores/core/dd_ball.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores::detail::filter {

using ddb::add;
using ddb::exact;
using ddb::mul;
using ddb::scale;
using ddb::sub;

// ---- why a pair went to the fallback ----
// Counted per outcome and printed to stderr at exit when the environment sets
// GYRORES_FILTER_STATS: a diagnostic for tuning the filter; it changes no row.
namespace {
enum class outcome : int {
  proved, out_of_range, constants, t_min_paper, root, r_res, theta_first, t_first, t_ratio,
  degeneracy_check, asy_bound, asy_difference, asy_columns, count
};
constexpr const char* outcome_names[] = {"proved",      "out of range", "constants",        "t_min_paper",
                                         "u*",          "r_res",        "theta_first",      "t_first",
                                         "t_ratio",     "degeneracy check", "asy bound",    "asy difference",
                                         "asy columns"};
static_assert(std::size(outcome_names) == std::size_t(outcome::count));

struct outcome_counts {
  const bool enabled = std::getenv("GYRORES_FILTER_STATS") != nullptr;
  std::array<std::atomic<std::uint64_t>, std::size_t(outcome::count)> n{};
  ~outcome_counts() {
    if (!enabled) return;
    std::uint64_t total = 0;
    for (const auto& c : n) total += c.load();
    std::fprintf(stderr, "certified filter: %llu pairs, %llu to the fallback\n", (unsigned long long)total,
                 (unsigned long long)(total - n[0].load()));
    for (std::size_t i = 1; i < n.size(); ++i)
      if (n[i].load() != 0) std::fprintf(stderr, "  %-18s %llu\n", outcome_names[i], (unsigned long long)n[i].load());
  }
};
outcome_counts counts;

void record(outcome o) {
  if (counts.enabled) counts.n[std::size_t(o)].fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

// ---- the rounding of a value v known to lie in [A.m - A.r, B.m + B.r] (both ends positive) ----
// With h = A.m.hi = B.m.hi and v = h + e, |e| small: v rounds to h (to nearest) iff e lies in
// (-gb, ga), gb and ga half the spacings below and above h. Each comparison is of doubles: a
// rounded sum c of two doubles is compared through c (1 - 2^-52), at most its exact value.
namespace {
struct spacing {
  double below, above;  // h - prev(h), next(h) - h (exact)
};
spacing spacing_of(double h) {  // h > 0 finite: its neighbours are the adjacent bit patterns
  const auto bits = std::bit_cast<std::uint64_t>(h);
  return {h - std::bit_cast<double>(bits - 1), std::bit_cast<double>(bits + 1) - h};
}
double at_most(double c) { return c * (1 - 0x1p-52); }
}  // namespace

bool round_nearest(const dd_ball& A, const dd_ball& B, double& out) {
  const double h = A.m.hi;
  if (!(h > 0) || B.m.hi != h) return false;
  const spacing g = spacing_of(h);
  if (!(A.r < at_most(A.m.lo + g.below / 2)) || !(B.r < at_most(g.above / 2 - B.m.lo))) return false;
  out = h;
  return true;
}
// Upward: v in (h, next(h)] rounds to next(h), v in (prev(h), h] to h.
bool round_up(const dd_ball& A, const dd_ball& B, double& out) {
  const double h = A.m.hi;
  if (!(h > 0) || B.m.hi != h) return false;
  const spacing g = spacing_of(h);
  if (A.r < A.m.lo && B.r < at_most(g.above - B.m.lo)) {
    out = h + g.above;
    return true;
  }
  if (B.r <= -B.m.lo && A.r < at_most(A.m.lo + g.below)) {
    out = h;
    return true;
  }
  return false;
}
// Downward: v in [h, next(h)) rounds to h, v in [prev(h), h) to prev(h).
bool round_down(const dd_ball& A, const dd_ball& B, double& out) {
  const double h = A.m.hi;
  if (!(h > 0) || B.m.hi != h) return false;
  const spacing g = spacing_of(h);
  if (A.r <= A.m.lo && B.r < at_most(g.above - B.m.lo)) {
    out = h;
    return true;
  }
  if (B.r < -B.m.lo && A.r < at_most(A.m.lo + g.below)) {
    out = h - g.below;
    return true;
  }
  return false;
}

// ---- the pair's constants ----
namespace {
// n/d for integers 0 <= n < 2^53, 0 < d < 2^53 as a ball: dd::quotient is within 2^-104 of it
// relatively (core/double_double.hpp), and n/d <= q.hi (1 + 2^-52). Half the divisions of ddb::div.
dd_ball quotient(double n, double d) {
  const double_double q = dd::quotient(n, d);
  return {q, ddb::up(0x1.0001p-104 * q.hi)};
}
}  // namespace

bool constants_of(constants& K, const resonant_pair<std::int64_t>& p) {
  K.a = double(std::int64_t(p.order()));
  K.b = double(p.delta());
  K.pi = ddb::pi();
  K.x = quotient(K.b, K.a);
  K.x2 = mul(K.x, K.x);
  return ddb::sqrt(K.sqrt_ts, exact(dd::of_int(p.tau() * p.sigma())));  // tau sigma < 2^62: exact
}

trig_point trig_at(const double_double& u) {
  trig_point t{u, {}, {}};
  ddb::sin_cos(exact(u), t.s, t.c);
  return t;
}

// For v = u + t (u = P.u, t in the ball U - u) Taylor's theorem gives |sin v - (sin u + t cos u)|
// <= t^2/2 and |cos v - (cos u - t sin u)| <= t^2/2 (|sin''|, |cos''| <= 1). sin u and cos u lie
// in P's balls, so the ball operations hold sin u + t cos u and cos u - t sin u for every such t,
// and the radii add upper_abs(t)^2/2 (rounded up by `up`). A third of a ball sin_cos's cost.
void sin_cos_near(const trig_point& P, const dd_ball& U, dd_ball& s, dd_ball& c) {
  const dd_ball t = sub(U, exact(P.u));
  const double ta = ddb::upper_abs(t), remainder = ta * ta * 0.5;
  s = add(P.s, mul(P.c, t));
  c = sub(P.c, mul(P.s, t));
  s.r = ddb::up(s.r + remainder);
  c.r = ddb::up(c.r + remainder);
}

// ---- interval Newton ----
// For f with one root z in the ball X = u0 +- rho, f(u0) in the ball fv and f' over X in the ball
// dfX (excluding 0): by the mean value theorem f(u0) = f'(xi) (u0 - z) with xi in X, so z lies in
// N = u0 - fv/dfX; and if N lies inside X, X holds a root (Moore's theorem), so z lies in N.
bool newton_enclosure(dd_ball& out, double u0, double rho, const dd_ball& fv, const dd_ball& dfX) {
  dd_ball q;
  if (!ddb::div(q, fv, dfX)) return false;
  out = sub(exact(u0), q);
  return std::fabs(out.m.hi - u0) * (1 + 0x1p-50) + std::fabs(out.m.lo) + out.r < rho * (1 - 0x1p-50);
}

// ---- step 1: u* ----
// F(u) = x sin u cos w - cos u sin w, w = mu - x u; sign(F) = sign(H(u) - mu) on (0, pi/2), and
// F = 0 only at u*. F' = 2x cos u cos w + (1 + x^2) sin u sin w; |F''| <= 2x (1 + x) +
// (1 + x^2)(1 + x) < 8 (x < 1, dw/du = -x), so F' over u0 +- rho lies within 8 rho of F'(u0).
dd_ball theorem_F(const constants& K, const dd_ball& mu, const trig_point& P, dd_ball* slope) {
  dd_ball sw, cw;
  ddb::sin_cos(sub(mu, mul(K.x, exact(P.u))), sw, cw);
  if (slope) *slope = add(mul(scale(K.x, 2), mul(P.c, cw)), mul(add(exact(1.0), K.x2), mul(P.s, sw)));
  return sub(mul(K.x, mul(P.s, cw)), mul(P.c, sw));
}

namespace {
// theorem_root, and in P the point u0 about which U was proved (radius_over's sines from it).
bool theorem_root_at(dd_ball& U, trig_point& P, const constants& K, int m_min) {
  const dd_ball mu = mul(scale(K.pi, 0.5), quotient(m_min, K.a));  // pi m/(2a)
  double u0;
  try {
    u0 = theorem_root_double(K.x.m.hi, mu.m.hi);
  } catch (const compute_error&) {
    return false;
  }
  if (!(u0 > 0x1p-40 && u0 < 1.5)) return false;
  const double rho = 0x1p-44 * u0;
  dd_ball slope;
  P = trig_at(double_double(u0));
  const dd_ball f0 = theorem_F(K, mu, P, &slope);
  slope.r = ddb::up(slope.r + 8 * rho);
  return newton_enclosure(U, u0, rho, f0, slope) && U.m.hi - U.r > 0 && U.m.hi + U.r < 1.5;
}
}  // namespace

bool theorem_root(dd_ball& U, const constants& K, int m_min) {
  trig_point P;
  return theorem_root_at(U, P, K, m_min);
}

// ---- step 2: the minimum's values ----
namespace {
// 1/a and 1/b as balls, formed once per pair, so that the quotients by a and b below are products.
struct reciprocals {
  dd_ball a, b;
};
dd_ball reciprocal(double n) { return quotient(1.0, n); }
// 1/pi and 1/pi^3, formed once.
const dd_ball& inverse_pi() {
  static const dd_ball v = [] {
    dd_ball q;
    ddb::div(q, exact(1.0), ddb::pi());
    return q;
  }();
  return v;
}
const dd_ball& inverse_pi_cubed() {
  static const dd_ball v = mul(mul(inverse_pi(), inverse_pi()), inverse_pi());
  return v;
}

// r(u) = x sqrt(1-x^2) sin^2 u/sqrt(cos^2 u + x^2 sin^2 u), x sqrt(1-x^2) = 2 b sqrt(tau sigma)/a^2,
// over a ball U given the balls s, c of its sine and cosine.
bool radius_over(dd_ball& r, const constants& K, const reciprocals& R, const dd_ball& s, const dd_ball& c) {
  dd_ball root;
  const dd_ball s2 = mul(s, s);
  if (!ddb::sqrt(root, add(mul(c, c), mul(K.x2, s2)))) return false;
  const dd_ball coefficient = mul(mul(scale(K.sqrt_ts, 2), K.x), R.a);  // 2 sqrt(tau sigma) (b/a)/a
  return ddb::div(r, mul(coefficient, s2), root);
}

struct minimum_values {
  double r_res = 0, theta_first = 0, t_first = 0, t_min_paper = 0, t_ratio = 0;
  bool r_positive = false, r_below_R_half_pi = false;
};

outcome prove_minimum(minimum_values& v, const constants& K, const reciprocals& R, int m_min,
                      const lobe_frame<int128>& first, int128 quarter_R_scaled, bool ratio) {
  const double key = double(lobe_order_key(first, int128(std::int64_t(K.a))));
  const dd_ball tmin = mul(mul(K.pi, K.sqrt_ts), R.b);  // pi sqrt(tau sigma)/b
  if (!round_nearest(tmin, tmin, v.t_min_paper))
    return outcome::t_min_paper;
  dd_ball U = exact(0.0);  // degenerate: u* = 0 exactly, r_res = 0 (the theorem's m_min = 0 lobes)
  if (m_min != 0) {
    dd_ball r, s, c;
    trig_point P;
    if (!theorem_root_at(U, P, K, m_min)) return outcome::root;
    sin_cos_near(P, U, s, c);
    if (!radius_over(r, K, R, s, c) || !round_nearest(r, r, v.r_res)) return outcome::r_res;
    v.r_positive = ddb::positive(r);
    // r_res^2 4 a^2 < 4 a^2 R(pi/2): the ball's square against the exact integer.
    const dd_ball four_a2 = exact(dd::of_int(int128(4) * std::int64_t(K.a) * std::int64_t(K.a)));
    v.r_below_R_half_pi = ddb::positive(sub(exact(dd::of_int(quarter_R_scaled)), mul(mul(r, r), four_a2)));
    if (first.m < 0) U = ddb::neg(U);  // the lobe's minimiser is sign(m) u*
  }
  const dd_ball theta = mul(scale(add(mul(K.pi, exact(key)), U), 2), R.a);  // 2 (k pi + u)/a
  if (!round_nearest(theta, theta, v.theta_first)) return outcome::theta_first;
  const dd_ball tf = mul(K.sqrt_ts, theta);
  if (!round_nearest(tf, tf, v.t_first)) return outcome::t_first;
  if (ratio) {  // theta b/pi
    const dd_ball q = mul(mul(theta, exact(K.b)), inverse_pi());
    if (!round_nearest(q, q, v.t_ratio)) return outcome::t_ratio;
  }
  return outcome::proved;
}

}  // namespace

// ---- step 3: the paper's error ----
// q(u) = (u - s) cos u + sin u = cos u (u + tan u - s), zero only at u_a on (-pi/2, pi/2).
// q' = 2 cos u + (s - u) sin u; |q''| = |-3 sin u + (s - u) cos u| <= 3 + |s - u| < 7 for
// u in (0, 1.5), s <= pi/2.
dd_ball paper_q(const dd_ball& s, const trig_point& P, dd_ball* slope) {
  const dd_ball us = sub(exact(P.u), s);
  if (slope) *slope = sub(scale(P.c, 2), mul(us, P.s));
  return add(mul(us, P.c), P.s);
}

namespace {
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
}  // namespace

// sin y - y cos y over the ball y (|y| < 1/2): Horner over the first N terms, N the fewest whose
// first omitted term is below 2^-75 of the first, plus that term's bound on the rest.
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

// sigma(d) at the point d, with u_a the ball ua (its cosine cua) and t = s - ua. With u = ua + d,
//   sigma' = -x (y sin y + (sec^2 u + 1) cos y + x (T + d) sin y)
// (P'(y) = y sin y, dy/dd = -x, d(T + d)/dd = sec^2 u + 1), and for u <= 1.2 (sec^2 u < 7.7,
// tan u < 2.6), |y| < 1/2, x < 1/2 the bracket's derivative in d is at most 1 (y sin y) +
// 2 sec^2 u tan u + (sec^2 u + 1) x |y| (the second term) + x (sec^2 u + 1) |y| + x^2 |T + d| (the
// third) < 1 + 40 + 2.2 + 2.2 + 1: |sigma''| < 50 x.
bool paper_sigma(dd_ball& out, const constants& K, const dd_ball& t, const dd_ball& ua, const dd_ball& cua,
                 const double_double& d, dd_ball* slope) {
  const dd_ball y = mul(K.x, sub(t, exact(d)));
  dd_ball P;
  if (!sin_minus_y_cos(P, y)) return false;
  dd_ball sd, cd, su, cu, sy, cy;
  ddb::sin_cos(exact(d), sd, cd);
  const dd_ball u = add(ua, exact(d));
  if (!(ddb::upper_abs(u) < 1.19)) return false;  // 1.2 over d0 +- rho_d (asy_d_bracket)
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

bool asy_difference(dd_ball& D, const constants& K, const dd_ball& s) {
  // u_a by interval Newton about the double root.
  double u0;
  try {
    u0 = paper_root_double(s.m.hi);
  } catch (const compute_error&) {
    return false;
  }
  if (!(u0 > 0x1p-40 && u0 < 1.5)) return false;
  const double rho = 0x1p-44 * u0;
  dd_ball slope, ua;
  const trig_point P = trig_at(double_double(u0));
  const dd_ball q0 = paper_q(s, P, &slope);
  slope.r = ddb::up(slope.r + 7 * rho);
  if (!newton_enclosure(ua, u0, rho, q0, slope)) return false;
  const dd_ball t = sub(s, ua);
  dd_ball sua, cua;
  sin_cos_near(P, ua, sua, cua);
  // d = u_c - u_a by interval Newton on sigma(., u_a) about the double estimate.
  const double d0 = sweep_asy_difference(K.x.m.hi, s.m.hi);
  if (!(d0 > 0)) return false;
  const double rho_d = 0x1p-30 * d0;
  dd_ball g0;
  if (!paper_sigma(g0, K, t, ua, cua, double_double(d0), &slope)) return false;
  // u <= 1.2 over d0 +- rho_d too (paper_sigma checked d0 with u_a's ball; rho_d < 2^-30).
  slope.r = ddb::up(slope.r + 50 * ddb::upper_abs(K.x) * rho_d);
  return newton_enclosure(D, d0, rho_d, g0, slope) && ddb::positive(D);
}

namespace {

struct asy_values {
  double error = 0, bound = 0, ratio = 0, constant = 0;
};

outcome prove_asy(asy_values& v, const constants& K, const reciprocals& R, std::int64_t a, std::int64_t b) {
  const auto node = paper_fast_node(a, b);  // the smaller k on a tie
  const std::int64_t m = a - 2 * node.k * b, am = m < 0 ? -m : m;
  const dd_ball bound = mul(mul(mul(mul(K.pi, K.pi), K.pi), K.x2), R.a);  // pi^3 x^2/a
  if (!round_down(bound, bound, v.bound)) return outcome::asy_bound;
  if (am == 0) {  // s = 0: u_c = u_a = 0, every column 0; as the fallback prints the upper end of
    // MPFI's [0, 0], which MPFI holds as [+0, -0]: "-0"
    v.error = v.ratio = v.constant = -0.0;
    return outcome::proved;
  }
  const dd_ball s = scale(mul(mul(K.pi, exact(double(am))), R.b), 0.5);  // pi |m|/(2b)
  dd_ball D;
  if (!asy_difference(D, K, s)) return outcome::asy_difference;
  const dd_ball D2 = scale(D, 2);
  const dd_ball inverse_x = quotient(K.a, K.b);
  const dd_ball c = mul(D2, mul(inverse_x, inverse_x));                // 2d/x^2
  const dd_ball e = mul(D2, R.a), r = mul(c, inverse_pi_cubed());  // 2d/a, 2d/(pi^3 x^2)
  if (!ddb::negative(sub(r, exact(1.0)))) return outcome::asy_columns;  // ratio < 1: the check passes
  if (!round_up(e, e, v.error) || !round_up(r, r, v.ratio) || !round_up(c, c, v.constant)) return outcome::asy_columns;
  return outcome::proved;
}

}  // namespace

}  // namespace gyrores::detail::filter

namespace gyrores::detail {

namespace {

// The minimisers' lobes (theorem/lobes.hpp): minimiser_lobes_euclid's machine-integer Euclid
// gives minimiser_lobes's list (that header's comment; tests/test_double_double.cpp compares
// them) at a tenth of the int128 version's cost; held as int128 frames for the checks. Its
// remainders, cofactors and frames stay below 2a, so int32 serves for a < 2^30 (32-bit divisions
// take half the time of 64-bit ones), int64 above.
template <class L> lobe_list<int128> lobes_as_int128(L a, L b) {
  lobe_list<int128> out;
  for (const auto& f : minimiser_lobes_euclid(a, b)) out.push_back({f.k, f.j, f.m});
  return out;
}
lobe_list<int128> lobes_of(std::int64_t a, std::int64_t b) {
  if (a < (std::int64_t(1) << 30)) return lobes_as_int128(std::int32_t(a), std::int32_t(b));
  return lobes_as_int128(a, b);
}

filter::outcome certified_row(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  using namespace filter;
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  if (a >= (std::int64_t(1) << 31)) return outcome::out_of_range;
  constants K;
  if (!constants_of(K, p)) return outcome::constants;
  const int m_min = theorem_m_min(a);
  const lobe_list<int128> lobes = lobes_of(a, b);
  const int128 quarter = sweep_quarter_R_scaled(a, b);
  const bool degenerate = p.delta_mod4() == 2;
  const reciprocals R{reciprocal(K.a), reciprocal(K.b)};
  minimum_values mv;
  if (const outcome o = prove_minimum(mv, K, R, m_min, lobes.front(), quarter, !degenerate); o != outcome::proved) return o;
  if (!degenerate && !(mv.r_positive && mv.r_below_R_half_pi)) return outcome::degeneracy_check;  // the fallback's
  const bool has_asy = sweep_has_check(cfg.checks, sweep_check::asy_bound) && 2 * b < a;
  asy_values av;
  if (has_asy)
    if (const outcome o = prove_asy(av, K, R, a, b); o != outcome::proved) return o;
  sweep_proved_facts f;
  f.quarter_R_scaled = quarter;
  f.m_min = m_min;
  f.lobes = std::span(lobes.begin(), lobes.size());
  f.r_positive = mv.r_positive;
  f.r_below_R_half_pi = mv.r_below_R_half_pi;
  f.has_asy = has_asy;
  f.asy_proved = has_asy;
  f.asy_within_bound = has_asy;  // prove_asy returns proved only with ratio < 1
  sweep_checks_from_facts(r, p, f, cfg);
  r.r_res = mv.r_res;
  r.theta_first = mv.theta_first;
  r.t_first = mv.t_first;
  r.t_min_paper = mv.t_min_paper;
  if (r.has_ratio) r.t_ratio = mv.t_ratio;
  if (r.has_asy) {
    r.asy_error = av.error;
    r.asy_bound = av.bound;
    r.asy_ratio = av.ratio;
    r.asy_constant = av.constant;
  }
  return outcome::proved;
}

}  // namespace

bool sweep_certified_filter(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  const filter::outcome o = certified_row(r, p, cfg);
  filter::record(o);
  return o == filter::outcome::proved;
}

}  // namespace gyrores::detail
