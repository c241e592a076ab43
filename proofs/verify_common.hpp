// Shared scaffolding of the proof programs proofs/verify_*.cpp: command line, tri-state
// verdicts, per-claim tallies, the log a reader can check, and a few interval helpers.
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
// exception.
#pragma once
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <deque>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gyrores/model/enumerate.hpp>
#include <gyrores/core/interval.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores::proofs {

enum class verdict { proved, refuted, undecided, not_applicable };

inline const char* verdict_name(verdict v) {
  switch (v) {
    case verdict::proved: return "proved";
    case verdict::refuted: return "refuted";
    case verdict::undecided: return "undecided";
    default: return "n/a";
  }
}

// a < b certainly -> proved; a >= b certainly -> refuted; otherwise undecided.
inline verdict decide_less(const mpfi_real& a, const mpfi_real& b) {
  if (certainly_less(a, b)) return verdict::proved;
  if (interval_lower(a) >= interval_upper(b)) return verdict::refuted;
  return verdict::undecided;
}
inline verdict decide_positive(const mpfi_real& a) {
  if (certainly_positive(a)) return verdict::proved;
  if (interval_upper(a) <= 0) return verdict::refuted;
  return verdict::undecided;
}
inline verdict decide_bool(bool holds) { return holds ? verdict::proved : verdict::refuted; }
// Conjunction: refuted if any refuted, else undecided if any undecided, else n/a if all n/a.
inline verdict verdict_and(verdict a, verdict b) {
  if (a == verdict::refuted || b == verdict::refuted) return verdict::refuted;
  if (a == verdict::undecided || b == verdict::undecided) return verdict::undecided;
  if (a == verdict::not_applicable) return b;
  if (b == verdict::not_applicable) return a;
  return verdict::proved;
}

// Decimal text of an enclosure, outward rounded, `d` significant digits: [lo, hi].
inline std::string enc(const mpfi_real& x, unsigned d = 12) {
  auto t = interval_to_decimal(x, d);
  return "[" + t.first + ", " + t.second + "]";
}

struct options {
  std::int64_t min_order = 3, max_order = 0;
  std::string log_path;
  std::map<std::string, std::string> extra;  // --key value pairs a program may read
  std::string command_line;
};

// Parses --max-order N (required), --min-order M, --log FILE, and any --key value listed in
// `extra_keys` (flags without a value: list them in `flags`).
inline options parse_options(int argc, char** argv, const std::vector<std::string>& extra_keys = {},
                             const std::vector<std::string>& flags = {}) {
  options o;
  for (int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
  auto usage = [&](const std::string& why) {
    std::cerr << argv[0] << ": " << why << "\nusage: " << argv[0]
              << " --max-order N [--min-order M] [--log FILE]";
    for (auto& k : extra_keys) std::cerr << " [--" << k << " V]";
    for (auto& k : flags) std::cerr << " [--" << k << "]";
    std::cerr << "\n";
    std::exit(3);
  };
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage("missing value after " + a);
      return argv[++i];
    };
    auto to_int = [&](const std::string& s) -> std::int64_t {
      try {
        std::size_t pos = 0;
        long long v = std::stoll(s, &pos);
        if (pos != s.size()) throw std::invalid_argument(s);
        return v;
      } catch (...) {
        usage("not an integer: '" + s + "'");
      }
      return 0;
    };
    if (a == "--max-order") o.max_order = to_int(value());
    else if (a == "--min-order") o.min_order = to_int(value());
    else if (a == "--log") o.log_path = value();
    else {
      bool known = false;
      for (auto& k : extra_keys)
        if (a == "--" + k) { o.extra[k] = value(); known = true; }
      for (auto& k : flags)
        if (a == "--" + k) { o.extra[k] = "1"; known = true; }
      if (!known) usage("unknown argument '" + a + "'");
    }
  }
  if (o.max_order < 3) usage("--max-order N with N >= 3 is required");
  if (o.min_order < 3) o.min_order = 3;
  return o;
}

// One claim's tally over the run.
struct claim {
  std::string id, statement;
  bool asserted = true;
  std::uint64_t count[4] = {0, 0, 0, 0};
  std::string first_refuted, first_undecided;
  std::vector<std::string> refuted_examples;  // the first few, enumeration order

