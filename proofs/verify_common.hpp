// Shared scaffolding of the proof programs proofs/verify_*.cpp: command line (CLI11), tri-state
// verdicts, per-claim tallies, the log a reader can check, and the loop over the pairs.
//
// Every program runs `verify_x --max-order N [--min-order M] [--log FILE]` over all resonant
// pairs 3 <= M <= tau + sigma <= N in the library's enumeration order (coprime_pairs: by order,
// then by sigma ascending) and decides each claim for each pair with interval arithmetic (MPFI,
// outward rounding) or exact integers. A decision is one of
//   proved      the claim holds for this pair, by the enclosures/integers printed in the log;
//   refuted     the claim fails for this pair, by the enclosures/integers printed in the log;
//   undecided   the enclosures were too wide to decide (never counted as proved);
//   n/a         the pair is outside the claim's hypotheses (e.g. x >= 1/2 for the lobe theorem).
// Each claim is either ASSERTED (the README says it holds; a refutation is a failure) or
// REPORTED (the paper's literal statement, known to be false: refutations are counted and the
// first one, in enumeration order, is the smallest counterexample).
//
// Exit status: 0 every pair decided and no asserted claim refuted; 1 an asserted claim was
// refuted for some pair; 2 some decision was undecided (and none refuted); 3 bad usage or an
// exception (one line on stderr).
#pragma once
#include <chrono>
#include <cstdint>
#include <deque>
#include <fstream>
#include <limits>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "reference/interval.hpp"
#include <gyrores/model/enumerate.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores::proofs {

enum class verdict { proved, refuted, undecided, not_applicable };

const char* verdict_name(verdict v);

// a < b certainly -> proved; a >= b certainly -> refuted; otherwise undecided.
verdict decide_less(const mpfi_real& a, const mpfi_real& b);
// a > 0 certainly -> proved; a <= 0 certainly -> refuted; otherwise undecided.
verdict decide_positive(const mpfi_real& a);
inline verdict decide_bool(bool holds) { return holds ? verdict::proved : verdict::refuted; }
// Conjunction: refuted if any refuted, else undecided if any undecided, else n/a if all n/a.
verdict verdict_and(verdict a, verdict b);

// Decimal text of an enclosure, outward rounded, `d` significant digits: [lo, hi].
std::string enc(const mpfi_real& x, unsigned d = 12);

// The common options of every program.
struct options {
  std::int64_t min_order = 3, max_order = 0;
  std::string log_path;
  std::string command_line;  // argv joined by spaces, for the log's header
};

// A program's own option, besides the common ones: an integer option (`value`, shown as
// `type_name`, checked to lie in [min, max]) or a flag (`flag`). Declared as data so that CLI11,
// heavy to compile, is compiled once (verify_common.cpp). `given`, if set, records whether the
// option appeared on the command line.
struct program_option {
  std::string name, type_name, help;
  std::int64_t* value = nullptr;
  bool* flag = nullptr;
  std::int64_t min = std::numeric_limits<std::int64_t>::min(), max = std::numeric_limits<std::int64_t>::max();
  bool show_default = false;
  bool* given = nullptr;
};

// Runs a proof program `name` (described by `description` in --help): parses its own options and
// --max-order N (required, N >= 3), --min-order M (below 3 means 3) and --log FILE, and returns
// body(options). Returns 0 after --help; 3 with one line on stderr for bad usage or an exception
// thrown by body.
int run_program(const std::string& name, const std::string& description, const std::vector<program_option>& own,
                int argc, char** argv, const std::function<int(const options&)>& body);

// One claim's tally over the run.
struct claim {
  std::string id, statement;
  bool asserted = true;
  std::uint64_t count[4] = {0, 0, 0, 0};
  std::string first_refuted, first_undecided;
  std::vector<std::string> refuted_examples;  // the first few, enumeration order

  void add(verdict v, const std::string& pair, const std::string& detail = "");
  std::uint64_t decided() const { return count[0] + count[1]; }
};

// The run: claims, the log, timing, summary and exit code.
class run {
 public:
  // Opens the log (usage_error if it cannot be written) and writes its header.
  run(std::string program, std::string purpose, const options& o);

  claim& add_claim(const std::string& id, const std::string& statement, bool asserted);
  claim& get(const std::string& id);
  // A free-form log line (per pair, or a note).
  void log(const std::string& line) {
    if (log_) *log_ << line << "\n";
  }
  bool logging() const { return bool(log_); }
  void note(const std::string& line) { notes_.push_back(line); }
  void count_pair() { ++pairs_; }
  double seconds() const;

  // Prints the summary (stdout and log) and returns the exit code.
  int finish();

 private:
  std::string summary_line(const claim& c) const;

  std::string program_, purpose_;
  options opt_;
  std::chrono::steady_clock::time_point start_;
  std::unique_ptr<std::ofstream> log_;
  std::deque<claim> claims_;  // deque: add_claim's references stay valid
  std::vector<std::string> notes_;
  std::uint64_t pairs_ = 0;
};

// Calls body(p) for every pair of orders [o.min_order, o.max_order] in enumeration order,
// counting each in R.
template <class F> void for_each_pair(run& R, const options& o, F&& body) {
  for (auto p64 : coprime_pairs(o.min_order, o.max_order)) {
    R.count_pair();
    body(p64);
  }
}

// The pair with big_int entries (what the certificate and proof-step APIs take).
inline resonant_pair<big_int> big_pair(const resonant_pair<std::int64_t>& p) {
  return resonant_pair<big_int>(big_int(p.tau()), big_int(p.sigma()));
}

}  // namespace gyrores::proofs
