// Running the harness: which cases run (and which are skipped, why), the references, the pilots
// (each case's result, scored, and the cost of one call) and the timing (Google Benchmark, in
// interleaved rounds). gyrores_bench.cpp chooses what to run and writes the outputs.
#pragma once
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core.hpp"
#include "reference.hpp"

namespace gyrores::bench {

struct planned_case {
  const method_def* method;
  const bench_pair* pair;
  const precision* prec;
};

struct run_plan {
  std::vector<planned_case> cases;  // pair-major: the rows a headline compares run next to each other
  std::vector<skip_note> skips;     // combinations a method's skip rule refuses, with the reason
};

// Every (pair, precision, method) not `excluded` (silently: not part of this run) is planned, or
// skipped with its method's reason. The plan points into the three vectors: keep them alive.
run_plan plan_cases(const std::vector<bench_pair>& pairs, const std::vector<precision>& precisions,
                    const std::vector<method_def>& methods,
                    const std::function<bool(const method_def&, const precision&)>& excluded);

// The reference of every pair at `digits` digits, by pair name (progress on stderr); `seconds`
// receives the total time.
std::map<std::string, reference> compute_references(const std::vector<bench_pair>& pairs, unsigned digits,
                                                    double& seconds);

// One row per planned case; the cases that did not fail, to be timed, with their row.
struct piloted_run {
  std::vector<measurement> rows;
  std::vector<bench_case> cases;
  std::vector<std::size_t> row_of_case;
};

// Builds and runs every case once (the pilot): scores its result against the reference and
// chooses the calls per repetition (about cfg.rep_seconds) and the repetitions (3 when a call
// exceeds 0.5 s, else cfg.repetitions). A case that throws becomes a failed row.
piloted_run run_pilots(const run_plan& plan, const std::map<std::string, reference>& refs, const run_config& cfg);

// Times every piloted case with Google Benchmark in rounds: round r runs repetition r of every
// case (in the plan's order), so slow drifts of a shared machine's load affect every case alike.
// Sets each row's median_ns (median of the per-call CPU times) and repetitions.
void time_cases(piloted_run& run);

}  // namespace gyrores::bench
