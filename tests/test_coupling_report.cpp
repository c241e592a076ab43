// The coupling report (design/coupling_report.hpp) on a resonant coupling over a horizon that
// holds its first minimum, and on a coupling that is not resonant. (Until the verified-digits
// contract left the tests, this case lived in tests/test_verified.cpp.)
#include <catch2/catch.hpp>

#include <gyrores/report/coupling_report.hpp>
#include <gyrores/gyrores.hpp>

using namespace gyrores;

TEST_CASE("coupling report: the resonant case over a horizon that holds t_first", "[coupling]") {
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
