// The cross-check: sweep rows against the global search (tests/reference/global_search.hpp), which
// assumes nothing of the lattice theorem: it brackets every root of q' and z' (all 4 tau critical
// points of R) and keeps the smallest R. Until sweep format version 2 this was the sweep's opt-in
// check `cross-check` (docs/formats.md, "Sweep format versions"); it is a test of the sources
// now: the rows come from the theorem (proofs/lattice-theorem.md), and this compares two methods
// in floating point, which proves nothing a user of a sweep needs.
//
// For every non-degenerate pair up to the order (degenerate pairs are decided by integers on
// both sides):
//  - double rows: their values are the theorem's minimum in double (theorem_minimum_double), and
//    that minimum passes cross_check_global: the same r_res and every minimiser to a relative
//    1e-9, with a clear gap to the next critical value (tests/reference/cross_check.hpp);
//  - certified double rows (proved roundings of the exact values): r_res, theta_first and the
//    minimiser count as the global search's in double, to a relative 1e-9;
//  - MPFR rows at 40 digits: the same against the global search at 50 digits, to 1e-30.
// As a reference tool: GYRORES_CROSS_CHECK_MAX_ORDER=N build/tests/test_cross_check runs every
// case up to order N (by default 200 for double rows, 150 certified, 30 in MPFR: about 4 s; the
// global search solves 4 tau roots per pair, ~1 ms at order 300 in double, and stops at order
// 100000).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include <gyrores/model/enumerate.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/theorem/minimum.hpp>

#include "reference/cross_check.hpp"
#include "reference/global_search.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;

namespace {

// The largest order of a case: GYRORES_CROSS_CHECK_MAX_ORDER if set, else the case's default.
std::int64_t max_order(std::int64_t by_default) {
  const char* s = std::getenv("GYRORES_CROSS_CHECK_MAX_ORDER");
  return s && *s ? std::atoll(s) : by_default;
}

// The failures of one case: all counted, the first few kept for the message.
struct failures {
  std::size_t count = 0;
  std::string first;
  void add(const std::string& what) {
    if (count++ < 5) first += what + "\n";
  }
};

sweep_config config_of(std::int64_t max_order) {
  sweep_config c;
  c.max_order = max_order;
  return c;
}

// A row of type T against the global search in T: r_res, theta_first and the minimiser count.
template <class T>
void compare_with_search(failures& f, const resonant_pair<std::int64_t>& p, const sweep_row<T>& row, const T& tol) {
  const auto g = inscribed_global<T>(p, T(1));
  const bool same = !row.failed && row.minimiser_count == int(g.minimisers.size()) &&
                    test::rel_error(row.r_res, g.r_res) <= tol && test::rel_error(row.theta_first, g.theta_first) <= tol;
  if (!same) f.add(p.str() + ": the row differs from the global search" + (row.failed ? " (" + row.note + ")" : ""));
}

}  // namespace

TEST_CASE("cross-check: double rows are the theorem's minimum, which the global search confirms", "[cross_check]") {
  const sweep_config cfg = config_of(max_order(200));
  failures f;
  std::size_t checked = 0;
  for (auto p : coprime_pairs(3, cfg.max_order)) {
    if (p.degenerate()) continue;
    const auto row = sweep_evaluate<double>(p, cfg);
    const minimum_double m = theorem_minimum_double(p);
    if (row.failed || row.r_res != m.r_res || row.theta_first != m.theta_first || m.theta_first != m.minimisers[0] ||
        row.minimiser_count != int(m.count))
      f.add(p.str() + ": the row is not the theorem's minimum");
    inscribed_result<double> theorem{};
    theorem.r_res = m.r_res;
    theorem.minimisers.assign(m.minimisers.begin(), m.minimisers.begin() + std::ptrdiff_t(m.count));
    try {
      cross_check_global(p, 1.0, theorem);
    } catch (const compute_error& e) {
      f.add(e.what());
    }
    ++checked;
  }
  INFO(f.first);
  CHECK(f.count == 0);
  CHECK(checked > 0);
}

TEST_CASE("cross-check: certified double rows agree with the global search", "[cross_check]") {
  sweep_config cfg = config_of(max_order(150));
  cfg.certified = true;
  failures f;
  for (auto p : coprime_pairs(3, cfg.max_order))
    if (!p.degenerate()) compare_with_search(f, p, sweep_evaluate<double>(p, cfg), 1e-9);
  INFO(f.first);
  CHECK(f.count == 0);
}

TEST_CASE("cross-check: MPFR rows at 40 digits agree with the global search at 50", "[cross_check]") {
  sweep_config cfg = config_of(max_order(30));
  cfg.digits = 40;
  scoped_digits sd(50);  // the global search's precision (process-wide; the rows carry their own)
  failures f;
  for (auto p : coprime_pairs(3, cfg.max_order))
    if (!p.degenerate()) compare_with_search(f, p, sweep_evaluate<mpfr_real>(p, cfg), mpfr_real("1e-30"));
  INFO(f.first);
  CHECK(f.count == 0);
}
