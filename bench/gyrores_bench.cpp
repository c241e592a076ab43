// gyrores-bench: speed against error for every way of computing the inscribed radius r_res and
// its minimiser, at every precision, against the peers a user would otherwise use, in one run.
//
//   gyrores-bench --quick [--csv FILE]            the check (< 60 s): double and 1000 digits;
//                                                 (6,5), (10^12+1,10^12), (1000,1); asymptotics,
//                                                 exact, naive TOMS 748, one evaluation, Arb,
//                                                 certified at 30 digits
//   gyrores-bench [--csv FILE] [--report FILE] [--plot-dir DIR]
//                                                 the full report (bench/run writes
//                                                 bench/RESULTS.md, results.csv and the plot)
// Other options: --methods a,b  --pairs '(6,5),(9,4)'  --precisions double,mp1000 (subsets),
// --python PATH (default $GYRORES_PYTHON or python3), --mpmath-script PATH, --no-mpmath, --list,
// --check (exit 1 when a gyrores method fails or falls short of its precision's digits: the
// ctest smoke test runs --quick --check).
//
// How a case is measured (speed_error/core.hpp): a pilot call computes the result, which is
// scored against the reference (speed_error/reference.hpp); then Google Benchmark times the bare
// computation: `iterations` calls per repetition (chosen from the pilot so that a repetition lasts
// about rep_seconds), 5 repetitions (3 for calls over 0.5 s), run in interleaved rounds, median
// of the per-call CPU times.
#include <benchmark/benchmark.h>
#include <gmp.h>
#include <mpfi.h>
#include <mpfr.h>
#include <time.h>

#include <boost/version.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
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

std::set<std::string> split_list(const std::string& s) {
  // Pairs contain commas: split on ',' outside parentheses.
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

void usage() {
  std::puts(
      "usage: gyrores-bench [--quick] [--csv FILE] [--report FILE] [--plot-dir DIR]\n"
      "                     [--methods LIST] [--pairs LIST] [--precisions LIST]\n"
      "                     [--python PATH] [--mpmath-script PATH] [--no-mpmath] [--list]\n"
      "Speed against error of every method computing r_res and its minimiser (see bench/RESULTS.md).\n"
      "  --quick       the check: double and 1000 digits on (6,5), (10^12+1,10^12), (1000,1) (< 60 s)\n"
      "  --csv FILE    one row per (method, precision, pair):\n"
      "                method,precision,pair,median_ns,correct_digits,evaluations\n"
      "  --report FILE the Markdown report (bench/RESULTS.md)\n"
      "  --plot-dir D  write D/speed_vs_error.gp (run gnuplot there for the SVG and PNG)\n"
      "  --list        print the cases and skipped combinations, run nothing\n"
      "  --check       exit 1 if a gyrores method failed or fell short of its precision's digits");
}

options parse(int argc, char** argv) {
  options o;
  const char* py = std::getenv("GYRORES_PYTHON");
  o.python = py ? py : "python3";
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "gyrores-bench: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--quick") o.quick = true;
    else if (a == "--list") o.list = true;
    else if (a == "--check") o.check = true;
    else if (a == "--no-mpmath") o.no_mpmath = true;
    else if (a == "--csv") o.csv = next();
    else if (a == "--report") o.report = next();
    else if (a == "--plot-dir") o.plot_dir = next();
    else if (a == "--python") o.python = next();
    else if (a == "--mpmath-script") o.mpmath_script = next();
    else if (a == "--methods") o.methods = split_list(next());
    else if (a == "--pairs") o.pairs = split_list(next());
    else if (a == "--precisions") o.precisions = split_list(next());
    else if (a == "--help" || a == "-h") {
      usage();
      std::exit(0);
    } else {
      std::fprintf(stderr, "gyrores-bench: unknown option %s (see --help)\n", a.c_str());
      std::exit(2);
    }
  }
  return o;
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

double thread_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

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

