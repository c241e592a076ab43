// Certificate data (reference/certificate.hpp).
#include "reference/certificate.hpp"

#include <gyrores/core/decimal.hpp>

namespace gyrores {

std::string cover_bound_text(const mpfr_real& bound, unsigned cover_bits) {
  return format_scientific(bound, certificate_digits_for_bits(cover_bits) + 2, MPFR_RNDU);
}

const certificate_obligation* find_obligation(const certificate& c, const std::string& id) {
  for (auto& o : c.obligations)
    if (o.id == id) return &o;
  return nullptr;
}

}  // namespace gyrores
