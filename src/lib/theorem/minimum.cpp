// include/gyrores/theorem/minimum.hpp: the theorem's minimum in double and as enclosures.
#include <gyrores/theorem/minimum.hpp>

#include <gyrores/core/double_double.hpp>

namespace gyrores {

GYRORES_DD_FAST minimum_double theorem_minimum_double(const resonant_pair<std::int64_t>& p) {
  using L = std::int64_t;
  const L a = L(p.order()), b = p.delta();
  minimum_double out;
  out.m_min = theorem_m_min(a);
  // r_res, theta_first and t_first in double-double, rounded once at the end: each is within
  // 2^-58 of its exact value before that rounding (theorem/root.hpp, core/double_double.hpp),
  // so within an ulp after it. The other minimisers are plain doubles.
  const bool exact = a < (L(1) << 53);  // a and b are doubles
  const double_double inv_a = exact ? dd::quotient(1, double(a)) : dd::div(1.0, dd::of_int(a));
  const double_double x = exact ? dd::quotient(double(b), double(a)) : dd::mul(inv_a, dd::of_int(b));
  const double_double sqrt_ts = dd::sqrt(dd::of_int(int128(p.tau()) * p.sigma()));
  double_double u;  // u* (0 for degenerate pairs)
  if (out.m_min > 0) {
    const double_double mu = dd::mul(dd::mul(dd::pi, inv_a), 0.5 * out.m_min);
    const root_double_double r = theorem_root_refined(x, mu);
    u = r.u;
    // sqrt(G(u*)) = x sqrt(1-x^2) sin^2 u/sqrt(cos^2 u + x^2 sin^2 u), sqrt(1-x^2) = 2 sqrt(tau sigma)/a.
    const double_double xs2 = dd::mul(x, dd::mul(r.sin_u, r.sin_u));
    const double_double E = dd::add(dd::mul(r.cos_u, r.cos_u), dd::mul(x, xs2));
    out.r_res = dd::div(dd::mul(xs2, dd::mul(sqrt_ts, dd::scale(inv_a, 2))), dd::sqrt(E)).hi;
  }
  out.u_star = u.hi;
  // theta = 2 (key pi + sign(m) u*)/a; (2j+1) a in the lobes' arithmetic reaches 2 a b: int64
  // below order 2^31 (the sweeps' hot path, where int128's modular inverse costs more), int128 above.
  const double two_over_a = 2 / double(a), pi = dd::pi.hi;
  auto put_lobes = [&](auto A, auto B) {
    for (const auto& f : minimiser_lobes(A, B)) {
      const L key = L(lobe_order_key(f, A));
      if (out.count == 0) {
        const double_double key_pi = dd::mul(dd::of_int(key), dd::pi);
        const double_double theta = dd::mul(dd::add(key_pi, f.m < 0 ? dd::neg(u) : u), dd::scale(inv_a, 2));
        out.theta_first = theta.hi;
        out.t_first = dd::mul(sqrt_ts, theta).hi;
      }
      out.minimisers[out.count] = (double(key) * pi + (f.m < 0 ? -u.hi : u.hi)) * two_over_a;
      out.lobes[out.count++] = {L(f.k), L(f.j), L(f.m)};  // k < a, j < b, |m| <= 2
    }
  };
  if (a < (L(1) << 31)) put_lobes(a, b);
  else put_lobes(int128(a), int128(b));
  out.minimisers[0] = out.theta_first;
  return out;
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
