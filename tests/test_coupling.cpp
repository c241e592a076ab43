// Any coupling n (include/gyrores/coupling.hpp): exact parsing, exact resonance detection on n^2,
// continued-fraction convergents, and the minimum of H_q over a horizon by exact bracketing of
// the critical points (checked against dense sampling and against the pair analysis).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <numeric>

#include "reference/horizon_scan.hpp"
#include <gyrores/gyrores.hpp>

#include "cli_checks.hpp"
#include "reference/coprime_count.hpp"
#include "reference/lattice.hpp"
#include "testing/cli_run.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using gyrores::test::cli_available;
using gyrores::test::check_rejected;
using gyrores::test::cli_json;
using gyrores::test::cli_run;

TEST_CASE("coupling: exact rational parsing", "[coupling]") {
  CHECK(parse_rational("0.25", "x") == big_rational(1, 4));
  CHECK(parse_rational("1e-3", "x") == big_rational(1, 1000));
  CHECK(parse_rational("-1.5E+2", "x") == big_rational(-150));
  CHECK(parse_rational("3/6", "x") == big_rational(1, 2));
  CHECK(parse_rational("-3/6", "x") == big_rational(-1, 2));
  CHECK(parse_rational(".5", "x") == big_rational(1, 2));
  // Leading zeros are decimal, not an octal prefix (mpz_int's string constructor would read
  // "011" as 9 and reject "09").
  CHECK(parse_rational("011", "x") == big_rational(11));
  CHECK(parse_rational("007/09", "x") == big_rational(7, 9));
  CHECK(parse_rational("0.09", "x") == big_rational(9, 100));
  CHECK(parse_rational("-00", "x") == big_rational(0));
  CHECK(parse_rational("2", "x") == big_rational(2));
  CHECK(parse_rational("0.2886751345948129", "x") == big_rational(big_int("2886751345948129"), big_int("10000000000000000")));
  for (const char* bad : {"", "abc", "1/0", "1.2.3", "1/-2", "1e", "e5", "1/", "/2", "0x10", "1e9999999", "--1"})
    CHECK_THROWS_AS(parse_rational(bad, "x"), usage_error);
  CHECK(rational_str(big_rational(6, 4)) == "3/2");
  CHECK(rational_str(big_rational(7)) == "7");
}

TEST_CASE("coupling: resonance decided exactly on n^2", "[coupling]") {
  auto pair_of = [](const coupling_spec& s) { return coupling_resonant_pair(s); };
  auto p = pair_of(coupling_spec::from_n2(big_rational(1, 12)));  // n = 1/sqrt(12): the paper's Fig. 1b
  REQUIRE(p);
  CHECK(p->tau() == 4);
  CHECK(p->sigma() == 3);
  p = pair_of(coupling_spec::from_n2(big_rational(4, 99)));  // (11, 9), paper Case A
  REQUIRE(p);
  CHECK(p->tau() == 11);
  CHECK(p->sigma() == 9);
  CHECK_FALSE(pair_of(coupling_spec::from_n(big_rational(2))));  // Fig. 1a: dense
  CHECK(coupling_spec::from_n(big_rational(2)).discriminant() == 32);
  p = pair_of(coupling_spec::from_n(big_rational(3, 2)));  // rational n can be resonant: (4, 1)
  REQUIRE(p);
  CHECK(p->tau() == 4);
  CHECK(p->sigma() == 1);
  p = pair_of(coupling_spec::from_n(big_rational(-5, 6)));  // the sign does not matter: (9, 4)
  REQUIRE(p);
  CHECK(p->tau() == 9);
  CHECK(p->sigma() == 4);
  // A decimal close to a resonant value is not resonant.
  CHECK_FALSE(pair_of(coupling_spec::from_n(parse_rational("0.2886751345948129", "n"))));
  CHECK_FALSE(pair_of(coupling_spec::from_n2(parse_rational("0.0833333333333333", "n2"))));
  CHECK_FALSE(pair_of(coupling_spec::from_n2(big_rational(1, 13))));
  CHECK_THROWS_AS(coupling_spec::from_n(big_rational(0)), usage_error);
  CHECK_THROWS_AS(coupling_spec::from_n2(big_rational(-1, 3)), usage_error);
}

