// The checks a sweep runs on every pair, and the sweep's configuration.
//
// Each check tests one of the paper's claims per pair (docs/mathematics.md §2, §3); what each
// one computes is in evaluate.hpp. A set of checks is a bit mask (bit i: check i), in the order
// of the enum, which is also the order of the rows' check columns and of the summary's checks
// (docs/formats.md). A sweep runs all four unless told otherwise.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gyrores {

enum class sweep_check : int { degeneracy = 0, paper_node = 1, asy_bound = 2, structure = 3 };
inline constexpr int sweep_check_count = 4;
using sweep_check_set = unsigned;  // bit i: check i
inline constexpr sweep_check_set sweep_all_checks = (1u << sweep_check_count) - 1;
// degeneracy, paper-node, asy-bound, structure: what a sweep checks unless told otherwise.
inline constexpr sweep_check_set sweep_default_checks = sweep_all_checks;

// The check's name as users type it ("paper-node"); i in [0, sweep_check_count), not checked.
const char* sweep_check_name(int i);
// The name of the rows' column holding check i's pass/fail status ("check_paper_node").
const char* sweep_check_column(int i);
inline bool sweep_has_check(sweep_check_set s, sweep_check c) { return (s >> int(c)) & 1u; }

// A comma-separated list of check names, "default" (sweep_default_checks) and "all" (every check);
// usage_error names an unknown (or empty) one.
sweep_check_set sweep_parse_checks(const std::string& list);
// The names of the checks in s, in check order.
std::vector<std::string> sweep_check_names(sweep_check_set s);

// Orders beyond this are refused: the int64/int128 fast paths and the phi sieve assume it,
// and a sweep there (~1.5e17 pairs) is out of reach anyway.
inline constexpr std::int64_t sweep_max_order_limit = std::int64_t(1) << 40;

struct sweep_config {
  std::int64_t min_order = 3;  // below 3 is treated as 3
  std::int64_t max_order = 0;
  std::int64_t shard_index = 0, shard_count = 1;
  sweep_check_set checks = sweep_default_checks;
  std::size_t max_examples = 5;  // violating pairs listed per check
  unsigned digits = 17;          // significant digits of reals in rows when T is wider than double
                                 // (mpfr_real: also the working precision, digits + 8, sweep_bits)
  bool certified = false;        // decide the checks by exact integers and intervals (sweep/certified.hpp)
  bool certified_filter = true;  // certified double rows: try the double-double balls first
                                 // (sweep/filtered.hpp; the rows are the same either way; false
                                 // only to test that)
  bool operator==(const sweep_config&) const = default;
};

// usage_error (naming the parameter) unless 3 <= max_order <= 2^40, min_order <= max_order and
// 0 <= shard_index < shard_count.
void sweep_validate(const sweep_config& c);

}  // namespace gyrores
