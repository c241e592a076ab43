// The lattice method (lattice.hpp) against the global search (global_search.hpp), which assumes
// nothing about where the minimum sits, and the structure the lattice method relies on
// (docs/mathematics.md §3, *observed*): checked here on every coprime pair up to order 300 in double, up to
// order 60 at 30 digits, and on random pairs up to order 3000 (fixed, printed seed; count scaled
// by GYRORES_TEST_MULTIPLIER).
#include <catch2/catch.hpp>

#include <iostream>
#include <numeric>
#include <random>
#include <sstream>
#include <vector>

#include "reference/cross_check.hpp"
#include <gyrores/model/enumerate.hpp>
#include "reference/global_search.hpp"
#include "reference/lattice.hpp"
#include <gyrores/theorem/lobes.hpp>
#include "testing/test_support.hpp"

using gyrores::mpfr_real;
using gyrores::resonant_pair;
using gyrores::scoped_digits;
using pair64 = resonant_pair<std::int64_t>;

namespace {

// Lattice vs global search on one pair: same number of minimisers, r_res and every minimiser
// within a relative `tol`. Returns false (after recording the failure) on a mismatch, so that a
// sweep stops at the first failing pair with its values printed. `global_count` receives the
// number of minimisers found by the global search.
template <class T> bool agree(const pair64& p, const T& tol, std::size_t* global_count = nullptr) {
  auto lat = gyrores::inscribed_lattice<T>(p, T(1));
  auto glo = gyrores::inscribed_global<T>(p, T(1));
  if (global_count) *global_count = glo.minimisers.size();
  bool ok = lat.minimisers.size() == glo.minimisers.size() && lat.degenerate == glo.degenerate &&
            gyrores::test::rel_error(lat.r_res, glo.r_res) <= tol;
  for (std::size_t k = 0; ok && k < lat.minimisers.size(); ++k)
    ok = gyrores::test::rel_error(lat.minimisers[k], glo.minimisers[k]) <= tol;
  ok = ok && gyrores::test::rel_error(lat.theta_first, glo.theta_first) <= tol &&
       gyrores::test::rel_error(lat.t_first, glo.t_first) <= tol;
  if (!ok) {
    std::ostringstream os;
    os.precision(std::numeric_limits<double>::max_digits10 + 15);
    os << "pair " << p.str() << " in " << gyrores::real_type_name<T>() << ": lattice r_res " << lat.r_res << " ("
       << lat.minimisers.size() << " minimisers), global r_res " << glo.r_res << " (" << glo.minimisers.size()
       << " minimisers)";
    for (std::size_t k = 0; k < std::max(lat.minimisers.size(), glo.minimisers.size()); ++k) {
      os << "\n  minimiser " << k << ": lattice ";
      if (k < lat.minimisers.size()) os << lat.minimisers[k]; else os << "-";
      os << ", global ";
      if (k < glo.minimisers.size()) os << glo.minimisers[k]; else os << "-";
    }
    FAIL_CHECK(os.str());
  }
  return ok;
}

}  // namespace

// One sweep checks both the agreement and the observed structure claim (docs/mathematics.md §3): the
// global search, which assumes nothing, finds exactly 2 minimisers for delta odd and 4 for
// delta = 0 mod 4 (degenerate pairs: the 2 zeros pi/2, 3 pi/2).
TEST_CASE("lattice = global search on every coprime pair up to order 300 (double, relative 1e-12); "
          "minimiser count 2 for delta odd, 4 for delta = 0 mod 4",
          "[lattice]") {
  std::size_t pairs = 0, failures = 0, count_failures = 0, odd = 0, four = 0;
  for (pair64 p : gyrores::coprime_pairs(3, 300)) {
    ++pairs;
    std::size_t n = 0;
    if (!agree<double>(p, 1e-12, &n) && ++failures >= 10) break;
    const std::size_t expect = p.degenerate() ? 2 : (p.delta_mod4() % 2 == 1 ? 2 : 4);
    if (!p.degenerate()) (expect == 2 ? odd : four) += 1;
    if (n != expect) {
      FAIL_CHECK("pair " << p.str() << " (delta mod 4 = " << p.delta_mod4() << "): " << n
                         << " global minimisers, expected " << expect);
      if (++count_failures >= 10) break;
    }
  }
  INFO(pairs << " pairs; " << odd << " with delta odd, " << four << " with delta = 0 mod 4");
  CHECK(failures == 0);
  CHECK(count_failures == 0);
  CHECK(pairs > 13000);  // sum over a <= 300 of phi(a)/2
  CHECK(odd > 0);
  CHECK(four > 0);
}

