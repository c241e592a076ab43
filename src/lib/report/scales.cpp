// include/gyrores/report/scales.hpp: proved values in the user's units.
#include <gyrores/report/scales.hpp>

#include <algorithm>

#include <gyrores/core/fixed_precision.hpp>

namespace gyrores {

enclosure scaled(const enclosure& e, const big_rational& k) {
  if (e.is_exact()) return enclosure::exact(e.lo_rational() * k);
  // k > 0 keeps the order of the ends; 64 more bits than the ends keep the product's width small.
  const mpfr_prec_t bits = std::max(mpfr_get_prec(e.lo()), mpfr_get_prec(e.hi())) + 64;
  exact_binary lo(bits), hi(bits);
  mpfr_mul_q(lo.get(), e.lo(), k.backend().data(), MPFR_RNDD);
  mpfr_mul_q(hi.get(), e.hi(), k.backend().data(), MPFR_RNDU);
  return enclosure(lo, hi);
}

enclosure scaled_sqrt(const enclosure& e, const big_rational& k2, mpfr_prec_t bits) {
  if (const auto k = rational_sqrt(k2)) return scaled(e, *k);
  const mpfr_prec_t prec = (e.is_exact() ? bits : std::max(mpfr_get_prec(e.lo()), mpfr_get_prec(e.hi()))) + 64;
  fixed_mpfi v(prec), k(prec);
  if (e.is_exact()) mpfi_set_q(v, e.lo_rational().backend().data());
  else mpfi_interv_fr(v, e.lo(), e.hi());
  mpfi_set_q(k, k2.backend().data());
  mpfi_sqrt(k, k);
  mpfi_mul(v, v, k);
  return enclosure(v);
}

big_rational share_factor(const big_rational& qdot0) { return big_rational(200) / (qdot0 * qdot0); }

}  // namespace gyrores
