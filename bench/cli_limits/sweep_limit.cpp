// gyrores-sweep-limit: the floor `gyrores sweep` is measured against (bench/cli_overhead.py):
// the same sweep in memory, with the kernel the CLI runs and nothing else. It enumerates the
// pairs of orders 3..M and evaluates each by sweep_run<double> (the engine's workers, the path
// without rows of src/lib/sweep/fast.cpp), merging every block into one accumulator (counts,
// examples, extremes and every t_first/(pi/|n|) in memory) on the calling thread: no file, no
// resume state, no process start-up. The quantiles the summary prints are timed apart.
//
//   gyrores-sweep-limit M [THREADS]     (THREADS default 2: the machine of the targets)
//
// One line of JSON on stdout: pairs, the sweep's wall and process CPU seconds, the quantiles'
// wall and CPU seconds, and the quantiles themselves (a cross-check against the CLI's summary).
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gyrores/sweep/sweep.hpp>

namespace {

double process_cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: gyrores-sweep-limit MAX_ORDER [THREADS]\n");
    return 2;
  }
  gyrores::sweep_config cfg;
  cfg.max_order = std::atoll(argv[1]);
  cfg.digits = 15;  // what `gyrores sweep` runs by default (double)
  gyrores::sweep_engine_options eo;
  eo.threads = argc > 2 ? unsigned(std::atoi(argv[2])) : 2;
  eo.block_size = 8192;  // the CLI's block size without rows (src/app/sweep.cpp)
  if (cfg.max_order < 3 || eo.threads < 1) {
    std::fprintf(stderr, "gyrores-sweep-limit: MAX_ORDER must be >= 3 and THREADS >= 1\n");
    return 2;
  }
  gyrores::sweep_accumulator acc;
  acc.max_examples = cfg.max_examples;
  const double c0 = process_cpu_seconds(), w0 = wall_seconds();
  const auto out = gyrores::sweep_run<double>(cfg, eo, [&](gyrores::sweep_block& b) { acc.merge(b.summary); });
  const double c1 = process_cpu_seconds(), w1 = wall_seconds();
  const auto q = acc.quantiles();
  const double c2 = process_cpu_seconds(), w2 = wall_seconds();
  if (!out.complete || out.done != acc.pairs) {
    std::fprintf(stderr, "gyrores-sweep-limit: the sweep did not complete\n");
    return 3;
  }
  std::printf(
      "{\"pairs\": %llu, \"threads\": %u, \"sweep_wall\": %.6f, \"sweep_cpu\": %.6f, \"quantiles_wall\": %.6f, "
      "\"quantiles_cpu\": %.6f, \"values\": %llu, \"median\": %.17g, \"p99\": %.17g}\n",
      static_cast<unsigned long long>(acc.pairs), out.threads, w1 - w0, c1 - c0, w2 - w1, c2 - c1,
      static_cast<unsigned long long>(q.count), q.median, q.p99);
  return 0;
}