TEST_CASE("coupling: round trip n^2 = (tau - sigma)^2/(tau sigma) for every pair up to order 120", "[coupling]") {
  int count = 0;
  for (auto p : coprime_pairs(3, 120)) {
    big_int t = p.tau(), s = p.sigma(), d = p.delta();
    auto back = coupling_resonant_pair(coupling_spec::from_n2(big_rational(d * d, t * s)));
    REQUIRE(back);
    CHECK(back->tau() == t);
    CHECK(back->sigma() == s);
    // Perturb n^2 slightly: never resonant with the same pair... and here never resonant at all
    // for this tiny perturbation (D becomes a non-square).
    auto near = coupling_resonant_pair(coupling_spec::from_n2(big_rational(d * d, t * s) + big_rational(1, big_int("1000000000007"))));
    CHECK_FALSE(near);
    ++count;
  }
  int expected = 0;
  for (std::int64_t a = 3; a <= 120; ++a) expected += int(coprime_pairs_of_order(a));
  CHECK(count == expected);
}

TEST_CASE("coupling: continued-fraction convergents of W1/W2 (exact)", "[coupling]") {
  // n = 2: W1/W2 = 3 + 2 sqrt(2) = [5; 1, 4, 1, 4, ...].
  auto cv = coupling_convergents(coupling_spec::from_n(big_rational(2)), 9);
  REQUIRE(cv.size() == 9);
  std::vector<int> want = {5, 1, 4, 1, 4, 1, 4, 1, 4};
  for (std::size_t i = 0; i < cv.size(); ++i) CHECK(cv[i].partial_quotient == want[i]);
  CHECK(cv[0].p == 5);
  CHECK(cv[0].q == 1);
  CHECK(cv[1].p == 6);
  CHECK(cv[2].p == 29);
  CHECK(cv[2].q == 5);
  // Best-approximation property |W1/W2 - p/q| < 1/q^2, checked at 200 bits; p q' - p' q = +-1.
  scoped_digits d(70);
  mpfr_real ratio = 3 + 2 * sqrt(mpfr_real(2));
  for (std::size_t i = 0; i < cv.size(); ++i) {
    mpfr_real pq = mpfr_real(cv[i].p) / mpfr_real(cv[i].q);
    CHECK(abs(ratio - pq) < 1 / (mpfr_real(cv[i].q) * mpfr_real(cv[i].q)));
    if (i > 0) CHECK(abs(big_int(cv[i].p * cv[i - 1].q - cv[i - 1].p * cv[i].q)) == 1);
  }
  // n^2 = 1/12 irrational neighbour n^2 = 1/13: convergents approach; resonant n^2: finite, ends at the pair.
  auto fin = coupling_convergents(coupling_spec::from_n2(big_rational(4, 99)), 20);
  REQUIRE(!fin.empty());
  CHECK(fin.back().p == 11);
  CHECK(fin.back().q == 9);
  auto c13 = coupling_convergents(coupling_spec::from_n2(big_rational(1, 13)), 6);
  CHECK(c13.size() == 6);
}

namespace {
// Dense sampling of H_q on [0, T] in long double: an independent (if inexact) minimum.
struct sampled {
  long double h, t;
};
sampled sample_min(double n, double T, int per_unit) {
  long double s = std::sqrt((long double)n * n + 4), w1 = (s + n) / 2, w2 = 2 / (s + n), r0 = 1 / s;
  sampled best{1e9L, 0};
  long N = long(T * per_unit);
  for (long i = 0; i <= N; ++i) {
    long double t = (long double)T * i / N;
    long double q = r0 * (std::sin(w1 * t) + std::sin(w2 * t)), qd = r0 * (w1 * std::cos(w1 * t) + w2 * std::cos(w2 * t));
    long double h = (q * q + qd * qd) / 2;
    if (h < best.h) best = {h, t};
  }
  return best;
}
}  // namespace

