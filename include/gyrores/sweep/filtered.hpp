// A filtered evaluation, after CGAL's Filtered_predicate (Filtered_kernel/include/CGAL/
// Filtered_predicate.h): a cheap filter that either decides, its result then the exact one
// (proof_status proved, core/status.hpp), or says why not; and the exact evaluation, which always
// decides and runs only when the filter did not. Written once for the sweep's three:
//   certified double rows   the theorem's double-double balls, then its MPFI proof
//                           (src/lib/sweep/certified_filter.cpp; off: --no-filter);
//   P3 in double rows       r_res^2 <= R(pi/2) in double beyond a proved error band, then the
//                           enclosure (src/lib/sweep/evaluate.cpp);
//   sweeps without rows     a pair's summary from the theorem's series form
//                           (theorem/minimum_series.hpp), then from its row (src/lib/sweep/fast.cpp).
// The off switch (use_filter false) runs the exact evaluation alone: the same results, which the
// tests compare. With GYRORES_FILTER_STATS set in the environment each filter counts its calls by
// outcome (the status's reason) and prints the counts to stderr at exit: a diagnostic for tuning
// a filter, which changes no result.
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

// filter(args...) -> proof_status, and exact(args...), which must give what a proved filter
// gives (both write their result through the arguments).
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
