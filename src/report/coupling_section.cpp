// The report's Section 7: couplings that are not resonant (the paper's Fig. 1a uses n = 2).
// (a) the minimum of H_q over [0, T] against T up to 10^12, and (b) the first time H_q falls to
// 1% of its initial value against n, resonant pairs marked. Every point is proved by the horizon
// theorem (theorem/horizon.hpp, proofs/horizon-theorem.md); the plotted doubles are read from the
// proved decimal strings, and every number printed in the markdown is such a string.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numeric>
#include <set>
#include <sstream>

#include <gyrores/model/coupling.hpp>
#include <gyrores/report/horizon_report.hpp>

#include "frontend/gnuplot.hpp"
#include "report/sections.hpp"

namespace gyrores::report {
namespace {

// (a): the horizons, 24 per decade from 1 to 10^12 (4 significant digits, exact decimals), and
// the couplings drawn: n = 2 (Fig. 1a; x = 1/sqrt 2 = [0; 1, 2, 2, ...]) and n = 0.1832 (a
// decimal of issue 23's measurements, whose k ||k x - 1/2|| varies widely on the records: uneven steps).
constexpr int horizon_per_decade = 24, horizon_decades = 12;
const char* const horizon_couplings[] = {"2", "0.1832"};

// (b): 240 decimal couplings from 0.05 to 5, evenly spaced in log n (4 significant digits), the
// table's, and every resonant pair with tau + sigma <= this order whose n lies in that range.
constexpr int absorb_samples = 240, absorb_pair_order = 16;
const char* const absorb_level_text = "1/200";  // 1% of H_q(0) = 1/2: 99% of the energy absorbed

// Decimal text of a number with 4 significant digits ("1778", "1.778e+05", "0.05"): parsed exactly.
std::string four_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string lobe_str(const std::optional<horizon_lobe>& l) { return l ? l->k.str() : std::string("-"); }

// The horizon texts: 10^(j/24), decades written exactly as "1eD".
std::vector<std::string> horizon_texts() {
  std::vector<std::string> out;
  for (int j = 0; j <= horizon_per_decade * horizon_decades; ++j)
    out.push_back(j % horizon_per_decade == 0 ? "1e" + std::to_string(j / horizon_per_decade)
                                              : four_digits(std::pow(10.0, double(j) / horizon_per_decade)));
  return out;
}

struct horizon_row {
  std::string t_text;
  horizon_minimum_report r;
};

std::vector<horizon_row> horizon_curve(const context& c, const coupling_spec& spec) {
  std::vector<horizon_row> rows;
  for (const auto& t : horizon_texts())
    rows.push_back({t, report_horizon_minimum(spec, horizon_time(parse_rational(t, "horizon")), c.digits)});
  return rows;
}

// Data: one block per coupling, "T h_min t_min lobe" (lobe -1: the end point t = T).
std::string horizon_data(const std::vector<std::vector<horizon_row>>& curves) {
  std::ostringstream d;
  d << "# gyrores report: min of H_q over [0, T] (horizon theorem, proved; qdot0 = 1, H_q(0) = 1/2)\n";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    d << (i ? "\n\n" : "") << "# index " << i << ": n = " << horizon_couplings[i] << ": T h_min t_min lobe\n";
    for (const auto& row : curves[i])
      d << row.t_text << " " << row.r.h_min.value << " " << row.r.t_min.value << " "
        << (row.r.lobe ? row.r.lobe->k.str() : std::string("-1")) << "\n";
  }
  return d.str();
}

// A guide of slope -4 through the last point of n = 2 (at T = 10^12).
std::string horizon_script(const figure_spec& s, const std::vector<horizon_row>& n2, const std::string& title) {
  std::ostringstream g;
  g << frontend::figure_script_head("report figure", title, s) << "set title " << frontend::gnuplot_string(title) << " noenhanced\n"
    << "set logscale xy\nset format x \"10^{%L}\"\nset format y \"10^{%L}\"\n"
    << "set xlabel \"horizon T\"\nset ylabel \"min of H_q over [0, T]\"\n"
    << "set grid lc rgb \"#dddddd\"\nset key below horizontal   # off the data\n"
    << "set xrange [1:1e12]\n"
    << "c4 = " << n2.back().r.h_min.value << " * 1e48   # the guide passes through n = 2 at T = 10^12\n"
    << "plot datafile index 0 using 1:2 with steps lw 1.5 lc rgb \"#1f77b4\" title \"n = 2\", \\\n"
    << "     '' index 1 using 1:2 with steps lw 1.5 lc rgb \"#ff7f0e\" title \"n = 0.1832\", \\\n"
    << "     c4 * x**(-4) with lines dt 2 lc rgb \"black\" title \"slope -4\"\n";
  return g.str();
}

// One coupling of (b) and its first time below the level.
struct absorb_point {
  std::string label;  // the decimal n, or the pair "(t, s)"
  double n = 0;
  first_below_report r;
  std::int64_t tau = 0, sigma = 0;  // the pair (resonant couplings)
};

// The decimal couplings of the table (also drawn).
const char* const absorb_table[] = {"0.05", "0.1", "0.5", "1", "2", "5"};

// The decimal couplings of (b): the log-spaced samples and the table's, in increasing order.
std::vector<std::string> absorb_texts() {
  std::vector<std::string> out(std::begin(absorb_table), std::end(absorb_table));
  for (int i = 0; i < absorb_samples; ++i) out.push_back(four_digits(0.05 * std::pow(100.0, double(i) / (absorb_samples - 1))));
  const auto value = [](const std::string& t) { return std::strtod(t.c_str(), nullptr); };
  std::sort(out.begin(), out.end(), [&](const std::string& a, const std::string& b) { return value(a) < value(b); });
  out.erase(std::unique(out.begin(), out.end(), [&](const std::string& a, const std::string& b) { return value(a) == value(b); }),
            out.end());
  return out;
}

std::vector<std::pair<std::int64_t, std::int64_t>> absorb_pairs() {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  for (std::int64_t t = 2; t < absorb_pair_order; ++t)
    for (std::int64_t s = 1; s < t && t + s <= absorb_pair_order; ++s) {
      const double n = double(t - s) / std::sqrt(double(t * s));
      if (std::gcd(t, s) == 1 && n >= 0.05 && n <= 5) out.push_back({t, s});
    }
  return out;
}

std::string absorb_data(const std::vector<absorb_point>& dec, const std::vector<absorb_point>& pairs) {
  std::ostringstream d;
  d << "# gyrores report: first t with H_q(t) <= 1/200 (1% of H_q(0)), horizon theorem, proved\n"
    << "# index 0: decimal couplings: n t_below lobe\n";
  for (const auto& p : dec) d << p.label << " " << p.r.t_below.value << " " << lobe_str(p.r.lobe) << "\n";
  d << "\n\n# index 1: resonant pairs that reach the level: n t_below tau sigma\n";
  bool any = false;
  for (const auto& p : pairs)
    if (!p.r.never) d << num(p.n) << " " << p.r.t_below.value << " \"" << p.label << "\"\n", any = true;
  if (!any) d << "NaN NaN \"\"\n";
  d << "\n\n# index 2: resonant pairs that never reach it (H_q min > 1/200): n label\n";
  any = false;
  for (const auto& p : pairs)
    if (p.r.never) d << num(p.n) << " 0 \"" << p.label << "\"\n", any = true;
  if (!any) d << "NaN NaN \"\"\n";
  return d.str();
}

// Two panels sharing the n axis: the times (log-log) below, and the resonant pairs that never
// reach the level on a strip of their own above (a log axis has no "never").
std::string absorb_script(const figure_spec& s, const std::string& title) {
  std::ostringstream g;
  g << frontend::figure_script_head("report figure", title, s) << "set multiplot title " << frontend::gnuplot_string(title) << " noenhanced\n"
    << "set logscale x\nset xrange [0.045:5.5]\nset grid lc rgb \"#dddddd\"\n"
    << "set lmargin (small ? 9 : 11)\nset rmargin (small ? 2 : 3)\n"
    << "# upper strip: resonant pairs whose H_q min exceeds the level\n"
    << "set origin 0, 0.72\nset size 1, 0.2\nset tmargin 0.5\nset bmargin 0\nset format x \"\"\n"
    << "set yrange [-1:1]\nunset ytics\nset ylabel \"never\"\n"
    << "unset key   # its entry is in the key below the lower panel, off the data\n"
    << "plot datafile index 2 using 1:(0) with points pt 9 ps 1.3 lc rgb \"#d62728\" notitle, \\\n"
    << "     '' index 2 using 1:(0):3 with labels offset 0,-1.2 notitle\n"
    << "# lower panel: the first time below the level\n"
    << "set origin 0, 0\nset size 1, 0.72\nset tmargin 0.3\nset bmargin (small ? 6.5 : 5.5)\n"
    << "set logscale y\nset yrange [*:*]\nset ytics autofreq\nset format x \"%g\"\nset format y \"10^{%L}\"\n"
    << "set xlabel \"coupling n\"\nset ylabel \"first t with H_q <= 1% of H_q(0)\"\n"
    << "set key below horizontal   # off the data\n"
    << "plot datafile index 0 using 1:2 with linespoints pt 7 ps 0.35 lw 0.8 lc rgb \"#1f77b4\" title \"decimal n (not resonant)\", \\\n"
    << "     '' index 1 using 1:2 with points pt 6 ps 1.3 lw 1.5 lc rgb \"#d62728\" title \"resonant pair\", \\\n"
    << "     NaN with points pt 9 ps 1.3 lc rgb \"#d62728\" title \"resonant pair, H_q min > 1% (strip above)\"\n"
    << "unset multiplot\n";
  return g.str();
}

// What the summary says of n = 2 (the paper's Fig. 1a coupling), as the tables print it.
struct n2_finding {
  std::string horizon, h_min;    // the last horizon of (a) ("12" of 10^12) and the minimum over [0, 10^12]
  std::string t_below, lobe;     // (b): the first t with H_q <= 1% and its lobe
};

std::string part_a(context& c, n2_finding& n2) {
  std::ostringstream md;
  std::vector<std::vector<horizon_row>> curves;
  for (const char* n : horizon_couplings) curves.push_back(horizon_curve(c, coupling_spec::from_n(parse_rational(n, "n"))));
  md << "### 7a. The minimum of H_q over [0, T], T up to 10^12\n\n"
     << "For a coupling that is not resonant the infimum of H_q over all time is 0, never attained; over [0, T] the "
        "minimum is the smallest lobe minimum inside [0, T] (or H_q(T) itself while it still decreases). Lobe k has "
        "minimum G(H^{-1}(pi nu_k)) with nu_k = ||k x - 1/2||, x = n/sqrt(n^2 + 4), increasing in nu_k: the curve is "
        "a staircase whose steps are the lobes k with record-small nu_k, and the horizon theorem finds them in "
        "O(log T) (`gyrores coupling N --horizon T`). Observed on these curves (not a theorem printed here): the "
        "lobe minima scale as nu_k^4 (H_q / (pi nu_k)^4 is the same at every record lobe of one coupling, to many "
        "digits), and for n = 2, x = 1/sqrt 2 is badly approximable, so k nu_k stays bounded away from 0 on the "
        "records: nu_k ~ 1/k ~ 1/T and the staircase falls as T^-4 (the dashed guide). n = 0.1832 (the exact "
        "decimal) is approximated less evenly (k nu_k varies widely on its records): fewer, deeper steps around the "
        "same slope. Each point is proved, "
        "24 horizons per decade; the table gives the decades (lobe `-`: the minimum is at t = T).\n\n"
     << "| n | T | lobe k | min H_q over [0, T] | first at t |\n|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (const auto& row : curves[i])
      if (row.t_text.rfind("1e", 0) == 0 && (row.t_text == "1e0" || (row.t_text.size() > 2 && (std::stoi(row.t_text.substr(2)) % 3 == 0))))
        md << "| " << horizon_couplings[i] << " | 10^" << row.t_text.substr(2) << " | " << lobe_str(row.r.lobe) << " | "
           << row.r.h_min.value << " | " << row.r.t_min.value << " |\n";
  md << "\n";
  n2.horizon = curves[0].back().t_text.substr(2);  // the table's last row: the decades are its rows
  n2.h_min = curves[0].back().r.h_min.value;
  const std::string title = "min of H_q over [0, T]: n = 2 (Fig. 1a) and n = 0.1832, horizon theorem";
  const auto spec = c.figs.spec("fig-coupling-horizon", 900, 560);
  c.figs.record("fig-coupling-horizon",
                frontend::write_figure_files(spec, horizon_data(curves), horizon_script(spec, curves[0], title)));
  md << c.figs.md("fig-coupling-horizon",
                  "The minimum of H_q over [0, T] against T (log-log), 24 proved horizons per decade drawn as steps; "
                  "the dashed line has slope -4.");
  return md.str();
}

// The pairs of the table: the lowest few and the paper's (4, 3), (6, 5), reaching the level or not.
const std::set<std::string> table_pairs = {"(2, 1)", "(3, 1)", "(4, 3)", "(5, 3)", "(6, 5)", "(9, 7)"};

std::string part_b(context& c, n2_finding& n2) {
  const big_rational level = parse_rational(absorb_level_text, "level");
  std::vector<absorb_point> dec, pairs;
  std::string resonant_decimals;
  for (const auto& n : absorb_texts()) {
    const auto spec = coupling_spec::from_n(parse_rational(n, "n"));
    if (const auto pair = coupling_resonant_pair(spec)) {  // an exact resonance (2.805 is (625, 64))
      resonant_decimals += (resonant_decimals.empty() ? "" : ", ") + n + ", the pair " + pair->str();
      continue;
    }
    dec.push_back({n, std::strtod(n.c_str(), nullptr), report_first_below(spec, level, c.digits)});
  }
  for (auto [t, s] : absorb_pairs())
    pairs.push_back({pair_name(t, s), double(t - s) / std::sqrt(double(t * s)),
                     report_first_below(coupling_spec::from_n2(big_rational((t - s) * (t - s), t * s)), level, c.digits), t, s});
  std::string never;
  for (const auto& p : pairs)
    if (p.r.never) never += (never.empty() ? "" : ", ") + p.label;
  std::ostringstream md;
  md << "### 7b. The time to absorb 99% of the energy, against n\n\n"
     << "The first t with H_q(t) <= 1/200 (1% of H_q(0) = 1/2), proved by the horizon theorem for " << dec.size()
     << " decimal couplings n from 0.05 to 5 (evenly spaced in log n, 4 significant digits, and those of the table; "
     << (resonant_decimals.empty() ? std::string("none is resonant") : "left out, resonant: " + resonant_decimals)
     << ") and for the "
     << pairs.size() << " resonant pairs with tau + sigma <= " << absorb_pair_order
     << " in that range (n = (tau - sigma)/sqrt(tau sigma), given exactly by n^2). A coupling that is not resonant "
        "always gets there (its infimum is 0); a resonant pair gets there only when its H_q min is at most the level: "
     << "of these pairs, " << (never.empty() ? std::string("none") : never)
     << " never do. Observed on the figure: decimal couplings close to a pair that never gets there take much longer "
        "(the spikes), and the time jumps where the first lobe reaching the level changes (`gyrores coupling N "
        "--below 1%`).\n\n"
     << "| coupling | n | first lobe reaching 1% | first t with H_q <= 1% |\n|---|---|---|---|\n";
  for (const char* n : absorb_table)
    for (const auto& p : dec)
      if (p.label == n) {
        md << "| decimal | " << n << " | " << lobe_str(p.r.lobe) << " | " << p.r.t_below.value << " |\n";
        if (p.label == "2") n2.t_below = p.r.t_below.value, n2.lobe = lobe_str(p.r.lobe);
      }
  for (const auto& p : pairs)
    if (table_pairs.count(p.label)) {
      const auto v = c.values(p.tau, p.sigma);
      md << "| pair " << p.label << " | " << v.n.value << " | " << (p.r.never ? "-" : lobe_str(p.r.lobe)) << " | "
         << (p.r.never ? "never: H_q min = " + v.h_min.value : p.r.t_below.value) << " |\n";
    }
  md << "\n";
  const std::string title = "first t with H_q <= 1% of H_q(0), against n (horizon theorem)";
  const auto spec = c.figs.spec("fig-coupling-absorb", 900, 600);
  c.figs.record("fig-coupling-absorb", frontend::write_figure_files(spec, absorb_data(dec, pairs), absorb_script(spec, title)));
  md << c.figs.md("fig-coupling-absorb",
                  "The first time H_q falls to 1% of its initial value against n (log-log): decimal couplings (blue), "
                  "resonant pairs that get there (red circles) and those whose H_q min stays above 1% (strip on top).");
  return md.str();
}

}  // namespace

std::string coupling_section(context& c) {
  const std::string heading = "7. Couplings that are not resonant: any horizon, any level";
  n2_finding n2;
  const std::string a = part_a(c, n2), b = part_b(c, n2);
  std::string text = "**A coupling that is not resonant.** For n = 2 the infimum of H_q over all time is 0, never attained: its minimum over [0, T] is " +
                     n2.h_min + " for T = 10^" + n2.horizon;
  if (!n2.t_below.empty()) text += ", and H_q first falls to 1/200 (1% of its initial value) at t = " + n2.t_below + " (lobe " + n2.lobe + ")";
  c.findings.push_back({heading, text + "."});
  return "## " + heading + "\n\n" + a + b;
}

}  // namespace gyrores::report
