// Data behind the figures (paper Figs. 1-4): trajectory samples on (q, q'), the analytic
// envelope x_d(phi), the inscribed and maximal circles, H_q(t) and H_z(t), and the Pareto
// scatter. Only data: drawing (gnuplot) lives in the CLI (src/gnuplot.hpp).
//
// Everything here is for plotting, in double. The marked values (r_res, t_first) come from the
// exact solvers (lattice method / degenerate formula for pairs, horizon_minimum for any n); the
// curves are plain samples, accurate to plotting resolution. The maximal circle has radius
// qdot0: H_q(0) = qdot0^2/2 = H, the whole energy, so max sqrt(q^2 + q'^2) = qdot0, attained at
// t = 0 where the trajectory touches the envelope at (0, qdot0).
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <gyrores/design/coupling.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/model/model.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

// Largest pair order the figures sample (64 samples per fast period: 64 (tau + sigma) points).
inline constexpr std::int64_t figure_max_order = 100000;
// Largest number of samples for one curve.
inline constexpr std::size_t figure_max_samples = 2000000;

struct phase_portrait {
  double n = 0, qdot0 = 1;
  bool resonant = false;
  std::int64_t tau = 0, sigma = 0;     // resonant only
  double t_span = 0;                   // trajectory sampled on [0, t_span]
  std::vector<plane_point<double>> trajectory, envelope;
  double r_inscribed = 0;  // resonant: r_res (exact solver); otherwise the min radius over [0, t_span]
  bool inscribed_is_infimum = false;  // resonant: r_inscribed is r_res over all time
  double r_max = 1;        // qdot0 (see header)
  plane_point<double> first_min{0, 0};  // (q, q') at t_first
  double t_first = 0;      // first time the inscribed radius is reached (within [0, t_span])
  double t_proxy = 0;      // pi/|n|
  // Dense samples around each minimiser (one fast period), for a zoomed view: the main
  // trajectory is sampled at plotting resolution only.
  std::vector<std::vector<plane_point<double>>> near_minimisers;
};

// The envelope boundary x_d(phi) (paper eq. boundary) at `samples` + 1 points, phi in [0, 2 pi].
inline std::vector<plane_point<double>> envelope_curve(double n, double v, std::size_t samples) {
  std::vector<plane_point<double>> out;
  const double two_pi = 2 * real_pi<double>();
  for (std::size_t i = 0; i <= samples; ++i) out.push_back(envelope_boundary(n, v, two_pi * double(i) / double(samples)));
  return out;
}

// Phase portrait of a resonant pair over one period theta in [0, 2 pi) (t in [0, 2 pi sqrt(tau sigma)]).
inline phase_portrait phase_portrait_of_pair(const resonant_pair<std::int64_t>& p, double v = 1) {
  if (p.order() > figure_max_order)
    throw usage_error("figures sample pairs up to order " + std::to_string(figure_max_order) + ", got " + p.str());
  auto c = resonant_constants_of<double>(p, v);
  auto r = inscribed_lattice<double>(p, v);
  phase_portrait f;
  f.n = c.n;
  f.qdot0 = v;
  f.resonant = true;
  f.tau = p.tau();
  f.sigma = p.sigma();
  const double two_pi = 2 * c.pi;
  f.t_span = two_pi * c.sqrt_ts;
  const double a = double(p.order()), b = double(p.delta());
  const std::size_t samples = std::size_t(std::max<double>(4000, 64 * a));
  for (std::size_t i = 0; i <= samples; ++i) {
    auto s = resonant_state_at(c, a, b, two_pi * double(i) / double(samples));
    f.trajectory.push_back({s.q, s.qdot});
  }
  f.envelope = envelope_curve(c.n, v, 2000);
  f.r_inscribed = r.r_res;
  f.inscribed_is_infimum = true;
  f.r_max = v;
  auto s = resonant_state_at(c, a, b, r.theta_first);
  f.first_min = {s.q, s.qdot};
  f.t_first = r.t_first;
  f.t_proxy = c.pi / c.n;
  for (double th0 : r.minimisers) {
    std::vector<plane_point<double>> seg;
    for (int i = -1000; i <= 1000; ++i) {
      auto st = resonant_state_at(c, a, b, th0 + c.pi / a * double(i) / 1000);
      seg.push_back({st.q, st.qdot});
    }
    f.near_minimisers.push_back(std::move(seg));
  }
  return f;
}

