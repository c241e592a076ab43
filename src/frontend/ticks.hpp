// Tick marks for the figures' axes (frontend/plots.hpp), chosen here rather than by gnuplot: every
// axis of every panel gets at least three labelled ticks whatever its range (gnuplot's automatic
// ticks give a log axis spanning less than two decades one label or none, and a list written
// `set xtics (expr)` is a single tick). tests/test_figures.cpp counts the labels in the images.
#pragma once
#include <string>
#include <vector>

namespace gyrores::frontend {

struct tick {
  double at;
  std::string label;  // gnuplot enhanced text ("0.5", "300", "10^{-3}", "3·10^{-3}")
};

// Ticks on a linear axis [lo, hi] (lo < hi): the multiples of the largest step 1, 2 or 5 x 10^k
// that puts at least `at_least` of them in the range (so at most about 2.5 times as many): 4
// for a full-width axis, 3 for a narrow panel.
std::vector<tick> linear_ticks(double lo, double hi, int at_least = 4);

// Ticks on a log axis [lo, hi] (0 < lo < hi): the powers of ten inside when there are at least
// three (every k-th one above six), else m x 10^k for m in {1, 3}, then {1, 2, 5}, then 1..9,
// and linear ticks (three at least) when the range is narrower still.
std::vector<tick> log_ticks(double lo, double hi);

// `set AXIStics (...)`: the ticks with their labels, or with no labels (a panel sharing the axis
// of the panel below: `labelled` false). AXIS is "x", "y", "x2" or "y2"; `font` is appended
// (e.g. `font ",9"`) when not empty.
std::string tics_command(const std::string& axis, const std::vector<tick>& ticks, bool labelled = true,
                         const std::string& font = "");

}  // namespace gyrores::frontend
