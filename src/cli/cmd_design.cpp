// gyrores design absorb|contain --tmax T [--beat B] [--max-order M] [--exclude-low L]
//                                [--delta D] [--proxy] [--candidates K] [--digits D] [--json]
//                                [--tolerance P% --level E [--horizon H]]
// The paper's design problems (eqs. design-absorb, design-contain) over resonant pairs up to
// order M, and the guarantee over a tolerance band on n: include/gyrores/app/design.hpp. No
// feasible pair: one line on stderr, exit 3.
#include <limits>
#include <optional>
#include <sstream>

#include <gyrores/app/design.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/theorem/horizon.hpp>
#include <gyrores/theorem/lobes.hpp>

#include "cli_options.hpp"
#include "cli_signals.hpp"
#include "commands.hpp"
#include "frontend/number_text.hpp"
#include "pair_output.hpp"

namespace gyrores::cli {

using frontend::decimal_text;
using frontend::energy_text;
using frontend::plain;

namespace {

// --delta not given (any value the user can give is checked, 0 included).
constexpr std::int64_t delta_unset = std::numeric_limits<std::int64_t>::min();

struct design_args {
  std::string problem, tmax, tolerance, level, horizon;
  pair_filter_flags filter;
  std::int64_t max_order = 200, delta = delta_unset, candidates = 5;
  int digits = 10;
  bool proxy = false, json = false;
};

// --tolerance P% with --level E (energy or % of H_q(0) = 1/2) and --horizon H (contain).
std::optional<app::design_tolerance> tolerance_of(const design_args& a, design_problem problem) {
  if (a.tolerance.empty()) {
    if (!a.level.empty() || !a.horizon.empty()) throw usage_error("--level and --horizon need --tolerance");
    return std::nullopt;
  }
  if (a.proxy) throw usage_error("--tolerance needs the exact first-hit time (not --proxy)");
  app::design_tolerance t;
  t.fraction = parse_tolerance_band(1, a.tolerance, "--tolerance").second - 1;  // the band 1 (1 -+ P/100)
  if (a.level.empty()) throw usage_error("--tolerance needs --level E: the energy to absorb down to (absorb) or to keep (contain)");
  t.level = parse_energy_level(a.level, "--level");
  if (!a.horizon.empty()) {
    if (problem == design_problem::absorb) throw usage_error("--horizon is for contain (absorb uses --tmax)");
    t.horizon = horizon_time(parse_positive_flag(a.horizon, "--horizon"));
  }
  return t;
}

// The request from the flags (usage_error naming the flag).
app::design_request request_of(const design_args& a) {
  app::design_request r;
  design_options& o = r.options;
  o.problem = app::parse_design_problem(a.problem);
  check_digits_flag(a.digits, 1, int(app::listed_digits_max));
  o.tmax = parse_positive_flag(a.tmax, "--tmax");
  apply_pair_filter_flags(a.filter, o.filter);
  if (a.delta != delta_unset && a.delta < 1) throw usage_error("--delta must be >= 1, got " + std::to_string(a.delta));
  check_flag_range(a.candidates, 0, 1000, "--candidates");
  if (a.delta != delta_unset) o.filter.delta = a.delta;
  o.time = a.proxy ? design_time::proxy : design_time::first_hit;
  o.max_order = a.max_order;
  o.candidates = std::size_t(a.candidates);
  check_max_order_flag(a.max_order);
  r.tmax_text = a.tmax;
  r.beat_text = a.filter.beat;
  r.digits = unsigned(a.digits);
  r.tolerance = tolerance_of(a, o.problem);
  return r;
}

std::string design_text(const design_args& a, const app::design_request& r, const app::design_outcome& out) {
  const design_result& res = out.result;
  std::ostringstream os;
  os << "design " << a.problem << ": " << (r.options.problem == design_problem::absorb ? "minimise" : "maximise")
     << " r_res (qdot0 = 1) subject to " << app::design_constraints_text(r) << "\n"
     << "  time constraint uses " << (a.proxy ? "the paper's proxy pi/|n| (heuristic)" : "the exact first-hit time t_first")
     << "; " << res.examined << " pairs examined, " << res.feasible << " feasible\n";
  const auto& v = out.values[0];
  os << "chosen " << res.ranked[0].pair().str() << "\n"
     << "  n             " << plain(v.n) << "\n"
     << "  r_res         " << radius_text(v) << "\n"
     << "  H_q min       " << energy_text(v) << "\n"
     << "  t_first       " << plain(v.t_first) << "  (exact first-hit time)\n"
     << "  pi/|n|        " << plain(v.t_min_paper) << "  (the paper's proxy)\n";
  if (out.chosen_exceeds_tmax)
    os << "  note: the exact first-hit time exceeds --tmax " << a.tmax
       << ": the proxy chose a pair that does not meet the time constraint\n";
  if (out.values.size() > 1) {
    os << "next best:\n  rank  pair          " << value_columns_header({"n", "r_res", "t_first", "pi/|n|"}, r.digits) << "\n";
    for (std::size_t i = 1; i < out.values.size(); ++i)
      os << "  " << rank_cell(i) << padded(res.ranked[i].pair().str(), 14) << values_columns(out.values[i]) << "\n";
  }
  os << "  ranking: objective, then smaller time, then smaller order; " << a.digits
     << " digits, each the correct rounding of a proved enclosure (" << lattice_theorem_id << ")\n";
  return os.str();
}

std::string tolerance_text(const design_args& a, design_problem problem, const tolerance_result& r) {
  std::ostringstream os;
  const bool absorb = problem == design_problem::absorb;
  os << "with tolerance " << a.tolerance << " on n: " << (absorb ? "H_q <= " : "H_q >= ") << a.level
     << (absorb ? " before --tmax " + a.tmax : " on [0, " + (a.horizon.empty() ? a.tmax : a.horizon) + "]")
     << " for every n of the band, proved (" << band_theorem_id << ")\n"
     << "  rank  pair          band of n                        " << padded(absorb ? "absorption guarantee" : "containment guarantee", 32)
     << "verdict\n";
  for (std::size_t i = 0; i < r.checked.size(); ++i) {
    const auto& c = r.checked[i];
    const auto [lo, hi] = c.guarantee.value.outward(4);
    os << "  " << rank_cell(i) << padded(c.point.pair().str(), 14)
       << padded("[" + decimal_text(c.n1, 8) + ", " + decimal_text(c.n2, 8) + "]", 33)
       << padded(c.guarantee.value.hi_rational() == 0 ? "0 (exactly)" : "[" + plain(lo) + ", " + plain(hi) + "]", 32)
       << (c.guarantee.interrupted ? "interrupted" : tolerance_verdict_name(c.verdict)) << "\n";
  }
  if (r.chosen) os << "chosen with tolerance: " << r.checked[*r.chosen].point.pair().str() << "\n";
  else if (r.interrupted) os << "interrupted: the pairs above were checked, the last one's bracket as far as it got\n";
  else
    os << "no pair among the " << r.checked.size() << " best ranked meets the guarantee with this tolerance"
       << " (a wider --tmax, a smaller tolerance or another --level may)\n";
  return os.str();
}

std::string run_design(const design_args& a) {
  app::design_request r = request_of(a);
  std::optional<signal_scope> signals;  // the band proofs stop on Ctrl-C: the brackets so far, exit 130
  if (r.tolerance) r.stop = signals.emplace().token();
  const app::design_outcome out = app::run_design(r);
  std::string text;
  if (!a.json) text = design_text(a, r, out) + (out.tolerance ? tolerance_text(a, r.options.problem, *out.tolerance) : "");
  else {
    json j = design_json(r.options, r.tmax_text, r.beat_text, out.result, out.values, out.chosen_exceeds_tmax, r.digits);
    if (out.tolerance) j["tolerance"] = tolerance_json(r.options.problem, *out.tolerance, a.tolerance, a.level);
    text = json_dump(j) + "\n";
  }
  if (out.tolerance && out.tolerance->interrupted) throw partial_answer{text, ""};
  return text;
}

command_runner install_design(CLI::App& app) {
  auto a = std::make_shared<design_args>();
  auto sub = options(app).subcommand("design", "Choose a resonant pair: absorb (min r_res) or contain (max r_res) under a time limit (qdot0 = 1: r_res scales by qdot0, the choice does not; docs/units.md)");
  sub.add("PROBLEM", a->problem, "absorb or contain", show::required);
  sub.add("--tmax", a->tmax, "time limit T (decimal or fraction); constraint time <= T", show::required);
  sub.add("--max-order", a->max_order, "search pairs with tau + sigma <= M (3..5000)", show::with_default);
  add_pair_filter_options(sub, a->filter);
  sub.add("--delta", a->delta, "only pairs with tau - sigma = D (follows the paper's Case A)");
  sub.flag("--proxy", a->proxy, "use the paper's proxy pi/|n| instead of the exact first-hit time");
  sub.add("--candidates", a->candidates, "runners-up to report", show::with_default);
  sub.add("--tolerance", a->tolerance, "the coupling is realised within n (1 -+ P%): prove the guarantee over that band");
  sub.add("--level", a->level, "with --tolerance: E (energy, or % of H_q(0) = 1/2) to absorb down to, or to keep");
  sub.add("--horizon", a->horizon, "with --tolerance, contain: keep H_q >= E on [0, H] (default --tmax)");
  add_output_options(sub, a->digits, a->json);
  return [a] { return run_design(*a); };
}

const command_registration registration{"design", install_design};

}  // namespace
}  // namespace gyrores::cli
