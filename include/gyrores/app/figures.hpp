// The application layer (include/gyrores/app/pair.hpp): the data of the figures, for
// `gyrores plot`, `gyrores pareto --plot`, the report's figures and gyrores.plot. What a phase or
// energy figure shows and over which span (design/figures.hpp), and which points the Pareto
// figure draws. Plotting data, in double (design/figures.hpp says which marks are exact).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <gyrores/design/design.hpp>
#include <gyrores/design/figures.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores::app {

// What a phase or energy figure shows: a resonant pair, or a coupling that is not resonant.
struct figure_subject {
  std::optional<resonant_pair<std::int64_t>> pair;
  double n = 0;                           // the coupling |n| > 0, without a pair
  std::optional<coupling_spec> coupling;  // that coupling exactly (its marks are the horizon theorem's)
};

// A pair (usage_error beyond figure_max_order); a coupling given exactly is its pair when it is
// resonant (coupling_resonant_pair), else |n|.
figure_subject figure_subject_of(const resonant_pair<big_int>& p);
figure_subject figure_subject_of(const coupling_spec& c);

// A pair over one period; a coupling over [0, span] (0: 200 pi/n, the paper's Figure 1a), its
// inscribed circle and marks the horizon theorem's minimum over the span (the span read exactly).
phase_portrait phase_figure(const figure_subject& s, double qdot0 = 1, double span = 0);
// H_q(t) and H_z(t) over [0, t_end] (0: one period of a pair, 8 pi/n for a coupling).
energy_series energy_figure(const figure_subject& s, double qdot0 = 1, double t_end = 0);

// Above this many pairs the Pareto figure thins the pairs it scatters to one per cell of 2 x 2
// pixels in the plot's log coordinates (a vector image of every pair of order 5000, 7.6 million
// points, was 395 MB; thinned it stays under a few MB and looks the same). The front is never thinned.
inline constexpr std::size_t pareto_thin_above = 50000;

// The points of a Pareto figure `width` x `height` pixels, in the time `which`.
struct pareto_figure_points {
  std::size_t pairs = 0;               // every pair given (thinned when more than pareto_thin_above)
  double t_lo = 0, t_hi = 0;           // the range of their times
  std::vector<design_point> positive, zeros;              // the pairs scattered: r_res > 0, r_res = 0
  std::vector<design_point> front_positive, front_zeros;  // the front, split the same way
  std::vector<design_point> labelled;  // the front's pairs named: its ends, then steps of half a decade in r_res
};
pareto_figure_points pareto_figure_points_of(const std::vector<design_point>& all, const std::vector<design_point>& front,
                                             design_time which, int width, int height);

}  // namespace gyrores::app
