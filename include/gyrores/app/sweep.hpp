// The application layer (include/gyrores/app/pair.hpp): `gyrores sweep`, `gyrores merge` and
// gyrores.sweep. A sweep runs the engine (sweep/engine.hpp) in the working type its digits
// choose, with its files and resume state (io/sweep_files.hpp: what is written when), or in
// memory for Python; a merge reads shard outputs (io/sweep_summary.hpp) into one summary.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <gyrores/core/real.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_files.hpp>
#include <gyrores/sweep/sweep.hpp>

namespace gyrores::app {

// Runs the sweep cfg with T as working type (MPFR: cfg.digits + 8 digits, sweep_bits; the
// process-wide MPFR precision is neither read nor set), writing the files named in `files`;
// progress, if set, is called after every block (on the calling thread). Returns complete =
// false when eo.max_pairs or *eo.stop ended the run early (a checkpoint was written: run again
// with files.resume to continue). usage_error for an invalid cfg, a file that cannot be written
// or read, or a resume state that is missing or for another sweep; an exception from the engine
// or from `progress` is rethrown after a checkpoint of the pairs done.
template <class T>
sweep_report sweep_to_files(const sweep_config& cfg, const sweep_files& files, const sweep_engine_options& eo,
                            const sweep_progress& progress = {});
// Compiled once in src/app/sweep.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_FILES_INSTANCES(PREFIX, T)                                                              \
  PREFIX template sweep_report sweep_to_files<T>(const sweep_config&, const sweep_files&, const sweep_engine_options&, \
                                                 const sweep_progress&);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_FILES_INSTANCES, extern)

struct sweep_request {
  sweep_config config;  // config.digits also chooses the working type: double up to 15 digits,
                        // float128 up to 30, MPFR beyond
  sweep_files files;
  sweep_engine_options engine;  // threads, max_pairs, stop (the block size is chosen here)
  bool allow_large = false;     // run beyond the size caps below
  sweep_progress progress;
};

// sweep_to_files in the working type of r.config.digits. usage_error as sweep_to_files, and for
// a sweep of more than 1e10 pairs or 100 GB of scratch and output (docs/formats.md, "Size caps")
// unless r.allow_large.
sweep_report run_sweep(const sweep_request& r);

// A sweep in double without files (the Python module), by sweep_run: with keep_rows every pair's
// row (sweep_evaluate), handed in enumeration order to on_block on the calling thread after each
// block of pairs (`rows` empty otherwise), with the pairs done and the total; returns the summary
// of `gyrores sweep --json` (io/sweep_summary.hpp). An exception from on_block stops the run and
// is rethrown after the workers have ended.
struct sweep_in_memory_request {
  sweep_config config;
  unsigned threads = 0;  // 0: every core
  bool keep_rows = true;
  std::function<void(std::vector<sweep_row<double>>& rows, std::uint64_t done, std::uint64_t total)> on_block;
};
json run_sweep_in_memory(const sweep_in_memory_request& r);

// The summary of the shard outputs `inputs` (sweep_merge), also written to summary_path if it is
// not empty: checked first to be writable, none of the inputs or their values files, and locked
// against other gyrores runs (io/files.hpp).
json run_merge(const std::vector<std::string>& inputs, const std::string& summary_path);

}  // namespace gyrores::app
