// gyrores sweep --max-order M [--min-order m] [--check LIST] [--certified] [--out FILE] [--format csv|jsonl]
//               [--summary FILE] [--threads N] [--shard I/N] [--resume] [--digits D] [--json] ...
// Visits every coprime pair with m <= tau + sigma <= M, checks the paper's claims per pair and
// prints a summary. The sweep request (working type, size caps, files and resume) is the
// application layer's, app/sweep.hpp; what the rows, summary, resume state and merge hold is in
// docs/formats.md.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <memory>

#include <gyrores/app/sweep.hpp>
#include <gyrores/io/sweep_summary.hpp>

#include "cli_output.hpp"
#include "cli_options.hpp"
#include "cli_signals.hpp"
#include "commands.hpp"

namespace gyrores::cli {
namespace {

struct sweep_args {
  std::int64_t max_order = 0, min_order = 3;
  std::string checks = "default", out, format, summary, shard = "0/1", state;
  unsigned threads = 0;
  bool resume = false, fresh = false, quiet = false, json = false, certified = false, no_filter = false, allow_large = false;
  int digits = 15;
  std::size_t examples = 5;
  double checkpoint = 300;
  long max_pairs = 0;  // signed, so that a negative count is refused rather than wrapped around
};

// More threads than this is a typo (the system refuses to start them: the sweep would abort).
constexpr unsigned max_threads = 4096;  // as the Python module's sweep()

std::string with_commas(std::uint64_t v) {
  const std::string digits = std::to_string(v);
  std::string s;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) s.push_back(',');
    s.push_back(digits[i]);
  }
  return s;
}

