// Cost of the exact inscribed radius (lattice method) against cheaper and naive alternatives.
// A report, not a test: nothing is asserted.
//
//  exact_double/<pair>   inscribed_lattice<double>: the exact r_res, all minimisers, O(log tau)
//  theta_asy/<pair>      the paper's theta_asy alone (asymptotic.hpp theta_asy_only<double>:
//                        k = round(a/(2b)), one bracketed root of u + tan u = s); heuristic, and
//                        defined only for x = b/a < 1/2, so not for (10^9, 1)
//  exact_1000/<pair>     inscribed_lattice<mpfr_real> at 1000 digits
//  one_eval_1000/<pair>  one evaluation of (q, q', z, z') at the same precision (lobe_eval): the
//                        unit of work; exact_1000/one_eval_1000 = cost in "evaluations"
//  naive_1000/<pair>     plain Boost TOMS 748 on the naive q'(theta) (sin/cos of tau*theta formed
//                        directly) over the fast half-period holding the minimiser, to full
//                        precision (eps_tolerance(bits - 2)), then |q| there
// Every benchmark runs 5 repetitions and reports the median; the ratios at the end are formed
// from the medians of this one run (CPU time). Pairs and inputs are fixed (no randomness).
// Counter `evals`: q' evaluations of the root solvers (exact: scout + polish, as reported in
// inscribed_result::evaluations; naive: TOMS 748 calls). Before the benchmarks, the program
// prints how far the naive 1000-digit r_res is from the exact one (the naive route is accurate
// at 1000 digits for these pairs; only its cost differs). Whole run: ~50 s wall on 2 shared cores.
#include <benchmark/benchmark.h>

#include <boost/math/constants/constants.hpp>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/model/resonant.hpp>
#include "testing/naive_toms748.hpp"

using gyrores::big_int;
using gyrores::mpfr_real;
using pair64 = gyrores::resonant_pair<std::int64_t>;

namespace {

constexpr unsigned kDigits = 1000;
constexpr int kRepetitions = 5;

struct named_pair {
  std::string name;
  pair64 p;
};

const std::vector<named_pair>& double_pairs() {
  static const std::vector<named_pair> v{{"(6,5)", pair64(6, 5)},
                                         {"(10^6+1,10^6)", pair64(1000001, 1000000)},
                                         {"(10^18+1,10^18)", pair64(1000000000000000001, 1000000000000000000)},
                                         {"(10^9,1)", pair64(1000000000, 1)}};
  return v;
}

const std::vector<named_pair>& mpfr_pairs() {
  static const std::vector<named_pair> v{{"(6,5)", pair64(6, 5)}, {"(10^6+1,10^6)", pair64(1000001, 1000000)}};
  return v;
}

bool asy_applicable(const pair64& p) { return 2 * p.delta() < p.order(); }

// The naive route at the current mpfr precision (src/testing/naive_toms748.hpp): TOMS 748 on
// q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) over [i pi/tau, (i+1) pi/tau], then
// r = rho0 |sin(tau theta) + sin(sigma theta)|. Returns r; `evals` receives the TOMS 748 count.
mpfr_real naive_r_res(const pair64& p, const big_int& i, std::uintmax_t& evals) {
  auto r = gyrores::test::naive_toms748<mpfr_real>(big_int(p.tau()), big_int(p.sigma()), i);
  evals = r.evaluations;
  return r.r;
}

// The fast half-period index i = floor(theta_first tau/pi) of the exact first minimiser.
big_int naive_interval(const pair64& p) {
  auto r = gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1));
  mpfr_real x = r.theta_first * mpfr_real(p.tau()) / boost::math::constants::pi<mpfr_real>();
  big_int z;
  mpfr_get_z(z.backend().data(), x.backend().data(), MPFR_RNDD);
  return z;
}

// 5 repetitions of >= 0.2 s each, medians (and mean, stddev, cv) reported instead of the runs.
void configure(benchmark::internal::Benchmark* b) {
  b->Repetitions(kRepetitions)->ReportAggregatesOnly(true)->MinTime(0.2);
}

