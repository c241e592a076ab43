// The interval Newton of tests/reference/interval_newton.hpp.
#include "reference/interval_newton.hpp"

#include "reference/interval.hpp"

namespace gyrores {

namespace {

mpfr_real width(const mpfi_real& x) { return interval_upper(x) - interval_lower(x); }

// N(X) = m - f(m)/f'(X), or nullopt when f'(X) may vanish (no step is possible).
std::optional<mpfi_real> newton_image(const interval_function& f, const interval_function& df, const mpfi_real& X) {
  mpfi_real m = interval_mid(X);
  mpfi_real dfX = df(X);
  if (!certainly_nonzero(dfX)) return std::nullopt;
  return mpfi_real(m - f(m) / dfX);
}

}  // namespace

std::optional<mpfi_real> interval_newton(const interval_function& f, const interval_function& df,
                                         const mpfr_real& guess, const mpfr_real& scale, int max_steps) {
  mpfr_real radius = ldexp(scale, -int(real_bits<mpfr_real>()) + 12);
  mpfi_real X = interval_of(guess - radius, guess + radius);
  bool proved = false;
  for (int step = 0; step < max_steps; ++step) {
    auto N = newton_image(f, df, X);
    if (!N) break;
    if (certainly_inside(*N, X)) {
      // Accepted: N(X) inside the interior of X proves the root; N(X) = N(X) ∩ X is the new X.
      proved = true;
      mpfi_real next = interval_intersect(*N, X);
      bool shrinks = width(next) < width(X);
      X = next;
      if (!shrinks) break;  // no progress left at this precision
    } else if (proved) {
      break;  // keep the last accepted enclosure
    } else {
      radius *= 4;  // the guess is too far for this radius: widen and retry
      X = interval_of(guess - radius, guess + radius);
    }
  }
  if (!proved) return std::nullopt;
  return X;
}

}  // namespace gyrores
