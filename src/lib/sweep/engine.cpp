// include/gyrores/sweep/engine.hpp: workers taking blocks of the lazy enumeration, delivery in
// enumeration order on the calling thread, the stop flag at block boundaries.
#include <gyrores/sweep/engine.hpp>

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <type_traits>

#include <gyrores/core/thread_caches.hpp>

#include "row_parts.hpp"

namespace gyrores {
namespace {

using pair64 = resonant_pair<std::int64_t>;

// The pairs of one shard in the order of coprime_pairs (model/enumerate.hpp: by order a, then
// sigma ascending; shard i of n keeps the positions = i mod n), as (a, sigma). It runs under the
// pipeline's lock, so it is kept cheap: coprimality of (a, s) is read from a table of a window of
// s, marked by the distinct primes of a (found once per order), instead of one gcd per candidate
// (a gcd at order 10^5 costs about as much as the table for a whole window). tests/test_sweep.cpp
// checks the rows against the plain enumeration through the summary.
class pair_stream {
 public:
  pair_stream(std::int64_t min_order, std::int64_t max_order, std::int64_t shard, std::int64_t shards)
      : a_(std::max<std::int64_t>(3, min_order) - 1), s_(0), max_(max_order), shard_(shard), shards_(shards) {
    next_order();
    advance();
    pos_ = 0;
    skip_to_shard();
  }
  bool done() const { return a_ > max_; }
  std::int64_t order() const { return a_; }
  std::int64_t sigma() const { return s_; }
  void next() {
    advance();
    ++pos_;
    skip_to_shard();
  }

 private:
  static constexpr std::int64_t window = 4096;
  void next_order() {
    ++a_;
    s_ = 0;
    win_lo_ = 1;
    win_hi_ = 1;  // empty: the first advance() fills it
    primes_.clear();
    std::int64_t n = a_;
    for (std::int64_t p = 2; p * p <= n; ++p)
      if (n % p == 0) {
        primes_.push_back(p);
        while (n % p == 0) n /= p;
      }
    if (n > 1) primes_.push_back(n);
  }
  // coprime_[s - win_lo_] for s in [win_lo_, win_hi_): gcd(a, s) = 1.
  void fill_window(std::int64_t lo) {
    win_lo_ = lo;
    win_hi_ = std::min(lo + window, (a_ + 1) / 2);  // s < a/2 (2 s < a)
    coprime_.assign(std::size_t(std::max<std::int64_t>(0, win_hi_ - win_lo_)), 1);
    for (std::int64_t p : primes_)
      for (std::int64_t m = ((lo + p - 1) / p) * p; m < win_hi_; m += p) coprime_[std::size_t(m - lo)] = 0;
  }
  // The next coprime (a, s) of the full enumeration.
  void advance() {
    for (;;) {
      ++s_;
      if (2 * s_ >= a_) {
        next_order();
        if (a_ > max_) return;
        s_ = 1;
      }
      if (s_ >= win_hi_) fill_window(s_);
      if (coprime_[std::size_t(s_ - win_lo_)]) return;
    }
  }
  void skip_to_shard() {
    while (a_ <= max_ && pos_ % shards_ != shard_) {
      advance();
      ++pos_;
    }
  }
  std::int64_t a_, s_, max_, shard_, shards_, pos_ = 0;
  std::int64_t win_lo_ = 1, win_hi_ = 1;
  std::vector<std::int64_t> primes_;
  std::vector<unsigned char> coprime_;
};

// The shared state of one run: the enumeration (guarded by mtx_), the blocks evaluated but not
// yet delivered, and the first failure.
class block_pipeline {
 public:
  block_pipeline(const sweep_config& cfg, const sweep_engine_options& opt, const sweep_block_evaluator& evaluate)
      : cfg_(cfg),
        opt_(opt),
        evaluate_(evaluate),
        threads_(opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency())),
        block_size_(std::max<std::size_t>(1, opt.block_size)),
        window_(4 * std::uint64_t(threads_)),
        it_(cfg.min_order, cfg.max_order, cfg.shard_index, cfg.shard_count),
        limit_(opt.max_pairs ? opt.start + opt.max_pairs : std::numeric_limits<std::uint64_t>::max()) {}

  sweep_outcome run(const std::function<void(sweep_block&)>& on_block) {
    // Resume: step over the pairs done before (nothing runs concurrently yet).
    while (taken_ < opt_.start && !it_.done()) {
      it_.next();
      ++taken_;
    }
    exhausted_ = it_.done();
    std::uint64_t done = taken_;  // before the workers start taking
    active_ = threads_;
    std::vector<std::thread> pool;
    pool.reserve(threads_);
    for (unsigned i = 0; i < threads_; ++i) pool.emplace_back([this] { worker(); });
    sweep_block blk;
    while (next_in_order(blk)) {
      try {
        done = blk.first + blk.count;
        on_block(blk);
      } catch (...) {
        fail(std::current_exception());
        break;
      }
    }
    for (auto& t : pool) t.join();
    if (failure_) std::rethrow_exception(failure_);
    return {done, it_.done() && done == taken_, threads_};
  }

 private:
  bool stop_requested() const { return opt_.stop && opt_.stop->load(std::memory_order_relaxed); }

