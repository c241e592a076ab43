// Every entry point of the library on 8 threads at once (docs/architecture.md, Conventions:
// nothing in the library writes process-wide state, so each may run on any thread): proved pair
// reports at 17, 50 and 300 digits, lattice-theorem certificates and their independent checker,
// small sweeps (double and MPFR rows, with and without --certified) and the coupling report
// (whose horizon minimum is proved in Arb). Each job's
// result, as text, must equal the same job's result run alone first.
//
// What it catches: a library function that sets Boost's process-wide default precision of
// mpfr_real/mpfi_real (a scoped_digits, or Boost's own operators on an mpfr_real whose
// precision differs from the default) makes a concurrent job compute at another precision, so
// its text differs; and a watcher thread reads the default throughout and fails the test on any
// change, even one restored before a result shows it (the first test case checks that the
// watcher sees such a write). The serial and the concurrent runs see different defaults, so a
// result that depends on the default at all differs too. Shared caches without locks, static scratch space or a global
// random state would garble some job's text.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gyrores/core/thread_caches.hpp>
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/report/coupling_report.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/io/sweep_rows.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/sweep/engine.hpp>
#include <gyrores/report/pair_report.hpp>

#include "certificate_checker.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;

namespace {

struct job {
  std::string name;
  std::function<std::string()> run;
};

resonant_pair<big_int> pair_of(const std::string& tau, const std::string& sigma) {
  return resonant_pair<big_int>(big_int(tau), big_int(sigma));
}

const std::vector<std::pair<std::string, std::string>> pairs{
    {"6", "5"}, {"9", "4"}, {"11", "9"}, {"1000000000000000000000000000001", "1000000000000000000000000000000"}};

// The rows (CSV) and the summary of a sweep of every pair up to max_order, in T.
template <class T> std::string sweep_text(std::int64_t max_order, bool certified, unsigned digits, unsigned threads) {
  sweep_config cfg;
  cfg.max_order = max_order;
  cfg.certified = certified;
  cfg.digits = digits;
  sweep_engine_options eo;
  eo.threads = threads;
  eo.block_size = 16;
  sweep_accumulator acc;
  acc.max_examples = cfg.max_examples;
  std::string rows;
  const auto out = sweep_run<T>(
      cfg, eo,
      [&](sweep_block& b) {
        acc.merge(b.summary);
        rows += b.rows;
      },
      [&](sweep_block& b, const sweep_row<T>& r) { sweep_format_row(b.rows, r, sweep_format::csv, cfg.digits); });
  return std::string(out.complete ? "complete\n" : "incomplete\n") + rows + sweep_accumulator_json(acc, cfg.checks).dump();
}

std::string coupling_text(const coupling_spec& spec, const std::string& horizon, unsigned digits, const json& input) {
  coupling_report_options opt;
  opt.digits = digits;
  opt.horizon = parse_rational(horizon, "horizon");
  opt.convergents = 3;
  return coupling_report_json(input, horizon, digits, analyse_coupling(spec, opt)).dump();
}

std::vector<job> all_jobs() {
  std::vector<job> jobs;
  for (const auto& [tau, sigma] : pairs) {
    const auto p = pair_of(tau, sigma);
    for (unsigned digits : {17u, 50u, 300u}) {
      jobs.push_back({"pair " + p.str() + " digits " + std::to_string(digits), [p, digits] {
                        pair_report_options opt;
                        opt.digits = digits;
                        opt.enclosures = true;
                        return pair_report_json(p, prove_pair(p, opt), true).dump();
                      }});
    }
    jobs.push_back({"certify and check " + p.str(), [p] {
                      const std::string text = certificate_to_json(certify_by_theorem(p, 40)).dump();
                      const auto v = gyrores_checker::check_theorem_certificate(text);
                      return text + "\n" + std::to_string(v.status) + " " + v.message;
                    }});
  }
  // Sweeps run worker threads of their own (1 or 2 here).
  jobs.push_back({"sweep double to order 60", [] { return sweep_text<double>(60, false, 17, 1); }});
  jobs.push_back({"sweep double certified to order 60", [] { return sweep_text<double>(60, true, 17, 2); }});
  jobs.push_back({"sweep mpfr 30 digits to order 60", [] { return sweep_text<mpfr_real>(60, false, 30, 2); }});
  jobs.push_back({"sweep mpfr 40 digits certified to order 60", [] { return sweep_text<mpfr_real>(60, true, 40, 1); }});
  // Not resonant: the horizon minimum by the two-run test, in long double and MPFR (12 digits), on
  // MPFR rungs of the ladder (40 and 100 digits); resonant: the pair's proved values.
  for (unsigned digits : {12u, 40u, 100u})
    jobs.push_back({"coupling n = 2, digits " + std::to_string(digits), [digits] {
                      return coupling_text(coupling_spec::from_n(big_rational(2)), "30", digits, json{{"n", "2"}});
                    }});
  jobs.push_back({"coupling n^2 = 1/12", [] {
                    return coupling_text(coupling_spec::from_n2(big_rational(1, 12)), "100", 20, json{{"n2", "1/12"}});
                  }});
  jobs.push_back({"horizon minimum n = 3/7, 25 digits", [] {
                    const auto h = report_horizon_minimum(coupling_spec::from_n(big_rational(3, 7)),
                                                         horizon_time(big_rational(20), true), 25);
                    return h.h_min.value + " " + h.t_min.value + " " + h.r_min.value + " " + h.proof.cut_lobe.str();
                  }});
  return jobs;
}

// Reads Boost's default precision of mpfr_real and mpfi_real until stopped, counting the reads
// that differ from the values it started with.
class default_precision_watch {
 public:
  default_precision_watch()
      : mpfr_(mpfr_real::default_precision()), mpfi_(mpfi_real::default_precision()), thread_([this] { watch(); }) {}
  ~default_precision_watch() { stop(); }
  // Stops the watcher; the number of reads that saw another default.
  long stop() {
    done_ = true;
    if (thread_.joinable()) thread_.join();
    return changes_;
  }
  long reads() const { return reads_; }
  long changes() const { return changes_; }

