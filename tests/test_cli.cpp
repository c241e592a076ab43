// The CLI as a user meets it: exit statuses, one-line errors with nothing on stdout, the JSON
// schema, and digits (checked against values computed here with the library at higher
// precision, and against the paper's (6,5) r_min = 5.075e-2).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gyrores/gyrores.hpp>
#include "reference/global_search.hpp"  // the reference the digits are checked against

#include "cli_checks.hpp"
#include "testing/cli_run.hpp"

using namespace gyrores::test;  // cli_run, cli_json, check_rejected, count_lines, temp_dir

namespace {

// Significant digits in "d.ddd...e+XX".
int mantissa_digits(const std::string& s) {
  int c = 0;
  for (char ch : s) {
    if (ch == 'e') break;
    if (ch >= '0' && ch <= '9') ++c;
  }
  return c;
}

}  // namespace

TEST_CASE("pair --json has the documented schema", "[cli]") {
  if (!cli_available()) return;
  auto j = cli_json("pair 6 5 --json --digits 30");
  for (const char* k : {"tau", "sigma", "delta", "delta_mod4", "v2_delta", "degenerate", "order", "beat_ratio", "n",
                        "omega1", "omega2", "rho0", "qdot0", "r_res", "h_min", "h_z_max", "theta_first", "t_first",
                        "minimisers", "t_min_paper", "format", "m_min", "theorem", "bits", "digits", "asymptotic",
                        "r_res_asy", "r_res_asy_rel_error"})
    CHECK(j.contains(k));
  CHECK(j["tau"].is_number_integer());
  CHECK(j["tau"] == 6);
  CHECK(j["sigma"] == 5);
  CHECK(j["delta"] == 1);
  CHECK(j["delta_mod4"] == 1);
  CHECK(j["v2_delta"] == 0);
  CHECK(j["order"] == 11);
  CHECK(j["degenerate"] == false);
  CHECK(j["digits"] == 30);
  CHECK(j["format"] == "gyrores-pair/2");
  CHECK(j["theorem"] == "lattice-theorem/1");
  CHECK(j["m_min"] == 1);
  CHECK(!j.contains("enclosures"));
  for (const char* k : {"n", "r_res", "theta_first", "t_first", "t_min_paper", "h_min"}) {
    REQUIRE(j[k].is_string());
    CHECK(mantissa_digits(j[k].get<std::string>()) == 30);
  }
  REQUIRE(j["minimisers"].size() == 2);
  // The paper prints r_min = 5.075e-2 for (6,5) (Section V, case B): right to 4 digits.
  CHECK(j["r_res"].get<std::string>().substr(0, 6) == "5.0745");
  // --enclosures: [lo, hi] under every real's key, holding the printed value.
  auto e = cli_json("pair 6 5 --json --digits 30 --enclosures");
  REQUIRE(e.contains("enclosures"));
  for (const char* k : {"n", "r_res", "h_min", "h_z_max", "theta_first", "t_first", "t_min_paper", "r_res_asy"}) {
    INFO(k);
    REQUIRE(e["enclosures"][k].size() == 2);
    const double lo = std::stod(e["enclosures"][k][0].get<std::string>()), hi = std::stod(e["enclosures"][k][1].get<std::string>());
    const double v = std::stod(e[k].get<std::string>());
    CHECK(lo <= v * (1 + 1e-15));
    CHECK(v <= hi * (1 + 1e-15));
  }
  CHECK(e["enclosures"]["minimisers"].size() == 2);
  CHECK(e["enclosures"]["asymptotic_lobes"].size() == 2);
  const auto text = cli_run("pair 6 5 --enclosures");
  REQUIRE(text.status == 0);
  CHECK(text.out.find("r_res         5.0745805791033372e-02  in [5.0745805791033372") != std::string::npos);
}

TEST_CASE("pair digits are all correct (against the library at 60 digits)", "[cli]") {
  if (!cli_available()) return;
  using namespace gyrores;
  for (auto [tau, sigma, digits] : {std::tuple{6, 5, 30}, {9, 4, 17}, {5, 1, 11}, {1000, 1, 40}, {101, 100, 25}}) {
    auto r = cli_run("pair " + std::to_string(tau) + " " + std::to_string(sigma) + " --json --digits " +
                 std::to_string(digits));
    INFO("pair " << tau << " " << sigma << " digits " << digits);
    REQUIRE(r.status == 0);
    auto j = nlohmann::json::parse(r.out);
    scoped_digits d(digits + 30);
    auto ref = inscribed_global<mpfr_real>(resonant_pair<std::int64_t>(tau, sigma), mpfr_real(1));
    CHECK(j["r_res"] == format_scientific(ref.r_res, unsigned(digits)));
    CHECK(j["theta_first"] == format_scientific(ref.theta_first, unsigned(digits)));
    CHECK(j["t_first"] == format_scientific(ref.t_first, unsigned(digits)));
    REQUIRE(j["minimisers"].size() == ref.minimisers.size());
    for (std::size_t i = 0; i < ref.minimisers.size(); ++i)
      CHECK(j["minimisers"][i] == format_scientific(ref.minimisers[i], unsigned(digits)));
  }
}

