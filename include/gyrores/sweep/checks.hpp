// The checks a sweep runs on every pair (the paper's claims, docs/mathematics.md §2, §3; what each
// computes: evaluate.hpp), the sweep's configuration, and its number of pairs. A set of checks is
// a bit mask in the enum's order, which is also the order of the rows' check columns and of the
// summary's checks (docs/formats.md).
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
inline constexpr sweep_check_set sweep_default_checks = sweep_all_checks;

// The check's name as users type it ("paper-node") and its rows' column ("check_paper_node");
// i in [0, sweep_check_count), not checked.
const char* sweep_check_name(int i);
const char* sweep_check_column(int i);
inline bool sweep_has_check(sweep_check_set s, sweep_check c) { return (s >> int(c)) & 1u; }

// A comma-separated list of check names, "default" and "all"; usage_error names an unknown (or
// empty) one.
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
  bool certified_filter = true;  // certified double rows: the double-double balls first (the same
                                 // rows; false only to test that)
  bool operator==(const sweep_config&) const = default;
};

// usage_error (naming the parameter) unless 3 <= max_order <= 2^40, min_order <= max_order and
// 0 <= shard_index < shard_count.
void sweep_validate(const sweep_config& c);

// Orders up to this are counted (the sieve takes 4 bytes per order: 40 MB).
inline constexpr std::int64_t sweep_count_limit = 10'000'000;

// Number of pairs with min_order <= tau + sigma <= max_order, without enumerating them (for
// progress, and for checking that each shard of a merge holds its share): the sum of phi(a)/2.
// min_order below 3 counts as 3; 0 if max_order < min_order; usage_error beyond sweep_count_limit.
std::uint64_t sweep_total_pairs(std::int64_t min_order, std::int64_t max_order);

// Pairs of shard i of n (0 <= i < n, not checked): the positions p < total with p = i mod n.
std::uint64_t sweep_shard_pairs(std::uint64_t total, std::int64_t i, std::int64_t n);

}  // namespace gyrores
