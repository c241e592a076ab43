// The hard cases of docs/mathematics.md §4 as one table-driven catalogue, checked against
// the independent high-precision reference (src/testing/high_precision_reference.hpp).
//
// Rows: huge pairs (delta = 1 up to 10^30, which needs big_int), a pair whose sum overflows 64
// bits, far-apart frequencies (x -> 1), the lowest orders, ties (1/(2x) a half-integer: (6,5)),
// four minimisers (delta = 0 mod 4: (5,1)), the (9,4) case where the minimum is not at the first
// slow node, and degenerate pairs (delta = 2 mod 4: r_res = 0 exactly). Every failure names the
// row (INFO). Checks:
//  - inscribed_lattice in double: relative error <= 1e-13 in r_res, theta_first and t_first;
//  - inscribed_lattice in mpfr_real at 50 digits: <= 1e-48;
//  - the precision ladder double, long double, float128, mpfr 50, 100, 1000, 10000 digits agrees
//    to the lower precision (the 10000-digit rung is also checked against the reference);
//  - degenerate huge pairs: r_res == 0 exactly, t_first = sqrt(tau sigma) pi/2;
//  - a demonstration that the naive formulation in double (sin(tau theta) with tau theta formed
//    in double) gets no digit of r_res right for (10^12+1, 10^12), while the lattice method does;
//  - the reference itself: its global mode (all critical points) and local mode (around a guess)
//    agree, and it matches the lattice method on every pair up to order 40 at 35 digits.
// Runtime: ~12 s (two global-mode scans of order 2e6 take ~3 s each).
#include <catch2/catch.hpp>

#include <chrono>
#include <iostream>
#include <iomanip>

#include "reference/cross_check.hpp"
#include <gyrores/model/enumerate.hpp>
#include "reference/global_search.hpp"
#include "reference/lattice.hpp"
#include <gyrores/core/decimal.hpp>
#include "testing/high_precision_reference.hpp"
#include "testing/naive_toms748.hpp"
#include "testing/test_support.hpp"

using gyrores::big_int;
using gyrores::mpfr_real;
using gyrores::resonant_pair;
using gyrores::scoped_digits;
namespace hp = gyrores::test::hp;

namespace {

struct hard_case {
  const char* tau;
  const char* sigma;
  const char* why;
};

// 10^k + c as text helpers would obscure the table: the numbers are written out.
const hard_case catalogue[] = {
    {"1000001", "1000000", "huge, delta = 1 (tie), 10^6"},
    {"1000000000001", "1000000000000", "huge, delta = 1, 10^12: naive double has no correct digit"},
    {"1000000000000000001", "1000000000000000000", "huge, delta = 1, 10^18 (int64)"},
    {"4611686018427387905", "4611686018427387903", "2^62 +- 1: sum overflows 64 bits (degenerate)"},
    {"1000000000000000000000000000001", "1000000000000000000000000000000", "10^30: big_int only"},
    {"1000000000", "1", "far apart, x -> 1 (10^9, 1)"},
    {"1000004", "3", "far apart, (10^6+4, 3)"},
    {"1000", "1", "far apart, (1000, 1)"},
    {"2", "1", "lowest order"},
    {"3", "2", "lowest order"},
    {"4", "1", "lowest order"},
    {"5", "2", "lowest order"},
    {"6", "5", "tie: 1/(2x) = 5.5"},
    {"9", "4", "minimum at 3 pi/5, not pi/5"},
    {"5", "1", "delta = 0 mod 4: four minimisers"},
    {"3", "1", "degenerate, delta = 2"},
    {"1000000000000000003", "1000000000000000001", "degenerate huge, delta = 2 (int64)"},
    {"1000000000000000000000000000003", "1000000000000000000000000000001", "degenerate, 10^30 (big_int)"},
};

bool fits_int64(const big_int& v) { return v <= big_int(std::numeric_limits<std::int64_t>::max()); }

// The library result for a catalogue row in T, through the int64 path when the pair fits.
template <class T> gyrores::inscribed_result<T> lattice_of(const big_int& tau, const big_int& sigma) {
  if (fits_int64(tau))
    return gyrores::inscribed_lattice<T>(resonant_pair<std::int64_t>(std::int64_t(tau), std::int64_t(sigma)), T(1));
  return gyrores::inscribed_lattice<T>(resonant_pair<big_int>(tau, sigma), T(1));
}

// Relative error of a library value (any real type) against a reference, in mpfr at the
// current precision (the value converted exactly).
template <class T> mpfr_real rel_err(const T& x, const mpfr_real& ref) {
  return gyrores::test::rel_error(gyrores::real_to_mpfr(x), ref);
}

std::string row_name(std::size_t i, const hard_case& c) {
  return "row " + std::to_string(i) + ": (" + c.tau + ", " + c.sigma + ") " + c.why;
}

// The reference for a row at `digits`; local mode (order beyond the scan) takes the library's
// theta_first as a starting guess only: in double when tau < 2^40 (a double theta pins the fast
// half-period pi/tau), otherwise the 50-digit one.
hp::hp_result reference_of(const big_int& tau, const big_int& sigma, unsigned digits) {
  if (tau + sigma <= hp::hp_scan_max_order) return hp::hp_reference(tau, sigma, digits);
  if (tau < (big_int(1) << 40)) {
    auto g = lattice_of<double>(tau, sigma);
    return hp::hp_reference(tau, sigma, digits, mpfr_real(g.theta_first));
  }
  scoped_digits d(50);
  auto g = lattice_of<mpfr_real>(tau, sigma);
  return hp::hp_reference(tau, sigma, digits, g.theta_first);
}

}  // namespace

