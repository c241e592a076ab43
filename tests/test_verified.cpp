// The verified-digits contract, which only the coupling report's horizon minimum still uses
// (core/precision.hpp, core/verified_digits.hpp, report/coupling_report.hpp): the digits are
// checked against independent values, and the failure modes against their documented errors.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "reference/precision.hpp"
#include "reference/verified_digits.hpp"
#include <gyrores/report/coupling_report.hpp>
#include <gyrores/gyrores.hpp>

using namespace gyrores;

TEST_CASE("verified digits: the precision plan follows the digits asked", "[verified]") {
  CHECK(plan_for_digits(11, false).kind == real_kind::f64);
  CHECK(plan_for_digits(11, false).bits == 53);
  CHECK(plan_for_digits(15, false).kind == real_kind::f80);
  CHECK(plan_for_digits(29, false).kind == real_kind::f128);
  CHECK(plan_for_digits(29, false).bits == 113);
  // Beyond float128: ceil(D log2 10) + 24 bits (30 digits: 100 + 24).
  CHECK(plan_for_digits(30, false).kind == real_kind::mpfr);
  CHECK(plan_for_digits(30, false).bits == 124);
  CHECK(plan_for_digits(5, true).kind == real_kind::mpfr);
  CHECK(plan_for_digits(5, true).name() == "mpfr");
  CHECK(plan_for_digits(12, false).name() == "long double");
  CHECK(with_real_type(plan_for_digits(40, false), [](auto tag) { return real_type_name<decltype(tag)>(); }).substr(0, 5) ==
        "mpfr(");
  CHECK(with_real_type(plan_for_digits(10, false), [](auto tag) { return real_type_name<decltype(tag)>(); }) == "double");
}

TEST_CASE("verified digits: settled values are accepted, unsettled ones throw compute_error", "[verified]") {
  // pi/7 to 25 digits: accepted, equal to the correctly rounded value.
  auto run = compute_verified_per_type(25, false, [](auto tag) {
    using T = decltype(tag);
    real_fields f;
    put_field(f, "x", T(real_pi<T>() / 7));
    return f;
  });
  scoped_digits d(60);
  CHECK(run.fields.at("x").at(0) == format_scientific(mpfr_real(real_pi<mpfr_real>() / 7), 25));
  CHECK(run.plan.kind == real_kind::f128);
  // A value that depends on the precision never settles: 5 rounds, then compute_error.
  int rounds = 0;
  CHECK_THROWS_AS(compute_verified(10, false,
                                   [&](const precision_plan& plan) {
                                     ++rounds;
                                     real_fields f;
                                     f["drift"] = {mpfr_real(plan.bits)};
                                     return f;
                                   }),
                  compute_error);
  CHECK(rounds == 10);  // two runs a round
  CHECK_THROWS_AS(check_verified_digits(0), usage_error);
  CHECK_THROWS_AS(check_verified_digits(10001), usage_error);
}

TEST_CASE("verified digits: a diagnostic that does not settle is partial or a bound, never an error", "[verified]") {
  // x settles; "partial" = 1/3 + 10^-15 per bit of the run: the runs differ by 6.4e-14, so 12
  // or 13 digits settle, not 20; "noise" = 2^-bits (pure rounding noise, like a closed form's
  // relative error): no digit settles.
  int rounds = 0;
  auto compute = [&](const precision_plan& plan) {
    ++rounds;
    scoped_digits d(80);
    real_fields f;
    f["x"] = {mpfr_real(mpfr_real(1) / 7)};
    f["partial"] = {mpfr_real(mpfr_real(1) / 3 + mpfr_real(plan.bits) * mpfr_real("1e-15"))};
    f["noise"] = {ldexp(mpfr_real(1), -int(plan.bits))};
    return f;
  };
  auto diagnostic = [](const std::string& name) { return name != "x"; };
  const auto run = compute_verified(20, false, compute, diagnostic);
  CHECK(rounds == 4);  // the diagnostics get a second round, then are accepted as they are
  scoped_digits d(40);
  CHECK(run.fields.at("x").at(0) == format_scientific(mpfr_real(mpfr_real(1) / 7), 20));
  REQUIRE(run.unsettled.count("partial"));
  const unsigned settled = run.unsettled.at("partial");
  CHECK(settled >= 10u);
  CHECK(settled <= 13u);
  CHECK(run.fields.at("partial").at(0) ==
        format_scientific(mpfr_real(mpfr_real(1) / 3 + mpfr_real(run.plan.bits) * mpfr_real("1e-15")), settled));
  REQUIRE(run.unsettled.count("noise"));
  CHECK(run.unsettled.at("noise") == 0u);
  // The bound covers both runs' values (2^-226 and 2^-331 in the second round: the check runs 64
  // bits beyond the plan's rung of 267 bits).
  CHECK(mpfr_real(run.fields.at("noise").at(0)) >= ldexp(mpfr_real(1), -int(run.plan.bits)));
  CHECK(run.unsettled.count("x") == 0);
  // Without the predicate the same computation is refused.
  CHECK_THROWS_AS(compute_verified(20, false, compute), compute_error);
}

