// gyrores design absorb|contain --tmax T [--beat B] [--max-order M] [--exclude-low L]
//                                [--delta D] [--proxy] [--candidates K] [--digits D] [--json]
// The paper's design problems (eqs. design-absorb, design-contain) over resonant pairs up to
// order M: see include/gyrores/design/design.hpp. No feasible pair: one line on stderr, exit 3.
#include <limits>
#include <sstream>

#include <gyrores/design/design.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/report/pair_report.hpp>
#include <gyrores/design/tolerance.hpp>
#include <gyrores/io/json.hpp>

#include "cli_options.hpp"
#include "cli_signals.hpp"
#include "commands.hpp"
#include "pair_output.hpp"

namespace gyrores::cli {
namespace {

// --delta not given (any value the user can give is checked, 0 included).
constexpr std::int64_t delta_unset = std::numeric_limits<std::int64_t>::min();

struct design_args {
  std::string problem, tmax, beat, tolerance, level, horizon;
  std::int64_t max_order = 200, exclude_low = 0, delta = delta_unset, candidates = 5;
  int digits = 10;
  bool proxy = false, json = false;
};

// The ranked pairs with their proved values (proved for the reported pairs only).
using design_rows = std::vector<std::pair<resonant_pair<big_int>, pair_report>>;

std::string constraint_text(const design_args& a, const design_options& o) {
  std::ostringstream os;
  os << (o.time == design_time::first_hit ? "t_first" : "pi/|n|") << " <= " << a.tmax;
  if (!a.beat.empty()) os << ", beat (tau+sigma)/(tau-sigma) >= " << a.beat;
  if (a.exclude_low > 0) os << ", tau+sigma > " << a.exclude_low << " (R_low excluded)";
  if (a.delta > 0) os << ", delta = " << a.delta;
  os << ", tau+sigma <= " << a.max_order;
  return os.str();
}

design_problem parse_problem(const std::string& text) {
  if (text == "absorb") return design_problem::absorb;
  if (text == "contain") return design_problem::contain;
  throw usage_error("the design problem must be 'absorb' or 'contain', got '" + text + "'");
}

// The options of the design problem from the flags (usage_error naming the flag).
design_options design_options_of(const design_args& a) {
  design_options o;
  o.problem = parse_problem(a.problem);
  check_digits_flag(a.digits, 1, 1000);
  o.tmax = parse_positive_flag(a.tmax, "--tmax");
  if (!a.beat.empty()) o.filter.beat_min = parse_positive_flag(a.beat, "--beat");
  if (a.exclude_low < 0) throw usage_error("--exclude-low must be >= 0");
  if (a.delta != delta_unset && a.delta < 1) throw usage_error("--delta must be >= 1, got " + std::to_string(a.delta));
  check_flag_range(a.candidates, 0, 1000, "--candidates");
  o.filter.exclude_low = a.exclude_low;
  if (a.delta != delta_unset) o.filter.delta = a.delta;
  o.time = a.proxy ? design_time::proxy : design_time::first_hit;
  o.max_order = a.max_order;
  o.candidates = std::size_t(a.candidates);
  check_max_order_flag(a.max_order);
  return o;
}

std::string design_json(const design_args& a, const design_result& res, const design_rows& rows, bool exact_exceeds) {
  json j;
  j["problem"] = a.problem;
  j["tmax"] = a.tmax;
  j["time"] = a.proxy ? "proxy" : "t_first";
  j["beat"] = a.beat.empty() ? json(nullptr) : json(a.beat);
  j["max_order"] = a.max_order;
  j["exclude_low"] = a.exclude_low;
  j["delta"] = a.delta > 0 ? json(a.delta) : json(nullptr);
  j["examined"] = res.examined;
  j["feasible"] = res.feasible;
  j["chosen"] = pair_values_json(rows[0].first, rows[0].second);
  j["chosen_t_first_exceeds_tmax"] = exact_exceeds;
  json c = json::array();
  for (std::size_t i = 1; i < rows.size(); ++i) c.push_back(pair_values_json(rows[i].first, rows[i].second));
  j["candidates"] = c;
  j["digits"] = a.digits;
  return json_dump(j) + "\n";
}

void runners_up_text(std::ostringstream& os, const design_rows& rows) {
  if (rows.size() <= 1) return;
  os << "next best:\n";
  os << "  rank  pair          n                 r_res             t_first           pi/|n|\n";
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& w = rows[i].second;
    std::string pr = rows[i].first.str();
    os << "  " << i + 1 << std::string(i + 1 < 10 ? 5 : 4, ' ') << pr << std::string(pr.size() < 14 ? 14 - pr.size() : 1, ' ')
       << w.n << "  " << w.r_res << "  " << w.t_first << "  " << w.t_min_paper << "\n";
  }
}

std::string design_text(const design_args& a, const design_options& o, const design_result& res, const design_rows& rows,
                        bool exact_exceeds) {
  std::ostringstream os;
  os << "design " << a.problem << ": " << (o.problem == design_problem::absorb ? "minimise" : "maximise")
     << " r_res (qdot0 = 1) subject to " << constraint_text(a, o) << "\n"
     << "  time constraint uses " << (a.proxy ? "the paper's proxy pi/|n| (heuristic)" : "the exact first-hit time t_first")
     << "; " << res.examined << " pairs examined, " << res.feasible << " feasible\n";
  const auto& v = rows[0].second;
  os << "chosen " << rows[0].first.str() << "\n"
     << "  n             " << v.n << "\n"
     << "  r_res         " << radius_text(v) << "\n"
     << "  H_q min       " << v.h_min << "\n"
     << "  t_first       " << v.t_first << "  (exact first-hit time)\n"
     << "  pi/|n|        " << v.t_min_paper << "  (the paper's proxy)\n";
  if (exact_exceeds)
    os << "  note: the exact first-hit time exceeds --tmax " << a.tmax
       << ": the proxy chose a pair that does not meet the time constraint\n";
  runners_up_text(os, rows);
  os << "  ranking: objective, then smaller time, then smaller order; " << a.digits
     << " digits, each the correct rounding of a proved enclosure (" << lattice_theorem_id << ")\n";
  return os.str();
}

// --tolerance P% with --level E (energy or % of H_q(0) = 1/2) and --horizon H (contain; default T_max).
std::optional<tolerance_options> tolerance_options_of(const design_args& a, const design_options& o) {
  if (a.tolerance.empty()) {
    if (!a.level.empty() || !a.horizon.empty()) throw usage_error("--level and --horizon need --tolerance");
    return std::nullopt;
  }
  if (a.proxy) throw usage_error("--tolerance needs the exact first-hit time (not --proxy)");
  auto percent = [](std::string t, const char* flag) {
    if (t.empty() || t.back() != '%') throw usage_error(std::string(flag) + " must be a percentage such as 1%, got " + t);
    t.pop_back();
    return parse_rational(t, flag) / 100;
  };
  tolerance_options t;
  t.fraction = percent(a.tolerance, "--tolerance");
  if (!(t.fraction > 0) || !(t.fraction < 1)) throw usage_error("--tolerance must be in (0%, 100%), got " + a.tolerance);
  if (a.level.empty()) throw usage_error("--tolerance needs --level E: the energy to absorb down to (absorb) or to keep (contain)");
  t.level = a.level.back() == '%' ? big_rational(percent(a.level, "--level") / 2) : parse_rational(a.level, "--level");
  if (t.level < 0) throw usage_error("--level must be >= 0, got " + a.level);
  t.horizon = horizon_time(o.tmax);
  if (!a.horizon.empty()) {
    if (o.problem == design_problem::absorb) throw usage_error("--horizon is for contain (absorb uses --tmax)");
    t.horizon = horizon_time(parse_positive_flag(a.horizon, "--horizon"));
  }
  t.max_pairs = std::max<std::size_t>(o.candidates + 1, 20);
  return t;
}

std::string tolerance_text(const design_args& a, const design_problem problem, const tolerance_result& r) {
  std::ostringstream os;
  const bool absorb = problem == design_problem::absorb;
  os << "with tolerance " << a.tolerance << " on n: " << (absorb ? "H_q <= " : "H_q >= ") << a.level
     << (absorb ? " before --tmax " + a.tmax : " on [0, " + (a.horizon.empty() ? a.tmax : a.horizon) + "]")
     << " for every n of the band, proved (" << horizon_theorem_id << ")\n"
     << "  rank  pair          band of n                        " << (absorb ? "worst" : "best") << " min H_q over the horizon   verdict\n";
  for (std::size_t i = 0; i < r.checked.size(); ++i) {
    const auto& c = r.checked[i];
    const band_extreme& e = absorb ? c.band.worst : c.band.best;
    const std::string pr = c.point.pair().str();
    os << "  " << i + 1 << std::string(i + 1 < 10 ? 5 : 4, ' ') << pr << std::string(pr.size() < 14 ? 14 - pr.size() : 1, ' ')
       << "[" << format_rational_scientific(c.band.n1, 8) << ", " << format_rational_scientific(c.band.n2, 8) << "]  "
       << (c.band.zero ? "0 (degenerate " + c.band.zero->pair.str() + ")"
                       : "[" + format_rational_scientific(e.lo, 4) + ", " + format_rational_scientific(e.hi, 4) + "]")
       << "  " << tolerance_verdict_name(c.verdict) << "\n";
  }
  if (r.chosen) os << "chosen with tolerance: " << r.checked[*r.chosen].point.pair().str() << "\n";
  else
    os << "no pair among the " << r.checked.size() << " best ranked meets the guarantee with this tolerance"
       << " (a wider --tmax, a smaller tolerance or another --level may)\n";
  return os.str();
}

json tolerance_json(const design_problem problem, const tolerance_result& r) {
  json checked = json::array();
  for (const auto& c : r.checked) {
    const band_extreme& e = problem == design_problem::absorb ? c.band.worst : c.band.best;
    checked.push_back({{"tau", c.point.tau}, {"sigma", c.point.sigma},
                       {"band", {rational_str(c.band.n1), rational_str(c.band.n2)}},
                       {"h_min_enclosure", {rational_str(e.lo), rational_str(e.hi)}},
                       {"degenerate_zero", c.band.zero ? json(c.band.zero->pair.str()) : json(nullptr)},
                       {"verdict", tolerance_verdict_name(c.verdict)}});
  }
  json j{{"checked", checked}, {"theorem", horizon_theorem_id}};
  j["chosen"] = r.chosen ? json{{"tau", r.checked[*r.chosen].point.tau}, {"sigma", r.checked[*r.chosen].point.sigma}}
                         : json(nullptr);
  return j;
}

std::string run_design(const design_args& a) {
  design_options o = design_options_of(a);
  const auto tol = tolerance_options_of(a, o);
  if (tol) o.candidates = tol->max_pairs;
  const auto res = design_solve(design_catalogue(a.max_order), o);
  if (!res.feasible_any())
    throw compute_error("no resonant pair meets the constraints (" + constraint_text(a, o) + "; " +
                        std::to_string(res.examined) + " pairs examined); nothing chosen");
  design_rows rows;
  for (const auto& p : res.ranked) {
    if (rows.size() > std::size_t(a.candidates)) break;  // --tolerance ranks more pairs than it shows
    resonant_pair<big_int> bp(big_int(p.tau), big_int(p.sigma));
    rows.push_back({bp, prove_pair_values(bp, unsigned(a.digits))});
  }
  const bool exact_exceeds = a.proxy && !design_time_within(res.ranked.front(), design_time::first_hit, o.tmax);
  if (!tol) return a.json ? design_json(a, res, rows, exact_exceeds) : design_text(a, o, res, rows, exact_exceeds);
  signal_scope signals;  // the band proofs stop on Ctrl-C (exit 130)
  tolerance_options t = *tol;
  t.band.stop = signals.token();
  const tolerance_result tr = design_with_tolerance(res.ranked, o.problem, t);
  if (!a.json) return design_text(a, o, res, rows, exact_exceeds) + tolerance_text(a, o.problem, tr);
  std::string text = design_json(a, res, rows, exact_exceeds);
  json j = json::parse(text);
  j["tolerance"] = tolerance_json(o.problem, tr);
  j["tolerance"]["percent"] = a.tolerance;
  j["tolerance"]["level"] = a.level;
  return json_dump(j) + "\n";
}

command_runner install_design(CLI::App& app) {
  auto a = std::make_shared<design_args>();
  auto sub = options(app).subcommand("design", "Choose a resonant pair: absorb (min r_res) or contain (max r_res) under a time limit");
  sub.add("PROBLEM", a->problem, "absorb or contain", show::required);
  sub.add("--tmax", a->tmax, "time limit T (decimal or fraction); constraint time <= T", show::required);
  sub.add("--beat", a->beat, "require (tau+sigma)/(tau-sigma) >= B (decimal or fraction)");
  sub.add("--max-order", a->max_order, "search pairs with tau + sigma <= M (3..5000)", show::with_default);
  sub.add("--exclude-low", a->exclude_low, "exclude the low-order set tau + sigma <= L");
  sub.add("--delta", a->delta, "only pairs with tau - sigma = D (follows the paper's Case A)");
  sub.flag("--proxy", a->proxy, "use the paper's proxy pi/|n| instead of the exact first-hit time");
  sub.add("--candidates", a->candidates, "runners-up to report", show::with_default);
  sub.add("--tolerance", a->tolerance, "the coupling is realised within n (1 -+ P%): prove the guarantee over that band");
  sub.add("--level", a->level, "with --tolerance: E (energy, or % of H_q(0) = 1/2) to absorb down to, or to keep");
  sub.add("--horizon", a->horizon, "with --tolerance, contain: keep H_q >= E on [0, H] (default --tmax)");
  add_digits_option(sub, a->digits);
  add_json_flag(sub, a->json);
  return [a] { return run_design(*a); };
}

const command_registration registration{"design", install_design};

}  // namespace
}  // namespace gyrores::cli