// Phase portrait for any n > 0 over t in [0, t_span] (the paper's Fig. 1a uses t_span = 200 pi/n).
// The inscribed circle drawn is the minimum radius over [0, t_span] (horizon_minimum); for a
// non-resonant n the infimum over all time is 0 (coupling.hpp).
inline phase_portrait phase_portrait_of_coupling(double n, double v, double t_span) {
  if (!(n > 0)) throw usage_error("the coupling n must be > 0 for a figure");
  if (!(t_span > 0)) throw usage_error("the time span must be > 0");
  auto w = modal_frequencies_of(n);
  const double per_fast = 2 * real_pi<double>() / w.omega1;
  double want = 64 * t_span / per_fast;
  if (want > double(figure_max_samples))
    throw usage_error("the time span is too long to sample (" + std::to_string(static_cast<long long>(want)) +
                      " points, limit " + std::to_string(figure_max_samples) + ")");
  const std::size_t samples = std::size_t(std::max(4000.0, want));
  phase_portrait f;
  f.n = n;
  f.qdot0 = v;
  f.t_span = t_span;
  for (std::size_t i = 0; i <= samples; ++i) {
    auto s = impulse_response(n, v, t_span * double(i) / double(samples));
    f.trajectory.push_back({s.q, s.qdot});
  }
  f.envelope = envelope_curve(n, v, 2000);
  auto hm = horizon_minimum<double>(n, v, t_span);
  f.r_inscribed = std::sqrt(2 * hm.h_min);
  f.first_min = {hm.q, hm.qdot};
  f.t_first = hm.t_min;
  f.r_max = v;
  f.t_proxy = real_pi<double>() / n;
  std::vector<plane_point<double>> seg;
  for (int i = -1000; i <= 1000; ++i) {
    auto st = impulse_response(n, v, hm.t_min + per_fast / 2 * double(i) / 1000);
    seg.push_back({st.q, st.qdot});
  }
  f.near_minimisers.push_back(std::move(seg));
  return f;
}

struct energy_sample {
  double t, h_q, h_z;
};

struct energy_series {
  double n = 0, qdot0 = 1;
  std::vector<energy_sample> samples;
  double t_first = 0;   // exact first-hit time of the minimum (pair: t_first; any n: over the span)
  double h_min = 0;     // the minimum of H_q it marks
  double t_proxy = 0;   // pi/|n| (the paper's proxy)
  double t_end = 0;
};

// H_q(t), H_z(t) on [0, t_end] for a resonant pair (t_end <= 0: one period 2 pi sqrt(tau sigma)).
inline energy_series energy_of_pair(const resonant_pair<std::int64_t>& p, double v = 1, double t_end = 0) {
  if (p.order() > figure_max_order)
    throw usage_error("figures sample pairs up to order " + std::to_string(figure_max_order) + ", got " + p.str());
  auto c = resonant_constants_of<double>(p, v);
  auto r = inscribed_lattice<double>(p, v);
  energy_series e;
  e.n = c.n;
  e.qdot0 = v;
  e.t_end = t_end > 0 ? t_end : 2 * c.pi * c.sqrt_ts;
  const double a = double(p.order()), b = double(p.delta());
  const double theta_end = e.t_end / c.sqrt_ts;
  double want = 64 * a * theta_end / (2 * c.pi);
  if (want > double(figure_max_samples)) throw usage_error("the time span is too long to sample");
  const std::size_t samples = std::size_t(std::max(4000.0, want));
  for (std::size_t i = 0; i <= samples; ++i) {
    double th = theta_end * double(i) / double(samples);
    auto s = resonant_state_at(c, a, b, th);
    e.samples.push_back({th * c.sqrt_ts, (s.q * s.q + s.qdot * s.qdot) / 2, (s.z * s.z + s.zdot * s.zdot) / 2});
  }
  e.t_first = r.t_first;
  e.h_min = r.h_min;
  e.t_proxy = c.pi / c.n;
  return e;
}

// H_q(t), H_z(t) on [0, t_end] for any n > 0; marks the minimum of H_q over [0, t_end].
inline energy_series energy_of_coupling(double n, double v, double t_end) {
  if (!(n > 0)) throw usage_error("the coupling n must be > 0 for a figure");
  if (!(t_end > 0)) throw usage_error("the time span must be > 0");
  auto w = modal_frequencies_of(n);
  double want = 64 * t_end * w.omega1 / (2 * real_pi<double>());
  if (want > double(figure_max_samples)) throw usage_error("the time span is too long to sample");
  const std::size_t samples = std::size_t(std::max(4000.0, want));
  energy_series e;
  e.n = n;
  e.qdot0 = v;
  e.t_end = t_end;
  for (std::size_t i = 0; i <= samples; ++i) {
    double t = t_end * double(i) / double(samples);
    auto s = impulse_response(n, v, t);
    e.samples.push_back({t, energy_q(s), energy_z(s)});
  }
  auto hm = horizon_minimum<double>(n, v, t_end);
  e.t_first = hm.t_min;
  e.h_min = hm.h_min;
  e.t_proxy = real_pi<double>() / n;
  return e;
}

}  // namespace gyrores
