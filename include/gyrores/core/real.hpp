// Real types gyrores runs on, and exact-as-possible conversions into them.
//
// Every numerical routine is a template on the real type T. Supported: double, long double,
// float128, cpp_bin_float_*, mpfr_fixed<D> (MPFR with D decimal digits fixed at compile time),
// mpfr_real (MPFR, precision chosen at run time) and, for the proof programs and the tests'
// oracles, mpfi_real (MPFI intervals). The MPFR and MPFI types use expression templates off, so
// `auto` in generic code holds a value, not an expression.
//
// Precision and threads. mpfr_real and mpfi_real take the precision of a new value from a
// process-wide default (Boost 1.74 keeps it in one static variable), and Boost's own operators
// and functions on them set that default for the duration of the call whenever an operand's
// precision differs from it. So mpfr_real and mpfi_real arithmetic is safe on several threads at
// once only while every value has the default precision and nobody changes the default. The
// library never changes it (docs/architecture.md, Conventions; only the tests, the proof programs
// and the benchmarks do, src/testing/test_support.hpp): proved code works on
// fixed_mpfr/fixed_mpfi (core/fixed_precision.hpp) or Arb balls, and generic code that needs a
// chosen MPFR precision runs in mpfr_fixed<D>, whose precision is part of the type.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfi.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include <gyrores/core/integer.hpp>