TEST_CASE("coupling: horizon minimum by critical points matches dense sampling", "[coupling]") {
  for (auto [n, T] : {std::pair{2.0, 60.0}, std::pair{0.3, 120.0}, std::pair{1.0, 40.0}, std::pair{5.0, 20.0}}) {
    INFO("n = " << n << ", T = " << T);
    auto r = horizon_minimum<long double>(n, 1.0L, T);
    auto s = sample_min(n, T, 20000);
    // Sampling can only overshoot the true minimum, by O(H'' dt^2) with dt = 5e-5.
    CHECK(r.h_min <= s.h + 1e-18L);
    CHECK(s.h - r.h_min <= 1e-6L);
    CHECK(std::fabs(double(r.t_min - s.t)) < 1e-3);
    // The reported state is H_q at t_min, evaluated independently.
    auto st = impulse_response<long double>(n, 1.0L, r.t_min);
    CHECK(std::fabs(double(energy_q(st) - r.h_min)) <= 1e-15);
    // Critical point count: one root of q' and one of z' per interval of length pi/W1, plus the
    // end point (t = 0 is the first root of z').
    double w1 = (std::sqrt(n * n + 4) + n) / 2;
    CHECK(std::fabs(double(r.critical_points) - (2 * w1 * T / M_PI + 1)) <= 3);
  }
}

TEST_CASE("coupling: horizon minimum of a resonant n equals the pair analysis once t_first is inside", "[coupling]") {
  scoped_digits d(40);
  for (auto [t, s] : {std::pair{4, 3}, std::pair{6, 5}, std::pair{9, 4}, std::pair{5, 1}}) {
    resonant_pair<std::int64_t> p(t, s);
    auto c = resonant_constants_of<mpfr_real>(p, mpfr_real(1));
    auto lat = inscribed_lattice<mpfr_real>(p, mpfr_real(1));
    // one full period plus a little: every minimiser inside; the first one is reported (mirror tie)
    auto r = horizon_minimum<mpfr_real>(c.n, mpfr_real(1), mpfr_real(2 * c.pi * c.sqrt_ts + 1));
    INFO(p.str());
    CHECK(abs(r.h_min - lat.h_min) < lat.h_min * mpfr_real("1e-30"));
    CHECK(abs(r.t_min - lat.t_first) < mpfr_real("1e-20"));
    CHECK_FALSE(r.at_horizon_end);
  }
  // Degenerate (11, 9): H_q = 0 at t_first = sqrt(99) pi/2, up to rounding of n.
  resonant_pair<std::int64_t> p(11, 9);
  auto c = resonant_constants_of<mpfr_real>(p, mpfr_real(1));
  auto r = horizon_minimum<mpfr_real>(c.n, mpfr_real(1), mpfr_real(40));
  CHECK(r.h_min < mpfr_real("1e-70"));
  CHECK(abs(r.t_min - c.sqrt_ts * c.pi / 2) < mpfr_real("1e-30"));
}

TEST_CASE("coupling: end point, zero horizon and limits", "[coupling]") {
  // H_q decreases from its maximum at t = 0: a short horizon has its minimum at t = T.
  auto r = horizon_minimum<double>(0.5, 1.0, 0.1);
  CHECK(r.at_horizon_end);
  CHECK(r.t_min == 0.1);
  auto z = horizon_minimum<double>(0.5, 1.0, 0.0);
  CHECK(z.h_min == Approx(0.5));
  CHECK(z.t_min == 0);
  CHECK_THROWS_AS(horizon_minimum<double>(0.5, 1.0, 1e9), usage_error);
  CHECK_THROWS_AS(horizon_minimum<double>(0.0, 1.0, 1.0), usage_error);
  CHECK_THROWS_AS(horizon_minimum<double>(0.5, -1.0, 1.0), usage_error);
  // n < 0 mirrors: same minimum.
  auto a = horizon_minimum<double>(-2.0, 1.0, 30.0), b = horizon_minimum<double>(2.0, 1.0, 30.0);
  CHECK(a.h_min == b.h_min);
  CHECK(a.t_min == b.t_min);
}

