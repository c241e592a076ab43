// src/testing/reference.hpp: the double scan (steps 1-2).
#include "testing/reference.hpp"

#include <cmath>
#include <stdexcept>

namespace gyrores::ref {

namespace {

// The local minimum of R in the grid interval [theta_i, theta_{i+1}], where dR goes from - (dlo)
// to + (dhi): Illinois false position on dR, ~6-10 evaluations to a step below 1e-8 of the grid
// step, which puts R within 4 tau^2 v^2 (1e-8 h)^2 < 1e-15 v^2 of the local minimum.
double locate_minimum(const naive_model<double>& m, double lo, double hi, double dlo, double dhi) {
  test::illinois_bracket br{lo, hi, dlo, dhi};
  const double h = hi - lo;
  double c = lo;
  for (int it = 0; it < 60; ++it) {
    const double prev = c;
    c = br.next();
    br.update(c, m.dR(c));
    if (std::fabs(c - prev) < 1e-8 * h || br.hi - br.lo < 1e-8 * h) break;
  }
  return c;
}

}  // namespace

scan_result scan_minima(std::int64_t tau, std::int64_t sigma, int points_per_order) {
  naive_model<double> m(tau, sigma);
  const std::int64_t n = std::int64_t(points_per_order) * (tau + sigma);
  std::vector<double> d(std::size_t(n + 1));
  for (std::int64_t i = 0; i <= n; ++i) d[std::size_t(i)] = m.dR(grid_theta<double>(i, n));
  scan_result out{n, {}, 0};
  for (std::int64_t i = 0; i < n; ++i) {
    const double dlo = d[std::size_t(i)], dhi = d[std::size_t(i + 1)];
    if (!(dlo < 0 && dhi >= 0)) continue;
    const double th = locate_minimum(m, grid_theta<double>(i, n), grid_theta<double>(i + 1, n), dlo, dhi);
    const double r = m.R(th);
    if (out.minima.empty() || r < out.min_radius_sq) out.min_radius_sq = r;
    out.minima.push_back({i, th, r});
  }
  if (out.minima.empty()) throw std::logic_error("reference scan found no local minimum");
  return out;
}

}  // namespace gyrores::ref
