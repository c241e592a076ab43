// The verified-digits contract as a C++ user calls it (core/precision.hpp,
// core/verified_digits.hpp, inscribed/verified_pair.hpp, design/coupling_report.hpp): the
// digits are checked against independent values (the global search in MPFR at 30 more digits,
// closed forms for degenerate pairs), and the failure modes against their documented errors.
#include <catch2/catch.hpp>

#include <string>

#include <gyrores/core/precision.hpp>
#include <gyrores/core/verified_digits.hpp>
#include <gyrores/design/coupling_report.hpp>
#include <gyrores/gyrores.hpp>
#include <gyrores/inscribed/verified_pair.hpp>

using namespace gyrores;

namespace {

resonant_pair<big_int> big_pair(std::int64_t t, std::int64_t s) { return resonant_pair<big_int>(big_int(t), big_int(s)); }

}  // namespace

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
  // The bound covers both runs' values (2^-226 and 2^-290 in the second round).
  CHECK(mpfr_real(run.fields.at("noise").at(0)) >= ldexp(mpfr_real(1), -int(run.plan.bits)));
  CHECK(run.unsettled.count("x") == 0);
  // Without the predicate the same computation is refused.
  CHECK_THROWS_AS(compute_verified(20, false, compute), compute_error);
}

TEST_CASE("verify_pair: every real of (6, 5) against the global search at higher precision", "[verified]") {
  for (unsigned digits : {16u, 30u}) {
    verified_pair_options opt;
    opt.digits = digits;
    const auto r = verify_pair(big_pair(6, 5), opt);
    scoped_digits d(digits + 30);
    const auto ref = inscribed_global<mpfr_real>(resonant_pair<std::int64_t>(6, 5), mpfr_real(1));
    INFO("digits " << digits);
    CHECK(r.r_res == format_scientific(ref.r_res, digits));
    CHECK(r.h_min == format_scientific(ref.h_min, digits));
    CHECK(r.theta_first == format_scientific(ref.theta_first, digits));
    CHECK(r.t_first == format_scientific(ref.t_first, digits));
    REQUIRE(r.minimisers.size() == ref.minimisers.size());
    for (std::size_t i = 0; i < ref.minimisers.size(); ++i)
      CHECK(r.minimisers[i] == format_scientific(ref.minimisers[i], digits));
    CHECK(r.method == "lattice");
    CHECK(r.cross_checked);
    CHECK_FALSE(r.degenerate);
    CHECK(r.digits == digits);
    // a/(2b) = 11/2: a tie, both lobes k = 5 and 6 (mirror images).
    REQUIRE(r.lobes.size() == 2);
    CHECK(r.lobes[0].k == "5");
    CHECK(r.lobes[1].k == "6");
    CHECK(r.lobes[0].error == r.lobes[1].error);
    CHECK(r.asymptotic_applicable);
    CHECK(r.r_res_asy.has_value());
  }
  // The value the tests and the paper's r_min = 5.075e-2 refer to.
  CHECK(verify_pair(big_pair(6, 5), {}).r_res.substr(0, 18) == "5.0745805791033372");
  CHECK(verify_pair_values(6, 5, 16).r_res == "5.074580579103337e-02");
}

TEST_CASE("verify_pair: a degenerate pair is exact; qdot0 scales r_res", "[verified]") {
  const auto r = verify_pair(big_pair(11, 9), {});
  CHECK(r.degenerate);
  CHECK(r.method == "degenerate-exact");
  CHECK_FALSE(r.cross_checked);
  CHECK(r.r_res == "0.0000000000000000e+00");
  scoped_digits d(50);
  const mpfr_real t_first = sqrt(mpfr_real(99)) * real_pi<mpfr_real>() / 2;  // (delta/2) pi/n
  CHECK(r.t_first == format_scientific(t_first, 17));
  CHECK(r.theta_first == format_scientific(mpfr_real(real_pi<mpfr_real>() / 2), 17));
  const auto v = verify_pair_values(11, 9, 12);
  CHECK(v.degenerate);
  CHECK(v.t_first == format_scientific(t_first, 12));
  CHECK(v.t_min_paper == format_scientific(t_first, 12));  // delta = 2: t_first = pi/n exactly

  verified_pair_options quarter;
  quarter.qdot0 = "0.25";
  quarter.digits = 20;
  const auto q = verify_pair(big_pair(9, 4), quarter);
  const auto ref = inscribed_global<mpfr_real>(resonant_pair<std::int64_t>(9, 4), mpfr_real("0.25"));
  CHECK(q.r_res == format_scientific(ref.r_res, 20));
  CHECK(q.qdot0 == "2.5000000000000000000e-01");
}

