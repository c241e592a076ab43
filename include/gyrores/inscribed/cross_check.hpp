// Cross-check of the lattice method against the global search ("trust, but check").
//
// The lattice method rests on an *observed* structure (docs/mathematics.md §3). Until that structure is
// proved, a lattice result can be checked against the global search, which assumes nothing.
// The check runs the global search in double (cheap: 4 tau root solves) and requires
//  - the same number of global minimisers, at the same theta (relative 1e-9),
//  - the same r_res (relative 1e-9; the digits themselves come from the lattice run in T),
//  - a clear gap: every other critical value of R exceeds the minimum by a relative 1e-7, so
//    that double precision could not have confused a near-tie (otherwise compute_error: the
//    caller must not trust either answer without more precision).
// Throws compute_error naming the pair and both values when they disagree.
#pragma once
#include <string>

#include <gyrores/core/decimal.hpp>
#include <gyrores/inscribed/global_search.hpp>
#include <gyrores/inscribed/lattice.hpp>

namespace gyrores {

// Largest order for which gyrores cross-checks by default (about 0.1 s in double).
inline constexpr std::int64_t cross_check_default_max_order = 20000;

template <class T, pair_integer I>
void cross_check_lattice(const resonant_pair<I>& p, const T& v, const inscribed_result<T>& lat) {
  if (lat.degenerate) return;  // decided by integer arithmetic, nothing to cross-check
  global_search_options opt;
  opt.max_order = std::numeric_limits<std::int64_t>::max();
  auto g = inscribed_global<double>(pair_cast<std::int64_t>(p), 1.0, opt);
  const double r_lat = static_cast<double>(lat.r_res / v);  // r_res is linear in v
  auto fail = [&](const std::string& what) {
    throw compute_error("cross-check failed for " + p.str() + ": " + what + " (lattice r_res/v = " +
                        root_describe(r_lat) + ", global search r_res/v = " + root_describe(g.r_res) + ")");
  };
  if (std::abs(r_lat - g.r_res) > 1e-9 * g.r_res) fail("r_res differs");
  if (g.minimisers.size() != lat.minimisers.size())
    fail(std::to_string(lat.minimisers.size()) + " lattice minimisers vs " + std::to_string(g.minimisers.size()) +
         " from the global search");
  for (std::size_t i = 0; i < g.minimisers.size(); ++i)
    if (std::abs(static_cast<double>(lat.minimisers[i]) - g.minimisers[i]) > 1e-9 * g.minimisers[i])
      fail("minimiser " + std::to_string(i) + " differs");
  if (g.next_radius_sq < g.r_res * g.r_res * (1 + 1e-7))
    fail("near-tie between distinct critical values; double precision cannot separate them");
}

// Compiled once in src/lib/inscribed/ for double, long double, float128 and mpfr_real.
#define GYRORES_CROSS_CHECK_INSTANCES(PREFIX, T) \
  PREFIX template void cross_check_lattice<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&, const inscribed_result<T>&); \
  PREFIX template void cross_check_lattice<T, big_int>(const resonant_pair<big_int>&, const T&, const inscribed_result<T>&);
GYRORES_FOR_COMPILED_REALS(GYRORES_CROSS_CHECK_INSTANCES, extern)

}  // namespace gyrores
