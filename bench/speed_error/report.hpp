// Writers: the raw CSV, the Markdown report (bench/RESULTS.md) and the gnuplot files of the
// speed-against-error plot (report.cpp), and the headline figures (headlines.cpp). Everything in
// them is computed from the rows of one run.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core.hpp"
#include "reference.hpp"

namespace gyrores::bench {

struct run_context {
  bool quick = false;
  std::string command, date, cpu, cores, load_before, load_after, compiler, flags, libraries, mpmath_status;
  double seconds = 0, reference_seconds = 0;
  unsigned reference_digits = 0;
};

// One headline target: per-pair values and the verdict.
struct headline {
  std::string id, target;
  std::vector<std::pair<std::string, std::string>> values;  // (pair/precision, text)
  int met = 0, total = 0;
  std::string remark;
};

// "ratio to best": time / the fastest time among rows of the same (pair, precision) whose
// correct digits are within 1 of the precision's nominal digits (or of the most any row reached
// there, if fewer).
std::map<const measurement*, double> ratios_to_best(const std::vector<measurement>& rows,
                                                   const std::vector<precision>& precisions);

std::vector<headline> compute_headlines(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs);

// CSV columns: method,precision,pair,median_ns,correct_digits,evaluations (empty: not applicable
// or failed).
void write_csv(const std::string& path, const std::vector<measurement>& rows);

void write_markdown(const std::string& path, const run_context& ctx, const std::vector<measurement>& rows,
                    const std::vector<skip_note>& skips, const std::vector<method_def>& methods,
                    const std::vector<bench_pair>& pairs, const std::vector<precision>& precisions,
                    const std::map<std::string, reference>& refs);

// Writes <dir>/speed_vs_error.gp (self-contained: data inline) rendering
// <dir>/speed_vs_error.svg and .png when run with gnuplot from <dir>.
void write_plot_script(const std::string& dir, const run_context& ctx, const std::vector<measurement>& rows,
                       const std::vector<method_def>& methods, const std::vector<bench_pair>& pairs);

// Text of a time per call ("617 ns", "2.17 ms"; "n/a" when not measured), of digits ("16.0").
std::string format_time(double ns);
std::string format_digits(double d);
// printf-style text of one number (`f` has one double conversion).
std::string format_number(const char* f, double v);
// A time or digit count is NaN when it was not measured.
inline bool is_measured(double v) { return v == v; }

}  // namespace gyrores::bench
