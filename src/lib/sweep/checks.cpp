// include/gyrores/sweep/checks.hpp: check names, check lists, configuration limits, the phi sieve.
#include <gyrores/sweep/checks.hpp>

#include <string>
#include <vector>

#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

const char* const check_names[sweep_check_count] = {"degeneracy", "paper-node", "asy-bound", "structure"};
const char* const check_columns[sweep_check_count] = {"check_degeneracy", "check_paper_node", "check_asy_bound",
                                                      "check_structure"};

// The set named by one element of a check list.
sweep_check_set parse_one_check(const std::string& name) {
  if (name == "all") return sweep_all_checks;
  if (name == "default") return sweep_default_checks;
  for (int i = 0; i < sweep_check_count; ++i)
    if (name == check_names[i]) return 1u << i;
  if (name == "cross-check")  // a check of sweeps before format version 2 (docs/formats.md)
    throw usage_error("the check cross-check is no longer part of sweeps: the comparison with the global search is "
                      "a test of gyrores's sources now (tests/test_cross_check.cpp)");
  throw usage_error("unknown check '" + name +
                    "' (expected default, all, degeneracy, paper-node, asy-bound, structure)");
}

}  // namespace

const char* sweep_check_name(int i) { return check_names[i]; }
const char* sweep_check_column(int i) { return check_columns[i]; }

sweep_check_set sweep_parse_checks(const std::string& list) {
  sweep_check_set s = 0;
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    s |= parse_one_check(list.substr(start, end - start));
    start = end + 1;
  }
  return s;
}

std::vector<std::string> sweep_check_names(sweep_check_set s) {
  std::vector<std::string> out;
  for (int i = 0; i < sweep_check_count; ++i)
    if ((s >> i) & 1u) out.push_back(check_names[i]);
  return out;
}

void sweep_validate(const sweep_config& c) {
  if (c.max_order < 3) throw usage_error("max_order must be >= 3, got " + std::to_string(c.max_order));
  if (c.max_order > sweep_max_order_limit)
    throw usage_error("max_order must be <= 2^40, got " + std::to_string(c.max_order));
  if (c.min_order > c.max_order)
    throw usage_error("min_order " + std::to_string(c.min_order) + " exceeds max_order " +
                      std::to_string(c.max_order));
  if (c.shard_count < 1 || c.shard_index < 0 || c.shard_index >= c.shard_count)
    throw usage_error("shard must be I/N with 0 <= I < N, got " + std::to_string(c.shard_index) + "/" +
                      std::to_string(c.shard_count));
}

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
