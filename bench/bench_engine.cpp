// Cost of the theorem's r_res (include/gyrores/theorem/) against cheaper, naive and older
// alternatives. A report, not a test: nothing is asserted.
//
//  theorem_double/<pair>     theorem_minimum_double: the theorem's r_res and every minimiser in
//                            double (lobes by integers, u* by safeguarded Newton); nothing proved
//  theta_asy/<pair>          the paper's theta_asy alone, reference (pre-theorem) implementation
//                            (asymptotic.hpp theta_asy_only<double>: k = round(a/(2b)), one
//                            bracketed root of u + tan u = s); heuristic, and defined only for
//                            x = b/a < 1/2, so not for (10^9, 1)
//  ref_lattice_double/<pair> reference (pre-theorem): the lattice scout and polish in double
//                            (inscribed_lattice<double>)
//  proved_1000/<pair>        theorem, proved: prove_minimum at the precision of 1000 digits
//                            (speed_error/theorem_path.hpp with_proved_minimum): enclosures of
//                            r_res and every minimiser
//  ref_lattice_1000/<pair>   reference (pre-theorem): inscribed_lattice<mpfr_real> at 1000 digits
//                            (double scout, Newton with precision doubling; nothing proved)
//  one_eval_1000/<pair>      one evaluation of (q, q', z, z') at 1000 digits (lobe_eval) at the
//                            theorem's first minimiser: the unit of work
//  naive_1000/<pair>         plain Boost TOMS 748 on the naive q'(theta) (sin/cos of tau*theta
//                            formed directly) over the fast half-period holding the minimiser, to
//                            full precision (eps_tolerance(bits - 2)), then |q| there
// Every benchmark runs 5 repetitions and reports the median; the ratios at the end are formed
// from the medians of this one run (CPU time). Pairs and inputs are fixed (no randomness).
// Counter `evals`: q' evaluations (ref_lattice: scout + polish, inscribed_result::evaluations;
// naive: TOMS 748 calls). Before the benchmarks, the program prints how far the naive 1000-digit
// r_res is from the proved one (the naive route is accurate at 1000 digits for these pairs; only
// its cost differs). bench/run's gyrores-bench is the full comparison (every precision, peer and
// method); this is the short one.
#include <benchmark/benchmark.h>

#include <boost/math/constants/constants.hpp>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gyrores/model/resonant.hpp>
#include "reference/lobe_frames.hpp"  // lobe_eval: the one-evaluation rows
#include "speed_error/pre_theorem.hpp"
#include "speed_error/theorem_path.hpp"
#include "testing/naive_toms748.hpp"
#include "testing/test_support.hpp"

using gyrores::big_int;
using gyrores::mpfr_real;
using pair64 = gyrores::resonant_pair<std::int64_t>;
using pair_big = gyrores::resonant_pair<big_int>;

