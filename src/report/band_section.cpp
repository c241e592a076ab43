// The report's Section 8: a coupling known only to a tolerance. For the 1% bands around n = 2
// (the paper's Fig. 1a coupling) and around the (6, 5) coupling (Case B), the containment and
// absorption guarantees over [0, T] against T from 1 to 10^30, beside the nominal coupling's own
// minimum: the band theorem (theorem/band.hpp, proofs/band-theorem.md) and the horizon theorem,
// every point proved and settled.
#include <sstream>
#include <vector>

#include <gyrores/design/design.hpp>
#include <gyrores/design/tolerance.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/theorem/band.hpp>
#include <gyrores/report/horizon_report.hpp>

#include "frontend/gnuplot.hpp"
#include "report/sections.hpp"

namespace gyrores::report {
namespace {

// Two horizons per decade, 1 to 10^30, as exact decimals ("1e7", "3.162e7").
constexpr int band_decades = 30;
std::vector<std::string> band_horizons() {
  std::vector<std::string> out;
  for (int d = 0; d <= band_decades; ++d) {
    out.push_back("1e" + std::to_string(d));
    if (d < band_decades) out.push_back("3.162e" + std::to_string(d));
  }
  return out;
}

struct band_row {
  std::string T;
  std::string nominal, absorption, containment;  // H_q, settled decimals ("0" when exactly 0)
  std::string absorption_at, containment_at;     // where attained: the pair or n^2
  enclosure absorption_value;                    // the absorption guarantee, proved
};

struct band_case {
  std::string name, stem;  // "n = 2", the figure's stem
  big_rational n1, n2;
  coupling_spec nominal;
};

std::string at_text(const band_coupling& c) {
  if (const auto p = coupling_resonant_pair(c.spec)) return p->str();
  return "n^2 = " + rational_str(c.spec.n2);
}

std::vector<band_row> band_rows(const band_case& b, unsigned digits) {
  std::vector<band_row> rows;
  band_options opt;
  opt.digits = digits;
  for (const auto& t : band_horizons()) {
    const horizon_time T(parse_rational(t, "horizon"));
    const band_extreme W = prove_band_absorption(b.n1, b.n2, T, opt), B = prove_band_containment(b.n1, b.n2, T, opt);
    const auto value = [&](const band_extreme& e) {
      return e.value.hi_rational() == 0 ? std::string("0") : e.value.rounded(digits).value_or("unsettled");
    };
    rows.push_back({t, report_horizon_minimum(b.nominal, T, digits).h_min.value, value(W), value(B), at_text(W.at), at_text(B.at),
                    W.value});
  }
  return rows;
}

// "T nominal absorption containment" (containment 0 as the plot's floor marker "NaN": a log
// axis has no 0; the markdown says where it becomes 0).
std::string band_data(const band_case& b, const std::vector<band_row>& rows) {
  std::ostringstream d;
  d << "# gyrores report: 1% band around " << b.name << ", n in [" << rational_str(b.n1) << ", " << rational_str(b.n2)
    << "]: T, min H_q over [0, T] of the nominal coupling, the absorption and containment guarantees (band-theorem/1)\n";
  for (const auto& r : rows)
    d << r.T << " " << r.nominal << " " << r.absorption << " " << (r.containment == "0" ? "NaN" : r.containment) << "\n";
  return d.str();
}

std::string band_script(const figure_spec& s, const std::string& title) {
  std::ostringstream g;
  g << frontend::figure_script_head("report figure", title, s) << "set title " << frontend::gnuplot_string(title) << " noenhanced\n"
    << "set logscale xy\nset format x \"10^{%L}\"\nset format y \"10^{%L}\"\n"
    << "set xlabel \"horizon T\"\nset ylabel \"H_q (qdot0 = 1, H_q(0) = 1/2)\"\n"
    << "set grid lc rgb \"#dddddd\"\nset key below maxcols 1   # off the data\nset xrange [1:1e30]\n"
    << "plot datafile using 1:3 with steps lw 2 lc rgb \"#d62728\" title \"absorption guarantee (highest minimum over the band)\", \\\n"
    << "     '' using 1:2 with steps lw 1.5 lc rgb \"#1f77b4\" title \"nominal coupling: min over [0, T]\", \\\n"
    << "     '' using 1:4 with steps lw 2 lc rgb \"#2ca02c\" title \"containment guarantee (lowest minimum)\"\n";
  return g.str();
}

// The summary's sentence for a band: the guarantees at the last horizon, as the table prints them.
std::string band_finding(const band_case& b, const std::vector<band_row>& rows) {
  const auto& last = rows.back();
  std::ostringstream f;
  f << "**A 1% tolerance on " << b.name << ".** By T = " << last.T << " every coupling of the band brings H_q down to "
    << last.absorption << " or below (" << share_of_initial_energy(last.absorption_value)
    << "; the highest, at " << last.absorption_at << ")";
  if (last.nominal != last.absorption) f << ", while the nominal coupling reaches " << last.nominal;
  for (const auto& r : rows)
    if (r.containment == "0") {
      f << "; from T = " << r.T << " on, some coupling of the band drains q completely (the degenerate pair " << r.containment_at << ")";
      break;
    }
  f << ".";
  return f.str();
}

std::string part(context& c, const std::string& heading, const band_case& b) {
  const auto rows = band_rows(b, c.digits);
  std::string zero_at;
  for (const auto& r : rows)
    if (r.containment == "0" && zero_at.empty()) zero_at = r.T + " (at the degenerate pair " + r.containment_at + ")";
  c.findings.push_back({heading, band_finding(b, rows)});
  std::ostringstream md;
  md << "#### " << b.name << " (1%: n in [" << rational_str(b.n1) << ", " << rational_str(b.n2) << "])\n\n"
     << "The containment guarantee falls to 0 exactly from T = " << (zero_at.empty() ? std::string("(never up to 10^30)") : zero_at)
     << " on: a coupling of the band then reaches H_q = 0 before T. The absorption guarantee settles at the all-time "
        "minimum of the band's pair of least odd denominator in x ("
     << rows.back().absorption_at << ").\n\n"
     << "| T | nominal min H_q | absorption guarantee | attained at | containment guarantee | attained at |\n"
     << "|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < rows.size(); i += 6) {
    const auto& r = rows[i];
    md << "| " << r.T << " | " << r.nominal << " | " << r.absorption << " | " << r.absorption_at << " | " << r.containment << " | "
       << r.containment_at << " |\n";
  }
  md << "\n";
  const std::string title = "1% band around " + b.name + ": the guarantees over [0, T] (band theorem)";
  const auto spec = c.figs.spec(b.stem, 900, 560);
  c.figs.record(b.stem, frontend::write_figure_files(spec, band_data(b, rows), band_script(spec, title)));
  md << c.figs.md(b.stem, "The absorption guarantee (red: no coupling of the band keeps more than this in q over [0, T]), "
                          "the nominal coupling's minimum (blue) and the containment guarantee (green: every coupling keeps "
                          "at least this; drawn until it is 0), against T, two proved horizons per decade.");
  return md.str();
}

}  // namespace