TEST_CASE("verified digits: MPFR plans run on the precision ladder, whatever the default precision", "[verified]") {
  CHECK(plan_working_bits({real_kind::f128, 113}) == 113);
  CHECK(plan_working_bits({real_kind::mpfr, 124}) == 134);  // mpfr_fixed<40>
  CHECK(plan_working_bits({real_kind::mpfr, 135}) == 267);  // mpfr_fixed<80>
  CHECK(plan_working_bits({real_kind::mpfr, mpfr_ladder_max_bits}) == mpfr_ladder_max_bits);
  CHECK_THROWS_AS(plan_working_bits({real_kind::mpfr, mpfr_ladder_max_bits + 1}), usage_error);
  CHECK_THROWS_AS(with_real_type({real_kind::mpfr, mpfr_ladder_max_bits + 1}, [](auto) { return 0; }), usage_error);
  // The type and the value's bits are the rung's, at any default precision; pi to all of them.
  scoped_digits low(20);
  const auto pi = with_real_type({real_kind::mpfr, 300}, [](auto tag) {
    using T = decltype(tag);
    return real_to_mpfr(real_pi<T>());
  });
  REQUIRE(mpfr_get_prec(pi.backend().data()) == 533);
  mpfr_t ref;
  mpfr_init2(ref, 533);
  mpfr_const_pi(ref, MPFR_RNDN);
  CHECK(mpfr_equal_p(ref, pi.backend().data()));
  mpfr_clear(ref);
  CHECK(mpfr_real::default_precision() == 20);
  // The two runs of a round are on different rungs (30 digits: 124 bits asked, 134 held; the check
  // 198 asked, 267 held), and the digits do not depend on the default precision.
  std::vector<unsigned> bits;
  auto third = [&](auto tag) {
    using T = decltype(tag);
    bits.push_back(real_bits<T>());
    real_fields f;
    put_field(f, "x", T(T(1) / 3));
    return f;
  };
  const auto run = compute_verified_per_type(30, false, third);
  CHECK(bits == std::vector<unsigned>{134, 267});
  CHECK(run.fields.at("x").at(0) == "3.33333333333333333333333333333e-01");
  // Beyond the ladder no round runs.
  int calls = 0;
  CHECK_THROWS_WITH(compute_verified(20500, false,
                                     [&](const precision_plan&) {
                                       ++calls;
                                       return real_fields{};
                                     }),
                    Catch::Contains("largest working type"));
  CHECK(calls == 0);
}

TEST_CASE("coupling report: the resonant case over a horizon that holds t_first", "[verified][coupling]") {
  const auto spec = coupling_spec::from_n(big_rational(2));
  // n^2 = 1/12 is the pair (4, 3); the default horizon 100 contains its t_first.
  coupling_report_options opt;
  opt.convergents = 3;
  const auto r = analyse_coupling(coupling_spec::from_n2(big_rational(1, 12)), opt);
  REQUIRE(r.pair);
  CHECK(r.pair->tau() == 4);
  CHECK(r.pair->sigma() == 3);
  REQUIRE(r.pair_values);
  CHECK(r.horizon.h_min.value == r.pair_values->h_min.value);
  CHECK(r.horizon.t_min.value == r.pair_values->t_first.value);
  CHECK(r.inf_attained);
  CHECK(r.inf_all_time == r.pair_values->h_min.value);
  CHECK(r.pair_values->r_res.value == prove_pair_values(resonant_pair<big_int>(big_int(4), big_int(3)), 12).r_res.value);
  // Not resonant: the infimum 0 is not attained.
  const auto n2 = analyse_coupling(spec, opt);
  CHECK_FALSE(n2.pair);
  CHECK(n2.inf_all_time == "0");
  CHECK_FALSE(n2.inf_attained);
  CHECK(n2.convergents.size() == 3);
  coupling_report_options neg;
  neg.horizon = big_rational(-1);
  CHECK_THROWS_AS(analyse_coupling(spec, neg), usage_error);
}