TEST_CASE("hard cases: double and 50-digit lattice against the high-precision reference", "[hard]") {
  std::uintmax_t evals_double = 0;
  for (std::size_t row = 0; row < std::size(catalogue); ++row) {
    const auto& c = catalogue[row];
    INFO(row_name(row, c));
    const big_int tau(c.tau), sigma(c.sigma);
    const bool degenerate = int(big_int((tau - sigma) % 4)) == 2;
    const auto t0 = std::chrono::steady_clock::now();
    auto ref = reference_of(tau, sigma, 60);
    const double t_ref = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    INFO("reference: " << (ref.global ? "global" : "local") << " mode, " << ref.critical_points
                       << " critical points, " << ref.candidates << " refined, " << ref.bits << " bits, " << t_ref
                       << " s");
    CHECK(ref.zero == degenerate);
    if (!degenerate) CHECK(ref.at_qdot_root);  // P4: the minimum is at a root of q'

    auto rd = lattice_of<double>(tau, sigma);
    evals_double += rd.evaluations;
    INFO("double lattice: " << rd.evaluations << " evaluations at " << rd.critical_points << " sites");
    CHECK(rd.evaluations <= 16 * std::max<std::size_t>(rd.critical_points, 1));
    CHECK(rd.minimisers.size() == ref.minimisers.size());
    scoped_digits d(70);
    if (degenerate) {
      CHECK(rd.degenerate);
      CHECK(rd.r_res == 0);
    } else {
      INFO("double r_res = " << std::setprecision(17) << rd.r_res << ", reference " << std::setprecision(30)
                             << ref.r_res);
      CHECK(rel_err(rd.r_res, ref.r_res) <= 1e-13);
    }
    CHECK(rel_err(rd.theta_first, ref.theta_first) <= 1e-13);
    CHECK(rel_err(rd.t_first, ref.t_first) <= 1e-13);
    for (std::size_t k = 0; k < std::min(rd.minimisers.size(), ref.minimisers.size()); ++k) {
      INFO("minimiser " << k);
      CHECK(rel_err(rd.minimisers[k], ref.minimisers[k]) <= 1e-13);
    }

    gyrores::inscribed_result<mpfr_real> rm;
    {
      scoped_digits d50(50);
      rm = lattice_of<mpfr_real>(tau, sigma);
    }
    CHECK(rm.minimisers.size() == ref.minimisers.size());
    if (degenerate) {
      CHECK(rm.degenerate);
      CHECK(rm.r_res == 0);
    } else {
      INFO("mpfr50 r_res = " << std::setprecision(55) << rm.r_res << ", reference " << ref.r_res);
      CHECK(rel_err(rm.r_res, ref.r_res) <= mpfr_real("1e-48"));
    }
    CHECK(rel_err(rm.theta_first, ref.theta_first) <= mpfr_real("1e-48"));
    CHECK(rel_err(rm.t_first, ref.t_first) <= mpfr_real("1e-48"));
    for (std::size_t k = 0; k < std::min(rm.minimisers.size(), ref.minimisers.size()); ++k) {
      INFO("minimiser " << k);
      CHECK(rel_err(rm.minimisers[k], ref.minimisers[k]) <= mpfr_real("1e-48"));
    }
  }
  // Evaluation budget (a count, not a time): the lattice method is O(log tau) in work; its
  // TOMS 748 solves cost ~10-13 q' evaluations per candidate site (1 site for x < 1/2, 5
  // otherwise), the same for 10^6 as for 10^30. Measured: 293 over this catalogue.
  INFO("double evaluations over the catalogue: " << evals_double);
  CHECK(evals_double <= 400);
}

