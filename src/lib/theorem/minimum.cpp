// include/gyrores/theorem/minimum.hpp: the theorem's minimum in double and as enclosures.
#include <gyrores/theorem/minimum.hpp>

#include <gyrores/core/double_double.hpp>
#include <gyrores/core/error.hpp>

#include "root_refined.hpp"

namespace gyrores {

namespace {

// 1/d for a double d (|d| < 2^53 an integer here, so nothing underflows) within 2^-105 (1 +
// 2^-52) relative, by a multiplication where dd::quotient divides again: q = RN(1/d) has |1/d -
// q| <= 2^-53 |q|, and its remainder r = 1 - q d is a double (the remainder of a correctly
// rounded quotient), formed exactly by one fma, |r| <= 2^-53 |d q| <= 2^-53 (1 + 2^-53). Then
// 1/d = q + r/d, and RN(r q) differs from r/d by |r| |q - 1/d| <= 2^-106 (1 + 2^-53) |q| plus
// its rounding, below the same; the last fast_two_sum is exact.
GYRORES_DD_INLINE double_double reciprocal(double d) {
  const double q = 1 / d;
  return dd::fast_two_sum(q, __builtin_fma(-q, d, 1) * q);
}

// x + y for |y| <= |x|/4 (no cancellation): the high parts by an exact two_sum, the low parts
// added to its error in double (two roundings, each below u^2 (|x| + |y| + |x + y|) <= u^2 10/3
// |x + y|): within 7 u^2 = 2^-103.2 relative (JMP's sloppy sum, bounded here by |y| <= |x|/4).
GYRORES_DD_INLINE double_double add_dominant(const double_double& x, const double_double& y) {
  const double_double s = dd::two_sum(x.hi, y.hi);
  return dd::fast_two_sum(s.hi, s.lo + (x.lo + y.lo));
}

// sqrt(x) for a double-double x > 0 (normal, |x.lo| <= ulp(x.hi)/2) within 4.2 u^2 relative,
// u = 2^-53: s = RN(sqrt(x.hi)), whose remainder e = x.hi - s^2 is a double formed exactly by one
// fma (the remainder of a correctly rounded square root), |e| <= (ulp(s)/2) (2s + ulp(s)/2) <=
// 2u s^2 (1 + u); then sqrt(x) = s + R/(2s) - R^2/(8 s^3) + ..., R = e + x.lo, |R| <= 3u s^2 (1 +
// 2u). The terms: R's rounding 3u^2 s^2/(2s) = 1.5u^2 s, the quotient's 1.5u^2 s, the dropped
// second order 9u^2 s/8: 4.125u^2 s (1 + 8u). (dd::sqrt forms R by a double-double sum: 4u^2,
// about 15 instructions more.)
GYRORES_DD_INLINE double_double sqrt_lean(const double_double& x) {
  const double s = std::sqrt(x.hi);
  return dd::fast_two_sum(s, (__builtin_fma(-s, s, x.hi) + x.lo) / (2 * s));
}

// The double path for a pair held in machine integers I (int64 for orders below 2^62, int128
// below 2^120).
//
// Error budget (each quantity in double-double, then rounded once to a double): 1/a and x = b/a
// are within 2^-104 and 2^-103 relative for a < 2^53 (reciprocal above, then one mul by the
// exact b, <= 2u^2) and within 2^-98
// above (a and b converted with relative error <= 2^-106, core/double_double.hpp of_int, then
// one div <= 15u^2 + 56u^3 and one mul <= 7u^2, u = 2^-53), mu = pi m/(2a) within 2^-97. The root
// u* moves by at most the relative perturbation of mu plus that of x: H(0) = 0 and H convex
// give mu <= u* H'(u*), so (mu/u*) du*/dmu = mu/(u* H') <= 1; and (x/u*) |du*/dx| =
// (x u + x t/(1 + x^2 t^2))/(u H') <= 1 since t <= u (1 + t^2) (tan u <= u sec^2 u). So the
// computed u* is within 2^-60 + 2^-95 relative of the exact pair's (theorem/root.hpp), and
// r_res, theta_first, t_first are within 2^-58 of their exact values before the last rounding
// (the argument is below, where they are formed), so within an ulp after it.
// Always inlined: each target clone of the callers below gets its own (FMA or not) code.
template <class I> GYRORES_DD_INLINE minimum_double_of<I> minimum_in(const I& tau, const I& sigma) {
  const I a = I(tau + sigma), b = I(tau - sigma);
  minimum_double_of<I> out;
  out.count = minimiser_lobes_euclid_into(a, b, out.lobes);
  out.m_min = theorem_m_min(a);
  if (out.count == 2) {  // the entries past the count are 0 (theorem/minimum.hpp)
    out.minimisers[2] = out.minimisers[3] = 0;
    out.lobes[2] = out.lobes[3] = {0, 0, 0};
  }
  const bool small = a < (I(1) << 53);  // a, b, tau and sigma are exact doubles
  const double_double inv_a = small ? reciprocal(double(a)) : dd::div(1.0, dd::of_int(a));
  // tau sigma: exact (two_prod of exact doubles), or a double-double product (7u^2).
  const double_double ts = small ? dd::two_prod(double(tau), double(sigma)) : dd::mul(dd::of_int(tau), dd::of_int(sigma));
  const double_double sqrt_ts = sqrt_lean(ts);
  if (out.m_min == 0) {  // r_res = 0 at theta = pi/2 and 3 pi/2 (correctly rounded: pi's double halved)
    const double_double half_pi = dd::scale(dd::pi, 0.5);
    out.u_star = out.r_res = 0;
    out.theta_first = half_pi.hi;
    out.t_first = dd::mul(sqrt_ts, half_pi).hi;
    out.minimisers = {half_pi.hi, dd::mul(dd::pi, 1.5).hi, 0, 0};
    return out;
  }
  const double_double x = small ? dd::mul(inv_a, double(b)) : dd::mul(inv_a, dd::of_int(b));
  const double_double mu = dd::scale(dd::mul(dd::pi, inv_a), 0.5 * out.m_min);
  // The root's start from the integers where they are exact doubles (x ~ b (1/a)'s high part,
  // mu/(2x) = pi m/(4b)): ready before x and mu are, whose double-double steps it would wait for.
  const double x_rough = small ? double(b) * inv_a.hi : x.hi;
  const double v = small ? (0.25 * out.m_min * dd::pi.hi) / double(b) : mu.hi / (2 * x.hi);
  const double_double two_over_a = dd::scale(inv_a, 2);
  const double_double s1 = dd::mul(sqrt_ts, two_over_a);  // sqrt(1 - x^2) = 2 sqrt(tau sigma)/a
  // theta = 2 (k pi + sign(m) u*)/a (k of the first lobe; k >= 1 and u* <= pi/4, so the sum is
  // add_dominant's) and t_first = sqrt(tau sigma) theta = (k pi + sign(m) u*) sqrt(1 - x^2).
  const lobe_frame<I>& first = out.lobes[0];
  const double_double k_pi = small ? dd::mul(dd::pi, double(first.k)) : dd::mul(dd::of_int(first.k), dd::pi);
  // The accepted Newton step (theorem/root_refined.hpp): u* = u + delta within 2^-61 u, and every
  // output formed at u, with delta entering last (the chain from the step's division to the
  // outputs is one multiply-add). r_res = s1 S(u*), S(t) = sin t sin(mu - x t), which is
  // stationary at the root: S' = -F, S'' = -(1 + x^2) S - 2x cos t cos w, and F(u*) = 0 gives
  // |F(u)| <= |u* - u| max F', so |S(u*) - S(u)| <= (u* - u)^2 (max F' + max |S''|/2) <= (u* -
  // u)^2 (3x cos u cos w + 3S) (1 + 2^-30). With S >= 0.86 x u^2 (sin t >= 0.9 t for t <= pi/4,
  // w >= x u near the root: H(u) >= 2xu), that is below 2^-67.3 S through the table (|u* - u|
  // <= 2^-35 u) and 2^-58.4 S by the small step (2^-30 u). So with sin u and sin w at u (within
  // 2^-63 each, or 2^-67 and 2^-66.4) r_res is within 2^-58.3 before its rounding. theta: k pi +
  // sign(m) u in double-double, then sign(m) delta (2/a) added to its low part: the error 2^-61
  // u (2/a) is below 2^-62.5 theta (k pi - u >= 3u); t_first likewise with sqrt(1 - x^2).
  const detail::root_step st = detail::root_step_of(x, mu, x_rough, v);
  out.r_res = dd::mul(s1, dd::mul(st.sin_u, st.sin_w)).hi;
  const double sd = first.m < 0 ? -st.delta : st.delta;
  const double_double arc = add_dominant(k_pi, double_double(first.m < 0 ? -st.u : st.u));
  const double_double th = dd::mul(arc, two_over_a), tf = dd::mul(arc, s1);
  out.theta_first = th.hi + __builtin_fma(sd, two_over_a.hi, th.lo);
  out.t_first = tf.hi + __builtin_fma(sd, s1.hi, tf.lo);
  const double u_star = st.u + st.delta;
  out.u_star = u_star;
  // The other minimisers: plain doubles (a few ulps).
  out.minimisers[0] = out.theta_first;
  for (std::size_t i = 1; i < out.count; ++i) {
    const lobe_frame<I>& f = out.lobes[i];
    const double k = small ? double(f.k) : dd::of_int(f.k).hi;  // (no int128 conversion call)
    out.minimisers[i] = (k * dd::pi.hi + (f.m < 0 ? -u_star : u_star)) * two_over_a.hi;
  }
  return out;
}

template <class I> minimum_double_of<I> narrowed(const minimum_double_of<int128>& m) {
  minimum_double_of<I> out{m.m_min, m.u_star, m.r_res, m.theta_first, m.t_first, m.minimisers, {}, m.count};
  for (std::size_t i = 0; i < 4; ++i) out.lobes[i] = {I(m.lobes[i].k), I(m.lobes[i].j), I(m.lobes[i].m)};
  return out;
}

// int64 pairs of order 2^62 and above, in int128 (out of line: the hot path below keeps a
// small frame; one version, without FMA clones: Clang refuses target_clones on a noinline
// function, and the fused multiply-adds are exact either way, through the C library's fma).
[[gnu::noinline]] minimum_double minimum_wide(const resonant_pair<std::int64_t>& p) {
  if (p.order() >= (int128(1) << 63)) throw usage_error("theorem_minimum_double: pair " + p.str() + " has order >= 2^63");
  return narrowed<std::int64_t>(minimum_in<int128>(p.tau(), p.sigma()));
}

}  // namespace

GYRORES_DD_FAST minimum_double theorem_minimum_double(const resonant_pair<std::int64_t>& p) {
  // tau > sigma, so tau < 2^61 keeps the order below 2^62 (one comparison, no int128 sum).
  if (p.tau() < (std::int64_t(1) << 61)) return minimum_in<std::int64_t>(p.tau(), p.sigma());  // the sweeps' hot path
  return minimum_wide(p);
}

GYRORES_DD_FAST minimum_double_of<int128> theorem_minimum_double(const resonant_pair<big_int>& p) {
  // The order from the int128 halves (p.order() would allocate a big_int): tau > sigma, so
  // tau < 2^120 makes the conversions exact and the sum below 2^121.
  const bool fits = boost::multiprecision::msb(p.tau()) < 120;
  const int128 tau = fits ? to_int128(p.tau()) : 0, sigma = fits ? to_int128(p.sigma()) : 0;
  if (!fits || tau + sigma >= (int128(1) << 120))
    throw usage_error("theorem_minimum_double: pair " + p.str() + " has order >= 2^120");
  return minimum_in<int128>(tau, sigma);
}

void minimiser_theta(fixed_mpfi& out, const theorem_constants& K, const big_int& a, const lobe_frame<big_int>& f,
                     const fixed_mpfi& U) {
  fixed_mpfi u(K.prec);
  if (f.m < 0) mpfi_neg(u, U);
  else mpfi_set(u, U);
  lobe_theta(out, K, lobe_order_key(f, a), u);
}

void lobe_theta(fixed_mpfi& out, const theorem_constants& K, const big_int& k, const fixed_mpfi& U) {
  mpfi_mul_z(out, K.pi, k.backend().data());  // by the integers: O(prec) each
  mpfi_add(out, out, U);
  mpfi_mul_2ui(out, out, 1);
  mpfi_div_z(out, out, K.ai.backend().data());
}

proof_status prove_minimum(minimum_enclosure& out, const theorem_constants& K, const resonant_pair<big_int>& p,
                           const fixed_mpfi& v) {
  const big_int a = p.order(), b = big_int(p.delta());
  const int m_min = p.strand_offset_min();
  if (m_min == 0) {
    mpfi_set_ui(out.r_res, 0);
    mpfi_set_ui(out.u_star.U, 0);
  } else {
    GYRORES_TRY_PROOF(prove_theorem_root(out.u_star, K, big_int(m_min)));
    theorem_radius(out.r_res, K, out.u_star.T);
    mpfi_mul(out.r_res, out.r_res, v);
  }
  mpfi_sqr(out.h_min, out.r_res);
  mpfi_div_2ui(out.h_min, out.h_min, 1);
  mpfi_sqr(out.h_z_max, v);
  mpfi_div_2ui(out.h_z_max, out.h_z_max, 1);
  mpfi_sub(out.h_z_max, out.h_z_max, out.h_min);
  out.lobes = minimiser_lobes_big(a, b).to_vector();
  out.minimisers.clear();
  for (const auto& f : out.lobes) {
    out.minimisers.push_back(std::make_unique<fixed_mpfi>(K.prec));
    minimiser_theta(*out.minimisers.back(), K, a, f, out.u_star.U);
  }
  return proof_status::proved();
}

}  // namespace gyrores
