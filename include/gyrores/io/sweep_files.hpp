// The files of one sweep run: the rows file (FILE.part, renamed when complete), the summary (and
// a shard run's values file), and the resume state written at checkpoints. What each holds and
// when it is written: docs/formats.md. The run that feeds them is app/sweep.hpp's.
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <gyrores/core/real.hpp>
#include <gyrores/io/files.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_rows.hpp>
#include <gyrores/sweep/sweep.hpp>

namespace gyrores {

// The default memory budget of a sweep's values: 2^27 values (1 GiB), or an eighth of the
// machine's physical memory if that is less (at least 2^20 values, 8 MB).
std::size_t sweep_default_values_in_memory();

struct sweep_files {
  std::string rows_path;  // empty: no rows
  sweep_format rows_format = sweep_format::csv;
  std::string summary_path;  // empty: no summary file
  std::string state_path;    // empty: derived (sweep_default_state_path)
  bool resume = false;
  // Without resume, a saved state is refused ("a saved run exists") unless fresh discards it.
  bool fresh = false;
  // Set: the state's lock, when another run holds it, is waited for (this is called once with
  // the reason) instead of refused, for a state path nobody named (./gyrores-sweep.resume).
  std::function<void(const std::string&)> on_lock_wait;
  double checkpoint_seconds = 300;  // periodic checkpoints (0: only when stopping early)
  // The memory budget of the t_first/proxy values, in values (8 bytes each): a run with at most
  // this many pairs holds its values in memory and the quantiles read them there; a larger one
  // (or one holding more than this many at once) writes them to the state's values file as they
  // pile up, and the quantiles read them back from it (docs/formats.md, "Quantiles").
  std::size_t values_in_memory = sweep_default_values_in_memory();
};

struct sweep_progress_info {
  std::uint64_t done = 0, total = 0;  // pairs of the shard; total 0 when unknown
  double seconds = 0;                 // this run
  std::uint64_t done_this_run = 0;
};
using sweep_progress = std::function<void(const sweep_progress_info&)>;

struct sweep_report {
  json summary;             // complete runs only (null otherwise)
  bool complete = false;
  std::uint64_t done = 0;   // pairs of the shard done
  std::uint64_t total = 0;  // pairs of the shard (0 if not counted)
  std::string state_path;   // where the resume state is (incomplete runs)
  unsigned threads = 1;
  double seconds = 0;       // this run
};

// The resume state's path: state_path, else ROWS.resume, else SUMMARY.resume, else
// gyrores-sweep.resume.
std::string sweep_default_state_path(const sweep_files& f);

// From opening (fresh, or restored from the resume state) through the blocks and checkpoints to
// the end. `cfg` is validated, min_order >= 3; `run` is sweep_run_json's. usage_error for a file
// that cannot be written or read, or a resume state that is missing, for another sweep or
// inconsistent.
class sweep_file_session {
 public:
  sweep_file_session(const sweep_config& cfg, const sweep_files& files, const json& run, const sweep_progress& progress);
  std::uint64_t start() const { return start_; }  // pairs of the shard done before this run
  void on_block(const sweep_block& b);
  // Makes what was delivered so far durable and resumable (docs/formats.md, resume state).
  void checkpoint();
  // After the engine returned: a checkpoint if the shard is not done, else the summary, the
  // values file (shard runs), the renamed rows file, and the state removed.
  sweep_report finish(const sweep_outcome& out);

 private:
  void check_paths_and_lock();
  void start_fresh();
  void restore();
  void restore_values(std::uint64_t count);
  void check_state_counts(std::uint64_t values_count) const;
  void check_rows_boundary() const;
  void write_values();
  void spill_values();
  void finish_complete(unsigned threads, sweep_report& rep);
  double elapsed() const;

  const sweep_config& cfg_;
  const sweep_files& files_;
  const sweep_progress& progress_;
  json run_, run_files_;
  std::vector<path_lock> locks_;  // the outputs' locks, held for the whole run (io/files.hpp)
  std::string state_, values_, rows_part_;
  bool rows_;
  append_file rows_file_;
  append_file values_file_;  // the state's values file: at checkpoints, and beyond the budget
  sweep_accumulator acc_;
  std::uint64_t total_ = 0, start_ = 0, done_ = 0;
  // The values are numbered in enumeration order. The values file holds [0, values_written_);
  // acc_.t_ratios' memory holds [memory_first_, memory_first_ + its size), memory_first_ <=
  // values_written_: a checkpoint writes the values in memory but keeps them there.
  std::uint64_t values_written_ = 0, memory_first_ = 0;
  std::size_t spill_at_ = 0;  // values in memory that go to the file (the budget, or 2^20)
  std::uint64_t rows_bytes_ = 0;      // bytes of rows_part holding whole, delivered blocks
  double seconds_before_ = 0, last_checkpoint_ = 0;
  sweep_pair_id last_{0, 0};
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace gyrores