 private:
  void watch() {
    while (!done_.load(std::memory_order_relaxed)) {
      std::atomic_signal_fence(std::memory_order_seq_cst);  // read the defaults again each time
      if (mpfr_real::default_precision() != mpfr_ || mpfi_real::default_precision() != mpfi_) ++changes_;
      ++reads_;
    }
  }
  const unsigned mpfr_, mpfi_;
  std::atomic<bool> done_{false};
  std::atomic<long> changes_{0}, reads_{0};
  std::thread thread_;
};

// Runs every job `rounds` times on `threads` threads, in a shuffled order (fixed seed) so that
// every kind of job overlaps every other; each thread takes the next run not yet taken. The
// results by round and job index.
std::vector<std::vector<std::string>> run_concurrently(const std::vector<job>& jobs, unsigned threads, int rounds) {
  std::vector<std::vector<std::string>> out(std::size_t(rounds), std::vector<std::string>(jobs.size()));
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // (round, job)
  for (std::size_t r = 0; r < std::size_t(rounds); ++r)
    for (std::size_t k = 0; k < jobs.size(); ++k) runs.emplace_back(r, k);
  std::mt19937 rng(20261125);
  std::shuffle(runs.begin(), runs.end(), rng);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < runs.size();) {
      const auto [round, k] = runs[i];
      try {
        out[round][k] = jobs[k].run();
      } catch (const std::exception& e) {
        out[round][k] = std::string("exception: ") + e.what();
      }
    }
    gyrores::release_thread_caches();  // MPFR's and Arb's per-thread caches (core/thread_caches.hpp)
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace

TEST_CASE("threads: the watcher sees a write of the default precision", "[threads]") {
  // The watcher is the part of the next test that does not depend on the jobs' timing: it must
  // notice a default changed and restored, as a scoped_digits in a library call would. On a
  // loaded machine it may not run for a while, so the write is repeated (up to 10 s) until seen.
  default_precision_watch watch;
  const unsigned old = mpfr_real::default_precision();
  const auto t0 = std::chrono::steady_clock::now();
  while (watch.changes() == 0 && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10)) {
    mpfr_real::default_precision(old + 7);
    std::this_thread::sleep_for(std::chrono::microseconds(100));
    mpfr_real::default_precision(old);
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  const long seen = watch.stop();
  INFO(watch.reads() << " reads");
  CHECK(seen > 0);
}

TEST_CASE("threads: 8 threads at once give every job's serial result", "[threads]") {
  const auto jobs = all_jobs();
  // The serial runs at one default precision, the concurrent ones at another: a result that
  // depends on the default (a value made at it, not at an explicit precision) differs too.
  const unsigned old_mpfr = mpfr_real::default_precision(), old_mpfi = mpfi_real::default_precision();
  mpfr_real::default_precision(23);
  mpfi_real::default_precision(23);
  std::vector<std::string> serial;
  for (const auto& j : jobs) {
    INFO(j.name);
    REQUIRE_NOTHROW(serial.push_back(j.run()));
  }
  mpfr_real::default_precision(61);
  mpfi_real::default_precision(61);
  default_precision_watch watch;
  const auto t0 = std::chrono::steady_clock::now();
  const auto concurrent = run_concurrently(jobs, 8, 6);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long changes = watch.stop();
  mpfr_real::default_precision(old_mpfr);
  mpfi_real::default_precision(old_mpfi);
  INFO("concurrent phase: " << seconds << " s, " << watch.reads() << " reads of the default precision");
  CHECK(changes == 0);
  for (std::size_t round = 0; round < concurrent.size(); ++round)
    for (std::size_t k = 0; k < jobs.size(); ++k) {
      INFO(jobs[k].name << ", round " << round);
      CHECK(concurrent[round][k] == serial[k]);
    }
  // The jobs are not trivial: each certificate holds, each sweep completed.
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    INFO(jobs[k].name);
    if (jobs[k].name.rfind("certify", 0) == 0) CHECK(serial[k].substr(serial[k].rfind('\n') + 1, 2) == "0 ");
    if (jobs[k].name.rfind("sweep", 0) == 0) CHECK(serial[k].rfind("complete\n", 0) == 0);
  }
}
