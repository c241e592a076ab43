// speed_error/runner.hpp: the plan, the references, the pilots and the timing.
#include "runner.hpp"

#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <utility>

#include "report.hpp"

namespace gyrores::bench {

namespace {

double thread_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
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

std::string case_name(const measurement& m) { return m.method + " " + m.precision + " " + m.pair; }

// The pilot of one case: its outcome scored into `m`, the cost of one call chosen from it.
void pilot_case(bench_case& c, measurement& m, const reference& ref, const run_config& cfg) {
  double t0 = thread_cpu_seconds();
  outcome o = c.pilot();
  double one = thread_cpu_seconds() - t0;
  if (one < 0.2) {  // a second, bare call: first calls pay for caches (e.g. MPFR's pi)
    t0 = thread_cpu_seconds();
    c.timed();
    one = thread_cpu_seconds() - t0;
  }
  score(m, o, ref);
  m.repetitions = one > 0.5 ? 3 : cfg.repetitions;
  m.iterations = std::max<std::int64_t>(1, std::int64_t(cfg.rep_seconds / std::max(one, 1e-9)));
}

}  // namespace

run_plan plan_cases(const std::vector<bench_pair>& pairs, const std::vector<precision>& precisions,
                    const std::vector<method_def>& methods,
                    const std::function<bool(const method_def&, const precision&)>& excluded) {
  run_plan plan;
  for (const auto& bp : pairs)
    for (const auto& pr : precisions)
      for (const auto& m : methods) {
        if (excluded(m, pr)) continue;
        const std::string why = m.skip(bp, pr);
        if (!why.empty()) plan.skips.push_back({m.name, pr.name, bp.name, why});
        else plan.cases.push_back({&m, &bp, &pr});
      }
  return plan;
}

std::map<std::string, reference> compute_references(const std::vector<bench_pair>& pairs, unsigned digits,
                                                    double& seconds) {
  std::map<std::string, reference> refs;
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& bp : pairs) {
    std::fprintf(stderr, "reference %-18s at %u digits ...", bp.name.c_str(), digits);
    refs[bp.name] = compute_reference(bp, digits);
    std::fprintf(stderr, " %.2f s (%s)\n", refs[bp.name].seconds, refs[bp.name].global ? "global" : "local");
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return refs;
}

piloted_run run_pilots(const run_plan& plan, const std::map<std::string, reference>& refs, const run_config& cfg) {
  piloted_run run;
  std::fprintf(stderr, "pilots (%zu cases) ...\n", plan.cases.size());
  for (const auto& p : plan.cases) {
    measurement m;
    m.method = p.method->name;
    m.precision = p.prec->name;
    m.pair = p.pair->name;
    try {
      bench_case c = p.method->make(*p.pair, *p.prec, refs.at(p.pair->name));
      pilot_case(c, m, refs.at(p.pair->name), cfg);
      run.row_of_case.push_back(run.rows.size());
      run.cases.push_back(std::move(c));
    } catch (const std::exception& e) {
      m.failed = true;
      m.note = e.what();
      m.digits_theta = m.digits_r = 0;
      std::fprintf(stderr, "  %-28s %-12s %-18s FAILED: %s\n", m.method.c_str(), m.precision.c_str(), m.pair.c_str(),
                   e.what());
    }
    run.rows.push_back(m);
  }
  return run;
}

void time_cases(piloted_run& run) {
  int bargc = 1;
  char arg0[] = "gyrores-bench";
  char* bargv[] = {arg0, nullptr};
  benchmark::Initialize(&bargc, bargv);
  int rounds = 0;
  for (std::size_t i = 0; i < run.cases.size(); ++i) rounds = std::max(rounds, run.rows[run.row_of_case[i]].repetitions);
  for (int round = 0; round < rounds; ++round)
    for (std::size_t i = 0; i < run.cases.size(); ++i) {
      const measurement& m = run.rows[run.row_of_case[i]];
      if (round >= m.repetitions) continue;
      const std::string name = case_name(m) + "#" + std::to_string(round);
      auto fn = run.cases[i].timed;
      benchmark::RegisterBenchmark(name.c_str(), [fn](benchmark::State& st) {
        for (auto _ : st) fn();
      })
          ->Iterations(m.iterations)
          ->Unit(benchmark::kNanosecond);
    }
  std::fprintf(stderr, "timing (%zu cases, %d rounds) ...\n", run.cases.size(), rounds);
  round_reporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  for (std::size_t i = 0; i < run.cases.size(); ++i) {
    measurement& m = run.rows[run.row_of_case[i]];
    auto it = rep.ns.find(case_name(m));
    if (it != rep.ns.end() && !it->second.empty()) {
      m.median_ns = median_of(it->second);
      m.round_ns = it->second;  // the reporter receives the runs in registration order: round by round
      m.repetitions = int(it->second.size());
    }
  }
  benchmark::Shutdown();
}

}  // namespace gyrores::bench