TEST_CASE("hard cases: degenerate huge pairs have r_res = 0 exactly and t_first = sqrt(tau sigma) pi/2", "[hard]") {
  const std::pair<const char*, const char*> rows[] = {
      {"1000000000000000003", "1000000000000000001"},
      {"4611686018427387905", "4611686018427387903"},
      {"1000000000000000000000000000003", "1000000000000000000000000000001"},
      {"100000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000003",
       "100000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000001"},
  };
  for (const auto& [ts, ss] : rows) {
    const big_int tau(ts), sigma(ss);
    INFO("pair (" << ts << ", " << ss << ")");
    REQUIRE(int(big_int((tau - sigma) % 4)) == 2);  // checked first: delta = 2 mod 4
    REQUIRE(gyrores::int_gcd(tau, sigma) == 1);
    // Independent check at high precision that q = q' = 0 at theta = pi/2 (naive forms).
    {
      scoped_digits d(gyrores::digits10_for_bits(unsigned(boost::multiprecision::msb(tau)) + 200));
      const mpfr_real pi = boost::math::constants::pi<mpfr_real>(), t(tau), s(sigma);
      const mpfr_real th = pi / 2;
      CHECK(abs(sin(t * th) + sin(s * th)) < mpfr_real("1e-50"));
      CHECK(abs(sqrt(t / s) * cos(t * th) + sqrt(s / t) * cos(s * th)) < mpfr_real("1e-50"));
    }
    scoped_digits d(60);
    const mpfr_real expect_t = sqrt(mpfr_real(tau)) * sqrt(mpfr_real(sigma)) * boost::math::constants::pi<mpfr_real>() / 2;
    if (boost::multiprecision::msb(tau) < 1000) {
      auto rd = lattice_of<double>(tau, sigma);
      CHECK(rd.degenerate);
      CHECK(rd.r_res == 0);
      CHECK(rd.h_min == 0);
      CHECK(rd.minimisers.size() == 2);
      CHECK(rel_err(rd.t_first, expect_t) <= 1e-15);
    }
    gyrores::inscribed_result<mpfr_real> rm;
    {
      scoped_digits d50(50);
      rm = lattice_of<mpfr_real>(tau, sigma);
    }
    CHECK(rm.degenerate);
    CHECK(rm.r_res == 0);
    CHECK(rel_err(rm.t_first, expect_t) <= mpfr_real("1e-48"));
  }
}

