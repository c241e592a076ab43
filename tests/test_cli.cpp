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
#include "testing/test_support.hpp"

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
  CHECK(text.out.find("r_res         0.050745805791033372  in [0.050745805791033372") != std::string::npos);
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
  CHECK(r.out.find("minimisers    1.5708e-50, 6.2832\n") != std::string::npos);  // plain from exponent -4
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

// ---- Numbers for people (issue 35): the text outputs' plain notation and shares of H_q(0) ----

namespace {

// The value after `key` on the first line of `text` that starts with "  " + key, up to two spaces.
std::string text_value(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\n  " + key);
  if (at == std::string::npos) return "";
  std::size_t start = text.find_first_not_of(' ', at + 3 + key.size());
  const std::size_t end = text.find_first_of("\n", start);
  std::string v = text.substr(start, end - start);
  const std::size_t gap = v.find("  ");
  return gap == std::string::npos ? v : v.substr(0, gap);
}

// The share "S" of "(S% of H_q(0))" on the line after `key`.
std::string share_on_line(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\n  " + key);
  if (at == std::string::npos) return "";
  const std::string line = text.substr(at + 1, text.find('\n', at + 1) - at - 1);
  const std::size_t open = line.find("  ("), pct = line.find("% of H_q(0))");
  if (open == std::string::npos || pct == std::string::npos) return "";
  return line.substr(open + 3, pct - open - 3);
}

// The printed share must be the correct 4-digit rounding of factor * h, where h is the exact
// value within half a unit of the last digit of `h_text` (a correct rounding to many more digits):
// both ends of that interval, times the exact factor, round to the printed digits.
void check_share(const std::string& share, const std::string& h_text, const gyrores::big_rational& factor) {
  using gyrores::big_rational;
  INFO("share " << share << ", H_q min " << h_text);
  REQUIRE(!share.empty());
  const std::size_t e = h_text.find('e');
  const int digits = mantissa_digits(h_text);
  const long e10 = std::stol(h_text.substr(e + 1));
  const big_rational h = gyrores::parse_rational(h_text, "h");
  // Half a unit in the last place: 10^(e10 - digits + 1) / 2 (e10 - digits + 1 < 0 here).
  const big_rational half_ulp(gyrores::big_int(1), 2 * boost::multiprecision::pow(gyrores::big_int(10), unsigned(digits - 1 - e10)));
  const big_rational shown = gyrores::parse_rational(share, "share");
  for (const big_rational& end : {big_rational(h - half_ulp), big_rational(h + half_ulp)})
    CHECK(gyrores::parse_rational(gyrores::format_rational_scientific(end * factor, 4), "rounded") == shown);
}

}  // namespace

TEST_CASE("pair: H_q min as a share of H_q(0), proved (200 H_q min at qdot0 = 1)", "[cli]") {
  if (!cli_available()) return;
  const auto text = cli_run("pair 6 5");
  REQUIRE(text.status == 0);
  const auto j = cli_json("pair 6 5 --json --digits 40");
  const std::string share = share_on_line(text.out, "H_q min");
  CHECK(share == "0.2575");  // 200 x 1.2875684026906381e-03 = 0.25751...
  check_share(share, j["h_min"].get<std::string>(), 200);
  // qdot0 = 3/7: H_q(0) = 9/98, the share is H_q min * 9800/9.
  const auto q = cli_run("pair 9 4 --qdot0 3/7 --digits 12");
  REQUIRE(q.status == 0);
  check_share(share_on_line(q.out, "H_q min"), cli_json("pair 9 4 --qdot0 3/7 --json --digits 40")["h_min"].get<std::string>(),
              gyrores::big_rational(9800, 9));
  // A degenerate pair: an exact zero, said so on both lines.
  const auto d = cli_run("pair 11 9 --digits 10");
  CHECK(text_value(d.out, "r_res") == "0");
  CHECK(text_value(d.out, "H_q min") == "0");
  CHECK(d.out.find("0.000000000e+00") == std::string::npos);
}

