// include/gyrores/design/figures.hpp
#include <gyrores/design/figures.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {
namespace {

// at(span * i / samples) for i = 0, ..., samples.
template <class F> auto sample_uniform(double span, std::size_t samples, F&& at) {
  std::vector<decltype(at(0.0))> out;
  out.reserve(samples + 1);
  for (std::size_t i = 0; i <= samples; ++i) out.push_back(at(span * double(i) / double(samples)));
  return out;
}

// at(center + half_width * i / 1000) for i = -1000, ..., 1000: the dense samples of the zoom
// around a minimiser.
template <class F> std::vector<plane_point<double>> sample_near(double center, double half_width, F&& at) {
  std::vector<plane_point<double>> seg;
  for (int i = -1000; i <= 1000; ++i) seg.push_back(at(center + half_width * double(i) / 1000));
  return seg;
}

// Max(4000, want) samples; usage_error when want exceeds figure_max_samples.
std::size_t sample_count(double want, const std::string& too_long) {
  if (want > double(figure_max_samples)) throw usage_error(too_long);
  return std::size_t(std::max(4000.0, want));
}

// The samples sorted by t, one per time.
void sort_by_time(std::vector<energy_sample>& samples) {
  std::sort(samples.begin(), samples.end(), [](const energy_sample& x, const energy_sample& y) { return x.t < y.t; });
  samples.erase(std::unique(samples.begin(), samples.end(), [](const energy_sample& x, const energy_sample& y) { return x.t == y.t; }),
                samples.end());
}

// Adds to `samples` (sorted by t) at(t) for t = tm and tm +- half_width / 2^k, k = 0..52, inside
// [0, t_end], for every tm of `times`; then sorts them by t again (duplicates dropped). On a log
// axis the dip around tm is then drawn at every scale, down to its bottom at tm exactly.
template <class F>
void refine_around(std::vector<energy_sample>& samples, const std::vector<double>& times, double half_width, double t_end,
                   F&& at) {
  for (double tm : times) {
    samples.push_back(at(tm));
    double h = half_width;
    for (int k = 0; k <= 52; ++k, h /= 2)
      for (double t : {tm - h, tm + h})
        if (t >= 0 && t <= t_end) samples.push_back(at(t));
  }
  sort_by_time(samples);
}

[[noreturn]] void throw_figure_order(const std::string& pair) {
  throw usage_error("figures sample pairs up to order " + std::to_string(figure_max_order) + ", got " + pair);
}

// p, after checking that figures sample it (order <= figure_max_order; usage_error otherwise).
const resonant_pair<std::int64_t>& figure_pair(const resonant_pair<std::int64_t>& p) {
  if (p.order() > figure_max_order) throw_figure_order(p.str());
  return p;
}

void check_figure_coupling(double n, double span) {
  if (!(n > 0)) throw usage_error("the coupling n must be > 0 for a figure");
  if (!(span > 0)) throw usage_error("the time span must be > 0");
}

// r_res for the amplitude v (r_res is linear in v; the times do not depend on it).
minimum_double scaled(minimum_double m, double v) {
  m.r_res *= v;
  return m;
}

// A pair's constants and minimum (double, the theorem: theorem/minimum.hpp; v scales r_res), and
// its state at theta.
// Throws usage_error beyond figure_max_order.
struct pair_figure_basis {
  resonant_constants<double> c;
  minimum_double r;
  double a, b;  // tau + sigma, tau - sigma
  pair_figure_basis(const resonant_pair<std::int64_t>& p, double v)
      : c(resonant_constants_of<double>(figure_pair(p), v)), r(scaled(theorem_minimum_double(p), v)),
        a(double(p.order())), b(double(p.delta())) {}
  auto state(double theta) const { return resonant_state_at(c, a, b, theta); }
  plane_point<double> point(double theta) const {
    auto s = state(theta);
    return {s.q, s.qdot};
  }
};

// The envelope boundary x_d(phi) (paper eq. boundary) at `samples` + 1 points, phi in [0, 2 pi].
std::vector<plane_point<double>> envelope_curve(double n, double v, std::size_t samples) {
  return sample_uniform(2 * real_pi<double>(), samples, [&](double phi) { return envelope_boundary(n, v, phi); });
}

plane_point<double> impulse_point(double n, double v, double t) {
  auto s = impulse_response(n, v, t);
  return {s.q, s.qdot};
}

}  // namespace

resonant_pair<std::int64_t> figure_pair_of(const resonant_pair<big_int>& p) {
  if (!pair_fits_int64(p) || p.order() > big_int(figure_max_order)) throw_figure_order(p.str());
  return pair_cast<std::int64_t>(p);
}