std::string clock_text(double s) {
  if (!(s >= 0) || s > 1e7) return "?";
  long t = long(s + 0.5);
  char buf[32];
  if (t >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  else std::snprintf(buf, sizeof buf, "%ld:%02ld", t / 60, t % 60);
  return buf;
}

// Progress on stderr: a redrawn bar on a terminal, a plain line every 10 s otherwise.
class progress_printer {
 public:
  explicit progress_printer(bool quiet) : quiet_(quiet), tty_(::isatty(2) == 1) {}
  void operator()(const sweep_progress_info& p) {
    if (quiet_) return;
    const double every = tty_ ? 0.2 : 10.0;
    if (p.seconds - last_ < every) return;
    last_ = p.seconds;
    draw(p);
  }
  void finish(const sweep_progress_info& p) {
    if (quiet_) return;
    if (tty_ && drawn_) {
      draw(p);
      std::fputs("\n", stderr);
    }
  }

 private:
  void draw(const sweep_progress_info& p) {
    const double rate = p.seconds > 0 ? double(p.done_this_run) / p.seconds : 0;
    char line[256];
    if (p.total > 0) {
      const double frac = double(p.done) / double(p.total);
      const double eta = rate > 0 ? double(p.total - std::min(p.done, p.total)) / rate : -1;
      std::string bar(30, ' ');
      for (int i = 0; i < int(frac * 30 + 1e-9) && i < 30; ++i) bar[std::size_t(i)] = '#';
      std::snprintf(line, sizeof line, "[%s] %5.1f%%  %s/%s pairs  %s pairs/s  ETA %s", bar.c_str(), 100 * frac,
                    with_commas(p.done).c_str(), with_commas(p.total).c_str(), with_commas(std::uint64_t(rate)).c_str(),
                    clock_text(eta).c_str());
    } else {
      std::snprintf(line, sizeof line, "%s pairs  %s pairs/s", with_commas(p.done).c_str(),
                    with_commas(std::uint64_t(rate)).c_str());
    }
    if (tty_) std::fprintf(stderr, "\r%s\x1b[K", line);
    else std::fprintf(stderr, "gyrores sweep: %s\n", line);
    std::fflush(stderr);
    drawn_ = true;
  }
  bool quiet_, tty_;
  bool drawn_ = false;
  double last_ = 0;
};

void parse_shard(const std::string& s, sweep_config& c) {
  auto slash = s.find('/');
  auto bad = [&] { return usage_error("--shard must be I/N with 0 <= I < N, got '" + s + "'"); };
  if (slash == std::string::npos) throw bad();
  try {
    std::size_t p1 = 0, p2 = 0;
    std::string a = s.substr(0, slash), b = s.substr(slash + 1);
    c.shard_index = std::stoll(a, &p1);
    c.shard_count = std::stoll(b, &p2);
    if (p1 != a.size() || p2 != b.size()) throw bad();
  } catch (const std::logic_error&) {
    throw bad();
  }
  if (c.shard_count < 1 || c.shard_index < 0 || c.shard_index >= c.shard_count) throw bad();
}

sweep_config config_of(const sweep_args& a) {
  if (a.max_order < 3) throw usage_error("--max-order must be >= 3 (the smallest pair (2, 1) has order 3), got " + std::to_string(a.max_order));
  if (a.max_order > (std::int64_t(1) << 40)) throw usage_error("--max-order must be <= 2^40 = 1099511627776");
  if (a.threads > max_threads)
    throw usage_error("--threads must be in [0, " + std::to_string(max_threads) + "] (0: all cores), got " + std::to_string(a.threads));
  if (a.max_pairs < 0) throw usage_error("--max-pairs must be >= 0 (0: no limit), got " + std::to_string(a.max_pairs));
  if (a.min_order < 3 || a.min_order > a.max_order)
    throw usage_error("--min-order must be in [3, --max-order], got " + std::to_string(a.min_order));
  if (a.examples > 1000) throw usage_error("--examples must be <= 1000");
  if (a.resume && a.fresh) throw usage_error("--resume and --fresh exclude each other");
  sweep_config cfg;
  cfg.max_order = a.max_order;
  cfg.min_order = a.min_order;
  cfg.checks = sweep_parse_checks(a.checks);
  parse_shard(a.shard, cfg);
  cfg.max_examples = a.examples;
  if (a.digits < 1 || a.digits > 1000) throw usage_error("--digits must be in [1, 1000], got " + std::to_string(a.digits));
  cfg.digits = unsigned(a.digits);
  cfg.certified = a.certified;
  cfg.certified_filter = !a.no_filter;
  sweep_validate(cfg);
  return cfg;
}

sweep_files files_of(const sweep_args& a) {
  if (!(a.checkpoint >= 0) || a.checkpoint > 1e9) throw usage_error("--checkpoint must be in [0, 1e9] seconds");
  sweep_files files;
  files.rows_path = a.out;
  const bool jsonl_name = a.out.size() >= 6 && a.out.substr(a.out.size() - 6) == ".jsonl";
  files.rows_format = sweep_parse_format(!a.format.empty() ? a.format : jsonl_name ? "jsonl" : "csv");
  files.summary_path = a.summary;
  files.state_path = a.state;
  files.resume = a.resume;
  files.fresh = a.fresh;
  // No file named: the default state ./gyrores-sweep.resume is shared by every such sweep run in
  // this directory; they take turns on it (docs/formats.md, "File safety and locks").
  if (a.out.empty() && a.summary.empty() && a.state.empty())
    files.on_lock_wait = [](const std::string& why) {
      std::fprintf(stderr, "gyrores sweep: %s: waiting for it to end (give --state FILE to run beside it)\n", why.c_str());
    };
  files.checkpoint_seconds = a.checkpoint;
  return files;
}

std::string run_sweep(const sweep_args& a) {
  app::sweep_request r;
  r.config = config_of(a);
  r.files = files_of(a);
  r.engine.threads = a.threads;
  r.engine.max_pairs = std::uint64_t(a.max_pairs);
  r.engine.stop = &stop_flag();  // set by the signal_scope below
  r.allow_large = a.allow_large;
  progress_printer pp(a.quiet);
  sweep_progress_info last;
  r.progress = [&](const sweep_progress_info& p) {
    last = p;
    pp(p);
  };
  signal_scope signals;
  const sweep_report rep = app::run_sweep(r);
  pp.finish(last);
  if (!rep.complete) {
    // Not "could not compute": a stop the user asked for, with its own status (cli_output.hpp).
    const bool interrupted = stop_flag().load();
    throw command_exit{interrupted ? exit_interrupted : exit_stopped,
                       std::string("gyrores sweep: ") + (interrupted ? "interrupted" : "stopped by --max-pairs") + " after " +
                           with_commas(rep.done) + (rep.total ? " of " + with_commas(rep.total) : "") +
                           " pairs; every finished pair is kept in the resume state '" + rep.state_path +
                           "': run the same command with --resume to continue"};
  }
  return a.json ? rep.summary.dump(2) + "\n" : sweep_summary_text(rep.summary);
}

command_runner install_sweep(CLI::App& app) {
  auto a = std::make_shared<sweep_args>();
  auto sub = options(app).subcommand("sweep", "Check the paper's claims over every resonant pair up to an order");
  sub.add("--max-order", a->max_order, "largest order tau + sigma (required, 3..2^40)", show::required);
  sub.add("--min-order", a->min_order, "smallest order tau + sigma", show::with_default);
  sub.add("--check,--checks", a->checks,
          "comma-separated checks: degeneracy, paper-node, asy-bound, structure; default or all: the four",
          show::with_default);
  sub.add("--out", a->out, "per-pair rows to FILE (written as FILE.part, renamed when complete)");
  sub.add("--format", a->format, "rows format: csv or jsonl (default: jsonl if FILE ends in .jsonl, else csv)");
  sub.add("--summary", a->summary, "summary as JSON to FILE (a shard run also writes FILE.values for merge)");
  sub.add("--threads", a->threads, "worker threads (0: all cores; at most 4096)", show::with_default);
  sub.add("--shard", a->shard, "only part I of N (0-based) of the enumeration; combine with 'gyrores merge'",
          show::with_default);
  sub.flag("--certified", a->certified,
           "decide degeneracy, paper-node, structure and asy-bound by exact integers and interval arithmetic "
           "(the lattice theorem): a pass is a proof, and the rows' values are the exact values rounded, each proved");
  sub.flag("--no-filter", a->no_filter,
           "with --certified: prove every row with MPFI alone, without the double-double filter first (the same "
           "rows, several times slower; for testing the filter)");
  sub.flag("--resume", a->resume, "continue an interrupted run from its resume state");
  sub.flag("--fresh", a->fresh, "discard a saved resume state and start again (without it, a saved state is refused)");
  sub.flag("--allow-large", a->allow_large, "run a sweep beyond 1e10 pairs or 100 GB of scratch and output");
  sub.add("--digits", a->digits,
          "working precision: <= 15 double, <= 30 float128, beyond MPFR (slower); rows print max(D, 17) digits",
          show::with_default);
  sub.add("--examples", a->examples, "violating pairs listed per check", show::with_default);
  sub.add("--state", a->state, "resume state file (default: OUT.resume, else SUMMARY.resume, else ./gyrores-sweep.resume)");
  sub.add("--checkpoint", a->checkpoint, "seconds between resume checkpoints (0: only when stopping)", show::with_default);
  sub.add("--max-pairs", a->max_pairs, "stop after this many pairs, leaving a resume state (exit 4; 0: no limit)",
          show::with_default);
  sub.flag("--quiet", a->quiet, "no progress on stderr");
  sub.flag("--json", a->json, "print the summary as JSON (the --summary schema) instead of text");
  return [a] { return run_sweep(*a); };
}

const command_registration registration{"sweep", install_sweep};

}  // namespace
}  // namespace gyrores::cli
