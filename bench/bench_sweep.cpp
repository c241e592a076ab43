// Sweep throughput: pairs per second of a summary-only sweep (sweep.hpp), with Google Benchmark.
// Counters: pairs_per_s (wall clock) and pairs_per_cpu_s (process CPU time, i.e. what the
// machine could do if it were idle; the bench machine is shared).
//
//   bench_sweep                                   orders <= 2000 in double (1, 2 threads), the
//                                                 certified sweep, MPFR rows at 40 digits (1, 2
//                                                 threads)
//   GYRORES_BENCH_SWEEP_FULL=1 bench_sweep --benchmark_filter=full
//                                                 the speed target: every pair of order <= 10^4
//                                                 (1.52e7 pairs), the default checks, all cores, once
// The same number comes from the CLI: `gyrores sweep --max-order 10000` prints pairs/s.
// Arguments of each case: max_order, threads, checks (bit mask, sweep.hpp order), mode (0 double,
// 1 double --certified, 2 mpfr_real at 40 digits). The work is
// deterministic (the enumeration), so there is no seed.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <gyrores/sweep/sweep.hpp>

namespace {

double process_cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

template <class T> std::uint64_t run_once(const gyrores::sweep_config& c, const gyrores::sweep_engine_options& eo,
                                           gyrores::sweep_accumulator& acc) {
  return gyrores::sweep_run<T>(c, eo, [&](gyrores::sweep_block& b) { acc.merge(b.summary); }).done;
}

void sweep_summary_only(benchmark::State& st) {
  gyrores::sweep_config c;
  c.max_order = st.range(0);
  c.checks = gyrores::sweep_check_set(st.range(2));
  const auto mode = st.range(3);
  c.certified = mode == 1;
  if (mode == 2) c.digits = 40;
  gyrores::sweep_engine_options eo;
  eo.threads = unsigned(st.range(1));
  std::uint64_t pairs = 0;
  double cpu = 0;
  for (auto _ : st) {
    gyrores::sweep_accumulator acc;
    const double c0 = process_cpu_seconds();
    const std::uint64_t done = mode == 2 ? run_once<gyrores::mpfr_real>(c, eo, acc) : run_once<double>(c, eo, acc);
    auto q = acc.quantiles();
    cpu += process_cpu_seconds() - c0;
    benchmark::DoNotOptimize(q.median);
    pairs += done;
  }
  st.counters["pairs"] = double(pairs) / double(st.iterations());
  st.counters["pairs_per_s"] = benchmark::Counter(double(pairs), benchmark::Counter::kIsRate);
  st.counters["pairs_per_cpu_s"] = double(pairs) / cpu;
}

constexpr std::int64_t defaults = gyrores::sweep_default_checks;
const std::vector<std::string> arg_names = {"max_order", "threads", "checks", "mode"};

BENCHMARK(sweep_summary_only)
    ->Name("sweep/M2000/default-checks")
    ->Args({2000, 1, defaults, 0})
    ->Args({2000, 2, defaults, 0})
    ->ArgNames(arg_names)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(sweep_summary_only)
    ->Name("sweep/M1000/certified")
    ->Args({1000, 2, defaults, 1})
    ->ArgNames(arg_names)
    ->UseRealTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(sweep_summary_only)
    ->Name("sweep/M500/mpfr40")
    ->Args({500, 1, defaults, 2})
    ->Args({500, 2, defaults, 2})
    ->ArgNames(arg_names)
    ->UseRealTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// The speed target (1.52e7 pairs, once): only with GYRORES_BENCH_SWEEP_FULL=1.
const bool full_registered = [] {
  const char* e = std::getenv("GYRORES_BENCH_SWEEP_FULL");
  if (e && *e && *e != '0')
    benchmark::RegisterBenchmark("sweep/full/M10000/default-checks", sweep_summary_only)
        ->Args({10000, 0, defaults, 0})
        ->ArgNames(arg_names)
        ->UseRealTime()
        ->Iterations(1)
        ->Unit(benchmark::kSecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