namespace {

struct ladder_values {
  std::string type;
  unsigned bits;  // precision of the rung
  mpfr_real r_res, theta_first, t_first;
  std::vector<mpfr_real> minimisers;
  double seconds;
};

template <class T> ladder_values ladder_run(const big_int& tau, const big_int& sigma) {
  const auto t0 = std::chrono::steady_clock::now();
  auto r = lattice_of<T>(tau, sigma);
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ladder_values v;
  v.type = gyrores::real_type_name<T>();
  v.bits = gyrores::real_bits<T>();
  v.seconds = sec;
  v.r_res = gyrores::real_to_mpfr(r.r_res);
  v.theta_first = gyrores::real_to_mpfr(r.theta_first);
  v.t_first = gyrores::real_to_mpfr(r.t_first);
  for (const auto& m : r.minimisers) v.minimisers.push_back(gyrores::real_to_mpfr(m));
  return v;
}

template <unsigned Digits> ladder_values ladder_mpfr(const big_int& tau, const big_int& sigma) {
  scoped_digits d(Digits);
  return ladder_run<mpfr_real>(tau, sigma);
}

}  // namespace

// Timing (Release build, 2 shared cores): the 10000-digit rung takes 0.06-0.23 s per pair and the
// 10000-digit reference 0.3-0.7 s, far below the 20 s limit, so all five pairs run the full
// ladder (the whole test case: ~3 s).
TEST_CASE("hard cases: precision ladder double ... mpfr 10000 digits agrees to the lower precision", "[hard][ladder]") {
  const std::pair<const char*, const char*> rows[] = {
      {"6", "5"}, {"9", "4"}, {"5", "1"}, {"1000000000001", "1000000000000"}, {"1000", "1"}};
  for (std::size_t row = 0; row < std::size(rows); ++row) {
    const big_int tau(rows[row].first), sigma(rows[row].second);
    INFO("ladder row " << row << ": (" << rows[row].first << ", " << rows[row].second << ")");
    std::vector<ladder_values> rungs;
    rungs.push_back(ladder_run<double>(tau, sigma));
    rungs.push_back(ladder_run<long double>(tau, sigma));
    rungs.push_back(ladder_run<gyrores::float128>(tau, sigma));
    rungs.push_back(ladder_mpfr<50>(tau, sigma));
    rungs.push_back(ladder_mpfr<100>(tau, sigma));
    rungs.push_back(ladder_mpfr<1000>(tau, sigma));
    rungs.push_back(ladder_mpfr<10000>(tau, sigma));
    scoped_digits d(10100);
    // Every rung against every higher one, at the lower rung's precision: 2^(8 - bits).
    for (std::size_t lo = 0; lo < rungs.size(); ++lo) {
      for (std::size_t hi = lo + 1; hi < rungs.size(); ++hi) {
        const auto& L = rungs[lo];
        const auto& H = rungs[hi];
        INFO(L.type << " vs " << H.type);
        const mpfr_real tol = ldexp(mpfr_real(1), 8 - int(L.bits));
        CHECK(gyrores::test::rel_error(L.r_res, H.r_res) <= tol);
        CHECK(gyrores::test::rel_error(L.theta_first, H.theta_first) <= tol);
        CHECK(gyrores::test::rel_error(L.t_first, H.t_first) <= tol);
        REQUIRE(L.minimisers.size() == H.minimisers.size());
        for (std::size_t k = 0; k < L.minimisers.size(); ++k)
          CHECK(gyrores::test::rel_error(L.minimisers[k], H.minimisers[k]) <= tol);
      }
    }
    std::cout << "ladder (" << rows[row].first << ", " << rows[row].second << "):";
    for (const auto& r : rungs) std::cout << " " << r.type << " " << r.seconds << " s;";
    std::cout << "\n";
    // The top rung against the independent reference at 10000 digits.
    const auto t0 = std::chrono::steady_clock::now();
    auto ref = reference_of(tau, sigma, 10000);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "  reference at 10000 digits: " << sec << " s\n";
    const mpfr_real tol = ldexp(mpfr_real(1), 8 - int(rungs.back().bits));
    CHECK(gyrores::test::rel_error(rungs.back().r_res, ref.r_res) <= tol);
    CHECK(gyrores::test::rel_error(rungs.back().theta_first, ref.theta_first) <= tol);
    CHECK(gyrores::test::rel_error(rungs.back().t_first, ref.t_first) <= tol);
  }
}

