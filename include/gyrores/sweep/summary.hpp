// The summary of a sweep: what it keeps of each row (sweep_record), and the mergeable
// accumulator with exact quantiles (docs/formats.md, sweep summary).
//
// The accumulator holds pairs, degenerate pairs, per check (pairs checked, violations, the first
// `max_examples` violating pairs in enumeration order), errors, the largest asy ratio and the
// largest constant error a/x^2 with their pairs (ties: the earlier pair), the number of
// non-degenerate pairs whose first minimiser is in the paper's lobe, and every value of
// t_first/(pi/|n|) over the non-degenerate pairs (degenerate pairs have exactly delta/2 there,
// by Thm. degenerate, and are left out). The values are kept exactly, one double each, in memory
// or (a long sweep: 10 GB at order 10^5) in files the io layer names (sweep/values.hpp), so the
// quantiles are exact order statistics: q-quantile = sorted[floor(q (n-1))] (the median is the
// lower median), found by radix selection in bounded memory. Accumulators merge exactly and in
// any grouping: counts add, examples are re-sorted by enumeration order (order a, then sigma) and
// cut, extremes compare by value then by enumeration order, values concatenate. Reals in the summary are doubles; with a
// wider T each is first printed (sweep_real_text) and read back, the same path a merge of row
// files takes, so single runs and merges agree bit for bit.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/sweep/real_text.hpp>
#include <gyrores/sweep/values.hpp>

namespace gyrores {

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

// What the summary keeps of row r, into s (all of it overwritten; s's strings keep their buffers,
// so that a worker reusing one record allocates nothing per pair). Reals wider than double are
// read back from their text (sweep_real_text at `digits`), as a merge of rows reads them.
template <class T> void sweep_record_fill(sweep_record& s, const sweep_row<T>& r, unsigned digits);

template <class T> sweep_record sweep_record_of(const sweep_row<T>& r, unsigned digits) {
  sweep_record s;
  sweep_record_fill(s, r, digits);
  return s;
}

// Compiled once in src/lib/sweep/summary.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_RECORD_INSTANCES(PREFIX, T)                                      \
  PREFIX template void sweep_record_fill<T>(sweep_record&, const sweep_row<T>&, unsigned); \
  PREFIX template sweep_record sweep_record_of<T>(const sweep_row<T>&, unsigned);
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
  sweep_values t_ratios;  // t_first/(pi/|n|), non-degenerate pairs (order irrelevant)

  void add(const sweep_record& r);
  // Check i's verdict s on pair id (none: not checked), as add counts it.
  void add_check(int i, sweep_status s, const sweep_pair_id& id);
  // Exact merge; the result does not depend on the grouping or order of merges.
  void merge(const sweep_accumulator& o);
  // Exact order statistics of t_ratios (a few passes over them when they are many).
  sweep_quantiles quantiles(const sweep_selection_options& opt = {}) const;
};

}  // namespace gyrores