std::string band_section(context& c) {
  const design_point p65 = design_point_of(resonant_pair<std::int64_t>(6, 5));
  const auto [a1, a2] = tolerance_band(p65, big_rational(1, 100));
  const band_case cases[] = {
      {"n = 2", "fig-band-n2", big_rational(198, 100), big_rational(202, 100), coupling_spec::from_n2(big_rational(4))},
      {"the (6, 5) coupling", "fig-band-65", a1, a2, coupling_spec::from_n2(big_rational(1, 30))}};
  std::ostringstream md;
  const std::string heading = "8. A coupling known to a tolerance: the band's guarantees";
  md << "## " << heading << "\n\n"
     << "A real coupling is known to a tolerance, n in [n1, n2]. Over [0, T] the **absorption guarantee** is the highest "
        "minimum of H_q over the band (every coupling drains q at least this far) and the **containment guarantee** the "
        "lowest (every coupling keeps at least this in q); both are proved and settled by the band theorem "
        "(`proofs/band-theorem.md`, `gyrores coupling N --tolerance 1% --horizon T`), each with the coupling where it is "
        "attained. Unlike the nominal coupling's minimum, which keeps falling (its infimum is 0), the absorption "
        "guarantee stops at the resonant pair of the band whose own minimum is the highest, and the containment "
        "guarantee drops to 0 as soon as a degenerate pair of the band has its zero before T.\n\n";
  for (const auto& b : cases) md << part(c, heading, b);
  return md.str();
}

}  // namespace gyrores::report
