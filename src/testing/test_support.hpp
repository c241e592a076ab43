// Helpers shared by the tests: relative error in any real type, the test multiplier.
#pragma once
#include <cstdlib>
#include <string>

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

}  // namespace gyrores::test
