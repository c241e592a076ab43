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

#include <gyrores/model/enumerate.hpp>

namespace gyrores {
namespace {

using pair64 = resonant_pair<std::int64_t>;

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
        range_(cfg.min_order, cfg.max_order, cfg.shard_index, cfg.shard_count),
        it_(range_.begin()),
        limit_(opt.max_pairs ? opt.start + opt.max_pairs : std::numeric_limits<std::uint64_t>::max()) {}

  sweep_outcome run(const std::function<void(sweep_block&)>& on_block);

 private:
  void skip_to_start();
  bool stop_requested() const { return opt_.stop && opt_.stop->load(std::memory_order_relaxed); }
  bool take_block(std::vector<pair64>& pairs, std::uint64_t& id, std::uint64_t& first);
  sweep_block evaluate_block(const std::vector<pair64>& pairs, std::uint64_t first) const;
  void worker();
  bool next_in_order(sweep_block& blk);
  void fail(std::exception_ptr e);

  const sweep_config& cfg_;
  const sweep_engine_options& opt_;
  const sweep_block_evaluator& evaluate_;
  const unsigned threads_;
  const std::size_t block_size_;
  const std::uint64_t window_;  // blocks in flight
  coprime_pairs range_;
  coprime_pairs::iterator it_;
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

// Resume: step over the pairs done before (nothing runs concurrently yet).
void block_pipeline::skip_to_start() {
  while (taken_ < opt_.start && !(it_ == range_.end())) {
    ++it_;
    ++taken_;
  }
  exhausted_ = it_ == range_.end();
}

// Under mtx_: the next block's pairs, its id and first index; false when no more work is wanted.
bool block_pipeline::take_block(std::vector<pair64>& pairs, std::uint64_t& id, std::uint64_t& first) {
  if (abort_ || exhausted_ || taken_ >= limit_ || stop_requested()) return false;
  pairs.clear();
  first = taken_;
  while (pairs.size() < block_size_ && taken_ < limit_ && !(it_ == range_.end())) {
    pairs.push_back(*it_);
    ++it_;
    ++taken_;
  }
  if (it_ == range_.end()) exhausted_ = true;
  id = next_id_++;
  return true;
}

sweep_block block_pipeline::evaluate_block(const std::vector<pair64>& pairs, std::uint64_t first) const {
  sweep_block blk;
  blk.first = first;
  blk.count = pairs.size();
  blk.summary.max_examples = cfg_.max_examples;
  evaluate_(pairs, blk);
  if (!pairs.empty()) blk.last = {pairs.back().tau(), pairs.back().sigma()};
  return blk;
}

void block_pipeline::fail(std::exception_ptr e) {
  std::lock_guard<std::mutex> lk(mtx_);
  if (!failure_) failure_ = e;
  abort_ = true;
  cv_work_.notify_all();
  cv_done_.notify_all();
}

void block_pipeline::worker() {
  std::vector<pair64> pairs;
  pairs.reserve(block_size_);
  for (;;) {
    std::uint64_t id = 0, first = 0;
    {
      std::unique_lock<std::mutex> lk(mtx_);
      cv_work_.wait(lk, [&] { return abort_ || next_id_ < next_write_ + window_; });
      if (!take_block(pairs, id, first)) break;
    }
    sweep_block blk;
    try {
      blk = evaluate_block(pairs, first);
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
  std::lock_guard<std::mutex> lk(mtx_);
  --active_;
  cv_done_.notify_all();
}

// The next block in enumeration order; false when the run is over (aborted, or every worker has
// ended and every block has been delivered).
bool block_pipeline::next_in_order(sweep_block& blk) {
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

sweep_outcome block_pipeline::run(const std::function<void(sweep_block&)>& on_block) {
  skip_to_start();
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
  sweep_outcome out;
  out.done = done;
  out.complete = it_ == range_.end() && done == taken_;
  out.threads = threads_;
  return out;
}

}  // namespace

sweep_outcome sweep_run_blocks(const sweep_config& cfg, const sweep_engine_options& opt,
                               const sweep_block_evaluator& evaluate,
                               const std::function<void(sweep_block&)>& on_block) {
  sweep_validate(cfg);
  block_pipeline pipeline(cfg, opt, evaluate);
  return pipeline.run(on_block);
}

}  // namespace gyrores