void register_all() {
  for (const auto& np : double_pairs()) {
    benchmark::RegisterBenchmark(("exact_double/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::inscribed_lattice<double>(p, 1.0).r_res);
      st.counters["evals"] = double(gyrores::inscribed_lattice<double>(p, 1.0).evaluations);
    })->Unit(benchmark::kNanosecond)->Apply(configure);
  }
  for (const auto& np : double_pairs()) {
    if (!asy_applicable(np.p)) continue;  // theta_asy_only throws usage_error for x >= 1/2
    benchmark::RegisterBenchmark(("theta_asy/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::theta_asy_only<double>(p));
    })->Unit(benchmark::kNanosecond)->Apply(configure);
  }
  for (const auto& np : mpfr_pairs()) {
    benchmark::RegisterBenchmark(("exact_1000/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      gyrores::scoped_digits d(kDigits);
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1)).r_res);
      st.counters["evals"] = double(gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1)).evaluations);
    })->Unit(benchmark::kMicrosecond)->Apply(configure);
    benchmark::RegisterBenchmark(("one_eval_1000/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      gyrores::scoped_digits d(kDigits);
      auto r = gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1));
      auto c = gyrores::resonant_constants_of<mpfr_real>(p, mpfr_real(1));
      const big_int a = gyrores::to_big(p.order());
      gyrores::lobe_frame<big_int> f{r.first.k, r.first.j, r.first.m};
      auto fr = gyrores::lobe_frame_real_of(c, f, a);
      const mpfr_real u = r.first.u;
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::lobe_eval(c, fr, u).q);
    })->Unit(benchmark::kMicrosecond)->Apply(configure);
    benchmark::RegisterBenchmark(("naive_1000/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      gyrores::scoped_digits d(kDigits);
      const big_int i = naive_interval(p);
      std::uintmax_t evals = 0;
      for (auto _ : st) benchmark::DoNotOptimize(naive_r_res(p, i, evals));
      st.counters["evals"] = double(evals);
    })->Unit(benchmark::kMicrosecond)->Apply(configure);
  }
}

// Console output as usual, plus the median CPU time (seconds) of every benchmark.
class median_reporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> median_s;
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const auto& r : runs)
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "median")
        median_s[r.run_name.function_name] = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  register_all();
  // Accuracy of the naive route at 1000 digits (it is accurate there; it is the cost that differs).
  {
    gyrores::scoped_digits d(kDigits);
    for (const auto& np : mpfr_pairs()) {
      std::uintmax_t evals = 0;
      const mpfr_real naive = naive_r_res(np.p, naive_interval(np.p), evals);
      const mpfr_real exact = gyrores::inscribed_lattice<mpfr_real>(np.p, mpfr_real(1)).r_res;
      const mpfr_real rel = abs(naive - exact) / exact;
      std::printf("naive_1000%s: %ju TOMS 748 evaluations, |naive - exact|/exact = %.3g\n", np.name.c_str(), evals,
                  double(rel));
    }
  }
  median_reporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);

  auto med = [&](const std::string& n) {
    auto it = rep.median_s.find(n);
    return it == rep.median_s.end() ? -1.0 : it->second;
  };
  std::printf("\nRatios of medians (CPU time, this run):\n");
  for (const auto& np : double_pairs()) {
    const double e = med("exact_double/" + np.name), t = med("theta_asy/" + np.name);
    if (e <= 0) continue;  // not run (--benchmark_filter)
    if (t > 0)
      std::printf("  exact_double/theta_asy      %-16s %8.2f   (%.3g ns vs %.3g ns)\n", np.name.c_str(), e / t, e * 1e9,
                  t * 1e9);
    else
      std::printf("  exact_double/theta_asy      %-16s      n/a   (theta_asy undefined for x >= 1/2; exact %.3g ns)\n",
                  np.name.c_str(), e * 1e9);
  }
  for (const auto& np : mpfr_pairs()) {
    const double e = med("exact_1000/" + np.name), o = med("one_eval_1000/" + np.name), n = med("naive_1000/" + np.name);
    if (e > 0 && o > 0)  // both run (--benchmark_filter)
      std::printf("  exact_1000/one_eval_1000    %-16s %8.2f   (%.3g us vs %.3g us)\n", np.name.c_str(), e / o, e * 1e6,
                  o * 1e6);
    if (e > 0 && n > 0)
      std::printf("  naive_1000/exact_1000       %-16s %8.2f   (%.3g us vs %.3g us)\n", np.name.c_str(), n / e, n * 1e6,
                  e * 1e6);
  }
  benchmark::Shutdown();
  return 0;
}
