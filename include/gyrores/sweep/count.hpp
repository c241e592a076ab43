// Counting the pairs of a sweep without enumerating them: for progress (done of total) and for
// checking that each shard given to a merge holds exactly its share.
#pragma once
#include <cstdint>

namespace gyrores {

// Orders up to this are counted (the sieve takes 4 bytes per order: 40 MB).
inline constexpr std::int64_t sweep_count_limit = 10'000'000;

// Number of pairs with min_order <= tau + sigma <= max_order: the sum of phi(a)/2 (a sieve of
// Euler's phi). min_order below 3 counts as 3; 0 if max_order < min_order. usage_error if
// max_order > sweep_count_limit.
std::uint64_t sweep_total_pairs(std::int64_t min_order, std::int64_t max_order);

// Pairs of shard i of n (0 <= i < n, not checked): the positions p < total with p = i mod n.
std::uint64_t sweep_shard_pairs(std::uint64_t total, std::int64_t i, std::int64_t n);

}  // namespace gyrores
