// The sweep engine: workers take blocks of consecutive pairs of one shard's enumeration
// (model/enumerate.hpp) and evaluate them; the calling thread receives the blocks strictly in
// enumeration order, so every output is independent of the thread count. A stop is honoured at
// block boundaries, after the blocks already taken are delivered: the pairs done are always a
// prefix of the enumeration, which is what a resume state records (docs/formats.md).
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <gyrores/core/real.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/summary.hpp>

namespace gyrores {

// One block of consecutive pairs of the shard, delivered in order.
struct sweep_block {
  std::uint64_t first = 0, count = 0;  // shard-relative index of the first pair, number of pairs
  sweep_accumulator summary;           // of this block alone
  std::string rows;                    // formatted rows (when a row formatter is given)
  std::vector<sweep_row<double>> kept;  // rows held in memory (app::run_sweep_in_memory)
  sweep_pair_id last{0, 0};            // last pair of the block
};

// What a run keeps of each row, on the workers: its text appended to the block's `rows`, or
// the row itself in `kept`.
template <class T> using sweep_row_sink = std::function<void(sweep_block&, const sweep_row<T>&)>;

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

// The pairs of cfg's shard from index opt.start on, evaluated by `evaluate` on the workers and
// handed to on_block in enumeration order on the calling thread, until the shard is exhausted,
// opt.max_pairs is reached or *opt.stop is set. usage_error if cfg is invalid (sweep_validate).
// An exception from on_block or `evaluate` stops the run and is rethrown here, after the workers
// have ended.
sweep_outcome sweep_run_blocks(const sweep_config& cfg, const sweep_engine_options& opt,
                               const sweep_block_evaluator& evaluate,
                               const std::function<void(sweep_block&)>& on_block);

// sweep_run_blocks with each pair evaluated by sweep_evaluate<T> (a failed pair is an error row,
// not a stop) and handed to keep_row, if set. Without rows a double sweep that is not certified
// takes each pair's summary from the theorem's series form where that decides it
// (src/lib/sweep/fast.cpp): the same summary, far cheaper.
template <class T>
sweep_outcome sweep_run(const sweep_config& cfg, const sweep_engine_options& opt,
                        const std::function<void(sweep_block&)>& on_block, const sweep_row_sink<T>& keep_row = {});

// Compiled once in src/lib/sweep/engine.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_ENGINE_INSTANCES(PREFIX, T)                                                        \
  PREFIX template sweep_outcome sweep_run<T>(const sweep_config&, const sweep_engine_options&,          \
                                             const std::function<void(sweep_block&)>&,                 \
                                             const sweep_row_sink<T>&);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ENGINE_INSTANCES, extern)

}  // namespace gyrores
