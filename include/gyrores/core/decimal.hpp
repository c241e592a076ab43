// Decimal input and output with every printed digit accounted for. Nothing here reads or writes
// Boost's process-wide default precision (core/real.hpp), so every function may run on any thread.
#pragma once
#include <mpfr.h>

#include <limits>
#include <string>

#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores {

namespace detail {
// An mpfr_real of exactly `bits` bits holding 0, made without reading Boost's default precision.
inline mpfr_real mpfr_real_of_bits(mpfr_prec_t bits) {
  mpfr_t t;
  mpfr_init2(t, bits);
  mpfr_set_zero(t, 1);
  mpfr_real r{mpfr_real::backend_type(t)};
  mpfr_clear(t);
  return r;
}
}  // namespace detail

// Exact copy of v as an mpfr_real (precision >= the bits of T; mpfr_real and mpfr_fixed: theirs).
template <class T> mpfr_real real_to_mpfr(const T& v) {
  if constexpr (is_mpfr_v<T>) {
    return v;  // copies precision and value
  } else if constexpr (is_mpfr_fixed_v<T>) {
    return mpfr_real{mpfr_real::backend_type(v.backend().data())};  // its precision and value
  } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, long double>) {
    mpfr_real r = detail::mpfr_real_of_bits(68);  // >= the 64 of long double
    mpfr_set_ld(r.backend().data(), static_cast<long double>(v), MPFR_RNDN);
    return r;
  } else if constexpr (std::is_same_v<T, float128>) {
    // Three doubles hold the 113 bits of a float128 exactly (53 + 53 + 53 >= 113).
    double hi = static_cast<double>(v);
    float128 rest = v - float128(hi);
    double mid = static_cast<double>(rest);
    double lo = static_cast<double>(rest - float128(mid));
    mpfr_real acc = detail::mpfr_real_of_bits(666);  // 200 digits: more than the 113 bits of v
    mpfr_set_d(acc.backend().data(), hi, MPFR_RNDN);
    mpfr_add_d(acc.backend().data(), acc.backend().data(), mid, MPFR_RNDN);
    mpfr_add_d(acc.backend().data(), acc.backend().data(), lo, MPFR_RNDN);
    return acc;
  } else {
    // Other binary types (cpp_bin_float): their round-trip text read back at their own bits.
    mpfr_real r = detail::mpfr_real_of_bits(std::numeric_limits<T>::digits);
    mpfr_set_str(r.backend().data(), v.str(0, std::ios_base::scientific).c_str(), 10, MPFR_RNDN);
    return r;
  }
}

// "d.ddd...e+XX" (at least two exponent digits) from the significant digits `digits` (no sign,
// no point, non-empty) and the decimal exponent e10 of the first one; "-" first if negative.
// The one spelling of scientific text (format_scientific, format_rational_scientific).
std::string scientific_text(bool negative, const std::string& digits, long e10);

// Scientific notation d.ddd...e+XX with `digits` significant digits (at least 1), correctly
// rounded in direction `rnd` (MPFR_RNDN: to nearest; MPFR_RNDD/RNDU: down/up, for the ends of
// an enclosure). Zero prints as 0.000...e+00. Precondition: v finite.
std::string format_scientific(const mpfr_real& v, unsigned digits, mpfr_rnd_t rnd = MPFR_RNDN);
std::string format_scientific(mpfr_srcptr v, unsigned digits, mpfr_rnd_t rnd = MPFR_RNDN);

// The rounding to nearest, `digits` significant digits, shared by every value of [lo, hi]:
// true with that text in `out` when lo and hi round alike (rounding is monotone, so then every
// value between them does: this is how a proved enclosure becomes a correctly rounded number);
// false when the interval straddles a rounding boundary (refine it). Precondition: lo <= hi, finite.
bool enclosure_rounding(mpfr_srcptr lo, mpfr_srcptr hi, unsigned digits, std::string& out);

// Parse a decimal integer (optional sign, digits only, any size; leading zeros are decimal, not
// an octal prefix). Throws usage_error naming `what`.
big_int parse_big_int(const std::string& text, const std::string& what);

}  // namespace gyrores
