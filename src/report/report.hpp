// The REPORT.md generator (`gyrores report`, README.md): DIR/REPORT.md with a summary of findings
// (each linked to its section, whose numbers it repeats), the paper's examples
// recomputed (proved digits), the two design cases, the Pareto front (a short table; the whole
// front in DIR/pareto-front.csv), a validation sweep, the
// couplings that are not resonant and the figures (PNG, SVG and PDF, with data and gnuplot scripts),
// from the application layer (include/gyrores/app/) and the library. Every file is written
// atomically (io/files.hpp); REPORT.md is written last and links only files that exist. Its own
// target, linked by the gyrores tool; the sections are in report/sections.hpp.
#pragma once
#include <cstdint>
#include <string>

namespace gyrores::report {

struct report_options {
  std::string out = "gyrores-report";  // the directory
  std::int64_t pareto_order = 200;     // the Pareto front over pairs up to this order (3..2000)
  std::int64_t sweep_order = 100;      // the validation sweep up to this order (3..1000)
  unsigned digits = 10;                // of every real printed (3..40)
};

// Writes the report (the ranges above are the caller's to check); returns what the command
// prints: the path of REPORT.md, then a note per figure not drawn.
std::string write_report(const report_options& o);

}  // namespace gyrores::report
