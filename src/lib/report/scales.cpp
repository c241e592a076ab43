// include/gyrores/report/scales.hpp: proved values in the user's units.
#include <gyrores/report/scales.hpp>

#include <algorithm>

#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/report/share.hpp>

namespace gyrores {

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

}  // namespace gyrores
