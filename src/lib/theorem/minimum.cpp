// include/gyrores/theorem/minimum.hpp: the theorem's minimum in double and as enclosures.
#include <gyrores/theorem/minimum.hpp>

#include <gyrores/core/double_double.hpp>
#include <gyrores/core/error.hpp>

namespace gyrores {

namespace {

// The double path for a pair held in machine integers I (int64 for orders below 2^62, int128
// below 2^120).
//
// Error budget (each quantity in double-double, then rounded once to a double): 1/a and x = b/a
// are within 2^-104 and 2^-103 relative for a < 2^53 (dd::quotient of exact doubles, then one mul
// by the exact b, <= 2u^2) and within 2^-98
// above (a and b converted with relative error <= 2^-106, core/double_double.hpp of_int, then
// one div <= 15u^2 + 56u^3 and one mul <= 7u^2, u = 2^-53), mu = pi m/(2a) within 2^-97. The root
// u* moves by at most the relative perturbation of mu plus that of x: H(0) = 0 and H convex
// give mu <= u* H'(u*), so (mu/u*) du*/dmu = mu/(u* H') <= 1; and (x/u*) |du*/dx| =
// (x u + x t/(1 + x^2 t^2))/(u H') <= 1 since t <= u (1 + t^2) (tan u <= u sec^2 u). So the
// computed u* is within 2^-60 + 2^-95 relative of the exact pair's (theorem/root.hpp), and
// r_res, theta_first, t_first are within 2^-58 of their exact values before the last rounding
// (r_res below; theta = 2 (k pi +- u*)/a with k pi - u* >= u*), so within an ulp after it.
// Always inlined: each target clone of the callers below gets its own (FMA or not) code.
template <class I> GYRORES_DD_INLINE minimum_double_of<I> minimum_in(const I& tau, const I& sigma) {
  const I a = I(tau + sigma), b = I(tau - sigma);
  minimum_double_of<I> out;
  out.count = minimiser_lobes_euclid_into(a, b, out.lobes);
  out.m_min = theorem_m_min(a);
  const bool small = a < (I(1) << 53);  // a, b, tau and sigma are exact doubles
  const double_double inv_a = small ? dd::quotient(1, double(a)) : dd::div(1.0, dd::of_int(a));
  // tau sigma: exact (two_prod of exact doubles), or a double-double product (7u^2).
  const double_double ts = small ? dd::two_prod(double(tau), double(sigma)) : dd::mul(dd::of_int(tau), dd::of_int(sigma));
  const double_double sqrt_ts = dd::sqrt(ts);
  if (out.m_min == 0) {  // r_res = 0 at theta = pi/2 and 3 pi/2 (correctly rounded: pi's double halved)
    const double_double half_pi = dd::scale(dd::pi, 0.5);
    out.theta_first = half_pi.hi;
    out.t_first = dd::mul(sqrt_ts, half_pi).hi;
    out.minimisers = {half_pi.hi, dd::mul(dd::pi, 1.5).hi};
    return out;
  }
  const double_double x = small ? dd::mul(inv_a, double(b)) : dd::mul(inv_a, dd::of_int(b));
  const double_double mu = dd::scale(dd::mul(dd::pi, inv_a), 0.5 * out.m_min);
  const root_double_double r = theorem_root_refined(x, mu);
  const double_double& u = r.u;
  out.u_star = u.hi;
  // r_res = sqrt(1-x^2) sin u* sin w*, w* = mu - x u*: at the root x tan u = tan w, so E =
  // cos^2 u + x^2 sin^2 u = cos^2 u/cos^2 w and sqrt(G) = x sqrt(1-x^2) sin^2 u/sqrt(E) =
  // sqrt(1-x^2) sin u (x sin u cos w/cos u) = sqrt(1-x^2) sin u sin w (no division, no square
  // root). sin u* within 2^-60 and sin w* within 2^-59.7 (theorem/root.hpp) and sqrt(1-x^2) =
  // 2 sqrt(tau sigma)/a within 2^-97 give r_res within 2^-58.8 before its rounding.
  const double_double two_over_a = dd::scale(inv_a, 2);
  const double_double s1 = dd::mul(sqrt_ts, two_over_a);  // sqrt(1 - x^2)
  out.r_res = dd::mul(s1, dd::mul(r.sin_u, r.sin_w)).hi;
  // theta = 2 (k pi + sign(m) u*)/a (k of the first lobe; k >= 1, so k pi - u* > pi/2) and
  // t_first = sqrt(tau sigma) theta = (k pi + sign(m) u*) sqrt(1 - x^2).
  const lobe_frame<I>& first = out.lobes[0];
  const double_double k_pi = dd::mul(dd::of_int(first.k), dd::pi);
  const double_double arc = dd::add(k_pi, first.m < 0 ? dd::neg(u) : u);
  out.theta_first = dd::mul(arc, two_over_a).hi;
  out.t_first = dd::mul(arc, s1).hi;
  // The other minimisers: plain doubles (a few ulps).
  out.minimisers[0] = out.theta_first;
  for (std::size_t i = 1; i < out.count; ++i) {
    const lobe_frame<I>& f = out.lobes[i];
    const double k = small ? double(f.k) : dd::of_int(f.k).hi;  // (no int128 conversion call)
    out.minimisers[i] = (k * dd::pi.hi + (f.m < 0 ? -u.hi : u.hi)) * two_over_a.hi;
  }
  return out;
}

template <class I> minimum_double_of<I> narrowed(const minimum_double_of<int128>& m) {
  minimum_double_of<I> out;
  out.m_min = m.m_min;
  out.u_star = m.u_star;
  out.r_res = m.r_res;
  out.theta_first = m.theta_first;
  out.t_first = m.t_first;
  out.minimisers = m.minimisers;
  out.count = m.count;
  for (std::size_t i = 0; i < m.count; ++i) out.lobes[i] = {I(m.lobes[i].k), I(m.lobes[i].j), I(m.lobes[i].m)};
  return out;
}

}  // namespace

GYRORES_DD_FAST minimum_double theorem_minimum_double(const resonant_pair<std::int64_t>& p) {
  const int128 a = p.order();
  if (a < (int128(1) << 62)) return minimum_in<std::int64_t>(p.tau(), p.sigma());  // the sweeps' hot path
  if (a >= (int128(1) << 63)) throw usage_error("theorem_minimum_double: pair " + p.str() + " has order >= 2^63");
  return narrowed<std::int64_t>(minimum_in<int128>(p.tau(), p.sigma()));
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

bool prove_minimum(minimum_enclosure& out, const theorem_constants& K, const resonant_pair<big_int>& p,
                   const fixed_mpfi& v) {
  const big_int a = p.order(), b = big_int(p.delta());
  const int m_min = p.strand_offset_min();
  if (m_min == 0) {
    mpfi_set_ui(out.r_res, 0);
    mpfi_set_ui(out.u_star.U, 0);
  } else {
    if (!prove_theorem_root(out.u_star, K, big_int(m_min))) return false;
    theorem_radius(out.r_res, K, out.u_star.T);
    mpfi_mul(out.r_res, out.r_res, v);
  }
  mpfi_sqr(out.h_min, out.r_res);
  mpfi_div_2ui(out.h_min, out.h_min, 1);
  mpfi_sqr(out.h_z_max, v);
  mpfi_div_2ui(out.h_z_max, out.h_z_max, 1);
  mpfi_sub(out.h_z_max, out.h_z_max, out.h_min);
  out.lobes = minimiser_lobes(a, b).to_vector();
  out.minimisers.clear();
  for (const auto& f : out.lobes) {
    out.minimisers.push_back(std::make_unique<fixed_mpfi>(K.prec));
    minimiser_theta(*out.minimisers.back(), K, a, f, out.u_star.U);
  }
  return true;
}

}  // namespace gyrores