TEST_CASE("coupling and design: min H_q with its share of H_q(0)", "[cli]") {
  if (!cli_available()) return;
  const auto text = cli_run("coupling 2 --horizon 37");
  REQUIRE(text.status == 0);
  const auto j = cli_json("coupling 2 --horizon 37 --json --digits 40");
  check_share(share_on_line(text.out, "min H_q"), j["h_min_horizon"].get<std::string>(), 200);
  const auto r = cli_run("coupling --n2 1/12");
  check_share(share_on_line(r.out, "H_q min"), cli_json("pair 4 3 --json --digits 40")["h_min"].get<std::string>(), 200);
  const auto design = cli_run("design contain --tmax 17 --beat 10");
  REQUIRE(design.status == 0);
  CHECK(!share_on_line(design.out, "H_q min").empty());
}

TEST_CASE("text outputs: plain notation with exactly the digits of the proved rounding", "[cli]") {
  if (!cli_available()) return;
  const auto t = cli_run("pair 6 5 --digits 10");
  REQUIRE(t.status == 0);
  CHECK(text_value(t.out, "t_first") == "16.35107798");
  CHECK(text_value(t.out, "H_q min") == "0.001287568403");
  // Every digit as in the JSON's scientific text: only the point moved.
  const auto j = cli_json("pair 6 5 --json");
  const std::string sci = j["t_first"].get<std::string>();  // 1.6351077975144872e+01
  CHECK(text_value(cli_run("pair 6 5").out, "t_first") == sci.substr(0, 1) + sci.substr(2, 1) + "." + sci.substr(3, sci.find('e') - 3));
  // Exponents outside [-4, 6] stay scientific.
  const auto c = cli_run("coupling 0.2 --horizon 40");
  CHECK(c.out.find("min H_q       1.15349511491e-08") != std::string::npos);
  CHECK(c.out.find("first at t =  15.6689755829\n") != std::string::npos);
}

TEST_CASE("coupling --quiet: no progress on stderr", "[cli]") {
  if (!cli_available()) return;
  // The flag is accepted (today's code refused it) and nothing reaches stderr; the progress line
  // itself shows only after a second of band proof (cmd_coupling.cpp), which no fast test reaches.
  const auto q = cli_run("coupling 2 --tolerance 5% --horizon 1e4 --quiet");
  CHECK(q.status == 0);
  CHECK(q.err.empty());
  CHECK(q.out.find("absorption guarantee") != std::string::npos);
}

TEST_CASE("coupling --n2 with --tolerance: rational ends enclosing n (1 -+ p) outward", "[cli]") {
  if (!cli_available()) return;
  using gyrores::big_rational;
  const auto j = cli_json("coupling --n2 1/12 --tolerance 1% --horizon 20 --json --convergents 0");
  const auto& band = j["band"];
  const big_rational n1 = gyrores::parse_rational(band["n1"].get<std::string>(), "n1"),
                     n2 = gyrores::parse_rational(band["n2"].get<std::string>(), "n2");
  const big_rational p(1, 100), sq(1, 12);
  // n1 <= sqrt(1/12) (1 - p) and n2 >= sqrt(1/12) (1 + p), compared squared (all positive) ...
  CHECK(n1 * n1 <= sq * (1 - p) * (1 - p));
  CHECK(n2 * n2 >= sq * (1 + p) * (1 + p));
  // ... and close (30 digits): a band 1e-25 narrower at each end would not enclose.
  const big_rational tiny(1, boost::multiprecision::pow(gyrores::big_int(10), 25));
  CHECK((n1 + tiny) * (n1 + tiny) > sq * (1 - p) * (1 - p));
  CHECK((n2 - tiny) * (n2 - tiny) < sq * (1 + p) * (1 + p));
  // The same guarantees as --band with those ends.
  const auto b = cli_json("coupling --band " + band["n1"].get<std::string>() + ":" + band["n2"].get<std::string>() +
                          " --horizon 20 --json");
  CHECK(b["band"]["absorption"]["h_min"] == band["absorption"]["h_min"]);
  CHECK(b["band"]["containment"]["h_min"] == band["containment"]["h_min"]);
  // The text says the band used contains the one asked.
  const auto t = cli_run("coupling --n2 1/12 --tolerance 1% --horizon 20 --convergents 0");
  REQUIRE(t.status == 0);
  CHECK(t.out.find("contains the band n (1 -+ 1%) asked") != std::string::npos);
  // A rational n: the exact band, as with N.
  const auto r = cli_json("coupling --n2 1/25 --tolerance 1% --horizon 40 --json --convergents 0");
  CHECK(r["band"]["n1"] == "99/500");
  CHECK(r["band"]["n2"] == "101/500");
  CHECK(cli_run("coupling --tolerance 1%").status == 2);
}
