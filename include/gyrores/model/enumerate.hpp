// Lazy enumeration of all resonant pairs with min_order <= tau + sigma <= max_order.
//
// Order (documented, deterministic): by order a = tau + sigma ascending, then by sigma
// ascending (so tau descending). The first pair is (2, 1). Nothing is materialised: the
// iterator holds (a, sigma) and steps to the next coprime pair, testing gcd(a, sigma) = 1
// (equivalent to gcd(tau, sigma) = 1).
// Sharding: with shard (i, n), only the pairs whose 0-based position in the full enumeration
// is congruent to i mod n are yielded; the n shards are disjoint and cover the enumeration.
#pragma once
#include <cstdint>
#include <iterator>
#include <numeric>

#include <gyrores/model/pair.hpp>

namespace gyrores {

class coprime_pairs {
 public:
  // Requires 1 <= max_order; min_order below 3 is treated as 3 (the smallest order).
  coprime_pairs(std::int64_t min_order, std::int64_t max_order, std::int64_t shard_index = 0,
                std::int64_t shard_count = 1)
      : min_(min_order < 3 ? 3 : min_order), max_(max_order), shard_(shard_index), shards_(shard_count) {
    if (shard_count < 1 || shard_index < 0 || shard_index >= shard_count)
      throw usage_error("shard must be I/N with 0 <= I < N");
  }

  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = resonant_pair<std::int64_t>;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = value_type;

    iterator() = default;
    value_type operator*() const { return value_type(a_ - s_, s_, known_coprime); }  // advance() tested gcd(a, s) = 1
    iterator& operator++() {
      step();
      skip_to_shard();
      return *this;
    }
    void operator++(int) { ++*this; }
    bool operator==(std::default_sentinel_t) const { return a_ > max_; }
    // 0-based position of the current pair in the full (unsharded) enumeration.
    std::int64_t position() const { return pos_; }

   private:
    friend class coprime_pairs;
    iterator(std::int64_t a, std::int64_t max, std::int64_t shard, std::int64_t shards)
        : a_(a), s_(0), max_(max), shard_(shard), shards_(shards) {
      advance();
      pos_ = 0;
      skip_to_shard();
    }
    // Move to the next coprime (a, s) after the current one (or the first for s_ = 0).
    void advance() {
      for (;;) {
        ++s_;
        if (2 * s_ >= a_) { ++a_; s_ = 1; }
        if (a_ > max_) return;
        if (std::gcd(a_, s_) == 1) return;
      }
    }
    void step() { advance(); ++pos_; }
    void skip_to_shard() {
      while (a_ <= max_ && pos_ % shards_ != shard_) step();
    }
    std::int64_t a_ = 0, s_ = 0, max_ = 0, shard_ = 0, shards_ = 1, pos_ = 0;
  };

  iterator begin() const { return iterator(min_, max_, shard_, shards_); }
  std::default_sentinel_t end() const { return {}; }

 private:
  std::int64_t min_, max_, shard_, shards_;
};

}  // namespace gyrores