TEST_CASE("lattice = global search on every coprime pair up to order 60 at 30 digits (relative 1e-28)", "[lattice]") {
  scoped_digits d(30);
  std::size_t pairs = 0, failures = 0;
  const mpfr_real tol("1e-28");
  for (pair64 p : gyrores::coprime_pairs(3, 60)) {
    ++pairs;
    if (!agree<mpfr_real>(p, tol) && ++failures >= 10) break;
  }
  INFO(pairs << " pairs");
  CHECK(failures == 0);
}

TEST_CASE("lattice = global search on random pairs up to order 3000 (double, fixed seed)", "[lattice][random]") {
  const std::uint64_t seed = 20240611;
  const int count = 300 * gyrores::test::multiplier();
  std::cout << "test_lattice random pairs: seed " << seed << ", " << count << " pairs\n";
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> order(3, 3000);
  std::uniform_int_distribution<int> edge(0, 19);
  int done = 0, failures = 0, tries = 0;
  while (done < count && tries < 100 * count) {
    ++tries;
    std::int64_t a = order(rng), s;
    switch (edge(rng)) {  // inject edge cases with probability 1/20 each
      case 0: s = (a - 1) / 2; break;  // delta = 1 or 2 (ties, degenerate)
      case 1: s = 1; break;            // far apart, x -> 1
      default: s = std::uniform_int_distribution<std::int64_t>(1, (a - 1) / 2)(rng);
    }
    if (s < 1 || 2 * s >= a || std::gcd(a, s) != 1) continue;
    pair64 p(a - s, s);
    INFO("seed " << seed << ", draw " << tries);
    if (!agree<double>(p, 1e-12) && ++failures >= 10) break;
    ++done;
  }
  CHECK(failures == 0);
  CHECK(done == count);
}

namespace {

// inscribed_lattice with `opt` against the default on every pair of `pairs` in T: the same
// number of minimisers, r_res and every minimiser within a relative `tol`. Records each mismatch
// (at most 10) and returns their count.
template <class T, class Pairs> std::size_t option_mismatches(const gyrores::lattice_options& opt, const Pairs& pairs,
                                                              const T& tol) {
  std::size_t failures = 0;
  for (pair64 p : pairs) {
    auto d = gyrores::inscribed_lattice<T>(p, T(1));
    auto o = gyrores::inscribed_lattice<T>(p, T(1), opt);
    bool ok = d.minimisers.size() == o.minimisers.size() && gyrores::test::rel_error(d.r_res, o.r_res) <= tol;
    for (std::size_t k = 0; ok && k < d.minimisers.size(); ++k)
      ok = gyrores::test::rel_error(d.minimisers[k], o.minimisers[k]) <= tol;
    if (!ok) {
      FAIL_CHECK("pair " << p.str() << " in " << gyrores::real_type_name<T>() << ": default r_res " << d.r_res
                         << ", with the option r_res " << o.r_res);
      if (++failures >= 10) break;
    }
  }
  return failures;
}

}  // namespace

TEST_CASE("lattice_options{window_always = true} agrees with the default path up to order 200", "[lattice]") {
  gyrores::lattice_options win;
  win.window_always = true;
  CHECK(option_mismatches<double>(win, gyrores::coprime_pairs(3, 200), 1e-13) == 0);
}

// The benchmark's "TOMS 748 in local coordinates" (bench/speed_error/methods_library.cpp) is
// this option: TOMS 748 in T at the lattice method's bracket, no double scout, no Newton.
TEST_CASE("lattice_solver::toms748_full agrees with the default solver up to order 200 and at 30 digits",
          "[lattice]") {
  const gyrores::lattice_options full{.solver = gyrores::lattice_solver::toms748_full};
  CHECK(option_mismatches<double>(full, gyrores::coprime_pairs(3, 200), 1e-12) == 0);
  scoped_digits d(30);
  const std::vector<pair64> few{pair64(6, 5),   pair64(9, 4),    pair64(5, 1),  pair64(101, 100),
                                pair64(1000, 1), pair64(101, 37), pair64(11, 9), pair64(1000001, 1000000)};
  CHECK(option_mismatches<mpfr_real>(full, few, mpfr_real("1e-28")) == 0);
}