phase_portrait phase_portrait_of_pair(const resonant_pair<std::int64_t>& p, double v) {
  const pair_figure_basis f0(p, v);
  const auto& c = f0.c;
  phase_portrait f;
  f.n = c.n;
  f.qdot0 = v;
  f.resonant = true;
  f.tau = p.tau();
  f.sigma = p.sigma();
  const double two_pi = 2 * c.pi;
  f.t_span = two_pi * c.sqrt_ts;
  const std::size_t samples = std::size_t(std::max<double>(4000, 64 * f0.a));
  f.trajectory = sample_uniform(two_pi, samples, [&](double th) { return f0.point(th); });
  f.envelope = envelope_curve(c.n, v, 2000);
  f.r_inscribed = f0.r.r_res;
  f.inscribed_is_infimum = true;
  f.r_max = v;
  f.first_min = f0.point(f0.r.theta_first);
  f.t_first = f0.r.t_first;
  f.t_proxy = c.pi / c.n;
  for (std::size_t i = 0; i < f0.r.count; ++i)
    f.near_minimisers.push_back(sample_near(f0.r.minimisers[i], c.pi / f0.a, [&](double th) { return f0.point(th); }));
  return f;
}

phase_portrait phase_portrait_of_coupling(double n, double v, double t_span, const figure_minimum& m) {
  check_figure_coupling(n, t_span);
  auto w = modal_frequencies_of(n);
  const double per_fast = 2 * real_pi<double>() / w.omega1;
  const double want = 64 * t_span / per_fast;
  const std::size_t samples =
      sample_count(want, "the time span is too long to sample (" + std::to_string(static_cast<long long>(want)) +
                             " points, limit " + std::to_string(figure_max_samples) + ")");
  phase_portrait f;
  f.n = n;
  f.qdot0 = v;
  f.t_span = t_span;
  f.trajectory = sample_uniform(t_span, samples, [&](double t) { return impulse_point(n, v, t); });
  f.envelope = envelope_curve(n, v, 2000);
  f.r_inscribed = v * std::sqrt(2 * m.h_min);
  f.first_min = impulse_point(n, v, m.t_min);
  f.t_first = m.t_min;
  f.r_max = v;
  f.t_proxy = real_pi<double>() / n;
  f.near_minimisers.push_back(sample_near(m.t_min, per_fast / 2, [&](double t) { return impulse_point(n, v, t); }));
  return f;
}

energy_series energy_of_pair(const resonant_pair<std::int64_t>& p, double v, double t_end) {
  const pair_figure_basis f0(p, v);
  const auto& c = f0.c;
  energy_series e;
  e.t_end = t_end > 0 ? t_end : 2 * c.pi * c.sqrt_ts;
  e.n = c.n;
  e.qdot0 = v;
  const double theta_end = e.t_end / c.sqrt_ts;
  const std::size_t samples = sample_count(64 * f0.a * theta_end / (2 * c.pi), "the time span is too long to sample");
  const auto at_theta = [&](double th) {
    auto s = f0.state(th);
    return energy_sample{th * c.sqrt_ts, (s.q * s.q + s.qdot * s.qdot) / 2, (s.z * s.z + s.zdot * s.zdot) / 2};
  };
  e.samples = sample_uniform(theta_end, samples, at_theta);
  e.t_first = f0.r.t_first;
  e.h_min = f0.r.r_res * f0.r.r_res / 2;
  e.t_proxy = c.pi / c.n;
  // The minimisers repeat every period 2 pi in theta; t_first is the first of them (theorem/minimum.hpp).
  std::vector<double> thetas;
  for (double period = 0; period <= theta_end; period += 2 * c.pi)
    for (std::size_t i = 0; i < f0.r.count; ++i)
      if (period + f0.r.minimisers[i] <= theta_end) thetas.push_back(period + f0.r.minimisers[i]);
  for (double th : thetas) e.t_minima.push_back(th == f0.r.theta_first ? e.t_first : th * c.sqrt_ts);
  // Refined in theta (the state's own variable), half a fast period around each minimiser.
  std::vector<energy_sample> by_theta;
  refine_around(by_theta, thetas, c.pi / f0.a, theta_end, [&](double th) { return energy_sample{th, 0, 0}; });
  for (const auto& s : by_theta) e.samples.push_back(at_theta(s.t));
  // The samples within rounding of t_first carry the theorem's time, so that curve and mark meet
  // exactly; then one sample per time.
  for (auto& s : e.samples)
    if (std::fabs(s.t - e.t_first) <= 1e-15 * e.t_first) s.t = e.t_first;
  sort_by_time(e.samples);
  return e;
}

energy_series energy_of_coupling(double n, double v, double t_end, const figure_minimum& m) {
  check_figure_coupling(n, t_end);
  auto w = modal_frequencies_of(n);
  const std::size_t samples =
      sample_count(64 * t_end * w.omega1 / (2 * real_pi<double>()), "the time span is too long to sample");
  energy_series e;
  e.n = n;
  e.qdot0 = v;
  e.t_end = t_end;
  const auto at = [&](double t) {
    auto s = impulse_response(n, v, t);
    return energy_sample{t, energy_q(s), energy_z(s)};
  };
  e.samples = sample_uniform(t_end, samples, at);
  e.t_first = m.t_min;
  e.h_min = v * v * m.h_min;
  e.t_proxy = real_pi<double>() / n;
  e.t_minima = {m.t_min};
  refine_around(e.samples, e.t_minima, real_pi<double>() / w.omega1, t_end, at);
  return e;
}

}  // namespace gyrores