TEST_CASE("huge pairs print exact integers and a lattice result", "[cli]") {
  if (!cli_available()) return;
  auto r = cli_run("pair 1000000000000000000000000000001 1000000000000000000000000000000 --json --digits 40");
  REQUIRE(r.status == 0);
  // Integers beyond 64 bits stay JSON numbers.
  CHECK(r.out.find("\"tau\": 1000000000000000000000000000001,") != std::string::npos);
  CHECK(r.out.find("\"order\": 2000000000000000000000000000001,") != std::string::npos);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j["format"] == "gyrores-pair/2");
  CHECK(mantissa_digits(j["r_res"].get<std::string>()) == 40);
}

TEST_CASE("integers with leading zeros are decimal, not octal", "[cli]") {
  if (!cli_available()) return;
  auto j = cli_json("pair 011 09 --json --digits 5");
  CHECK(j["tau"] == 11);
  CHECK(j["sigma"] == 9);
}

TEST_CASE("degenerate pairs: r_res is exactly zero, first zero at pi/2", "[cli]") {
  if (!cli_available()) return;
  auto j = cli_json("pair 11 9 --json");
  CHECK(j["degenerate"] == true);
  CHECK(j["m_min"] == 0);
  CHECK(j["r_res"] == "0.0000000000000000e+00");
  CHECK(j["theta_first"] == "1.5707963267948966e+00");
  // t_first = sqrt(99) pi/2 = (delta/2) pi/n.
  CHECK(j["t_first"] == "1.5629226114141468e+01");
}

TEST_CASE("bad input: one line on stderr, nothing on stdout, exit 2 or 3", "[cli]") {
  if (!cli_available()) return;
  struct row {
    const char* args;
    int status;
    const char* needle;
  };
  for (auto [args, status, needle] : {
           row{"pair 6 4", 2, "reduced pair (3, 2)"},
           row{"pair 5 6", 2, "tau must exceed sigma"},
           row{"pair 5 5", 2, "tau must exceed sigma"},
           row{"pair 6 0", 2, "sigma must be >= 1"},
           row{"pair 6 -1", 2, ""},
           row{"pair 6.5 5", 2, "integer"},
           row{"pair x 5", 2, "integer"},
           row{"pair 6", 2, "SIGMA"},
           row{"pair 6 5 --digits 0", 2, "--digits"},
           row{"pair 6 5 --digits 10001", 2, "--digits"},
           row{"pair 6 5 --digits abc", 2, ""},
           row{"pair 6 5 --qdot0 0", 2, "--qdot0"},
           row{"pair 6 5 --qdot0 -2", 2, "--qdot0"},
           row{"pair 6 5 --qdot0 abc", 2, "--qdot0"},
           row{"pair 6 5 --bogus", 2, "--bogus"},
           row{"pair 6 5 --method magic", 2, "--method"},
           row{"frobnicate", 2, "unknown subcommand 'frobnicate' (gyrores --help lists them)"},
           // A typo of a subcommand or of an option is named with its nearest spelling.
           row{"pari 6 5", 2, "unknown subcommand 'pari' (did you mean 'pair'?)"},
           row{"cuopling 2", 2, "did you mean 'coupling'?"},
           row{"pair 6 5 --digts 5", 2, "did you mean '--digits' for '--digts'?"},
           row{"coupling 2 --horizn 10", 2, "did you mean '--horizon' for '--horizn'?"},
           row{"pair 6 5 --estimate", 2, "--estimate"},
       }) {
    check_rejected(args, status, needle);
  }
}

