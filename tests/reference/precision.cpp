// include/gyrores/core/precision.hpp
#include "reference/precision.hpp"

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

unsigned plan_working_bits(const precision_plan& plan) {
  switch (plan.kind) {
    case real_kind::f64: return unsigned(std::numeric_limits<double>::digits);
    case real_kind::f80: return unsigned(std::numeric_limits<long double>::digits);
    case real_kind::f128: return unsigned(std::numeric_limits<float128>::digits);
    case real_kind::mpfr: break;
  }
  for (unsigned k = 0; k < mpfr_ladder_rungs; ++k)
    if (plan.bits <= mpfr_ladder_bits(k)) return mpfr_ladder_bits(k);
  detail::throw_beyond_mpfr_ladder(plan.bits);
}

void detail::throw_beyond_mpfr_ladder(unsigned bits) {
  throw usage_error("an MPFR precision of " + std::to_string(bits) + " bits is beyond the largest working type (" +
                    std::to_string(mpfr_ladder_max_bits) + " bits)");
}

}  // namespace gyrores
