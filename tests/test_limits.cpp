// The envelope of the coupling inputs (include/gyrores/model/limits.hpp, docs/formats.md "Limits
// of the coupling inputs"), at its edges: the producer's numbers and the checker's own copy agree;
// every certificate `gyrores coupling ... --certificate FILE` writes with exit 0 at an edge (T
// from 10^-1000 to 10^1000, n^2 from 10^-300 to 10^300, levels down to 10^-100, the longest n^2
// text) is accepted by `gyrores check`; just past each edge the producer refuses (exit 2, one
// line naming the limit). The edges, not a sweep: seconds in all.
#include <catch2/catch.hpp>

#include <gyrores/model/inputs.hpp>
#include <gyrores/model/limits.hpp>

#include <string>

#include "horizon_checker.hpp"
#include "testing/cli_run.hpp"
#include "cli_checks.hpp"

using namespace gyrores;

namespace {

// `coupling ARGS --certificate FILE` must exit 0 and `check FILE` must accept what it wrote.
void produced_and_checked(const std::string& args, const test::temp_dir& dir) {
  static int serial = 0;
  const std::string file = dir / ("c" + std::to_string(++serial) + ".json");
  INFO("coupling " << args.substr(0, 200));
  auto r = test::cli_run("coupling " + args + " --certificate " + file);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  r = test::cli_run("check " + file);
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.out.find("certificate holds (horizon-theorem/1)") != std::string::npos);
}

// As above, or the producer's documented refusal (exit 3, one line: a root within
// 10^-(digits+15) of pi/2, where no certificate of that many digits can state it), writing nothing.
void produced_and_checked_or_refused(const std::string& args, const test::temp_dir& dir) {
  const std::string file = dir / "refused.json";
  INFO("coupling " << args.substr(0, 200));
  const auto r = test::cli_run("coupling " + args + " --certificate " + file);
  if (r.status == 0) return produced_and_checked(args, dir);
  CHECK(r.status == 3);
  CHECK(test::count_lines(r.err) == 1);
  CHECK(r.err.find("certificate's decimals cannot decide it") != std::string::npos);
  CHECK(test::cli_run("check " + file).status == 2);  // nothing written
}

std::string pow10_text(long e) { return "1e" + std::to_string(e); }

}  // namespace

TEST_CASE("the producer's limits and the checker's copy agree", "[limits]") {
  CHECK(limits::horizon_exponent == gyrores_checker::coupling_horizon_exponent);
  CHECK(limits::n2_exponent == gyrores_checker::coupling_n2_exponent);
  CHECK(limits::level_exponent == gyrores_checker::coupling_level_exponent);
  CHECK(limits::rational_chars == gyrores_checker::coupling_max_rational_chars);
  CHECK(limits::lobe_digits == gyrores_checker::coupling_max_integer_digits);
}

TEST_CASE("the parsers refuse just past each limit and accept at it", "[limits]") {
  const long h = limits::horizon_exponent, n = limits::n2_exponent, l = limits::level_exponent;
  CHECK(parse_horizon_time(pow10_text(h), "--horizon").value == big_rational(boost::multiprecision::pow(big_int(10), unsigned(h))));
  CHECK_NOTHROW(parse_horizon_time(pow10_text(-h), "--horizon"));
  CHECK_NOTHROW(parse_horizon_time("0", "--horizon"));
  CHECK_THROWS_AS(parse_horizon_time(pow10_text(h + 1), "--horizon"), usage_error);
  CHECK_THROWS_AS(parse_horizon_time("10000000000000000000000000000001" + std::string(size_t(h - 30), '0') , "--horizon"), usage_error);
  CHECK_THROWS_AS(parse_horizon_time(pow10_text(-h - 1), "--horizon"), usage_error);
  CHECK_NOTHROW(parse_energy_level(pow10_text(-l), "--below"));
  CHECK_NOTHROW(parse_energy_level("0", "--below"));
  CHECK_THROWS_AS(parse_energy_level(pow10_text(-l - 1), "--below"), usage_error);
  CHECK_NOTHROW(check_coupling_limits(parse_rational(pow10_text(n), "n2"), "n2"));
  CHECK_NOTHROW(check_coupling_limits(parse_rational(pow10_text(-n), "n2"), "n2"));
  CHECK_THROWS_AS(check_coupling_limits(parse_rational(pow10_text(n + 1), "n2"), "n2"), usage_error);
  CHECK_THROWS_AS(check_coupling_limits(parse_rational(pow10_text(-n - 1), "n2"), "n2"), usage_error);
  // A band's ends are couplings too: n^2 within the limits.
  CHECK_THROWS_AS(parse_band("1e-300:1e-299", "--band"), usage_error);
  CHECK_THROWS_AS(parse_band("1e299:1e300", "--band"), usage_error);
  CHECK_NOTHROW(parse_band("1e-150:1e150", "--band"));
}

