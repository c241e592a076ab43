// A filtered evaluation, after CGAL's Filtered_predicate: a cheap filter that either decides
// (proof_status proved, core/status.hpp: its result is then the exact one) or says why not, and
// the exact evaluation, run only when the filter did not decide. The sweep's three: certified
// double rows (double-double balls, then MPFI; off: --no-filter), P3 in double rows (double
// beyond a proved error band, then the enclosure) and sweeps without rows (the series form, then
// the row). use_filter false runs the exact evaluation alone: the same results, which the tests
// compare. With GYRORES_FILTER_STATS set each filter prints its outcome counts to stderr at exit
// (a diagnostic for tuning a filter; no result changes).
#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include <gyrores/core/status.hpp>

namespace gyrores {

// The outcome counts of one filter (a static object: it prints when the program ends).
class filter_counts {
 public:
  explicit filter_counts(const char* name);
  ~filter_counts();
  void record(const proof_status& s) {
    if (!enabled_) return;
    if (s) decided_.fetch_add(1, std::memory_order_relaxed);
    else add(s.reason());
  }

 private:
  void add(const char* reason);
  static constexpr std::size_t slots = 32;  // distinct reasons counted (more are dropped)
  const char* name_;
  const bool enabled_;
  std::atomic<std::uint64_t> decided_{0};
  std::array<std::atomic<const char*>, slots> reason_{};
  std::array<std::atomic<std::uint64_t>, slots> count_{};
};

// filter(args...) -> proof_status and exact(args...) write their result through the arguments;
// exact must give what a proved filter gives.
template <class Filter, class Exact> struct filtered {
  filter_counts& counts;
  Filter filter;
  Exact exact;
  template <class... A> void operator()(bool use_filter, A&&... args) const {
    if (use_filter) {
      const proof_status s = filter(args...);
      counts.record(s);
      if (s) return;
    }
    exact(args...);
  }
};
template <class Filter, class Exact> filtered(filter_counts&, Filter, Exact) -> filtered<Filter, Exact>;

}  // namespace gyrores
