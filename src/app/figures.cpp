// include/gyrores/app/figures.hpp
#include <gyrores/app/figures.hpp>

#include <algorithm>
#include <cmath>

#include <gyrores/app/coupling.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores::app {
namespace {

// The pairs of `all` with r_res = 0 (`zeros`) or > 0: every one, or above pareto_thin_above
// pairs one per cell of a (w/2) x (h/2) grid over [log t] x [log r] (over [log t] alone for the zeros).
std::vector<design_point> scattered(const std::vector<design_point>& all, design_time which, int w, int h, bool zeros) {
  std::vector<design_point> pts;
  for (const auto& p : all)
    if ((p.r_res == 0) == zeros) pts.push_back(p);
  if (all.size() <= pareto_thin_above || pts.empty()) return pts;
  double t0 = 1e300, t1 = 0, r0 = 1e300, r1 = 0;
  for (const auto& p : pts) {
    const double t = design_time_of(p, which);
    t0 = std::min(t0, t), t1 = std::max(t1, t);
    if (!zeros) r0 = std::min(r0, p.r_res), r1 = std::max(r1, p.r_res);
  }
  const int cx = std::max(1, w / 2), cy = zeros ? 1 : std::max(1, h / 2);
  const auto cell = [](double v, double lo, double hi, int n) {
    if (!(hi > lo)) return 0;
    return std::clamp(int((std::log(v) - std::log(lo)) / (std::log(hi) - std::log(lo)) * n), 0, n - 1);
  };
  std::vector<char> taken(std::size_t(cx) * std::size_t(cy), 0);
  std::vector<design_point> kept;
  for (const auto& p : pts) {
    const int i = cell(design_time_of(p, which), t0, t1, cx), j = zeros ? 0 : cell(p.r_res, r0, r1, cy);
    char& c = taken[std::size_t(j) * std::size_t(cx) + std::size_t(i)];
    if (!c) kept.push_back(p), c = 1;
  }
  return kept;
}

// The minimum of H_q over [0, span] (qdot0 = 1), proved by the horizon theorem, as doubles.
figure_minimum theorem_minimum(const coupling_spec& c, double span) {
  if (!std::isfinite(span)) throw usage_error("the time span must be finite");
  const coupling_doubles d = run_coupling_doubles(c, horizon_time(big_rational(span)), std::nullopt, {});
  return {d.t_min, d.h_min};
}

}  // namespace

figure_subject figure_subject_of(const resonant_pair<big_int>& p) { return {figure_pair_of(p)}; }

figure_subject figure_subject_of(const coupling_spec& c) {
  if (const auto p = coupling_resonant_pair(c)) return figure_subject_of(*p);
  return {std::nullopt, c.abs_n<double>(), c};
}

phase_portrait phase_figure(const figure_subject& s, double qdot0, double span) {
  if (s.pair) return phase_portrait_of_pair(*s.pair, qdot0);
  if (!(span > 0)) span = 200 * real_pi<double>() / s.n;
  return phase_portrait_of_coupling(s.n, qdot0, span, theorem_minimum(*s.coupling, span));
}

energy_series energy_figure(const figure_subject& s, double qdot0, double t_end) {
  if (s.pair) return energy_of_pair(*s.pair, qdot0, t_end);
  if (!(t_end > 0)) t_end = 8 * real_pi<double>() / s.n;
  return energy_of_coupling(s.n, qdot0, t_end, theorem_minimum(*s.coupling, t_end));
}

pareto_figure_points pareto_figure_points_of(const std::vector<design_point>& all, const std::vector<design_point>& front,
                                             design_time which, int width, int height) {
  pareto_figure_points f;
  f.pairs = all.size();
  f.t_lo = 1e300;
  for (const auto& p : all) {
    const double t = design_time_of(p, which);
    f.t_lo = std::min(f.t_lo, t), f.t_hi = std::max(f.t_hi, t);
  }
  f.positive = scattered(all, which, width, height, false);
  f.zeros = scattered(all, which, width, height, true);
  double last = 0;
  for (std::size_t i = 0; i < front.size(); ++i) {
    const design_point& p = front[i];
    if (p.r_res == 0) f.front_zeros.push_back(p);
    if (!(p.r_res > 0)) continue;
    f.front_positive.push_back(p);
    if (f.labelled.empty() || i + 1 == front.size() || std::fabs(std::log10(p.r_res) - last) >= 0.5)
      f.labelled.push_back(p), last = std::log10(p.r_res);
  }
  return f;
}

}  // namespace gyrores::app
