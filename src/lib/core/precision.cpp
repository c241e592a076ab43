// include/gyrores/core/precision.hpp
#include <gyrores/core/precision.hpp>

namespace gyrores {

std::string precision_plan::name() const {
  switch (kind) {
    case real_kind::f64: return "double";
    case real_kind::f80: return "long double";
    case real_kind::f128: return "float128";
    case real_kind::mpfr: return "mpfr";
  }
  return "?";
}

precision_plan plan_for_digits(unsigned digits, bool needs_mpfr) {
  if (!needs_mpfr) {
    if (digits <= 11) return {real_kind::f64, 53};
    if (digits <= 15) return {real_kind::f80, 64};
    if (digits <= 29) return {real_kind::f128, 113};
  }
  // ceil(D log2 10) + 24 (the same as the former floor(D * 3.32192809488736) + 25: D log2 10 is
  // never an integer).
  return {real_kind::mpfr, digits10_to_bits(digits) + 24};
}

}  // namespace gyrores
