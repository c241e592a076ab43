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

// The rows of the table: the whole front when it has at most pareto_table_rows pairs, else every
// k-th pair by exact t_first (k the smallest step that fits) and the last pair, so both ends show.
constexpr std::size_t pareto_table_rows = 15;
std::vector<std::size_t> table_rows(std::size_t front_size, std::size_t& step) {
  step = 1;
  if (front_size > pareto_table_rows) step = (front_size - 1 + (pareto_table_rows - 2)) / (pareto_table_rows - 1);
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < front_size; i += step) rows.push_back(i);
  if (!rows.empty() && rows.back() != front_size - 1) rows.push_back(front_size - 1);
  return rows;
}

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
  const std::string heading = "5. Pareto front (Figure 4), pairs with tau + sigma <= " + std::to_string(M);
  md << "## " << heading << "\n\n";
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
     << front_observation(c, p.front);
  std::size_t step = 1;
  const auto rows = table_rows(p.front.size(), step);
  write_file_atomically(c.dir / "pareto-front.csv", pareto_csv(p.front, p.values));
  md << "The front by exact t_first, ";
  if (step == 1)
    md << "all " << p.front.size() << " pairs";
  else
    md << rows.size() << " of its " << p.front.size() << " pairs (one in every " << step << " from the fastest, and the slowest)";
  if (!p.front.empty()) {
    const auto end = [&](std::size_t i) {
      const auto& v = p.values[i];
      return pair_name(p.front[i].tau, p.front[i].sigma) + " (r_res = " + (v.degenerate ? std::string("0 exactly") : v.r_res.value) +
             ", t_first = " + v.t_first.value + ")";
    };
    c.findings.push_back({heading, "**Pareto front.** " + std::to_string(p.front.size()) + " of the " + std::to_string(p.pairs.size()) +
                                       " pairs with tau + sigma <= " + std::to_string(M) +
                                       " are non-dominated for absorption (lower r_res, lower exact t_first), from the fastest, " + end(0) +
                                       ", to the slowest, " + end(p.front.size() - 1) +
                                       "; the whole front is in pareto-front.csv."});
  }
  md << "; the whole front, one pair a line, in [pareto-front.csv](pareto-front.csv):\n\n" << pair_table_head;
  for (std::size_t i : rows) md << pair_row(p.front[i], p.values[i]);
  md << "\n";
  c.figs.record("fig4-pareto", frontend::write_pareto_figure(c.figs.spec("fig4-pareto", 900, 640), p.pairs, p.front,
                                                              design_time::first_hit,
                                                              "Fig. 4: Pareto front, tau+sigma <= " + std::to_string(M) +
                                                                  " (absorb: min r_res, min t_first)"));
  md << c.figs.md("fig4-pareto", "Figure 4: r_res against the exact first-hit time (log axes) for every pair; degenerate pairs (r_res = 0) on the bottom line; the Pareto front in red.");
  return md.str();
}

}  // namespace gyrores::report