TEST_CASE("cross_check_lattice accepts a true result and rejects tampered ones", "[lattice][cross_check]") {
  for (pair64 p : {pair64(6, 5), pair64(9, 4), pair64(5, 1), pair64(1000, 1), pair64(101, 37)}) {
    INFO("pair " << p.str());
    auto lat = gyrores::inscribed_lattice<double>(p, 1.0);
    CHECK_NOTHROW(gyrores::cross_check_global(p, 1.0, lat));

    auto bad_r = lat;
    bad_r.r_res *= 1 + 1e-6;
    CHECK_THROWS_AS(gyrores::cross_check_global(p, 1.0, bad_r), gyrores::compute_error);

    auto bad_theta = lat;
    bad_theta.minimisers.front() *= 1 + 1e-6;
    CHECK_THROWS_AS(gyrores::cross_check_global(p, 1.0, bad_theta), gyrores::compute_error);

    auto bad_count = lat;
    bad_count.minimisers.pop_back();
    CHECK_THROWS_AS(gyrores::cross_check_global(p, 1.0, bad_count), gyrores::compute_error);
  }
  {
    // The same in mpfr_real, whose r_res carries digits the double check cannot see: a relative
    // 1e-6 error is still rejected.
    scoped_digits d(40);
    pair64 p(9, 4);
    auto lat = gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(2));
    CHECK_NOTHROW(gyrores::cross_check_global(p, mpfr_real(2), lat));
    lat.r_res *= 1 + mpfr_real("1e-6");
    CHECK_THROWS_AS(gyrores::cross_check_global(p, mpfr_real(2), lat), gyrores::compute_error);
  }
}

// Issue 12: the minimiser 2u*/a ~ 1.57e-50 of (3 10^50 + 1, 10^50) and its mirror 2 pi - 1.57e-50,
// which rounds to 2 pi in every type. The order is decided on the exact frames, so the mirror
// comes last whatever the rounding; the frames are reduced to k in [0, a), theorem order
// (tests/reference/lattice.hpp: minimiser_lobes_modular, an independent ordering of the same frames).
template <class T> void check_near_zero_minimiser() {
  using gyrores::big_int;
  big_int sigma = 1;
  for (int i = 0; i < 50; ++i) sigma *= 10;
  const big_int tau = 3 * sigma + 1;
  const resonant_pair<big_int> p(tau, sigma);
  const auto r = gyrores::inscribed_lattice<T>(p, T(1));
  REQUIRE(r.minimisers.size() == 2);
  CHECK(r.theta_first == r.minimisers[0]);
  CHECK(double(r.theta_first) > 1.5707e-50);
  CHECK(double(r.theta_first) < 1.5709e-50);
  CHECK(double(r.minimisers[1]) > 6.28);
  CHECK(r.first.k >= 0);
  CHECK(r.first.k < p.order());
  const auto lobes = gyrores::minimiser_lobes_modular(big_int(p.order()), big_int(p.delta()));
  REQUIRE(lobes.size() == 2);
  CHECK(r.first.k == lobes[0].k);
  CHECK(r.first.m == lobes[0].m);
  CHECK((r.first.u > 0) == (lobes[0].m > 0));
}

TEST_CASE("lattice: a minimiser just past 0 sorts before its mirror just below 2 pi (issue 12)", "[lattice]") {
  check_near_zero_minimiser<double>();
  check_near_zero_minimiser<long double>();
  check_near_zero_minimiser<gyrores::float128>();
  scoped_digits d(40);
  check_near_zero_minimiser<mpfr_real>();
}

// Pairs held as big_int that fit in 128 bits run the lattice in int128 arithmetic (no GMP
// temporaries); the window mode of the same pair needs a tau beyond 2^124 and stays in big_int.
// Both must give the same minimiser: the same r_res and theta_first to a few ulps, in double
// and at 1000 digits (where the polish uses the fused sine-cosine and the precision ladder).
TEST_CASE("lattice: int128 and big_int arithmetic agree on (10^30+1, 10^30) and (2^100+3, 2^100-1)", "[lattice][big]") {
  using gyrores::big_int;
  for (auto [t, s] : {std::pair<const char*, const char*>{"1000000000000000000000000000001", "1000000000000000000000000000000"},
                      {"1267650600228229401496703205379", "1267650600228229401496703205375"}}) {
    const resonant_pair<big_int> p{big_int(t), big_int(s)};
    INFO(p.str());
    const gyrores::lattice_options window{.window_always = true};
    {
      auto d = gyrores::inscribed_lattice<double>(p, 1.0), w = gyrores::inscribed_lattice<double>(p, 1.0, window);
      CHECK(gyrores::test::rel_error(d.r_res, w.r_res) <= 1e-14);
      CHECK(gyrores::test::rel_error(d.theta_first, w.theta_first) <= 1e-14);
    }
    scoped_digits sd(1000);
    auto d = gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1)),
         w = gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1), window);
    const mpfr_real tol("1e-995");
    CHECK(gyrores::test::rel_error(d.r_res, w.r_res) <= tol);
    CHECK(gyrores::test::rel_error(d.theta_first, w.theta_first) <= tol);
  }
}
