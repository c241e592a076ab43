// No wrong number and no refused valid input in verify_pair (inscribed/verified_pair.hpp), on the
// inputs of issue 12: a minimiser 1.57e-50 past 0 whose mirror 2 pi - 1.57e-50 once wrapped to 0;
// an exact beat ratio on a rounding tie; a diagnostic (the closed form's relative error, nearly
// all cancellation) that blocked the answer; exact rationals rounded once (core/rational.hpp).
//
// Oracles: the independent high-precision reference (src/testing/high_precision_reference.hpp,
// naive forms at brute precision, its minimisers compared in MPFR at its own precision), exact
// integer arithmetic written out here, and hand-rounded decimal strings.
#include <catch2/catch.hpp>

#include <string>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/inscribed/verified_pair.hpp>

#include "testing/high_precision_reference.hpp"
#include "testing/naive_forms.hpp"

using namespace gyrores;

namespace {

big_int pow10(unsigned e) {
  big_int r = 1;
  for (unsigned i = 0; i < e; ++i) r *= 10;
  return r;
}

verified_pair_report report(const resonant_pair<big_int>& p, unsigned digits) {
  verified_pair_options opt;
  opt.digits = digits;
  return verify_pair(p, opt);
}

}  // namespace

TEST_CASE("format_rational_scientific: correct rounding, ties to even, carries", "[truth][rational]") {
  CHECK(format_rational_scientific(big_rational(2305843009213693950), 17) == "2.3058430092136940e+18");
  CHECK(format_rational_scientific(big_rational(2305843009213693950), 18) == "2.30584300921369395e+18");
  CHECK(format_rational_scientific(big_rational(2305843009213693950), 19) == "2.305843009213693950e+18");
  CHECK(format_rational_scientific(big_rational(25, 100), 1) == "2e-01");   // tie, 2 even
  CHECK(format_rational_scientific(big_rational(35, 100), 1) == "4e-01");   // tie, 3 odd
  CHECK(format_rational_scientific(big_rational(-15, 100), 1) == "-2e-01");
  CHECK(format_rational_scientific(big_rational(251, 1000), 1) == "3e-01");
  CHECK(format_rational_scientific(big_rational(1, 3), 5) == "3.3333e-01");
  CHECK(format_rational_scientific(big_rational(2, 3), 5) == "6.6667e-01");
  CHECK(format_rational_scientific(big_rational(9999, 1000), 3) == "1.00e+01");  // carry into a new decade
  CHECK(format_rational_scientific(big_rational(95), 1) == "1e+02");
  CHECK(format_rational_scientific(big_rational(1, 1000), 3) == "1.00e-03");
  CHECK(format_rational_scientific(big_rational(0), 4) == "0.000e+00");
  CHECK(format_rational_scientific(big_rational(0), 1) == format_scientific(mpfr_real(0), 1));
  // Agrees with MPFR's correct rounding wherever the value is a binary number.
  for (int num : {1, 3, 5, 7, 125, 1023, 4097})
    for (unsigned d : {1u, 2u, 3u, 6u})
      CHECK(format_rational_scientific(big_rational(num, 1024), d) == format_scientific(mpfr_real(num / 1024.0), d));
}