TEST_CASE("hard cases: the naive formulation in double fails on (10^12+1, 10^12), the lattice method does not",
          "[hard][naive]") {
  const std::int64_t tau = 1000000000001, sigma = 1000000000000;
  auto lat = gyrores::inscribed_lattice<double>(resonant_pair<std::int64_t>(tau, sigma), 1.0);
  // Naive: Boost TOMS 748 on q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) with tau*theta
  // formed in double, on the fast half-period [i pi/tau, (i+1) pi/tau] holding the lattice's
  // theta_first; then r = |q| there (src/testing/naive_toms748.hpp, the benchmark's peer).
  const double i = std::floor(lat.theta_first * double(tau) / boost::math::constants::pi<double>());
  // The naive route runs (q' changes sign over the half-period even in double); it is its value
  // that is wrong.
  gyrores::test::naive_toms748_result<double> naive{};
  REQUIRE_NOTHROW(naive = gyrores::test::naive_toms748<double>(big_int(tau), big_int(sigma), big_int(std::int64_t(i))));
  const double r_naive = naive.r;

  scoped_digits d(70);
  auto ref = reference_of(big_int(tau), big_int(sigma), 60);
  const mpfr_real err_naive = rel_err(r_naive, ref.r_res), err_lat = rel_err(lat.r_res, ref.r_res);
  std::cout << "naive double r_res = " << std::setprecision(17) << r_naive << " (rel. error " << std::setprecision(3)
            << double(err_naive) << "), lattice = " << std::setprecision(17) << lat.r_res << " (rel. error "
            << std::setprecision(3) << double(err_lat) << "), reference = " << std::setprecision(20) << ref.r_res
            << "\n";
  CHECK(err_naive > 1e-3);
  CHECK(err_lat <= 1e-13);
}

TEST_CASE("hard cases: the reference agrees with itself (global vs local mode) and with the lattice at low order",
          "[hard][reference]") {
  // Global mode (every critical point) against local mode (guess neighbourhood), both 40 digits.
  const std::pair<std::int64_t, std::int64_t> rows[] = {{6, 5}, {9, 4}, {5, 1}, {1000, 1}, {13, 2}, {1000001, 1000000}};
  for (const auto& [t, s] : rows) {
    INFO("pair (" << t << ", " << s << ")");
    auto g = gyrores::inscribed_lattice<double>(resonant_pair<std::int64_t>(t, s), 1.0);
    auto rg = hp::hp_reference(big_int(t), big_int(s), 40);
    auto rl = hp::hp_reference(big_int(t), big_int(s), 40, mpfr_real(g.theta_first), true);
    CHECK(rg.global);
    CHECK_FALSE(rl.global);
    scoped_digits d(45);
    CHECK(gyrores::test::rel_error(rl.r_res, rg.r_res) <= mpfr_real("1e-38"));
    CHECK(gyrores::test::rel_error(rl.theta_first, rg.theta_first) <= mpfr_real("1e-38"));
    CHECK(rl.minimisers.size() == rg.minimisers.size());
  }
  // Every pair up to order 40: the global-mode reference at 40 digits against the lattice at 35.
  for (gyrores::resonant_pair<std::int64_t> p : gyrores::coprime_pairs(3, 40)) {
    INFO("pair " << p.str());
    auto ref = hp::hp_reference(big_int(p.tau()), big_int(p.sigma()), 40);
    gyrores::inscribed_result<mpfr_real> lat;
    {
      scoped_digits d(35);
      lat = gyrores::inscribed_lattice<mpfr_real>(p, mpfr_real(1));
    }
    scoped_digits d(45);
    CHECK(ref.zero == p.degenerate());
    if (p.degenerate()) CHECK(lat.r_res == 0);
    else CHECK(gyrores::test::rel_error(lat.r_res, ref.r_res) <= mpfr_real("1e-33"));
    CHECK(gyrores::test::rel_error(lat.theta_first, ref.theta_first) <= mpfr_real("1e-33"));
    REQUIRE(lat.minimisers.size() == ref.minimisers.size());
    for (std::size_t k = 0; k < ref.minimisers.size(); ++k)
      CHECK(gyrores::test::rel_error(lat.minimisers[k], ref.minimisers[k]) <= mpfr_real("1e-33"));
  }
}
