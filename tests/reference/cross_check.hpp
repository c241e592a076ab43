// The skeptic's cross-validation: a result (r_res and every minimiser, in any real type) against
// the global search (global_search.hpp), which assumes nothing of the lattice theorem. The
// tests' oracle (tests/test_cross_check.cpp checks sweep rows with it; tests/test_lattice.cpp
// checks that it refuses wrong results).
// The check runs the global search in double (4 tau root solves, limited by
// global_search_options::max_order) and requires
//  - the same number of global minimisers, at the same theta (relative 1e-9),
//  - the same r_res (relative 1e-9),
//  - a clear gap: every other critical value of R exceeds the minimum by a relative 1e-7, so
//    that double precision could not have confused a near-tie (otherwise compute_error: neither
//    answer is to be trusted without more precision).
// Throws compute_error naming the pair and both values when they disagree.
#pragma once
#include <string>

#include <gyrores/core/decimal.hpp>

#include "reference/global_search.hpp"

namespace gyrores {

template <class T, pair_integer I>
void cross_check_global(const resonant_pair<I>& p, const T& v, const inscribed_result<T>& lat) {
  if (lat.degenerate) return;  // decided by integer arithmetic, nothing to cross-check
  global_search_options opt;
  opt.max_order = std::numeric_limits<std::int64_t>::max();
  auto g = inscribed_global<double>(pair_cast<std::int64_t>(p), 1.0, opt);
  const double r_lat = static_cast<double>(lat.r_res / v);  // r_res is linear in v
  auto fail = [&](const std::string& what) {
    throw compute_error("cross-check failed for " + p.str() + ": " + what + " (checked r_res/v = " +
                        root_describe(r_lat) + ", global search r_res/v = " + root_describe(g.r_res) + ")");
  };
  if (std::abs(r_lat - g.r_res) > 1e-9 * g.r_res) fail("r_res differs");
  if (g.minimisers.size() != lat.minimisers.size())
    fail(std::to_string(lat.minimisers.size()) + " checked minimisers vs " + std::to_string(g.minimisers.size()) +
         " from the global search");
  for (std::size_t i = 0; i < g.minimisers.size(); ++i)
    if (std::abs(static_cast<double>(lat.minimisers[i]) - g.minimisers[i]) > 1e-9 * g.minimisers[i])
      fail("minimiser " + std::to_string(i) + " differs");
  if (g.next_radius_sq < g.r_res * g.r_res * (1 + 1e-7))
    fail("near-tie between distinct critical values; double precision cannot separate them");
}

// Compiled once in tests/reference/instances_*.cpp for double, long double, float128 and mpfr_real.
#define GYRORES_CROSS_CHECK_INSTANCES(PREFIX, T) \
  PREFIX template void cross_check_global<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&, const inscribed_result<T>&); \
  PREFIX template void cross_check_global<T, big_int>(const resonant_pair<big_int>&, const T&, const inscribed_result<T>&);
GYRORES_FOR_COMPILED_REALS(GYRORES_CROSS_CHECK_INSTANCES, extern)

}  // namespace gyrores