  void add(verdict v, const std::string& pair, const std::string& detail = "") {
    ++count[int(v)];
    std::string what = pair + (detail.empty() ? "" : " (" + detail + ")");
    if (v == verdict::refuted) {
      if (first_refuted.empty()) first_refuted = what;
      if (refuted_examples.size() < 8) refuted_examples.push_back(pair);
    }
    if (v == verdict::undecided && first_undecided.empty()) first_undecided = what;
  }
  std::uint64_t decided() const { return count[0] + count[1]; }
};

// The run: claims, the log, timing, summary and exit code.
class run {
 public:
  run(std::string program, std::string purpose, const options& o)
      : program_(std::move(program)), purpose_(std::move(purpose)), opt_(o),
        start_(std::chrono::steady_clock::now()) {
    if (!o.log_path.empty()) {
      log_ = std::make_unique<std::ofstream>(o.log_path);
      if (!*log_) {
        std::cerr << program_ << ": cannot write log '" << o.log_path << "'\n";
        std::exit(3);
      }
    }
    std::time_t now = std::time(nullptr);
    char buf[64];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
    header_ = "# " + program_ + ": " + purpose_ + "\n# command: " + o.command_line + "\n# started: " + buf +
              "\n# pairs: all coprime tau > sigma >= 1 with " + std::to_string(o.min_order) +
              " <= tau + sigma <= " + std::to_string(o.max_order) +
              ", by order then sigma ascending\n# decisions: proved / refuted / undecided / n/a (interval "
              "arithmetic, MPFI, outward rounding; integers exact)\n";
    if (log_) *log_ << header_;
  }

  claim& add_claim(const std::string& id, const std::string& statement, bool asserted) {
    claim c;
    c.id = id;
    c.statement = statement;
    c.asserted = asserted;
    claims_.push_back(std::move(c));
    if (log_) *log_ << "# claim " << id << (asserted ? " [asserted]" : " [reported]") << ": " << statement << "\n";
    return claims_.back();
  }
  claim& get(const std::string& id) {
    for (auto& c : claims_)
      if (c.id == id) return c;
    throw std::logic_error("no claim " + id);
  }
  // A free-form log line (per pair, or a note).
  void log(const std::string& line) {
    if (log_) *log_ << line << "\n";
  }
  bool logging() const { return bool(log_); }
  void note(const std::string& line) {
    notes_.push_back(line);
  }
  void count_pair() { ++pairs_; }

  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  // Prints the summary (stdout and log) and returns the exit code.
  int finish() {
    std::ostringstream s;
    char tbuf[64];
    std::snprintf(tbuf, sizeof tbuf, "%.1f", seconds());
    s << "# summary: " << program_ << ", " << pairs_ << " pairs, orders " << opt_.min_order << ".." << opt_.max_order
      << ", " << tbuf << " s\n";
    int code = 0;
    for (auto& c : claims_) {
      s << "#  " << c.id << (c.asserted ? " [asserted]" : " [reported]") << ": proved " << c.count[0] << ", refuted "
        << c.count[1] << ", undecided " << c.count[2] << ", n/a " << c.count[3];
      if (!c.first_refuted.empty()) s << "; first refuted: " << c.first_refuted;
      if (!c.first_undecided.empty()) s << "; first undecided: " << c.first_undecided;
      s << "\n";
      if (c.refuted_examples.size() > 1) {
        s << "#     refuted (first " << c.refuted_examples.size() << "):";
        for (auto& e : c.refuted_examples) s << " " << e;
        s << "\n";
      }
      if (c.asserted && c.count[1] > 0) code = 1;
      if (code == 0 && c.count[2] > 0) code = 2;
    }
    for (auto& n : notes_) s << "# note: " << n << "\n";
    s << "# result: "
      << (code == 0 ? "every decision made; every asserted claim proved for every pair"
                    : code == 1 ? "FAILURE: an asserted claim was refuted" : "INCOMPLETE: undecided decisions")
      << "\n";
    std::cout << s.str();
    if (log_) *log_ << s.str();
    return code;
  }

 private:
  std::string program_, purpose_;
  options opt_;
  std::chrono::steady_clock::time_point start_;
  std::unique_ptr<std::ofstream> log_;
  std::string header_;
  std::deque<claim> claims_;  // deque: add_claim's references stay valid
  std::vector<std::string> notes_;
  std::uint64_t pairs_ = 0;
};

// Runs body() and maps exceptions to exit code 3 with a one-line message.
template <class F> int guarded_main(const char* name, F&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace gyrores::proofs