namespace gyrores {

using float128 = boost::multiprecision::float128;
using mpfr_real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>,
                                                boost::multiprecision::et_off>;
using mpfi_real = boost::multiprecision::number<boost::multiprecision::mpfi_float_backend<0>,
                                                boost::multiprecision::et_off>;

// The real types the compiled part of the library (src/lib/) instantiates: the ones the CLI uses.
// A header lists its instantiations once, as a macro X(PREFIX, T) expanding to declarations
// "PREFIX template R f<T>(...);", and writes GYRORES_FOR_COMPILED_REALS(X, extern) after the
// templates (explicit instantiation declarations: users do not instantiate them again); one .cpp
// in src/lib/ writes GYRORES_FOR_COMPILED_REALS(X, ) (the explicit instantiation definitions).
// Other real types (cpp_bin_float, mpfi_real, ...) are instantiated implicitly where used.
#define GYRORES_FOR_COMPILED_REALS(X, PREFIX) \
  X(PREFIX, double) X(PREFIX, long double) X(PREFIX, ::gyrores::float128) X(PREFIX, ::gyrores::mpfr_real)

// MPFR with D > 0 decimal digits (digits10_2_2(D) bits) fixed by the type: Boost's precision
// guards do nothing for it, so it never reads or writes the process-wide default.
template <unsigned Digits10>
using mpfr_fixed = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<Digits10>,
                                                 boost::multiprecision::et_off>;

template <class T> inline constexpr bool is_mpfr_v = std::is_same_v<T, mpfr_real>;
namespace detail {
template <class T> struct is_mpfr_fixed : std::false_type {};
template <unsigned D>
struct is_mpfr_fixed<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D>,
                                                   boost::multiprecision::et_off>> : std::bool_constant<(D > 0)> {};
}  // namespace detail
template <class T> inline constexpr bool is_mpfr_fixed_v = detail::is_mpfr_fixed<T>::value;
template <class T> inline constexpr bool is_mpfi_v = std::is_same_v<T, mpfi_real>;
template <class T> inline constexpr bool is_variable_precision_v = is_mpfr_v<T> || is_mpfi_v<T>;

// Working precision of T in bits (for mpfr_real/mpfi_real: the current default precision).
template <class T> unsigned real_bits() {
  if constexpr (is_variable_precision_v<T>)
    return unsigned(boost::multiprecision::detail::digits10_2_2(T::default_precision()));
  else
    return unsigned(std::numeric_limits<T>::digits);
}

// Unit roundoff 2^(1 - bits) of T at the current precision.
template <class T> T real_epsilon() {
  using std::ldexp;
  return ldexp(T(1), 1 - int(real_bits<T>()));
}

// ceil(digits log2 10): the bits that carry `digits` decimal digits, with log2(10) rounded up to
// 18 digits in 128-bit integer arithmetic: exact for every precision up to 10^6 digits (checked
// against 60-digit logarithms; tests/test_core.cpp checks a sample).
inline unsigned digits10_to_bits(unsigned digits) {
  constexpr unsigned __int128 log2_10 = 3321928094887362348ull;  // 10^-18 units
  return unsigned((digits * log2_10 + 999999999999999999ull) / 1000000000000000000ull);
}

// pi in T, correctly rounded. mpfr_fixed: by MPFR at each call (MPFR caches pi per thread):
// Boost's pi<T>() for a fixed-precision MPFR type computes pi at that precision when the
// program starts (a static initialiser per type), which large fixed types must not cost every
// process.
template <class T> T real_pi() {
  if constexpr (is_mpfr_fixed_v<T>) {
    T r;
    mpfr_const_pi(r.backend().data(), MPFR_RNDN);
    return r;
  } else {
    return boost::math::constants::pi<T>();
  }
}

// sin x and cos x of one argument, together: the model's lobe-frame evaluations need both of two
// angles. Generic types: std/Boost sin and cos (GCC fuses them into one sincos for double).
// mpfr_real: one fused evaluation by Arb (src/lib/core/real_sin_cos.cpp), results at the current
// default precision and correctly rounded (Ziv's test on Arb's ball, MPFR when undecided), so
// equal to sin(x) and cos(x) bit for bit.
template <class T> struct sin_cos_pair {
  T s, c;
};
template <class T> sin_cos_pair<T> real_sin_cos(const T& x) {
  using std::cos;
  using std::sin;
  return {sin(x), cos(x)};
}
sin_cos_pair<mpfr_real> real_sin_cos(const mpfr_real& x);

template <class T> T real_from_int(const big_int& v);
template <class T> T real_from_int(int128 v) {
  if (v >= std::numeric_limits<std::int64_t>::min() && v <= std::numeric_limits<std::int64_t>::max())
    return T(std::int64_t(v));
  if constexpr (std::is_floating_point_v<T>) return T(v);  // built-in rounding conversion
  else return real_from_int<T>(to_big(v));
}

// Integers to T with one rounding where T allows it (MPFR: exact rounding; double, long double:
// the built-in conversion from int64 or int128 below 2^126; others via decimal text, correctly
// rounded by their parsers).
template <class T> T real_from_int(const big_int& v) {
  if constexpr (is_variable_precision_v<T> || is_mpfr_fixed_v<T>) {
    return T(v);
  } else {
    if (v == 0) return T(0);
    const std::size_t top = mpz_sizeinbase(v.backend().data(), 2) - 1;  // msb(|v|), no temporary
    if (top < 62) return T(std::int64_t(v));
    if constexpr (std::is_floating_point_v<T>)
      if (top < 126) return T(to_int128(v));  // the built-in conversion: one rounding, no text
    if constexpr (std::is_floating_point_v<T>)
      return T(std::stold(v.str()));
    else
      return T(v.str());
  }
}
template <class T> T real_from_int(std::int64_t v) { return T(v); }

// Type name for messages and JSON.
template <class T> std::string real_type_name() {
  if constexpr (std::is_same_v<T, double>) return "double";
  else if constexpr (std::is_same_v<T, long double>) return "long double";
  else if constexpr (std::is_same_v<T, float128>) return "float128";
  else if constexpr (is_mpfr_v<T> || is_mpfr_fixed_v<T>) return "mpfr(" + std::to_string(real_bits<T>()) + " bits)";
  else if constexpr (is_mpfi_v<T>) return "mpfi(" + std::to_string(real_bits<T>()) + " bits)";
  else return "binary" + std::to_string(real_bits<T>());
}

}  // namespace gyrores