// The minimiser of the naive R (src/testing/naive_forms.hpp, tau theta formed directly) in
// [lo, hi], by bisection on dR/dtheta at the current precision; requires dR(lo) < 0 < dR(hi).
mpfr_real naive_minimiser(const test::naive_forms<mpfr_real>& f, mpfr_real lo, mpfr_real hi, int bits) {
  REQUIRE(f.dR(lo) < 0);
  REQUIRE(f.dR(hi) > 0);
  for (int i = 0; i < bits; ++i) {
    const mpfr_real mid = (lo + hi) / 2;
    (f.dR(mid) < 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

TEST_CASE("verify_pair: the minimiser 1.57e-50 and its mirror at every digit count (issue 12)", "[truth]") {
  const big_int sigma = pow10(50), tau = 3 * sigma + 1;
  const resonant_pair<big_int> p(tau, sigma);
  // The independent truth: the naive R's minimum in the fast half-period around 1.57e-50 (tau
  // theta in [4.2, 5.1]), at 450 digits (R ~ 4.5e-203 is a cancellation of O(1) terms); its
  // mirror 2 pi - theta has the same R (R(-theta) = R(theta)), and R(0) = qdot0^2 = 1 is not it.
  scoped_digits sd(450);
  const test::naive_forms<mpfr_real> f(real_from_int<mpfr_real>(tau), real_from_int<mpfr_real>(sigma));
  const mpfr_real theta = naive_minimiser(f, mpfr_real("1.4e-50"), mpfr_real("1.7e-50"), 1200);
  const mpfr_real mirror = 2 * real_pi<mpfr_real>() - theta;
  const mpfr_real t_first = sqrt(real_from_int<mpfr_real>(big_int(tau * sigma))) * theta;
  const mpfr_real r_res = sqrt(f.R(theta));
  CHECK(format_scientific(theta, 5) == "1.5708e-50");
  CHECK(format_scientific(t_first, 5) == "2.7207e+00");
  CHECK(format_scientific(sqrt(f.R(mirror)), 30) == format_scientific(r_res, 30));
  CHECK(f.R(mpfr_real(0)) > 0.5);
  for (unsigned d : {1u, 2u, 5u, 11u, 12u, 15u, 16u, 17u, 20u, 29u, 30u, 45u, 60u, 100u, 200u}) {
    INFO("digits " << d);
    const auto r = report(p, d);
    CHECK(r.theta_first == format_scientific(theta, d));
    CHECK(r.t_first == format_scientific(t_first, d));
    CHECK(r.r_res == format_scientific(r_res, d));
    REQUIRE(r.minimisers.size() == 2);
    CHECK(r.minimisers[0] == format_scientific(theta, d));
    CHECK(r.minimisers[1] == format_scientific(mirror, d));
  }
}

TEST_CASE("verify_pair: an exact beat ratio on a rounding tie is rounded once (issue 12)", "[truth]") {
  const resonant_pair<big_int> p(big_int("2305843009213693951"), big_int("2305843009213693949"));
  const auto r = report(p, 17);
  // (tau + sigma)/(tau - sigma) = 4611686018427387900/2 = 2305843009213693950; 17 digits: ...939|50, ties to even.
  CHECK(r.beat_ratio == "2.3058430092136940e+18");
  CHECK(report(p, 18).beat_ratio == "2.30584300921369395e+18");
  // delta = 2: a degenerate pair, r_res = 0 exactly at pi/2 and 3 pi/2.
  CHECK(r.degenerate);
  CHECK(r.r_res == "0.0000000000000000e+00");
  scoped_digits sd(40);
  CHECK(r.theta_first == format_scientific(mpfr_real(real_pi<mpfr_real>() / 2), 17));
}

TEST_CASE("verify_pair: exact fields with a tie at D digits (qdot0, n, omega, rho0, h_z_max)", "[truth]") {
  // (9, 4): tau sigma = 36, n = 5/6, omega1 = 3/2, omega2 = 2/3, beat ratio 13/5 = 2.6.
  verified_pair_options opt;
  opt.digits = 1;
  opt.qdot0 = "0.25";
  auto r = verify_pair(resonant_pair<big_int>(big_int(9), big_int(4)), opt);
  CHECK(r.omega1 == "2e+00");  // 1.5: tie, to even
  CHECK(r.omega2 == "7e-01");
  CHECK(r.qdot0 == "2e-01");   // 0.25: tie, to even
  CHECK(r.beat_ratio == "3e+00");
  CHECK(r.rho0 == "1e-01");    // 0.25 * 6/13 = 0.115...
  // Degenerate (5, 3): h_z_max = qdot0^2/2 = 0.045 exactly, a tie at 1 digit; r_res = h_min = 0.
  opt.qdot0 = "0.3";
  r = verify_pair(resonant_pair<big_int>(big_int(5), big_int(3)), opt);
  CHECK(r.h_z_max == "4e-02");
  CHECK(r.r_res == "0e+00");
  CHECK(r.qdot0 == "3e-01");
  opt.digits = 2;
  CHECK(verify_pair(resonant_pair<big_int>(big_int(5), big_int(3)), opt).h_z_max == "4.5e-02");
}

TEST_CASE("verify_pair: an unsettled diagnostic does not block the answer (issue 12)", "[truth]") {
  const big_int sigma = pow10(400), tau = sigma + 1;
  const resonant_pair<big_int> p(tau, sigma);
  const auto r = report(p, 17);
  // x = 1/(2 10^400 + 1): the answer is checked against the reference, which examines the fast
  // half-periods (width 3e-400) around its guess: the guess is the library's theta at 430 digits.
  const std::string guess = report(p, 430).theta_first;
  scoped_digits sd(900);
  const auto ref = test::hp::hp_reference(tau, sigma, 30, mpfr_real(guess), true);
  CHECK(r.r_res == format_scientific(ref.r_res, 17));
  CHECK(r.theta_first == format_scientific(ref.theta_first, 17));
  CHECK(r.t_first == format_scientific(ref.t_first, 17));
  REQUIRE(r.r_res_asy_rel_error);
  // Whatever settled is marked; a marked value has fewer than 17 digits or is a bound.
  for (const auto& [name, settled] : r.unsettled) {
    INFO(name);
    CHECK(settled < 17u);
    CHECK((name.rfind("asymptotic.lobes.", 0) == 0 || name == "r_res_asy" || name == "r_res_asy_rel_error"));
  }
}
