// Helpers shared by the tests and the benchmark: relative error in any real type, the test
// multiplier, a precision scope that is a no-op for the fixed-precision types.
#pragma once
#include <cstdlib>
#include <optional>
#include <string>

#include <gyrores/core/real.hpp>

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
