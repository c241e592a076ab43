// Helpers shared by the tests, the benchmark and the proof programs: the default precision of
// mpfr_real and mpfi_real set for a scope, binary <-> decimal digits, relative error in any real
// type, the test multiplier, a precision scope that is a no-op for the fixed-precision types.
#pragma once
#include <cstdlib>
#include <optional>
#include <string>

#include <gyrores/core/real.hpp>

namespace gyrores {

// Sets the default decimal precision of mpfr_real and mpfi_real for a scope, restoring it after.
// Boost 1.74 keeps this default in one process-wide variable, so this is for single-threaded
// programs only: the library never uses it (core/real.hpp); the tests' oracles, the proof
// programs and the benchmarks do.
class scoped_digits {
 public:
  explicit scoped_digits(unsigned digits10)
      : old_r_(mpfr_real::default_precision()), old_i_(mpfi_real::default_precision()) {
    mpfr_real::default_precision(digits10);
    mpfi_real::default_precision(digits10);
  }
  ~scoped_digits() {
    mpfr_real::default_precision(old_r_);
    mpfi_real::default_precision(old_i_);
  }
  scoped_digits(const scoped_digits&) = delete;
  scoped_digits& operator=(const scoped_digits&) = delete;

 private:
  unsigned old_r_, old_i_;
};

// floor(bits log10 2): the decimal digits that `bits` bits always carry (log10(2) rounded down
// to 18 digits: exact up to 3 * 10^6 bits, like digits10_to_bits in core/real.hpp).
inline unsigned bits_to_digits10(unsigned bits) {
  constexpr unsigned __int128 log10_2 = 301029995663981195ull;  // 10^-18 units
  return unsigned(bits * log10_2 / 1000000000000000000ull);
}
// p/q in T (two integer roundings and one division: relative error <= 1.5 ulp).
template <class T, class I> T real_from_ratio(const I& p, const I& q) {
  return real_from_int<T>(p) / real_from_int<T>(q);
}
// Decimal digits to request from MPFR (whose precision Boost sets in digits) so that it carries
// at least `bits` bits.
inline unsigned digits10_for_bits(unsigned bits) { return bits_to_digits10(bits) + 1u; }

}  // namespace gyrores

namespace gyrores::test {

// GYRORES_TEST_MULTIPLIER scales randomised loops (default 1; CI or nightly runs can raise it).
inline int multiplier() {
  const char* s = std::getenv("GYRORES_TEST_MULTIPLIER");
  int m = (s && *s) ? std::atoi(s) : 1;
  return m < 1 ? 1 : m;
}

// |x - ref| / |ref| (or |x| when ref == 0), in T.
template <class T> T rel_error(const T& x, const T& ref) {
  using std::fabs;
  if (ref == 0) return fabs(x);
  return fabs((x - ref) / ref);
}

// The default precision of mpfr_real and mpfi_real set to `digits` decimal digits for the scope
// when `variable` (the working type is mpfr_real or mpfi_real), nothing otherwise; e.g.
// precision_scope s(is_variable_precision_v<T>, 50) in code templated on the real type T.
class precision_scope {
 public:
  precision_scope(bool variable, unsigned digits) {
    if (variable) scope_.emplace(digits);
  }

 private:
  std::optional<scoped_digits> scope_;
};

}  // namespace gyrores::test
