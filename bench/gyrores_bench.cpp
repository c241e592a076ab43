// gyrores-bench: speed against error for every way of computing the inscribed radius r_res and
// its minimiser, at every precision, against the peers a user would otherwise use, in one run.
// The main methods are the theorem's path (include/gyrores/theorem/: theorem_double in double,
// theorem_proved and theorem_report as proved enclosures, certificate); its limits are the
// theorem-aware peers (peer_newton, peer_arb_ball, peer_arb_calc: the theorem implemented without
// gyrores); the library's methods from before the theorem (ref_*, the paper's asymptotics) are
// comparison methods.
//
//   gyrores-bench --quick [--csv FILE]            the check (< 60 s): double and 1000 digits;
//                                                 (6,5), (10^12+1,10^12), (1000,1),
//                                                 (10^30+1,10^30); asymptotics, theorem (double,
//                                                 proved, report, certificate), reference
//                                                 lattice, naive TOMS 748, one evaluation, Arb,
//                                                 the theorem-aware peers; the certified paths
//                                                 and the Arb peers also at 30 and 10000 digits
//   gyrores-bench [--csv FILE] [--report FILE] [--plot-dir DIR]
//                                                 the full report (bench/run writes
//                                                 bench/RESULTS.md, results.csv and the plot)
// Other options: --methods a,b  --pairs '(6,5),(9,4)'  --precisions double,mp1000 (subsets),
// --python PATH (default $GYRORES_PYTHON or python3), --mpmath-script PATH, --no-mpmath, --list,
// --check (exit 1 when a gyrores method fails or falls short of its precision's digits: the
// ctest smoke test runs --quick --check). Bad options: a one-line error, exit 2.
//
// How a case is measured (speed_error/core.hpp, speed_error/runner.hpp): a pilot call computes
// the result, which is scored against the reference (speed_error/reference.hpp); then Google
// Benchmark times the bare computation: `iterations` calls per repetition (chosen from the pilot
// so that a repetition lasts about rep_seconds), 9 repetitions (5 with --quick, 3 for calls over
// 0.5 s), run in interleaved rounds, median of the per-call CPU times.
#include <CLI/CLI.hpp>
#include <gmp.h>
#include <mpfi.h>
#include <mpfr.h>

#include <boost/version.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "speed_error/core.hpp"
#include "speed_error/methods.hpp"
#include "speed_error/peer_mpmath.hpp"
#include "speed_error/reference.hpp"
#include "speed_error/report.hpp"
#include "speed_error/runner.hpp"

#ifndef GYRORES_BENCH_FLAGS
#define GYRORES_BENCH_FLAGS "?"
#endif
#ifndef GYRORES_BENCH_MPMATH_SCRIPT
#define GYRORES_BENCH_MPMATH_SCRIPT "mpmath_peer.py"
#endif

using namespace gyrores::bench;
using gyrores::big_int;