  // Under mtx_: the next block's pairs as (a, sigma), its id and first index; false when no more
  // work is wanted. The pairs themselves are built by the worker, outside the lock.
  bool take_block(std::vector<std::pair<std::int64_t, std::int64_t>>& raw, std::uint64_t& id, std::uint64_t& first) {
    if (abort_ || exhausted_ || taken_ >= limit_ || stop_requested()) return false;
    raw.clear();
    first = taken_;
    while (raw.size() < block_size_ && taken_ < limit_ && !it_.done()) {
      raw.emplace_back(it_.order(), it_.sigma());
      it_.next();
      ++taken_;
    }
    if (it_.done()) exhausted_ = true;
    id = next_id_++;
    return true;
  }

  void fail(std::exception_ptr e) {
    std::lock_guard<std::mutex> lk(mtx_);
    if (!failure_) failure_ = e;
    abort_ = true;
    cv_work_.notify_all();
    cv_done_.notify_all();
  }

  void worker() {
    std::vector<std::pair<std::int64_t, std::int64_t>> raw;
    std::vector<pair64> pairs;
    raw.reserve(block_size_);
    pairs.reserve(block_size_);
    for (;;) {
      std::uint64_t id = 0, first = 0;
      {
        std::unique_lock<std::mutex> lk(mtx_);
        cv_work_.wait(lk, [&] { return abort_ || next_id_ < next_write_ + window_; });
        if (!take_block(raw, id, first)) break;
      }
      sweep_block blk;
      try {
        pairs.clear();
        for (const auto& [a, s] : raw) pairs.emplace_back(a - s, s, known_coprime);  // from pair_stream's table
        blk.first = first;
        blk.count = pairs.size();
        blk.summary.max_examples = cfg_.max_examples;
        evaluate_(pairs, blk);
        if (!pairs.empty()) blk.last = {pairs.back().tau(), pairs.back().sigma()};
      } catch (...) {
        fail(std::current_exception());
        break;
      }
      {
        std::lock_guard<std::mutex> lk(mtx_);
        ready_.emplace(id, std::move(blk));
      }
      cv_done_.notify_all();
    }
    release_thread_caches();  // the certified checks and MPFR rows use MPFR and Arb on this thread
    std::lock_guard<std::mutex> lk(mtx_);
    --active_;
    cv_done_.notify_all();
  }

  // The next block in enumeration order; false when the run is over (aborted, or every worker has
  // ended and every block has been delivered).
  bool next_in_order(sweep_block& blk) {
    {
      std::unique_lock<std::mutex> lk(mtx_);
      cv_done_.wait(lk, [&] { return abort_ || ready_.count(next_write_) || (active_ == 0 && next_write_ == next_id_); });
      if (abort_) return false;
      auto f = ready_.find(next_write_);
      if (f == ready_.end()) return false;
      blk = std::move(f->second);
      ready_.erase(f);
      ++next_write_;
    }
    cv_work_.notify_all();
    return true;
  }

  const sweep_config& cfg_;
  const sweep_engine_options& opt_;
  const sweep_block_evaluator& evaluate_;
  const unsigned threads_;
  const std::size_t block_size_;
  const std::uint64_t window_;  // blocks in flight
  pair_stream it_;
  const std::uint64_t limit_;
  std::uint64_t taken_ = 0;  // pairs handed out (shard-relative, from 0)
  bool exhausted_ = false;

  std::mutex mtx_;
  std::condition_variable cv_work_, cv_done_;
  std::uint64_t next_id_ = 0, next_write_ = 0;
  std::map<std::uint64_t, sweep_block> ready_;
  unsigned active_ = 0;
  bool abort_ = false;
  std::exception_ptr failure_;
};

}  // namespace

sweep_outcome sweep_run_blocks(const sweep_config& cfg, const sweep_engine_options& opt,
                               const sweep_block_evaluator& evaluate,
                               const std::function<void(sweep_block&)>& on_block) {
  sweep_validate(cfg);
  return block_pipeline(cfg, opt, evaluate).run(on_block);
}

template <class T>
sweep_outcome sweep_run(const sweep_config& cfg, const sweep_engine_options& opt,
                        const std::function<void(sweep_block&)>& on_block, const sweep_row_sink<T>& keep_row) {
  const bool fast = std::is_same_v<T, double> && !keep_row && !cfg.certified;
  // The largest asy constant computed so far in this run, shared by the workers as a hint: any
  // value a pair of the run has given is a valid one (src/lib/sweep/fast.cpp), so relaxed order
  // suffices.
  std::atomic<double> asy_known{0};
  auto evaluate = [&cfg, &keep_row, fast, &asy_known](const std::vector<pair64>& pairs, sweep_block& blk) {
    blk.summary.t_ratios.reserve(pairs.size());
    if constexpr (std::is_same_v<T, double>) {
      if (fast) {
        double known = asy_known.load(std::memory_order_relaxed);
        sweep_rows::fast_block(pairs, blk, cfg, known);
        double seen = asy_known.load(std::memory_order_relaxed);
        while (known > seen && !asy_known.compare_exchange_weak(seen, known, std::memory_order_relaxed)) {
        }
        return;
      }
    }
    // One row and one record for the whole block, overwritten pair by pair: no allocation per
    // pair (the same values as sweep_evaluate's).
    sweep_row<T> row;
    sweep_record rec;
    for (const auto& p : pairs) {
      sweep_evaluate_to(row, p, cfg);
      sweep_record_fill(rec, row, cfg.digits);
      blk.summary.add(rec);
      if (keep_row) keep_row(blk, row);
    }
  };
  return sweep_run_blocks(cfg, opt, evaluate, on_block);
}

GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ENGINE_INSTANCES, )

}  // namespace gyrores