TEST_CASE("certificates at the edges of the limits are written and accepted", "[limits][cli]") {
  if (!test::cli_available()) return;
  test::temp_dir dir("limits");
  const long h = limits::horizon_exponent, n = limits::n2_exponent, l = limits::level_exponent;
  // Horizons, from the smallest to the largest, at both ends of the couplings.
  for (const std::string& T : {pow10_text(-h), std::string("1e-900"), std::string("1e200"), std::string("1e300"), pow10_text(h)})
    produced_and_checked("2 --horizon " + T, dir);
  produced_and_checked("--n2 " + pow10_text(n) + " --horizon " + pow10_text(h), dir);
  produced_and_checked("--n2 " + pow10_text(-n) + " --horizon " + pow10_text(h) + " --digits 160", dir);
  // Couplings, from the smallest to the largest (a tiny one's lobe-0 root lies within about n^2
  // of pi/2: refused at these digits, with the reason).
  for (const std::string& n2 : {std::string("1e60"), pow10_text(n)}) produced_and_checked("--n2 " + n2 + " --horizon 100", dir);
  for (const std::string& n2 : {pow10_text(-n), std::string("1e-60")}) produced_and_checked_or_refused("--n2 " + n2 + " --horizon 100", dir);
  // Levels down to the smallest (its crossing needs about 50 digits: --digits 40 gives 55), and at
  // the supremum 1 - x^2 of the lobe values (n = 2: 2E = 1/2).
  produced_and_checked("2 --horizon 10 --digits 40 --below " + pow10_text(-l), dir);
  for (const std::string& E : {std::string("1e-40"), std::string("50%"), std::string("1/4"),
                               std::string("1/4+"), std::string("1/4-")}) {
    std::string level = E;
    if (E == "1/4+") level = "25000000000000000000000000000001/100000000000000000000000000000000";
    if (E == "1/4-") level = "24999999999999999999999999999999/100000000000000000000000000000000";
    produced_and_checked("2 --horizon 10 --below " + level, dir);
  }
  // The longest n^2 text: 2000 characters, (10^999 + 1)/2^3316 reduced (about 6.3).
  const big_int two = boost::multiprecision::pow(big_int(2), 3316u);
  const std::string longest = rational_str(big_rational(boost::multiprecision::pow(big_int(10), 999u) + 1, two));
  REQUIRE(longest.size() == limits::rational_chars);
  produced_and_checked("--n2 " + longest + " --horizon 1e30 --below 1e-6", dir);

  // Just past each limit: refused before any work, naming the flag.
  test::check_rejected("coupling 2 --horizon " + pow10_text(h + 1), 2, "--horizon must be at most");
  test::check_rejected("coupling 2 --horizon " + pow10_text(-h - 1), 2, "--horizon must be 0 or at least");
  test::check_rejected("coupling --n2 " + pow10_text(n + 1), 2, "must lie in [10^-300, 10^300]");
  test::check_rejected("coupling --n2 " + pow10_text(-n - 1), 2, "must lie in [10^-300, 10^300]");
  test::check_rejected("coupling 2 --below " + pow10_text(-l - 1), 2, "--below must be 0 or at least");
  const std::string too_long =
      rational_str(big_rational(boost::multiprecision::pow(big_int(10), 1000u) + 1, two));
  REQUIRE(too_long.size() == limits::rational_chars + 1);
  test::check_rejected("coupling --n2 " + too_long, 2, "characters");
  // The largest horizon of all, 10^100000, and the band ends past the limits: one line, exit 2.
  test::check_rejected("coupling 2 --horizon 1e100000", 2, "--horizon must be at most");
  test::check_rejected("coupling --band 1e299:1e300", 2, "--band N1 squared");
  test::check_rejected("coupling --band 1e-300:1e300", 2, "--band N1 squared");
  test::check_rejected("coupling --band 1e-300:1e-299", 2, "--band N1 squared");
}
