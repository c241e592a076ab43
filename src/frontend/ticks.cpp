// src/frontend/ticks.hpp
#include "frontend/ticks.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "frontend/gnuplot.hpp"

namespace gyrores::frontend {
namespace {

// %g of a tick value, with the rounding noise of k * step removed (0.30000000000000004 -> 0.3).
std::string plain(double v, double step) {
  if (std::fabs(v) < 1e-9 * step) v = 0;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  const std::string s = buf;
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  // "4e-05" -> "4·10^{-5}" (enhanced text, as the log axes write their labels)
  return s.substr(0, e) + "·10^{" + std::to_string(std::stoi(s.substr(e + 1))) + "}";
}

// m x 10^k as gnuplot enhanced text: "10^{k}" for m = 1, "m·10^{k}" otherwise; plain digits
// from 1 to 900 ("1", "3", "10", "300").
std::string power_label(int m, int k) {
  if (k >= 0 && k <= 2) return std::to_string(m * (k == 2 ? 100 : k == 1 ? 10 : 1));
  const std::string p = "10^{" + std::to_string(k) + "}";
  return m == 1 ? p : std::to_string(m) + "·" + p;
}

}  // namespace

std::vector<tick> linear_ticks(double lo, double hi, int at_least) {
  std::vector<tick> out;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return out;
  // Steps m x 10^e from the range's own decade down: the first with `at_least` multiples inside.
  const int e0 = int(std::ceil(std::log10(hi - lo)));
  for (int e = e0; e > e0 - 4 && out.empty(); --e)
    for (int m : {5, 2, 1}) {
      const double step = m * std::pow(10.0, e);
      const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
      if (last - first + 1 < at_least) continue;
      for (double i = first; i <= last; ++i) out.push_back({i * step, plain(i * step, step)});
      break;
    }
  return out;
}

std::vector<tick> log_ticks(double lo, double hi) {
  std::vector<tick> out;
  if (!(lo > 0) || !(hi > lo) || !std::isfinite(hi)) return out;
  const double eps = 1e-9;
  const int k0 = int(std::ceil(std::log10(lo) - eps)), k1 = int(std::floor(std::log10(hi) + eps));
  if (k1 - k0 + 1 >= 3) {
    const int stride = (k1 - k0) / 6 + 1;  // at most seven labels
    for (int k = k0; k <= k1; k += stride) out.push_back({std::pow(10.0, k), power_label(1, k)});
    return out;
  }
  const std::vector<std::vector<int>> mantissas = {{1, 3}, {1, 2, 5}, {1, 2, 3, 4, 5, 6, 7, 8, 9}};
  for (const auto& ms : mantissas) {
    out.clear();
    for (int k = k0 - 1; k <= k1; ++k)
      for (int m : ms) {
        const double v = m * std::pow(10.0, k);
        if (v >= lo * (1 - eps) && v <= hi * (1 + eps)) out.push_back({v, power_label(m, k)});
      }
    if (out.size() >= 3) return out;
  }
  return linear_ticks(lo, hi, 3);
}

std::string tics_command(const std::string& axis, const std::vector<tick>& ticks, bool labelled, const std::string& font) {
  std::ostringstream g;
  g << "set " << axis << "tics (";
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    char at[40];
    std::snprintf(at, sizeof at, "%.10g", ticks[i].at);
    g << (i ? ", " : "") << gnuplot_string(labelled ? ticks[i].label : "") << " " << at;
  }
  g << ")";
  if (!font.empty()) g << " " << font;
  return g.str() + "\n";
}

}  // namespace gyrores::frontend
