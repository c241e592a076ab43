// include/gyrores/report/share.hpp: energies as shares of H_q(0), proved.
#include <gyrores/report/share.hpp>

#include <algorithm>

namespace gyrores {

big_rational share_factor(const big_rational& qdot0) { return big_rational(200) / (qdot0 * qdot0); }

enclosure scaled(const enclosure& e, const big_rational& k) {
  if (e.is_exact()) return enclosure::exact(e.lo_rational() * k);
  // k > 0 keeps the order of the ends; 64 more bits than the ends keep the product's width small.
  const mpfr_prec_t bits = std::max(mpfr_get_prec(e.lo()), mpfr_get_prec(e.hi())) + 64;
  exact_binary lo(bits), hi(bits);
  mpfr_mul_q(lo.get(), e.lo(), k.backend().data(), MPFR_RNDD);
  mpfr_mul_q(hi.get(), e.hi(), k.backend().data(), MPFR_RNDU);
  return enclosure(lo, hi);
}

}  // namespace gyrores