namespace {

struct options {
  bool quick = false, list = false, no_mpmath = false, check = false;
  std::string csv, report, plot_dir, python, mpmath_script = GYRORES_BENCH_MPMATH_SCRIPT;
  std::set<std::string> methods, pairs, precisions;
};

// The subsets of --methods, --pairs, --precisions: split on ',' outside parentheses (pairs
// contain commas).
std::set<std::string> split_list(const std::string& s) {
  std::set<std::string> out;
  std::string cur;
  int depth = 0;
  for (char ch : s) {
    if (ch == '(') ++depth;
    if (ch == ')') --depth;
    if (ch == ',' && depth == 0) {
      if (!cur.empty()) out.insert(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  if (!cur.empty()) out.insert(cur);
  return out;
}

void add_options(CLI::App& app, options& o, std::string& methods, std::string& pairs, std::string& precisions) {
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.add_flag("--quick", o.quick,
               "the check: double, 30, 1000 and 10000 digits on (6,5), (10^12+1,10^12), (1000,1), (10^30+1,10^30) "
               "(< 60 s)");
  app.add_option("--csv", o.csv,
                 "one row per (method, precision, pair): method,precision,pair,median_ns,correct_digits,evaluations")
      ->type_name("FILE");
  app.add_option("--report", o.report, "the Markdown report (bench/RESULTS.md)")->type_name("FILE");
  app.add_option("--plot-dir", o.plot_dir, "write DIR/speed_vs_error.gp (run gnuplot there for the SVG and PNG)")
      ->type_name("DIR");
  app.add_option("--methods", methods, "run only these methods, e.g. theorem_double,ref_global")->type_name("LIST");
  app.add_option("--pairs", pairs, "run only these pairs, e.g. '(6,5),(9,4)'")->type_name("LIST");
  app.add_option("--precisions", precisions, "run only these precisions, e.g. double,mp1000")->type_name("LIST");
  app.add_option("--python", o.python, "the Python of the mpmath peer (default: $GYRORES_PYTHON or python3)")
      ->type_name("PATH");
  app.add_option("--mpmath-script", o.mpmath_script, "the mpmath peer's script (bench/mpmath_peer.py)")
      ->type_name("PATH");
  app.add_flag("--no-mpmath", o.no_mpmath, "do not run the mpmath peer");
  app.add_flag("--list", o.list, "print the cases and skipped combinations, run nothing");
  app.add_flag("--check", o.check, "exit 1 if a gyrores method failed or fell short of its precision's digits");
}

// The options, or the exit status when the run ends here (help: 0, bad options: 2).
std::optional<int> parse(int argc, char** argv, options& o) {
  CLI::App app{"Speed against error of every method computing r_res and its minimiser (see bench/RESULTS.md)",
               "gyrores-bench"};
  const char* py = std::getenv("GYRORES_PYTHON");
  o.python = py ? py : "python3";
  std::string methods, pairs, precisions;
  add_options(app, o, methods, pairs, precisions);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    std::fprintf(stderr, "gyrores-bench: error: %s (see --help)\n", msg.c_str());
    return 2;
  }
  o.methods = split_list(methods);
  o.pairs = split_list(pairs);
  o.precisions = split_list(precisions);
  return std::nullopt;
}

bench_pair make_pair(const std::string& name, const std::string& group, const std::string& tau, const std::string& sigma) {
  return {name, group, gyrores::resonant_pair<big_int>(big_int(tau), big_int(sigma))};
}

std::vector<bench_pair> all_pairs() {
  return {make_pair("(6,5)", "low", "6", "5"),
          make_pair("(9,4)", "low", "9", "4"),
          make_pair("(5,1)", "low", "5", "1"),
          make_pair("(101,100)", "mid", "101", "100"),
          make_pair("(1000,1)", "mid", "1000", "1"),
          make_pair("(10^6+1,10^6)", "huge", "1000001", "1000000"),
          make_pair("(10^12+1,10^12)", "huge", "1000000000001", "1000000000000"),
          make_pair("(10^18+1,10^18)", "huge", "1000000000000000001", "1000000000000000000"),
          make_pair("(10^30+1,10^30)", "beyond 64 bits", "1000000000000000000000000000001",
                    "1000000000000000000000000000000")};
}

std::vector<precision> all_precisions() {
  return {{"double", real_kind::dbl, 16},    {"long_double", real_kind::ldbl, 19}, {"float128", real_kind::f128, 34},
          {"mp30", real_kind::mp, 30},       {"mp50", real_kind::mp, 50},          {"mp100", real_kind::mp, 100},
          {"mp1000", real_kind::mp, 1000},   {"mp10000", real_kind::mp, 10000}};
}

// ---- what runs ------------------------------------------------------------------------------

bool wanted(const std::set<std::string>& subset, const std::string& name) { return subset.empty() || subset.count(name); }

// The items of `all` (pairs, precisions, methods) in this run, in their order: with --quick only
// those named in `quick_names`, and only those of `subset` when the option gave one.
template <class Item>
std::vector<Item> selected(const std::vector<Item>& all, bool quick, const std::set<std::string>& quick_names,
                           const std::set<std::string>& subset) {
  std::vector<Item> out;
  for (const auto& item : all)
    if ((!quick || quick_names.count(item.name)) && wanted(subset, item.name)) out.push_back(item);
  return out;
}

std::vector<method_def> all_methods(const options& opt, const run_config& cfg) {
  std::vector<method_def> all = library_methods(cfg);
  for (auto& m : theorem_peer_methods(cfg)) all.push_back(m);
  if (!opt.quick)
    for (auto& m : odeint_methods(cfg)) all.push_back(m);
  for (auto& m : arb_methods(cfg)) all.push_back(m);
  return all;
}

// Quick mode: 30 and 10000 digits only for the certified paths and the Arb peers they are
// measured against (headline L2).
bool quick_excluded(const options& opt, const method_def& m, const precision& pr) {
  if (!opt.quick) return false;
  if (pr.name == "mp30" || pr.name == "mp10000")
    return !std::set<std::string>{"certificate", "theorem_proved", "theorem_report", "peer_arb_ball", "peer_arb_calc"}
                .count(m.name);
  return false;
}

void print_list(const run_plan& plan) {
  for (const auto& p : plan.cases)
    std::printf("run  %-28s %-12s %s\n", p.method->name.c_str(), p.prec->name.c_str(), p.pair->name.c_str());
  for (const auto& s : plan.skips)
    std::printf("skip %-28s %-12s %-18s %s\n", s.method.c_str(), s.precision.c_str(), s.pair.c_str(), s.reason.c_str());
}

// ---- the run's context (machine, libraries) ---------------------------------------------------

std::string read_first_line_matching(const std::string& file, const std::string& key) {
  std::ifstream f(file);
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(key, 0) == 0) {
      auto p = line.find(':');
      if (p != std::string::npos) {
        std::string v = line.substr(p + 1);
        while (!v.empty() && v.front() == ' ') v.erase(v.begin());
        return v;
      }
    }
  return "unknown";
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  f >> a >> b >> c;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f/%.2f/%.2f", a, b, c);
  return buf;
}

std::string library_versions() {
  std::ostringstream lib;
  lib << "Boost " << BOOST_VERSION / 100000 << '.' << BOOST_VERSION / 100 % 1000 << " (Math, Multiprecision, Odeint), "
      << "GMP " << gmp_version << ", MPFR " << mpfr_get_version() << ", MPFI " << mpfi_get_version()
      << ", Google Benchmark 1.7.1";
  if (arb_available()) lib << ", " << arb_library_version();
  else lib << ", Arb: not built (libflint-arb-dev missing; Arb rows skipped)";
  return lib.str();
}

run_context describe_run(int argc, char** argv, const options& opt) {
  run_context ctx;
  ctx.quick = opt.quick;
  ctx.load_before = load_average();
  std::ostringstream cmd;
  cmd << "gyrores-bench";
  for (int i = 1; i < argc; ++i) cmd << ' ' << argv[i];
  ctx.command = opt.report.empty() ? cmd.str() : "bench/run";
  std::time_t now = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  ctx.date = buf;
  ctx.cpu = read_first_line_matching("/proc/cpuinfo", "model name");
  ctx.cores = std::to_string(std::thread::hardware_concurrency());
  ctx.compiler = std::string("g++ ") + __VERSION__;
  ctx.flags = GYRORES_BENCH_FLAGS;
  ctx.libraries = library_versions();
  return ctx;
}

// ---- after the timing -----------------------------------------------------------------------

// The mpmath peer, in the same run (not in --quick, nor with --no-mpmath or a --methods list
// without it). Its rows are appended to `rows`.
void run_mpmath(const options& opt, const char* argv0, const std::vector<bench_pair>& pairs,
                const std::vector<precision>& precisions, const std::map<std::string, reference>& refs,
                run_context& ctx, std::vector<measurement>& rows) {
  if (opt.quick || opt.no_mpmath || !wanted(opt.methods, "mpmath_findroot")) {
    ctx.mpmath_status = opt.quick ? "not part of --quick" : "disabled (--no-mpmath or --methods)";
    return;
  }
  std::string script = opt.mpmath_script;
  if (!std::filesystem::exists(script)) {
    auto alt = std::filesystem::path(argv0).parent_path() / "../share/gyrores/mpmath_peer.py";
    if (std::filesystem::exists(alt)) script = alt.string();
  }
  std::fprintf(stderr, "mpmath peer ...\n");
  auto mp = run_mpmath_peer(opt.python, script, pairs, precisions, refs);
  ctx.mpmath_status = mp.status;
  for (auto& m : mp.rows) rows.push_back(m);
}

void print_summary(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs, const run_context& ctx) {
  std::printf("%-28s %-12s %-18s %12s %8s %8s %8s %8s\n", "method", "precision", "pair", "median", "digits", "theta",
              "r_res", "evals");
  for (const auto& m : rows)
    std::printf("%-28s %-12s %-18s %12s %8s %8s %8s %8s%s\n", m.method.c_str(), m.precision.c_str(), m.pair.c_str(),
                m.failed ? "failed" : format_time(m.median_ns).c_str(), format_digits(m.digits()).c_str(),
                format_digits(m.digits_theta).c_str(), format_digits(m.digits_r).c_str(),
                m.evaluations ? std::to_string(*m.evaluations).c_str() : "", m.failed ? (" " + m.note).c_str() : "");
  std::printf("\nHeadline ratios (this run):\n");
  for (const auto& h : compute_headlines(rows, pairs)) {
    if (h.values.empty()) continue;
    std::printf("%s %s: %d of %d met\n", h.id.c_str(), h.target.c_str(), h.met, h.total);
    for (const auto& [k, v] : h.values) std::printf("    %-26s %s\n", k.c_str(), v.c_str());
  }
  std::printf("\ntotal %.1f s (references %.1f s), load average %s -> %s\n", ctx.seconds, ctx.reference_seconds,
              ctx.load_before.c_str(), ctx.load_after.c_str());
}

// --check: the library's methods (the theorem's path and the references from before it) and the
// theorem-aware peers must deliver their precision: digits >= nominal - 1.5 (certificates: at
// least the digits they claim; a proved enclosure must also hold the reference, and the Arb
// peers' roundings must be the reference's). Prints each short row; returns their count.
int check_rows(const std::vector<measurement>& rows, const std::vector<precision>& precisions) {
  int bad = 0;
  const std::set<std::string> checked{"theorem_double",    "theorem_proved",    "theorem_report", "certificate",
                                      "ref_lattice",       "ref_newton_polish", "ref_toms748_local", "ref_global",
                                      "peer_newton",       "peer_arb_ball",     "peer_arb_calc"};
  for (const auto& m : rows) {
    if (!checked.count(m.method)) continue;
    double nominal = 0;
    for (const auto& pr : precisions)
      if (pr.name == m.precision) nominal = pr.digits;
    const double need = m.method == "certificate" ? nominal : nominal - 1.5;
    if (m.note.find("ENCLOSURE MISSES") != std::string::npos || m.note.find("DIFFERS") != std::string::npos) {
      std::printf("CHECK FAILED: %s %s %s: %s\n", m.method.c_str(), m.precision.c_str(), m.pair.c_str(),
                  m.note.c_str());
      ++bad;
      continue;
    }
    if (m.failed || !(m.digits() >= need) || !(m.median_ns > 0)) {
      std::printf("CHECK FAILED: %s %s %s: %s digits (need %.1f)%s\n", m.method.c_str(), m.precision.c_str(),
                  m.pair.c_str(), format_digits(m.digits()).c_str(), need, m.failed ? (" " + m.note).c_str() : "");
      ++bad;
    }
  }
  std::printf("check: %d of the library's and the theorem-aware peers' rows short of their precision\n", bad);
  return bad;
}

// Reference digits: beyond the most precise result measured.
unsigned reference_digits_for(const std::vector<precision>& precisions) {
  unsigned max_digits = 16;
  for (const auto& pr : precisions) max_digits = std::max(max_digits, pr.digits);
  return max_digits + std::max(100u, max_digits / 10);
}

}  // namespace

int main(int argc, char** argv) {
  options opt;
  if (auto status = parse(argc, argv, opt)) return *status;
  const auto t_start = std::chrono::steady_clock::now();
  run_context ctx = describe_run(argc, argv, opt);
  run_config cfg;
  cfg.quick = opt.quick;
  cfg.rep_seconds = opt.quick ? 0.01 : 0.02;
  // 9 repetitions in the full run: its medians decide the headline ratios, and on a shared machine a
  // median of 5 short repetitions still moves with one burst of load.
  cfg.repetitions = opt.quick ? 5 : 9;

  const std::vector<bench_pair> pairs =
      selected(all_pairs(), opt.quick, {"(6,5)", "(10^12+1,10^12)", "(1000,1)", "(10^30+1,10^30)"}, opt.pairs);
  const std::vector<precision> precisions =
      selected(all_precisions(), opt.quick, {"double", "mp30", "mp1000", "mp10000"}, opt.precisions);
  const std::vector<method_def> methods =
      selected(all_methods(opt, cfg), opt.quick,
               {"theta_asy", "r_res_asy", "theorem_double", "theorem_proved", "theorem_report", "ref_lattice",
                "naive_toms748", "one_eval", "arb_newton", "certificate", "peer_newton", "peer_arb_ball",
                "peer_arb_calc"},
               opt.methods);
  const run_plan plan = plan_cases(pairs, precisions, methods, [&](const method_def& m, const precision& pr) {
    return quick_excluded(opt, m, pr);
  });
  if (opt.list) {
    print_list(plan);
    return 0;
  }

  ctx.reference_digits = reference_digits_for(precisions);
  const auto refs = compute_references(pairs, ctx.reference_digits, ctx.reference_seconds);
  piloted_run run = run_pilots(plan, refs, cfg);
  time_cases(run);
  std::vector<measurement>& rows = run.rows;
  run_mpmath(opt, argv[0], pairs, precisions, refs, ctx, rows);
  ctx.load_after = load_average();
  ctx.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();

  if (!opt.csv.empty()) write_csv(opt.csv, rows);
  if (!opt.report.empty()) write_markdown(opt.report, ctx, rows, plan.skips, methods, pairs, precisions, refs);
  if (!opt.plot_dir.empty()) write_plot_script(opt.plot_dir, ctx, rows, methods, pairs);
  print_summary(rows, pairs, ctx);
  if (opt.check) return check_rows(rows, precisions) ? 1 : 0;
  return 0;
}