namespace {

constexpr unsigned kDigits = 1000;
constexpr int kRepetitions = 5;

struct named_pair {
  std::string name;
  pair64 p;
  pair_big big() const { return gyrores::pair_cast<big_int>(p); }
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

// The proved r_res and theta_first at 1000 digits (midpoints of their enclosures), as text.
struct proved_values {
  std::string r_res, theta_first;
};
proved_values proved_1000(const pair_big& p) {
  proved_values out;
  gyrores::bench::with_proved_minimum(p, kDigits, [&](const gyrores::minimum_enclosure& M) {
    out.r_res = gyrores::bench::enclosure_mid_text(M.r_res);
    out.theta_first = gyrores::bench::enclosure_mid_text(*M.minimisers.front());
  });
  return out;
}

// The naive route at the current mpfr precision (src/testing/naive_toms748.hpp): TOMS 748 on
// q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) over [i pi/tau, (i+1) pi/tau], then
// r = rho0 |sin(tau theta) + sin(sigma theta)|. Returns r; `evals` receives the TOMS 748 count.
mpfr_real naive_r_res(const pair64& p, const big_int& i, std::uintmax_t& evals) {
  auto r = gyrores::test::naive_toms748<mpfr_real>(big_int(p.tau()), big_int(p.sigma()), i);
  evals = r.evaluations;
  return r.r;
}

// The fast half-period index i = floor(theta_first tau/pi) of the proved first minimiser.
big_int naive_interval(const pair64& p) {
  const mpfr_real theta(proved_1000(gyrores::pair_cast<big_int>(p)).theta_first);
  mpfr_real x = theta * mpfr_real(p.tau()) / boost::math::constants::pi<mpfr_real>();
  big_int z;
  mpfr_get_z(z.backend().data(), x.backend().data(), MPFR_RNDD);
  return z;
}

// 5 repetitions of >= 0.2 s each, medians (and mean, stddev, cv) reported instead of the runs.
void configure(benchmark::internal::Benchmark* b) {
  b->Repetitions(kRepetitions)->ReportAggregatesOnly(true)->MinTime(0.2);
}

void register_double() {
  for (const auto& np : double_pairs()) {
    benchmark::RegisterBenchmark(("theorem_double/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::theorem_minimum_double(p).r_res);
    })->Unit(benchmark::kNanosecond)->Apply(configure);
  }
  for (const auto& np : double_pairs()) {
    if (!asy_applicable(np.p)) continue;  // theta_asy_only throws usage_error for x >= 1/2
    benchmark::RegisterBenchmark(("theta_asy/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::theta_asy_only<double>(p));
    })->Unit(benchmark::kNanosecond)->Apply(configure);
  }
  for (const auto& np : double_pairs()) {
    benchmark::RegisterBenchmark(("ref_lattice_double/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::inscribed_lattice<double>(p, 1.0).r_res);
      st.counters["evals"] = double(gyrores::inscribed_lattice<double>(p, 1.0).evaluations);
    })->Unit(benchmark::kNanosecond)->Apply(configure);
  }
}

void register_1000() {
  for (const auto& np : mpfr_pairs()) {
    benchmark::RegisterBenchmark(("proved_1000/" + np.name).c_str(), [p = np.big()](benchmark::State& st) {
      for (auto _ : st)
        gyrores::bench::with_proved_minimum(p, kDigits, [](const gyrores::minimum_enclosure& M) {
          benchmark::DoNotOptimize(&M);
        });
    })->Unit(benchmark::kMicrosecond)->Apply(configure);
    benchmark::RegisterBenchmark(("ref_lattice_1000/" + np.name).c_str(), [p = np.p](benchmark::State& st) {
      gyrores::scoped_digits d(kDigits);
      for (auto _ : st) benchmark::DoNotOptimize(gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1)).r_res);
      st.counters["evals"] = double(gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1)).evaluations);
    })->Unit(benchmark::kMicrosecond)->Apply(configure);
    benchmark::RegisterBenchmark(("one_eval_1000/" + np.name).c_str(), [np](benchmark::State& st) {
      gyrores::scoped_digits d(kDigits);
      const auto fm = gyrores::bench::theorem_first_minimiser(np.big());
      auto c = gyrores::resonant_constants_of<mpfr_real>(np.p, mpfr_real(1));
      const big_int a = gyrores::to_big(np.p.order());
      auto fr = gyrores::lobe_frame_real_of(c, fm.frame, a);
      const mpfr_real u = fm.u;
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

// "<label> <pair> <num/den>  (<num> vs <den>)" when both ran (--benchmark_filter may skip them).
void print_ratio(const median_reporter& rep, const char* label, const std::string& pair, const std::string& num,
                 const std::string& den, double unit, const char* unit_name) {
  auto med = [&](const std::string& n) {
    auto it = rep.median_s.find(n);
    return it == rep.median_s.end() ? -1.0 : it->second;
  };
  const double a = med(num + "/" + pair), b = med(den + "/" + pair);
  if (a > 0 && b > 0)
    std::printf("  %-34s %-16s %8.2f   (%.3g %s vs %.3g %s)\n", label, pair.c_str(), a / b, a * unit, unit_name,
                b * unit, unit_name);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  register_double();
  register_1000();
  // Accuracy of the naive route at 1000 digits (it is accurate there; it is the cost that differs).
  {
    gyrores::scoped_digits d(kDigits);
    for (const auto& np : mpfr_pairs()) {
      std::uintmax_t evals = 0;
      const mpfr_real naive = naive_r_res(np.p, naive_interval(np.p), evals);
      const mpfr_real proved(proved_1000(np.big()).r_res);
      const mpfr_real rel = abs(naive - proved) / proved;
      std::printf("naive_1000/%s: %ju TOMS 748 evaluations, |naive - proved|/proved = %.3g\n", np.name.c_str(), evals,
                  double(rel));
    }
  }
  median_reporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);

  std::printf("\nRatios of medians (CPU time, this run):\n");
  for (const auto& np : double_pairs()) {
    if (!asy_applicable(np.p))
      std::printf("  %-34s %-16s      n/a   (theta_asy undefined for x >= 1/2)\n", "theorem_double/theta_asy",
                  np.name.c_str());
    print_ratio(rep, "theorem_double/theta_asy", np.name, "theorem_double", "theta_asy", 1e9, "ns");
    print_ratio(rep, "ref_lattice_double/theorem_double", np.name, "ref_lattice_double", "theorem_double", 1e9, "ns");
  }
  for (const auto& np : mpfr_pairs()) {
    print_ratio(rep, "proved_1000/one_eval_1000", np.name, "proved_1000", "one_eval_1000", 1e6, "us");
    print_ratio(rep, "naive_1000/proved_1000", np.name, "naive_1000", "proved_1000", 1e6, "us");
    print_ratio(rep, "ref_lattice_1000/proved_1000", np.name, "ref_lattice_1000", "proved_1000", 1e6, "us");
  }
  benchmark::Shutdown();
  return 0;
}