TEST_CASE("certify writes a certificate that check accepts; tampering and corruption are rejected", "[cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("cli_cert");
  const std::string dir = tmp.path();
  std::string file = dir + "/c.json";
  auto r = cli_run("certify 6 5 --digits 50 --out " + file);
  REQUIRE(r.status == 0);
  CHECK(r.out.empty());
  // No temporary left beside the file (written atomically).
  std::vector<std::string> names;
  for (auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  CHECK(names == std::vector<std::string>{"c.json"});
  auto ok = cli_run("check " + file);
  CHECK(ok.status == 0);
  CHECK(ok.out.find("holds") != std::string::npos);

  const std::string text = gyrores::test::read_text(file);
  auto j = nlohmann::json::parse(text);
  CHECK(j["format"] == "gyrores-certificate/2");
  CHECK(j["tau"] == "6");  // integers as exact decimal strings
  CHECK(j["claims"]["r_res"][0].get<std::string>().substr(0, 10) == "5.07458057");
  auto write = [&](const std::string& name, const std::string& body) {
    std::ofstream out(dir + "/" + name);
    out << body;
    return dir + "/" + name;
  };
  // A claim that does not hold: exit 1, naming it.
  auto t1 = j;
  t1["claims"]["r_res"][1] = t1["claims"]["r_res"][0];
  auto bad = cli_run("check " + write("narrow.json", t1.dump()));
  CHECK(bad.status == 1);
  CHECK(bad.err.find("r_res") != std::string::npos);
  auto t2 = j;
  t2["tau"] = "7";
  CHECK(cli_run("check " + write("pair.json", t2.dump())).status == 1);
  auto t3 = j;
  t3["minimiser_lobes"].erase(t3["minimiser_lobes"].begin());
  CHECK(cli_run("check " + write("drop.json", t3.dump())).status == 1);
  auto t5 = j;
  t5["tau"] = 6;  // a JSON number is not the format's integer
  CHECK(cli_run("check " + write("number.json", t5.dump())).status == 2);
  // The retired cover format /1 is refused at once, exit 2 (test_certificate_retired.cpp).
  auto t6 = j;
  t6["format"] = "gyrores-certificate/1";
  CHECK(cli_run("check " + write("retired.json", t6.dump())).status == 2);
  // Unreadable or malformed: exit 2.
  CHECK(cli_run("check " + write("trunc.json", text.substr(0, text.size() / 2))).status == 2);
  CHECK(cli_run("check " + write("garbage.json", "not json")).status == 2);
  auto t4 = j;
  t4.erase("claims");
  CHECK(cli_run("check " + write("noclaims.json", t4.dump())).status == 2);
  CHECK(cli_run("check " + dir + "/missing.json").status == 2);
  // Bad input to certify.
  CHECK(cli_run("certify 6 4").status == 2);
  CHECK(cli_run("certify 6 5 --digits 0").status == 2);
}

// Issue 12: the inputs that printed a wrong number or exited 3. The values are the independent
// reference's (tests/test_pair_report.cpp checks them at every digit count against
// src/testing/high_precision_reference.hpp).
TEST_CASE("pair: a minimiser near 0 and its mirror near 2 pi are printed right (issue 12)", "[cli]") {
  if (!cli_available()) return;
  const std::string sigma = "1" + std::string(50, '0'), tau = "3" + std::string(49, '0') + "1";
  for (const char* d : {"5", "12"}) {
    INFO("digits " << d);
    auto j = cli_json("pair " + tau + " " + sigma + " --json --digits " + d);
    const std::string th = std::string(d) == "5" ? "1.5708e-50" : "1.57079632679e-50";
    CHECK(j["theta_first"] == th);
    CHECK(j["t_first"] == (std::string(d) == "5" ? "2.7207e+00" : "2.72069904635e+00"));
    REQUIRE(j["minimisers"].size() == 2);
    CHECK(j["minimisers"][0] == th);
    CHECK(j["minimisers"][1] == (std::string(d) == "5" ? "6.2832e+00" : "6.28318530718e+00"));
  }
  const auto r = cli_run("pair " + tau + " " + sigma + " --digits 5");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("theta_first   1.5708e-50") != std::string::npos);
  CHECK(r.out.find("minimisers    1.5708e-50, 6.2832e+00") != std::string::npos);
}

TEST_CASE("pair: exact ties and cancelling asymptotics are proved, not exit 3 (issue 12)", "[cli]") {
  if (!cli_available()) return;
  auto j = cli_json("pair 2305843009213693951 2305843009213693949 --json");
  CHECK(j["beat_ratio"] == "2.3058430092136940e+18");
  const std::string big = "1" + std::string(400, '0');
  auto r = cli_run("pair " + big.substr(0, 400) + "1 " + big);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("r_res ") != std::string::npos);
  // The closed form's relative error is nearly all cancellation (x ~ 5e-401): proved like the
  // rest, to 17 digits. (The JSON holds 401-digit integers, beyond what the parser takes: read
  // as text.)
  auto k = cli_run("pair " + big.substr(0, 400) + "1 " + big + " --json");
  REQUIRE(k.status == 0);
  const auto at = k.out.find("\"r_res_asy_rel_error\": \"");
  REQUIRE(at != std::string::npos);
  CHECK(mantissa_digits(k.out.substr(at + 24, k.out.find('"', at + 24) - at - 24)) == 17);
}
