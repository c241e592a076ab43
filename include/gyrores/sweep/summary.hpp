// What a sweep's summary keeps of its rows (docs/formats.md, sweep summary): a mergeable
// accumulator of counts, the first violating pairs, the extremes of the asy columns and every
// t_first/(pi/|n|) for exact quantiles (values.hpp). Accumulators merge exactly in any grouping:
// counts add, examples are re-sorted by enumeration order and cut, extremes compare by value then
// by enumeration order, values concatenate. Reals are doubles; with a wider T each is first
// printed as rows print it and read back, as a merge of row files does, so that single runs and
// merges agree bit for bit.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <gyrores/core/decimal.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/sweep/values.hpp>

namespace gyrores {

// Reals as rows and summaries print them: doubles in the shortest form that reads back exactly,
// wider types with max(digits, 17) significant digits, correctly rounded (an mpfr_real from its
// own bits, at its own precision).
std::string sweep_double_text(double v);
template <class T> std::string sweep_real_text(const T& v, unsigned digits) {
  if constexpr (std::is_same_v<T, double>) return sweep_double_text(v);
  else if constexpr (is_mpfr_v<T>) return format_scientific(v.backend().data(), digits < 17 ? 17 : digits);
  else return format_scientific(real_to_mpfr(v), digits < 17 ? 17 : digits);
}
// Text to double, correctly rounded; compute_error on text that is not a whole real number.
double sweep_text_double(const std::string& s);

// What the summary needs of one row, in doubles (the merge of row files rebuilds exactly this).
struct sweep_record {
  std::int64_t tau = 0, sigma = 0;
  int delta_mod4 = 0;
  bool failed = false;
  std::array<sweep_status, sweep_check_count> status{};
  bool has_ratio = false;
  double t_ratio = 0;
  int first_at_paper_node = -1;
  bool has_asy = false;
  double asy_ratio = 0, asy_constant = 0;
  std::string asy_ratio_text, asy_constant_text;  // empty for T = double (text = shortest form)
};

// What the summary keeps of row r, into s (all of it overwritten; its strings keep their buffers:
// a worker reusing one record allocates nothing per pair).
template <class T> void sweep_record_fill(sweep_record& s, const sweep_row<T>& r, unsigned digits);

// Compiled once in src/lib/sweep/summary.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_RECORD_INSTANCES(PREFIX, T)                                          \
  PREFIX template std::string sweep_real_text<T>(const T&, unsigned);                      \
  PREFIX template void sweep_record_fill<T>(sweep_record&, const sweep_row<T>&, unsigned);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_RECORD_INSTANCES, extern)

using sweep_pair_id = std::pair<std::int64_t, std::int64_t>;  // (tau, sigma)

// Enumeration order: by order tau + sigma, then sigma.
bool sweep_pair_before(const sweep_pair_id& x, const sweep_pair_id& y);

struct sweep_tally {
  std::uint64_t checked = 0, violations = 0;
  std::vector<sweep_pair_id> examples;  // first few, in enumeration order
  bool operator==(const sweep_tally&) const = default;
};

struct sweep_extreme {
  bool set = false;
  double value = 0;
  std::string text;  // exact text when the run was wider than double; empty: shortest form of value
  sweep_pair_id pair{0, 0};
  std::string str() const;
  // Larger value wins; on equal values the earlier pair. NaN is ignored.
  void offer(double v, const std::string& t, const sweep_pair_id& p);
  void merge(const sweep_extreme& o);
  bool operator==(const sweep_extreme& o) const;
};

struct sweep_quantiles {
  std::uint64_t count = 0;
  double min = 0, p01 = 0, p10 = 0, median = 0, p90 = 0, p99 = 0, max = 0;
};

struct sweep_accumulator {
  std::size_t max_examples = 5;
  std::uint64_t pairs = 0, degenerate = 0;
  std::uint64_t first_at_paper_node = 0;  // non-degenerate pairs whose first minimiser is in the paper's lobe
  std::array<sweep_tally, sweep_check_count> checks{};
  sweep_tally errors;  // checked = 0; violations = failed pairs
  sweep_extreme asy_ratio_max, sharp_constant;
  sweep_values t_ratios;  // t_first/(pi/|n|), non-degenerate pairs (degenerate: delta/2 exactly)

  void add(const sweep_record& r);
  // Exact merge; the result does not depend on the grouping or order of merges.
  void merge(const sweep_accumulator& o);
  // q-quantile = sorted[floor(q (n-1))] of t_ratios (the median is the lower median), by radix
  // selection with options for where the values are.
  sweep_quantiles quantiles() const;
};

}  // namespace gyrores