// Collects the CPU time per call of every repetition (one Google Benchmark run per
// repetition, named "<case>#<round>"); prints one line per run.
class round_reporter : public benchmark::BenchmarkReporter {
 public:
  std::map<std::string, std::vector<double>> ns;
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred) continue;
      const std::string full = r.run_name.function_name;
      const std::string name = full.substr(0, full.rfind('#'));
      const double t = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e9;
      ns[name].push_back(t);
      std::fprintf(stderr, "  %-56s %12s\n", full.c_str(), format_time(t).c_str());
    }
  }
};

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv) {
  options opt = parse(argc, argv);
  const auto t_start = std::chrono::steady_clock::now();
  run_context ctx;
  ctx.quick = opt.quick;
  ctx.load_before = load_average();
  {
    std::ostringstream cmd;
    cmd << "gyrores-bench";
    for (int i = 1; i < argc; ++i) cmd << ' ' << argv[i];
    ctx.command = opt.report.empty() ? cmd.str() : "bench/run";
  }
  {
    std::time_t now = std::time(nullptr);
    char buf[64];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    ctx.date = buf;
  }
  ctx.cpu = read_first_line_matching("/proc/cpuinfo", "model name");
  ctx.cores = std::to_string(std::thread::hardware_concurrency());
  ctx.compiler = std::string("g++ ") + __VERSION__;
  ctx.flags = GYRORES_BENCH_FLAGS;
  {
    std::ostringstream lib;
    lib << "Boost " << BOOST_VERSION / 100000 << '.' << BOOST_VERSION / 100 % 1000 << " (Math, Multiprecision, Odeint), "
        << "GMP " << gmp_version << ", MPFR " << mpfr_get_version() << ", MPFI " << mpfi_get_version()
        << ", Google Benchmark 1.7.1";
    if (arb_available()) lib << ", " << arb_library_version();
    else lib << ", Arb: not built (libflint-arb-dev missing; Arb rows skipped)";
    ctx.libraries = lib.str();
  }

  run_config cfg;
  cfg.quick = opt.quick;
  cfg.rep_seconds = opt.quick ? 0.01 : 0.02;
  cfg.repetitions = 5;

  // Pairs, precisions and methods of this run.
  std::vector<bench_pair> pairs;
  for (auto& bp : all_pairs()) {
    if (opt.quick && bp.name != "(6,5)" && bp.name != "(10^12+1,10^12)" && bp.name != "(1000,1)") continue;
    if (!opt.pairs.empty() && !opt.pairs.count(bp.name)) continue;
    pairs.push_back(bp);
  }
  std::vector<precision> precisions;
  for (auto& pr : all_precisions()) {
    if (opt.quick && pr.name != "double" && pr.name != "mp30" && pr.name != "mp1000") continue;
    if (!opt.precisions.empty() && !opt.precisions.count(pr.name)) continue;
    precisions.push_back(pr);
  }
  std::vector<method_def> methods;
  for (auto& m : library_methods(cfg)) methods.push_back(m);
  if (!opt.quick)
    for (auto& m : odeint_methods(cfg)) methods.push_back(m);
  for (auto& m : arb_methods(cfg)) methods.push_back(m);
  const std::set<std::string> quick_methods{"theta_asy", "r_res_asy", "exact", "naive_toms748",
                                            "one_eval",  "arb_newton", "certified"};
  {
    std::vector<method_def> kept;
    for (auto& m : methods) {
      if (opt.quick && !quick_methods.count(m.name)) continue;
      if (!opt.methods.empty() && !opt.methods.count(m.name)) continue;
      kept.push_back(m);
    }
    methods = kept;
  }
  // Quick mode: 30 digits only for the certified-vs-uncertified pair of rows.
  auto quick_excluded = [&](const method_def& m, const precision& pr) {
    if (!opt.quick) return false;
    if (pr.name == "mp30") return m.name != "certified" && m.name != "exact";
    if (m.name == "certified") return pr.name != "mp30";
    return false;
  };

  // Cases and skips.
  std::vector<skip_note> skips;
  struct planned {
    const method_def* m;
    const bench_pair* bp;
    const precision* pr;
  };
  std::vector<planned> plan;
  // Pair-major order: the rows a headline compares (same pair and precision) run next to each other.
  for (const auto& bp : pairs)
    for (const auto& pr : precisions)
      for (const auto& m : methods) {
        if (quick_excluded(m, pr)) continue;
        const std::string why = m.skip(bp, pr);
        if (!why.empty()) skips.push_back({m.name, pr.name, bp.name, why});
        else plan.push_back({&m, &bp, &pr});
      }
  if (opt.list) {
    for (const auto& p : plan) std::printf("run  %-28s %-12s %s\n", p.m->name.c_str(), p.pr->name.c_str(), p.bp->name.c_str());
    for (const auto& s : skips)
      std::printf("skip %-28s %-12s %-18s %s\n", s.method.c_str(), s.precision.c_str(), s.pair.c_str(), s.reason.c_str());
    return 0;
  }

  // References.
  unsigned max_digits = 16;
  for (const auto& pr : precisions) max_digits = std::max(max_digits, pr.digits);
  ctx.reference_digits = max_digits + std::max(100u, max_digits / 10);
  std::map<std::string, reference> refs;
  {
    const auto t0 = std::chrono::steady_clock::now();
    for (const auto& bp : pairs) {
      std::fprintf(stderr, "reference %-18s at %u digits ...", bp.name.c_str(), ctx.reference_digits);
      refs[bp.name] = compute_reference(bp, ctx.reference_digits);
      std::fprintf(stderr, " %.2f s (%s)\n", refs[bp.name].seconds, refs[bp.name].global ? "global" : "local");
    }
    ctx.reference_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  // Pilots: result, score, cost per call.
  std::vector<measurement> rows;
  std::vector<bench_case> cases;
  std::vector<std::size_t> row_of_case;
  std::fprintf(stderr, "pilots (%zu cases) ...\n", plan.size());
  for (const auto& p : plan) {
    measurement m;
    m.method = p.m->name;
    m.precision = p.pr->name;
    m.pair = p.bp->name;
    try {
      bench_case c = p.m->make(*p.bp, *p.pr, refs.at(p.bp->name));
      double t0 = thread_cpu_seconds();
      outcome o = c.pilot();
      double one = thread_cpu_seconds() - t0;
      if (one < 0.2) {  // a second, bare call: first calls pay for caches (e.g. MPFR's pi)
        t0 = thread_cpu_seconds();
        c.timed();
        one = thread_cpu_seconds() - t0;
      }
      score(m, o, refs.at(p.bp->name));
      m.repetitions = one > 0.5 ? 3 : cfg.repetitions;
      m.iterations = std::max<std::int64_t>(1, std::int64_t(cfg.rep_seconds / std::max(one, 1e-9)));
      row_of_case.push_back(rows.size());
      cases.push_back(std::move(c));
    } catch (const std::exception& e) {
      m.failed = true;
      m.note = e.what();
      m.digits_theta = m.digits_r = 0;
      std::fprintf(stderr, "  %-28s %-12s %-18s FAILED: %s\n", m.method.c_str(), m.precision.c_str(), m.pair.c_str(),
                   e.what());
    }
    rows.push_back(m);
  }

  // Timing: one Google Benchmark run over every case, in rounds: round r runs repetition r of
  // every case (in the pair-major order), so slow drifts of the shared machine's load affect
  // every case alike instead of whichever ran during a busy minute.
  {
    int bargc = 1;
    char arg0[] = "gyrores-bench";
    char* bargv[] = {arg0, nullptr};
    benchmark::Initialize(&bargc, bargv);
    int rounds = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) rounds = std::max(rounds, rows[row_of_case[i]].repetitions);
    for (int round = 0; round < rounds; ++round)
      for (std::size_t i = 0; i < cases.size(); ++i) {
        const measurement& m = rows[row_of_case[i]];
        if (round >= m.repetitions) continue;
        const std::string name = m.method + " " + m.precision + " " + m.pair + "#" + std::to_string(round);
        auto fn = cases[i].timed;
        benchmark::RegisterBenchmark(name.c_str(), [fn](benchmark::State& st) {
          for (auto _ : st) fn();
        })
            ->Iterations(m.iterations)
            ->Unit(benchmark::kNanosecond);
      }
    std::fprintf(stderr, "timing (%zu cases, %d rounds) ...\n", cases.size(), rounds);
    round_reporter rep;
    benchmark::RunSpecifiedBenchmarks(&rep);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      measurement& m = rows[row_of_case[i]];
      auto it = rep.ns.find(m.method + " " + m.precision + " " + m.pair);
      if (it != rep.ns.end() && !it->second.empty()) {
        m.median_ns = median_of(it->second);
        m.repetitions = int(it->second.size());
      }
    }
    benchmark::Shutdown();
  }

  // Peer (b): mpmath, in the same run.
  if (!opt.quick && !opt.no_mpmath && (opt.methods.empty() || opt.methods.count("mpmath_findroot"))) {
    std::string script = opt.mpmath_script;
    if (!std::filesystem::exists(script)) {
      auto alt = std::filesystem::path(argv[0]).parent_path() / "../share/gyrores/mpmath_peer.py";
      if (std::filesystem::exists(alt)) script = alt.string();
    }
    std::fprintf(stderr, "mpmath peer ...\n");
    auto mp = run_mpmath_peer(opt.python, script, pairs, precisions, refs);
    ctx.mpmath_status = mp.status;
    for (auto& m : mp.rows) rows.push_back(m);
  } else {
    ctx.mpmath_status = opt.quick ? "not part of --quick" : "disabled (--no-mpmath or --methods)";
  }

  ctx.load_after = load_average();
  ctx.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();

  // Outputs.
  if (!opt.csv.empty()) write_csv(opt.csv, rows);
  if (!opt.report.empty()) write_markdown(opt.report, ctx, rows, skips, methods, pairs, precisions, refs);
  if (!opt.plot_dir.empty()) write_plot_script(opt.plot_dir, ctx, rows, methods, pairs);

  // Console summary.
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
  if (opt.check) {
    // The library's exact methods must deliver their precision: digits >= nominal - 1.5
    // (certificates: at least the digits they claim).
    int bad = 0;
    const std::set<std::string> exact_methods{"exact", "newton_doubling", "toms748_local", "global", "certified"};
    for (const auto& m : rows) {
      if (!exact_methods.count(m.method)) continue;
      double nominal = 0;
      for (const auto& pr : precisions)
        if (pr.name == m.precision) nominal = pr.digits;
      const double need = m.method == "certified" ? nominal : nominal - 1.5;
      if (m.failed || !(m.digits() >= need) || !(m.median_ns > 0)) {
        std::printf("CHECK FAILED: %s %s %s: %s digits (need %.1f)%s\n", m.method.c_str(), m.precision.c_str(),
                    m.pair.c_str(), format_digits(m.digits()).c_str(), need, m.failed ? (" " + m.note).c_str() : "");
        ++bad;
      }
    }
    std::printf("check: %d of the library's rows short of their precision\n", bad);
    return bad ? 1 : 0;
  }
  return 0;
}
