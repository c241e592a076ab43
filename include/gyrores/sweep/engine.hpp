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
#include <type_traits>
#include <vector>

#include <gyrores/core/real.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/sweep/fast.hpp>
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
// block's `rows` (it runs on the workers).
namespace detail {

// The pairs of a block of a double sweep without rows: the fast path of sweep/fast.hpp where it
// decides a pair, else the row's way into `row` and `rec` (the same contribution); `known` is
// the largest asy constant computed so far (updated).
inline void sweep_fast_block(const std::vector<resonant_pair<std::int64_t>>& pairs, sweep_block& blk,
                             const sweep_config& cfg, sweep_row<double>& row, sweep_record& rec, double& known) {
  std::vector<std::int64_t> pass_ks;
  sweep_fast_pass_ks(pairs, pass_ks);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (sweep_fast_add(blk.summary, pairs[i], cfg, known, pass_ks[i])) continue;
    sweep_evaluate_to(row, pairs[i], cfg);
    sweep_record_fill(rec, row, cfg.digits);
    blk.summary.add(rec);
    // A row's computed constant (sweep_asy_double_of, or an enclosure's midpoint) is a valid
    // known value: a pair of this run with it is in the summary (fast.cpp, sweep_fast_asy_below).
    if (rec.has_asy && !rec.failed && rec.asy_constant > known) known = rec.asy_constant;
  }
}

}  // namespace detail

// Without rows (no format_row), double sweeps take the fast path of sweep/fast.hpp for the pairs
// it decides: the same summary, at a fraction of a row's cost.
template <class T>
sweep_outcome sweep_run(const sweep_config& cfg, const sweep_engine_options& opt,
                        const std::function<void(sweep_block&)>& on_block,
                        const sweep_row_formatter<T>& format_row = {}) {
  const bool fast = std::is_same_v<T, double> && !format_row && detail::sweep_fast_config(cfg);
  std::atomic<double> asy_known{0};  // the largest asy constant computed so far in this run
  auto evaluate = [&cfg, &format_row, fast, &asy_known](const std::vector<resonant_pair<std::int64_t>>& pairs,
                                                        sweep_block& blk) {
    // One row and one record for the whole block, overwritten pair by pair: no allocation per
    // pair (they are the same values as sweep_evaluate's and sweep_record_of's).
    sweep_row<T> row;
    sweep_record rec;
    blk.summary.t_ratios.reserve(pairs.size());
    if constexpr (std::is_same_v<T, double>) {
      if (fast) {
        double known = asy_known.load(std::memory_order_relaxed);
        detail::sweep_fast_block(pairs, blk, cfg, row, rec, known);
        detail::sweep_fast_publish(asy_known, known);
        return;
      }
    }
    for (const auto& p : pairs) {
      sweep_evaluate_to(row, p, cfg);
      sweep_record_fill(rec, row, cfg.digits);
      blk.summary.add(rec);
      if (format_row) format_row(blk.rows, row);
    }
  };
  return sweep_run_blocks(cfg, opt, evaluate, on_block);
}

// Compiled once in src/lib/sweep/instances.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_ENGINE_INSTANCES(PREFIX, T)                                                        \
  PREFIX template sweep_outcome sweep_run<T>(const sweep_config&, const sweep_engine_options&,          \
                                             const std::function<void(sweep_block&)>&,                 \
                                             const sweep_row_formatter<T>&);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ENGINE_INSTANCES, extern)

}  // namespace gyrores
