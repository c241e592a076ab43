// include/gyrores/sweep/count.hpp: the phi sieve and shard shares.
#include <gyrores/sweep/count.hpp>

#include <string>
#include <vector>

#include <gyrores/core/error.hpp>

namespace gyrores {

std::uint64_t sweep_total_pairs(std::int64_t min_order, std::int64_t max_order) {
  if (min_order < 3) min_order = 3;
  if (max_order < min_order) return 0;
  if (max_order > sweep_count_limit)
    throw usage_error("sweep_total_pairs: orders beyond " + std::to_string(sweep_count_limit) + " are not counted");
  std::vector<std::uint32_t> phi(std::size_t(max_order) + 1);
  for (std::size_t i = 0; i < phi.size(); ++i) phi[i] = std::uint32_t(i);
  for (std::size_t pr = 2; pr < phi.size(); ++pr)
    if (phi[pr] == pr)
      for (std::size_t m = pr; m < phi.size(); m += pr) phi[m] -= phi[m] / std::uint32_t(pr);
  std::uint64_t s = 0;
  for (std::int64_t a = min_order; a <= max_order; ++a) s += phi[std::size_t(a)] / 2;
  return s;
}

std::uint64_t sweep_shard_pairs(std::uint64_t total, std::int64_t i, std::int64_t n) {
  return total > std::uint64_t(i) ? (total - std::uint64_t(i) + std::uint64_t(n) - 1) / std::uint64_t(n) : 0;
}

}  // namespace gyrores
