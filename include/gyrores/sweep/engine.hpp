// The sweep engine: evaluates the pairs of one shard on worker threads and delivers the results
// in enumeration order, so that every output is independent of the thread count.
//
// The calling thread enumerates nothing itself; `threads` workers take blocks of consecutive
// pairs from the shared lazy enumeration (model/enumerate.hpp, sharded), evaluate them, and hand
// back per-block results; the calling thread consumes the blocks strictly in enumeration order
// (rows text, accumulator). A stop flag is honoured at block boundaries: blocks already taken are
// finished and delivered, so the pairs done are always a prefix of the shard's enumeration, which
// is what a resume state records (docs/formats.md). Every real type runs on every worker: a
// row never reads or writes Boost's process-wide MPFR precision (evaluate.hpp).
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <gyrores/core/real.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/sweep/summary.hpp>

namespace gyrores {

// One block of consecutive pairs of the shard, delivered in order.
struct sweep_block {
  std::uint64_t first = 0, count = 0;  // shard-relative index of the first pair, number of pairs
  sweep_accumulator summary;           // of this block alone
  std::string rows;                    // formatted rows (when a row formatter is given)
  sweep_pair_id last{0, 0};            // last pair of the block
};

template <class T> using sweep_row_formatter = std::function<void(std::string&, const sweep_row<T>&)>;

struct sweep_engine_options {
  unsigned threads = 0;            // 0: std::thread::hardware_concurrency()
  std::size_t block_size = 1024;   // pairs per block (the stop flag is honoured between blocks)
  std::uint64_t start = 0;         // skip this many pairs of the shard (resume)
  std::uint64_t max_pairs = 0;     // stop after this many pairs in this call (0: no limit)
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by a signal handler) to stop cleanly
};

struct sweep_outcome {
  std::uint64_t done = 0;   // pairs of the shard done after this call (start + pairs evaluated)
  bool complete = false;    // the shard's enumeration was exhausted
  unsigned threads = 1;     // workers used
};

// Fills blk.summary (whose max_examples is already set) and blk.rows from the block's pairs, in
// their order. Runs on a worker thread: it must be safe to call concurrently.
using sweep_block_evaluator =
    std::function<void(const std::vector<resonant_pair<std::int64_t>>& pairs, sweep_block& blk)>;

// The engine for any evaluation of pairs: the pairs of cfg's shard from index opt.start on, in
// blocks of opt.block_size, evaluated by `evaluate` on opt.threads workers (0: every core) and
// handed to on_block in enumeration order, on the calling thread. Returns when the shard is
// exhausted, opt.max_pairs is reached, or *opt.stop is set (after finishing and delivering every
// block already started). usage_error if cfg is invalid (sweep_validate). An exception thrown by
// on_block or by `evaluate` stops the run and is rethrown here, after the workers have ended.
sweep_outcome sweep_run_blocks(const sweep_config& cfg, const sweep_engine_options& opt,
                               const sweep_block_evaluator& evaluate,
                               const std::function<void(sweep_block&)>& on_block);

// sweep_run_blocks with each pair evaluated by sweep_evaluate<T> (computation failures become
// error rows, they do not stop the run); format_row, if set, appends a row's text to the
// block's `rows` (it runs on the workers). Without rows (no format_row) a double sweep that is
// not certified takes each pair's summary from the theorem's series form where that decides it
// (src/lib/sweep/fast.cpp): the same summary, at a fraction of a row's cost.
template <class T>
sweep_outcome sweep_run(const sweep_config& cfg, const sweep_engine_options& opt,
                        const std::function<void(sweep_block&)>& on_block,
                        const sweep_row_formatter<T>& format_row = {});

// Compiled once in src/lib/sweep/engine.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_ENGINE_INSTANCES(PREFIX, T)                                                        \
  PREFIX template sweep_outcome sweep_run<T>(const sweep_config&, const sweep_engine_options&,          \
                                             const std::function<void(sweep_block&)>&,                 \
                                             const sweep_row_formatter<T>&);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ENGINE_INSTANCES, extern)

}  // namespace gyrores
