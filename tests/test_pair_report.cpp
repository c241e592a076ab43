// Every real `gyrores pair` prints (report/pair_report.hpp, prove_pair) is the correct rounding
// of its exact value: compared, field by field and digit for digit, with independent
// high-precision values, on the hard cases of docs/mathematics.md §4 and on random pairs, at 17,
// 50 and 1000 digits.
//
// Oracles (no library numerics): the high-precision reference of src/testing/ (the naive forms
// at brute precision, every critical point scanned, tau theta formed directly) for r_res, the
// minimisers, theta_first and t_first; its lobe root for theta_c; and, written out here, plain
// MPFR formulas for the model's constants and bisection on u + tan u = s for the paper's root.
// The comparison is the D-digit rounding of an oracle carried at far more bits than D: a value
// on a rounding boundary would show as a mismatch, never as a pass.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/report/pair_report.hpp>

#include "testing/high_precision_reference.hpp"
#include "testing/naive_forms.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;

namespace {

big_int pow10(unsigned e) {
  big_int r = 1;
  for (unsigned i = 0; i < e; ++i) r *= 10;
  return r;
}

pair_report report(const resonant_pair<big_int>& p, unsigned digits, const std::string& qdot0 = "1") {
  pair_report_options opt;
  opt.digits = digits;
  opt.qdot0 = parse_rational(qdot0, "qdot0");
  opt.enclosures = true;
  opt.doubles = true;
  return prove_pair(p, opt);
}

mpfr_real mp(const big_int& v) { return real_from_int<mpfr_real>(v); }

// The root of u + tan u = s in (-pi/2, pi/2) by bisection (g increases), to the current precision.
mpfr_real paper_root_by_bisection(const mpfr_real& s) {
  mpfr_real lo = -real_pi<mpfr_real>() / 2, hi = real_pi<mpfr_real>() / 2;
  const int bits = int(real_bits<mpfr_real>()) + 4;
  for (int i = 0; i < bits; ++i) {
    const mpfr_real mid = (lo + hi) / 2;
    (mid + tan(mid) < s ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// Checks one field: the report's text against the oracle rounded to D digits, its double against
// the oracle rounded to nearest (MPFR), and the enclosure around the oracle.
void check_real(const std::string& name, const proved_real& got, const mpfr_real& truth, unsigned digits) {
  INFO(name);
  CHECK(got.value == format_scientific(truth, digits));
  CHECK(got.nearest == mpfr_get_d(truth.backend().data(), MPFR_RNDN));
  const mpfr_real lo(got.enclosure.first), hi(got.enclosure.second);
  CHECK(lo <= truth);
  CHECK(truth <= hi);
}

// The whole report of p at `digits` against the oracles.
void check_pair(const resonant_pair<big_int>& p, unsigned digits) {
  INFO("pair " << p.str() << ", " << digits << " digits");
  const pair_report r = report(p, digits);
  const big_int a = p.order(), b = big_int(p.delta()), tau = p.tau(), sigma = p.sigma();
  const unsigned log10a = unsigned(boost::multiprecision::msb(a) * 0.30103) + 1;
  // The oracle's digits: D plus what the asymptotic error and r_res_asy - r_res cancel
  // (O(a^-2) relative), plus a margin.
  const unsigned ref_digits = digits + 3 * log10a + 15;
  const bool global = a <= big_int(test::hp::hp_scan_max_order);
  // Local mode needs a starting guess (only a guess: the reference examines the fast
  // half-periods around it on its own); the report's first minimiser, read at ref_digits.
  // (Read at ref_digits: mpfr_real's default of 20 digits would not pin a half-period of 1e-30.)
  mpfr_real guess;
  if (!global) {
    scoped_digits sd(ref_digits + 10);
    guess = mpfr_real(report(p, std::min(ref_digits, 10000u)).theta_first.value);
  }
  const auto hp = global ? test::hp::hp_reference(tau, sigma, ref_digits)
                         : test::hp::hp_reference(tau, sigma, ref_digits, guess, true);
  scoped_digits sd(ref_digits + 20 + 2 * log10a);
  const mpfr_real pi = real_pi<mpfr_real>(), A = mp(a), Bd = mp(b), ts = mp(big_int(tau * sigma));
  const mpfr_real x = Bd / A;
  check_real("beat_ratio", r.beat_ratio, A / Bd, digits);
  check_real("n", r.n, Bd / sqrt(ts), digits);
  check_real("omega1", r.omega1, sqrt(mp(tau) / mp(sigma)), digits);
  check_real("omega2", r.omega2, sqrt(mp(sigma) / mp(tau)), digits);
  check_real("rho0", r.rho0, sqrt(ts) / A, digits);
  check_real("qdot0", r.qdot0, mpfr_real(1), digits);
  check_real("t_min_paper", r.t_min_paper, pi * sqrt(ts) / Bd, digits);
  if (p.degenerate()) {
    CHECK(r.r_res.value == format_scientific(mpfr_real(0), digits));
    CHECK(hp.zero);
    check_real("theta_first", r.theta_first, pi / 2, digits);
    check_real("t_first", r.t_first, sqrt(ts) * pi / 2, digits);
    check_real("h_z_max", r.h_z_max, mpfr_real(0.5), digits);
  } else {
    check_real("r_res", r.r_res, hp.r_res, digits);
    check_real("h_min", r.h_min, hp.radius_sq / 2, digits);
    check_real("h_z_max", r.h_z_max, mpfr_real(0.5) - hp.radius_sq / 2, digits);
    check_real("theta_first", r.theta_first, hp.theta_first, digits);
    check_real("t_first", r.t_first, hp.t_first, digits);
    // Every minimiser: the reference's (global mode) or the first and its mirror (local mode).
    const std::size_t expected = p.strand_offset_min() == 2 ? 4 : 2;
    REQUIRE(r.minimisers.size() == expected);
    if (hp.global) {
      REQUIRE(hp.minimisers.size() == expected);
      for (std::size_t i = 0; i < expected; ++i) check_real("minimiser", r.minimisers[i], hp.minimisers[i], digits);
    } else {
      check_real("minimiser 0", r.minimisers.front(), hp.theta_first, digits);
      check_real("last minimiser (mirror)", r.minimisers.back(), 2 * pi - hp.theta_first, digits);
    }
  }
  if (2 * b >= a) {
    CHECK(!r.asymptotic_applicable);
    CHECK(!r.r_res_asy);
    return;
  }
  REQUIRE(r.asymptotic_applicable);
  const auto node = paper_fast_node(a, b);
  REQUIRE(r.lobes.size() == (node.tie ? 2u : 1u));
  for (std::size_t i = 0; i < r.lobes.size(); ++i) {
    const auto& l = r.lobes[i];
    const big_int k = node.k + big_int(i), m = a - 2 * k * b;
    CHECK(l.k == k);
    CHECK(l.m == m);
    CHECK(l.holds_global_min == (abs(m) == p.strand_offset_min()));
    const mpfr_real s = pi * mp(m) / (2 * Bd);
    const mpfr_real u_asy = m == 0 ? mpfr_real(0) : paper_root_by_bisection(s);  // s = 0: the root is 0
    const mpfr_real theta_asy = 2 * (mp(k) * pi + u_asy) / A;
    const auto lobe = test::hp::hp_lobe_root(tau, sigma, k, ref_digits);
    const mpfr_real theta_c = lobe.theta;
    const mpfr_real error = abs(theta_c - theta_asy), bound = pi * pi * pi * x * x / A;
    check_real("s", l.s, s, digits);
    check_real("u_asy", l.u_asy, u_asy, digits);
    check_real("theta_asy", l.theta_asy, theta_asy, digits);
    check_real("theta_c", l.theta_c, theta_c, digits);
    if (m != 0) {  // m = 0 (b = 2): both roots are 0 exactly, error 0
      check_real("error", l.error, error, digits);
      check_real("ratio", l.ratio, error / bound, digits);
    }
    check_real("bound", l.bound, bound, digits);
  }
  REQUIRE(r.r_res_asy);
  const mpfr_real u = p.degenerate() ? mpfr_real(0) : paper_root_by_bisection(pi * p.strand_offset_min() / (2 * Bd));
  const mpfr_real r_asy = x * abs(sin(u) * tan(u));
  check_real("r_res_asy", *r.r_res_asy, r_asy, digits);
  if (!p.degenerate()) check_real("r_res_asy_rel_error", *r.r_res_asy_rel_error, abs(r_asy - hp.r_res) / hp.r_res, digits);
}

std::vector<resonant_pair<big_int>> hard_cases() {
  std::vector<resonant_pair<big_int>> out;
  for (auto [t, s] : {std::pair{2, 1}, {3, 2}, {4, 1}, {5, 2}, {6, 5}, {9, 4}, {5, 1}, {11, 9}, {5, 3}, {101, 100},
                      {1000, 1}, {41, 35}, {7, 3}})
    out.emplace_back(big_int(t), big_int(s));
  out.emplace_back(pow10(6) + 1, pow10(6));
  out.emplace_back(pow10(6) + 4, big_int(3));
  out.emplace_back(pow10(9), big_int(1));
  out.emplace_back(pow10(12) + 1, pow10(12));
  out.emplace_back(pow10(18) + 1, pow10(18));
  out.emplace_back(big_int(1) << 64, (big_int(1) << 64) - 1);     // the sum overflows 64 bits
  out.emplace_back((big_int(1) << 63) + 1, (big_int(1) << 63) - 1);  // delta = 2: degenerate, sum 2^64
  out.emplace_back(pow10(30) + 1, pow10(30));
  return out;
}

}  // namespace

TEST_CASE("prove_pair: every real of the hard cases is the correct rounding (17 and 50 digits)", "[pair_report]") {
  for (const auto& p : hard_cases())
    for (unsigned d : {17u, 50u}) check_pair(p, d);
}

TEST_CASE("prove_pair: random pairs, every real the correct rounding (17, 50, 1000 digits)", "[pair_report]") {
  std::mt19937_64 rng(20261125);
  auto random_pair = [&](std::int64_t max_order) {
    while (true) {
      const std::int64_t a = std::uniform_int_distribution<std::int64_t>(3, max_order)(rng);
      const std::int64_t s = std::uniform_int_distribution<std::int64_t>(1, (a - 1) / 2)(rng);
      if (std::gcd(a - s, s) == 1) return resonant_pair<big_int>(big_int(a - s), big_int(s));
    }
  };
  for (int i = 0; i < 12; ++i) check_pair(random_pair(i < 8 ? 200 : 20000), i % 2 ? 17 : 50);
  for (int i = 0; i < 3; ++i) check_pair(random_pair(60), 1000);
  check_pair(resonant_pair<big_int>(big_int(6), big_int(5)), 1000);
  check_pair(resonant_pair<big_int>(pow10(12) + 1, pow10(12)), 1000);
}

TEST_CASE("prove_pair: the doubles are filled only when asked", "[pair_report]") {
  pair_report_options opt;
  opt.digits = 3;
  const resonant_pair<big_int> p(big_int(6), big_int(5));
  CHECK(prove_pair(p, opt).r_res.nearest == 0);
  opt.doubles = true;
  const pair_report r = prove_pair(p, opt);
  CHECK(r.r_res.value == "5.07e-02");
  // The doubles nearest 0.05074580579103337246371565... and sqrt(6/5) (mpmath at 200 bits).
  CHECK(r.r_res.nearest == 0x1.9fb5ab090352fp-5);
  CHECK(r.omega1.nearest == 1.0954451150103321);
  CHECK(r.beat_ratio.nearest == 11.0);  // an exact field: its rational rounded once
}

TEST_CASE("prove_pair: exact fields are rounded once from their rational, ties to even", "[pair_report]") {
  // (9, 4): tau sigma = 36, n = 5/6, omega1 = 3/2, omega2 = 2/3, beat ratio 13/5.
  auto r = report(resonant_pair<big_int>(big_int(9), big_int(4)), 1, "0.25");
  CHECK(r.omega1.value == "2e+00");  // 1.5: a tie, to even
  CHECK(r.omega2.value == "7e-01");
  CHECK(r.qdot0.value == "2e-01");  // 0.25: a tie, to even
  CHECK(r.beat_ratio.value == "3e+00");
  CHECK(r.rho0.value == "1e-01");  // 0.25 * 6/13
  // Degenerate (5, 3): h_z_max = qdot0^2/2 = 0.045 exactly, a tie at 1 digit; r_res = h_min = 0.
  r = report(resonant_pair<big_int>(big_int(5), big_int(3)), 1, "0.3");
  CHECK(r.h_z_max.value == "4e-02");
  CHECK(r.r_res.value == "0e+00");
  INFO(r.r_res.enclosure.first << ", " << r.r_res.enclosure.second);
  CHECK(r.r_res.enclosure == std::pair<std::string, std::string>{"0.000e+00", "0.000e+00"});
  CHECK(report(resonant_pair<big_int>(big_int(5), big_int(3)), 2, "0.3").h_z_max.value == "4.5e-02");
  // An exact beat ratio on a tie: (tau + sigma)/(tau - sigma) = 2305843009213693950; 17 digits: ...939|50.
  const resonant_pair<big_int> tie(big_int("2305843009213693951"), big_int("2305843009213693949"));
  CHECK(report(tie, 17).beat_ratio.value == "2.3058430092136940e+18");
  CHECK(report(tie, 18).beat_ratio.value == "2.30584300921369395e+18");
}

TEST_CASE("prove_pair: a minimiser 1.57e-50 past 0 and its mirror just below 2 pi", "[pair_report]") {
  const big_int sigma = pow10(50), tau = 3 * sigma + 1;
  const resonant_pair<big_int> p(tau, sigma);
  // The naive R's minimum in the fast half-period around 1.57e-50, at 450 digits, by bisection on
  // dR; its mirror 2 pi - theta has the same R.
  scoped_digits sd(450);
  const test::naive_forms<mpfr_real> f(mp(tau), mp(sigma));
  mpfr_real lo("1.4e-50"), hi("1.7e-50");
  REQUIRE(f.dR(lo) < 0);
  REQUIRE(f.dR(hi) > 0);
  for (int i = 0; i < 1200; ++i) {
    const mpfr_real mid = (lo + hi) / 2;
    (f.dR(mid) < 0 ? lo : hi) = mid;
  }
  const mpfr_real theta = (lo + hi) / 2, mirror = 2 * real_pi<mpfr_real>() - theta;
  for (unsigned d : {1u, 2u, 5u, 16u, 17u, 30u, 60u, 200u}) {
    INFO("digits " << d);
    const auto r = report(p, d);
    CHECK(r.theta_first.value == format_scientific(theta, d));
    CHECK(r.t_first.value == format_scientific(mpfr_real(sqrt(mp(big_int(tau * sigma))) * theta), d));
    CHECK(r.r_res.value == format_scientific(mpfr_real(sqrt(f.R(theta))), d));
    REQUIRE(r.minimisers.size() == 2);
    CHECK(r.minimisers[1].value == format_scientific(mirror, d));
  }
}

TEST_CASE("prove_pair: bad input is a usage_error naming it", "[pair_report]") {
  const resonant_pair<big_int> p(big_int(6), big_int(5));
  CHECK_THROWS_WITH(report(p, 0), "digits must be in [1, 10000], got 0");
  CHECK_THROWS_WITH(report(p, 10001), "digits must be in [1, 10000], got 10001");
  CHECK_THROWS_AS(report(p, 17, "0"), usage_error);
  CHECK_THROWS_AS(report(p, 17, "-1"), usage_error);
  CHECK_THROWS_AS(report(p, 17, "abc"), usage_error);
  // qdot0 scales r_res exactly: 3 r_res(1) rounds like r_res(3) (both proved).
  CHECK(report(p, 20, "3").r_res.value == format_scientific(mpfr_real(3 * mpfr_real(report(p, 40).r_res.value)), 20));
}
