// include/gyrores/sweep/checks.hpp: check names, check lists, configuration limits.
#include <gyrores/sweep/checks.hpp>

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

}  // namespace gyrores
