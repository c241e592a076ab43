// include/gyrores/theorem/minimum.hpp: the theorem's minimum in double and as enclosures.
#include <gyrores/theorem/minimum.hpp>

#include <cmath>
#include <numbers>

namespace gyrores {

minimum_double theorem_minimum_double(const resonant_pair<std::int64_t>& p) {
  using L = std::int64_t;
  constexpr double pi = std::numbers::pi;
  const L a = L(p.order()), b = p.delta();
  minimum_double out;
  out.m_min = theorem_m_min(a);
  const double ad = double(a), x = double(b) / ad;
  const double sqrt_ts = std::sqrt(double(p.tau()) * double(p.sigma()));
  if (out.m_min > 0) {
    out.u_star = theorem_root_double(x, pi * out.m_min / (2 * ad));
    // sqrt(G) = x sqrt(1-x^2) t^2/sqrt((1 + t^2)(1 + x^2 t^2)), sqrt(1-x^2) = 2 sqrt(tau sigma)/a.
    const double t = std::tan(out.u_star), t2 = t * t;
    out.r_res = x * (2 * sqrt_ts / ad) * t2 / std::sqrt((1 + t2) * (1 + x * x * t2));
  }
  // (2j+1) a in the lobes' arithmetic reaches 2 a b: int64 below order 2^31 (the sweeps' hot
  // path, where int128's modular inverse costs more), int128 above.
  auto put_lobes = [&](auto A, auto B) {
    for (const auto& f : minimiser_lobes(A, B)) {
      const double u = f.m < 0 ? -out.u_star : out.u_star;
      out.minimisers[out.count] = 2 * (double(lobe_order_key(f, A)) * pi + u) / ad;
      out.lobes[out.count++] = {L(f.k), L(f.j), L(f.m)};  // k < a, j < b, |m| <= 2
    }
  };
  if (a < (L(1) << 31)) put_lobes(a, b);
  else put_lobes(int128(a), int128(b));
  out.theta_first = out.minimisers[0];
  out.t_first = sqrt_ts * out.theta_first;
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
  fixed_mpfi kk(K.prec);
  mpfi_set_z(kk, k.backend().data());
  mpfi_mul(out, K.pi, kk);
  mpfi_add(out, out, U);
  mpfi_mul_2ui(out, out, 1);
  mpfi_div(out, out, K.a);
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
  out.lobes = minimiser_lobes(a, b);
  out.minimisers.clear();
  for (const auto& f : out.lobes) {
    out.minimisers.push_back(std::make_unique<fixed_mpfi>(K.prec));
    minimiser_theta(*out.minimisers.back(), K, a, f, out.u_star.U);
  }
  return true;
}

}  // namespace gyrores
