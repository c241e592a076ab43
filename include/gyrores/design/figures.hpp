// Data behind the figures (paper Figs. 1-3): trajectory samples on (q, q'), the analytic
// envelope x_d(phi), the inscribed and maximal circles, H_q(t) and H_z(t). Only data: what a
// figure shows is chosen in the application layer (app/figures.hpp, also the Pareto figure's
// points), drawing (gnuplot) lives beside the CLI (src/frontend/plots.hpp).
//
// Everything here is for plotting, in double. The marked values (r_res, t_first) come from the
// exact solvers (the lattice theorem in double for pairs, theorem/minimum.hpp; horizon_minimum
// for any n); the
// curves are plain samples, accurate to plotting resolution. The maximal circle has radius
// qdot0: H_q(0) = qdot0^2/2 = H, the whole energy, so max sqrt(q^2 + q'^2) = qdot0, attained at
// t = 0 where the trajectory touches the envelope at (0, qdot0).
#pragma once
#include <cstdint>
#include <vector>

#include <gyrores/model/model.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// Largest pair order the figures sample (64 samples per fast period: 64 (tau + sigma) points).
inline constexpr std::int64_t figure_max_order = 100000;
// Largest number of samples for one curve.
inline constexpr std::size_t figure_max_samples = 2000000;

// p as the figures take it (64-bit integers); usage_error beyond figure_max_order.
resonant_pair<std::int64_t> figure_pair_of(const resonant_pair<big_int>& p);

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

// Phase portrait of a resonant pair over one period theta in [0, 2 pi) (t in [0, 2 pi sqrt(tau sigma)]).
// Throws usage_error beyond figure_max_order.
phase_portrait phase_portrait_of_pair(const resonant_pair<std::int64_t>& p, double v = 1);

// The minimum of H_q over a coupling figure's span for qdot0 = 1 and its first time: the horizon
// theorem's (app/figures.hpp proves them; the figures scale h_min by qdot0^2).
struct figure_minimum {
  double t_min = 0, h_min = 0;
};

// Phase portrait for any n > 0 over t in [0, t_span] (the paper's Fig. 1a uses t_span = 200 pi/n).
// The inscribed circle drawn is the minimum radius over [0, t_span], `m`; for a non-resonant n
// the infimum over all time is 0 (model/coupling.hpp). Throws usage_error for n <= 0, t_span <= 0
// or more than figure_max_samples samples.
phase_portrait phase_portrait_of_coupling(double n, double v, double t_span, const figure_minimum& m);

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
  // Every time in [0, t_end] at which H_q takes the marked minimum h_min, t_first included (a
  // pair: each minimiser of the theorem in every period; any n: t_first alone). The samples are
  // refined around each (a geometric sequence of offsets down to rounding, the time itself
  // included), so that the drawn curve reaches its marks even where the dip is far narrower
  // than the uniform spacing (n = 2 over [0, 50]: a dip to 1.4e-7 between samples 0.01 apart).
  std::vector<double> t_minima;
};

// H_q(t), H_z(t) on [0, t_end] for a resonant pair (t_end <= 0: one period 2 pi sqrt(tau sigma)).
// Throws usage_error beyond figure_max_order or figure_max_samples.
energy_series energy_of_pair(const resonant_pair<std::int64_t>& p, double v = 1, double t_end = 0);

// H_q(t), H_z(t) on [0, t_end] for any n > 0; marks the minimum m of H_q over [0, t_end].
// Throws usage_error for n <= 0, t_end <= 0 or more than figure_max_samples samples.
energy_series energy_of_coupling(double n, double v, double t_end, const figure_minimum& m);

}  // namespace gyrores
