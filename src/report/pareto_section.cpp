// The report's Section 5: the Pareto front (the paper's Figure 4), its table, CSV and figure.
#include <sstream>

#include <gyrores/app/pareto.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/io/files.hpp>

#include "report/sections.hpp"

namespace gyrores::report {
namespace {

// One markdown table row for a pair with proved values.
std::string pair_row(const design_point& p, const pair_report& v) {
  std::ostringstream os;
  os << "| " << pair_name(p.tau, p.sigma) << " | " << p.delta() << " | " << v.n << " | "
     << (v.degenerate ? "0 (exact)" : v.r_res.value) << " | " << v.t_first << " | " << v.t_min_paper << " |\n";
  return os.str();
}

const char* const pair_table_head =
    "| pair | delta | n | r_res | exact t_first | proxy pi/n |\n|---|---|---|---|---|---|\n";

std::string front_observation(const context& c, const std::vector<design_point>& front) {
  std::ostringstream md;
  md << "Observation (this data, not a theorem): the fastest pair is " << pair_name(front.front().tau, front.front().sigma)
     << " (t_first = " << c.values(front.front().tau, front.front().sigma).t_first << "), and the front runs down a family of pairs whose ratio tau/sigma "
        "tends to 3 until it ends at the degenerate pair (3, 1), r_res = 0 at t_first = sqrt(3) pi/2 = "
     << c.values(3, 1).t_first
     << ". Every slower pair, including all near-irrational (small n) ones, is dominated by (3, 1): with exact times, deep "
        "exchange does not have to be slow; the paper's trade-off picture holds only among pairs that exclude (3, 1).\n\n";
  return md.str();
}

}  // namespace

std::string pareto_section(context& c, std::int64_t M) {
  std::ostringstream md;
  md << "## 5. Pareto front (Figure 4), pairs with tau + sigma <= " << M << "\n\n";
  app::pareto_request r;  // `gyrores pareto --max-order M`
  r.max_order = M;
  r.digits = c.digits;
  const app::pareto_outcome p = app::run_pareto(r);
  std::vector<design_point> nondeg;
  for (const auto& q : p.pairs)
    if (!q.degenerate) nondeg.push_back(q);
  const auto front_nd = pareto_front(nondeg, pareto_orientation::absorb, design_time::first_hit);
  md << "Orientation: absorption, lower r_res and lower exact t_first are better (`gyrores pareto --max-order " << M
     << "`). " << p.front.size() << " of " << p.pairs.size() << " pairs are non-dominated"
     << " (" << front_nd.size() << " when degenerate pairs are excluded, `--exclude-degenerate`).\n\n"
     << front_observation(c, p.front) << pair_table_head;
  for (std::size_t i = 0; i < p.front.size(); ++i) md << pair_row(p.front[i], p.values[i]);
  write_file_atomically(c.dir / "pareto-front.csv", pareto_csv(p.front, p.values));
  md << "\nThe front as CSV: [pareto-front.csv](pareto-front.csv).\n\n";
  c.figs.record("fig4-pareto", frontend::write_pareto_figure(c.figs.spec("fig4-pareto", 900, 640), p.pairs, p.front,
                                                              design_time::first_hit,
                                                              "Fig. 4: Pareto front, tau+sigma <= " + std::to_string(M) +
                                                                  " (absorb: min r_res, min t_first)"));
  md << c.figs.md("fig4-pareto", "Figure 4: r_res against the exact first-hit time (log axes) for every pair; degenerate pairs (r_res = 0) on the bottom line; the Pareto front in red.");
  return md.str();
}

}  // namespace gyrores::report