TEST_CASE("coupling: the too-long-horizon message states the count without overflow (issue 12)", "[coupling]") {
  auto message = [](double n, double horizon) {
    try {
      horizon_minimum<double>(n, 1.0, horizon);
    } catch (const usage_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // 2 T W1/pi critical points: W1 ~ sqrt(n) for large n (modal_frequencies_of).
  const std::string huge = message(1e308, 100.0), big = message(1e30, 100.0), small = message(0.5, 1e9);
  INFO(huge << " | " << big << " | " << small);
  CHECK(huge.find("more than 1.8e+308 critical points") != std::string::npos);
  CHECK(big.find("about ") != std::string::npos);
  CHECK(big.find("e+") != std::string::npos);
  CHECK(small.find("about ") != std::string::npos);
  for (const auto& m : {huge, big, small}) CHECK(m.find('-') == std::string::npos);
}

// ------------------------------------------------------------------------------------ CLI

TEST_CASE("cli coupling: resonance detection and JSON keys", "[coupling][cli]") {
  if (!cli_available()) return;
  struct row {
    const char* args;
    bool resonant;
    int tau, sigma;
  };
  for (const auto& w : std::vector<row>{{"--n2 1/12", true, 4, 3},
                                        {"--n2 4/99", true, 11, 9},
                                        {"2", false, 0, 0},
                                        {"0.2886751345948129", false, 0, 0},
                                        {"3/2", true, 4, 1},
                                        {"--n2 0.04", false, 0, 0}}) {
    INFO(w.args);
    auto j = cli_json(std::string("coupling ") + w.args + " --json --horizon 30 --convergents 4");
    for (const auto* k : {"resonant", "pair", "h_min_horizon", "t_min_horizon", "convergents", "inf_all_time", "inf_reason"})
      CHECK(j.contains(k));
    CHECK(j["resonant"] == w.resonant);
    CHECK(j["h_min_horizon"].is_string());
    CHECK(j["t_min_horizon"].is_string());
    if (w.resonant) {
      CHECK(j["pair"]["tau"] == w.tau);
      CHECK(j["pair"]["sigma"] == w.sigma);
    } else {
      CHECK(j["pair"].is_null());
      CHECK(j["inf_all_time"] == "0");
      REQUIRE(j["convergents"].size() == 4);
      for (auto& c : j["convergents"]) {
        CHECK(c["tau"].is_number_integer());
        CHECK(c["sigma"].is_number_integer());
        if (c.contains("r_res")) {
          CHECK(c["r_res"].is_string());
          CHECK(c["t_first"].is_string());
        }
      }
    }
  }
  // (4, 3) with a horizon covering t_first: the horizon minimum is the pair's H_min at t_first.
  auto j = cli_json("coupling --n2 1/12 --json --digits 15");
  CHECK(j["h_min_horizon"] == j["pair_analysis"]["h_min"]);
  CHECK(j["t_min_horizon"] == j["pair_analysis"]["t_first"]);
  // Same horizon, computed by critical points from a rational n close to 1/sqrt(12): close, not equal.
  // Horizon 11: only the first minimiser (10.03) is inside, not its mirror image (11.74), which
  // would be a near-tie for a near-resonant n.
  auto near = cli_run("coupling 0.2886751345948129 --json --digits 6 --horizon 11");
  REQUIRE(near.status == 0);
  auto jn = nlohmann::json::parse(near.out);
  CHECK(jn["resonant"] == false);
  CHECK(std::stod(jn["t_min_horizon"].get<std::string>()) == Approx(10.0328509170).margin(1e-4));
}

TEST_CASE("cli coupling: bad input exits 2 with one line and no stdout", "[coupling][cli]") {
  if (!cli_available()) return;
  for (const char* bad : {"coupling", "coupling 1 --n2 1/12", "coupling abc", "coupling 0", "coupling --n2 0",
                          "coupling 1/0", "coupling 2 --horizon -1", "coupling 2 --digits 0", "coupling 2 --below -1",
                          "coupling 2 --below x%", "coupling 2 --horizon 1e9e", "coupling 2 --horizon pi"})
    check_rejected(bad);
}

TEST_CASE("cli coupling: any horizon and any coupling size answer (the horizon theorem)", "[coupling][cli]") {
  if (!cli_available()) return;
  // Horizons that the critical-point scan could never reach, and a huge coupling.
  for (const char* args : {"coupling 2 --horizon 1e9 --json", "coupling 0.1832 --horizon 1e100 --json",
                           "coupling 2 --horizon 100pi --below 1% --json"}) {
    const auto j = cli_json(args);
    INFO(args);
    CHECK(j["theorem"] == "horizon-theorem/1");
    CHECK(j["h_min_horizon"].is_string());
    CHECK(j["enclosures"]["t_min_horizon"].size() == 2);
  }
  // n = 1e150, the largest coupling accepted (n^2 = 10^300: docs/formats.md, limits): exact
  // integers of 300 digits in the JSON (beyond nlohmann's doubles: read as text). One past it is
  // refused up front, naming the limit.
  const auto huge = cli_run("coupling 1e150 --json --convergents 1");
  CHECK(huge.status == 0);
  CHECK(huge.out.find("\"theorem\": \"horizon-theorem/1\"") != std::string::npos);
  const auto beyond = cli_run("coupling 1e308 --json --convergents 1");
  CHECK(beyond.status == 2);
  CHECK(beyond.err.find("10^300") != std::string::npos);
  // --certificate: the independent checker accepts what coupling wrote.
  const std::string cert = (std::filesystem::temp_directory_path() / ("gyrores-coupling-cert-" + std::to_string(::getpid()) + ".json")).string();
  std::filesystem::remove(cert);
  CHECK(cli_run("coupling 0.1832 --horizon 1e30 --below 1% --convergents 0 --certificate " + cert).status == 0);
  const auto checked = cli_run("check " + cert);
  CHECK(checked.status == 0);
  CHECK(checked.out.find("horizon-theorem/1") != std::string::npos);
  std::filesystem::remove(cert);
  check_rejected("coupling 2 --horizon 100pi --certificate " + cert);
  // Bands: the absorption and containment guarantees over [0, T] (docs/formats.md "Band
  // guarantees"), settled; a degenerate pair inside (11, 9) makes the containment one 0, there.
  const auto band = cli_json("coupling --band 0.18:0.19 --horizon 20 --band-digits 4 --json");
  CHECK(band["band"]["format"] == "gyrores-band/2");
  CHECK(band["band"]["absorption"]["settled"] == true);
  CHECK(band["band"]["containment"]["h_min"].get<std::string>().size() == 9);  // 4 digits: d.ddde-XX
  const auto tol = cli_json("coupling 0.201 --tolerance 1% --horizon 40 --below 1e-3 --json");
  CHECK(tol["band"]["containment"]["at"]["pair"]["tau"] == 11);
  CHECK(tol["band"]["containment"]["enclosure"][1] == "0.00000000000000e+00");
  CHECK(tol["band"]["first_below"]["settled"] == true);
  for (const char* bad : {"coupling --band 2:1", "coupling --band 1", "coupling 2 --tolerance 5", "coupling --tolerance 1%",
                          "coupling 2 --n2 4 --tolerance 1%", "coupling 2 --band 1:3 --tolerance 1%"})
    check_rejected(bad);
  // --n2 with --tolerance: n = sqrt(4) = 2 is rational, the exact band of N = 2.
  const auto by_n2 = cli_json("coupling --n2 4 --tolerance 1% --horizon 10 --json --convergents 0");
  CHECK(by_n2["band"]["n1"] == "99/50");
  CHECK(by_n2["band"]["n2"] == "101/50");
  const auto b = cli_json("coupling 2 --horizon 100pi --below 1% --json");
  CHECK(b["below"]["level"] == "1/200");
  CHECK(b["t_below"].is_string());
}
