// The number of resonant pairs of one order, for the tests of the enumeration (model/enumerate.hpp)
// and of the sweep's counts.
#pragma once
#include <cstdint>

namespace gyrores {

// Number of pairs with order exactly a: phi(a)/2 for a >= 3 (each coprime s < a/2 counts once).
inline std::int64_t coprime_pairs_of_order(std::int64_t a) {
  if (a < 3) return 0;
  std::int64_t n = a, phi = a;
  for (std::int64_t p = 2; p * p <= n; ++p)
    if (n % p == 0) {
      while (n % p == 0) n /= p;
      phi -= phi / p;
    }
  if (n > 1) phi -= phi / n;
  return phi / 2;
}

}  // namespace gyrores
