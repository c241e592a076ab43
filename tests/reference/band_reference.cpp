// tests/reference/band_reference.hpp
#include "reference/band_reference.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gyrores::reference {

namespace {

constexpr double pi = std::numbers::pi;

double H(double x, double u) { return x * u + std::atan2(x * std::sin(u), std::cos(u)); }

// H_x^{-1}(c), c in [0, (1 + x) pi/2], by bisection on [0, pi/2].
double H_inverse(double x, double c) {
  double lo = 0, hi = pi / 2;
  for (int i = 0; i < 200 && hi - lo > 1e-17; ++i) {
    const double m = (lo + hi) / 2;
    (H(x, m) < c ? lo : hi) = m;
  }
  return (lo + hi) / 2;
}

// G with 1 - x^2 given (4/(n^2 + 4): formed from x it cancels as x -> 1).
double G(double x, double one_minus_x2, double u) {
  const double s = std::sin(u), c = std::cos(u);
  return one_minus_x2 * x * x * s * s * s * s / (c * c + x * x * s * s);
}

// R = q^2 + q'^2 at time t (qdot0 = 1), from q = rho0 (sin W1 t + sin W2 t) and
// q' = rho0 (W1 cos W1 t + W2 cos W2 t).
double R(double n, double t) {
  const double s = std::sqrt(n * n + 4), w1 = (s + n) / 2, w2 = 2 / (s + n), rho0 = 1 / s;
  const double q = rho0 * (std::sin(w1 * t) + std::sin(w2 * t));
  const double qd = rho0 * (w1 * std::cos(w1 * t) + w2 * std::cos(w2 * t));
  return q * q + qd * qd;
}

}  // namespace

double band_minimum(double n, double T) {
  const double s = std::sqrt(n * n + 4), x = n / s, one_minus_x2 = 4 / (n * n + 4), alpha_T = s * T / 2;
  const long kc = long(std::floor(alpha_T / pi + 0.5));
  // Every lobe k < kc is inside [0, T] (lobe 0 by its u >= 0 half); lobe kc when its minimiser is.
  double best_nu = 2;
  for (long k = 0; k <= kc; ++k) {
    const double y = double(k) * x - 0.5, nu = k == 0 ? 0.5 : std::fabs(y - std::round(y));
    if (k == kc) {
      const double mu = (0.5 - (double(k) * x - std::floor(double(k) * x))) * pi;
      const double u = k == 0 ? H_inverse(x, pi / 2) : (mu >= 0 ? 1 : -1) * H_inverse(x, std::fabs(mu));
      const double side_u = (k >= 1 && std::fabs(std::fabs(mu) - pi / 2) < 1e-15) ? -std::fabs(u) : u;
      if (double(k) * pi + side_u > alpha_T) continue;
    }
    best_nu = std::min(best_nu, nu);
  }
  const double lobes = best_nu > 1 ? INFINITY : G(x, one_minus_x2, H_inverse(x, pi * best_nu));
  return std::min(lobes, R(n, T)) / 2;
}

double band_first_below(double n, double E, double t_max, double step) {
  if (R(n, 0) <= 2 * E) return 0;
  for (double t = step; t <= t_max; t += step) {
    // A narrow dip between two samples: also look at the sample's local minimum by a few golden
    // steps when R rises after falling.
    if (R(n, t) <= 2 * E) {
      double lo = t - step, hi = t;
      for (int i = 0; i < 100; ++i) {
        const double m = (lo + hi) / 2;
        (R(n, m) <= 2 * E ? hi : lo) = m;
      }
      return hi;
    }
  }
  return -1;
}

}  // namespace gyrores::reference