TEST_CASE("verify_pair: the global search, and the documented errors", "[verified]") {
  verified_pair_options global;
  global.solver = solver_choice::global_search;
  global.digits = 20;
  const auto g = verify_pair(big_pair(9, 4), global);
  const auto l = verify_pair(big_pair(9, 4), verified_pair_options{20});
  CHECK(g.method == "global-search");
  CHECK(g.r_res == l.r_res);
  CHECK(g.t_first == l.t_first);
  CHECK_FALSE(g.cross_checked);

  verified_pair_options bad;
  bad.digits = 0;
  CHECK_THROWS_AS(verify_pair(big_pair(6, 5), bad), usage_error);
  for (const char* q : {"0", "-1", "abc", ""}) {
    verified_pair_options o;
    o.qdot0 = q;
    CHECK_THROWS_AS(verify_pair(big_pair(6, 5), o), usage_error);
  }
  CHECK_THROWS_AS(check_qdot0_text("-2", "--qdot0"), usage_error);
  CHECK_THROWS_AS(verify_pair(big_pair(200001, 2), global), compute_error);
  CHECK_THROWS_AS(verify_pair_values(6, 5, 0), usage_error);
  // The paper's Case B quotes the lobe k = 6 of (6, 5); it has no lobe k = 7.
  const auto lobe = verify_paper_lobe(big_pair(6, 5), big_int(6), 6);
  CHECK(lobe.theta_asy.substr(0, 4) == "3.29");
  CHECK_THROWS_AS(verify_paper_lobe(big_pair(6, 5), big_int(7), 6), compute_error);
}

TEST_CASE("coupling report: verified horizon minimum and the resonant case", "[verified][coupling]") {
  // n = 2 over [0, 100 pi] (the paper's Fig. 1a span), against horizon_minimum at 60 digits.
  const auto spec = coupling_spec::from_n(big_rational(2));
  const auto h = verify_horizon_minimum(spec, exact_horizon{big_rational(100), true}, 12);
  {
    scoped_digits d(60);
    const auto ref = horizon_minimum<mpfr_real>(mpfr_real(2), mpfr_real(1), mpfr_real(100 * real_pi<mpfr_real>()));
    CHECK(h.h_min == format_scientific(ref.h_min, 12));
    CHECK(h.t_min == format_scientific(ref.t_min, 12));
    CHECK(h.r_min == format_scientific(mpfr_real(sqrt(2 * ref.h_min)), 12));
    CHECK(h.critical_points == ref.critical_points);
  }
  // n^2 = 1/12 is the pair (4, 3); the default horizon 100 contains its t_first.
  coupling_report_options opt;
  opt.convergents = 3;
  const auto r = analyse_coupling(coupling_spec::from_n2(big_rational(1, 12)), opt);
  REQUIRE(r.pair);
  CHECK(r.pair->tau() == 4);
  CHECK(r.pair->sigma() == 3);
  REQUIRE(r.pair_values);
  CHECK(r.h_min_horizon == r.pair_values->h_min);
  CHECK(r.t_min_horizon == r.pair_values->t_first);
  CHECK(r.inf_attained);
  CHECK(r.inf_all_time == r.pair_values->h_min);
  CHECK(r.pair_values->r_res == verify_pair_values(4, 3, 12).r_res);
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
