// The retired cover certificate ("gyrores-certificate/1", docs/formats.md): `gyrores check` and
// gyrores.check refuse a /1 file at once, whatever it says, with exit 2 and one line saying how to
// re-certify. The files below are written here, as an attacker would write them:
//   * (10^30+1, 10^30) and (2^64+1, 2^64) with the Rayleigh parameter t = "1e20": the old checker
//     converted floor(t/3) to a long, the slow-node loop ran zero times and it answered
//     "certificate holds" (exit 0) without running the cover;
//   * (10^9, 1) with the "all-lobes" strategy: the old checker re-ran the cover over 10^9 lobes
//     (about 17 hours).
// `gyrores certify --cover`, which wrote /1, is gone too.
#include <catch2/catch.hpp>

#include <gyrores/io/certificate_json.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "testing/cli_run.hpp"

using namespace gyrores;

namespace {

struct retired_file {
  const char* name;
  std::string text;
};

// A /1 certificate in the layout the old `gyrores certify --cover` wrote (statements shortened):
// the claims are honest enclosures of the pair; `cover` and `rayleigh` carry the attack.
std::string cover_certificate(const std::string& tau, const std::string& sigma, const std::string& bits,
                              bool global, const std::string& note, const std::string& claims,
                              const std::string& root, const std::string& basin, const std::string& cover,
                              const std::string& rayleigh_t) {
  std::string rayleigh = rayleigh_t.empty() ? "" :
      R"(, {"id": "rayleigh", "statement": "for |cos beta| >= sin(t x): ...", "data": {"t": ")" + rayleigh_t + R"("}})";
  return R"({"format": "gyrores-certificate/1", "tau": )" + tau + R"(, "sigma": )" + sigma +
         R"(, "digits": 20, "working_bits": )" + bits + R"(, "cover_bits": )" + bits +
         R"(, "degenerate": false, "global_minimality": )" + (global ? "true" : "false") +
         R"(, "global_minimality_note": ")" + note + R"(", "claims": )" + claims +
         R"(, "minimiser_count": )" + (global ? "2" : "null") + R"(, "obligations": [)" +
         R"({"id": "local-root", "statement": "interval Newton: ...", "data": )" + root + "}, " +
         R"({"id": "basin", "statement": "on Y: ...", "data": )" + basin + "}, " +
         R"({"id": "symmetry", "statement": "R(2 pi - theta) = R(theta) ...", "data": {"images": "2"}}, )" +
         R"({"id": "cover", "statement": "R > bound on [0, 2 pi) outside the basins ...", "data": )" + cover + "}" +
         rayleigh + "]}\n";
}

std::vector<retired_file> retired_files() {
  return {
      {"rayleigh_overflow_1e30.json",
       cover_certificate(
           "1000000000000000000000000000001", "1000000000000000000000000000000", "164", true, "proved (slow-nodes)",
           R"({"r_res": ["2.805481690955225337702018765804730803455946914609084e-31", "2.805481690955225337702018765804730803455946914609349e-31"],
               "theta_first": ["3.141592653589793238462643383278642550608150019612597e+00", "3.141592653589793238462643383278642550608150019612651e+00"],
               "t_first": ["3.141592653589793238462643383280213346934944916231805e+30", "3.141592653589793238462643383280213346934944916231901e+30"]})",
           R"({"X_hi": "7.104627377755168567474282675020891086867003364499087e-01", "X_lo": "7.104627377755168567474282675020891086867003364498899e-01",
               "j": "0", "k": "1000000000000000000000000000000", "m": "1"})",
           R"({"Y_hi": "1.065694106663275285121142401253133663030050504674848282685e+00",
               "Y_lo": "3.552313688877584283737141337510445543433501682249503184832e-01", "bits": "164"})",
           R"({"bits": "164", "bound": "7.87072751828499049040661609279107656273442204449003159e-62", "boxes": "0", "lobes": "0",
               "strategy": "slow-nodes"})",
           "1e20")},
      {"rayleigh_overflow_2p64.json",
       cover_certificate(
           "18446744073709551617", "18446744073709551616", "129", true, "proved (slow-nodes)",
           R"({"r_res": ["1.5208546721009809331445024155029363986478e-20", "1.5208546721009809331445024155029363986628e-20"],
               "theta_first": ["3.1415926535897932384160046059656497511570e+00", "3.1415926535897932384160046059656497511615e+00"],
               "t_first": ["5.7952155664616982739785071193656395956324e+19", "5.7952155664616982739785071193656395956487e+19"]})",
           R"({"X_hi": "7.1046273777551685674742826750208910868802e-01", "X_lo": "7.1046273777551685674742826750208910868581e-01",
               "j": "0", "k": "18446744073709551616", "m": "1"})",
           R"({"Y_hi": "1.0656941066632752851211424012531336630305592767e+00",
               "Y_lo": "3.5523136888775842837371413375104455434345853523e-01", "bits": "129"})",
           R"({"bits": "129", "bound": "2.312998933651382231921669448324586569747978e-40", "boxes": "0", "lobes": "0",
               "strategy": "slow-nodes"})",
           "1e20")},
      {"all_lobes_1e9.json",
       cover_certificate(
           "1000000000", "1", "93", false, "not proved: an undecided box",
           R"({"r_res": ["0", "3.90130368513174579549457599271e-23"], "theta_first": null, "t_first": null})",
           R"({"X_hi": "-7.85398164182846473798507319186e-10", "X_lo": "-7.85398164182846473798507319375e-10",
               "j": "249999999", "k": "250000000", "m": "-1"})",
           R"({"Y_hi": "-3.92699082091423236899253659640380801e-10", "Y_lo": "-1.17809724627426971069776097890938746e-09",
               "bits": "93"})",
           R"({"bits": "93", "bound": "1.5220170443622539939909848390790e-45", "boxes": "0", "lobes": "0",
               "strategy": "all-lobes"})",
           "")},
  };
}

// The refusal names the retired format and says how to re-certify.
void check_refusal_line(const std::string& line) {
  CHECK(line.find("gyrores-certificate/1") != std::string::npos);
  CHECK(line.find("retired") != std::string::npos);
  CHECK(line.find("gyrores certify TAU SIGMA --digits D --out FILE") != std::string::npos);
  CHECK(line.find("gyrores-certificate/2") != std::string::npos);
  CHECK(line.find("gyrores check FILE") != std::string::npos);
  CHECK(line.find('\n') == std::string::npos);
}

}  // namespace

TEST_CASE("a /1 certificate is recognised by its format and refused with how to re-certify", "[certificate][retired]") {
  for (const auto& f : retired_files()) {
    INFO(f.name);
    CHECK(certificate_format_of(f.text) == retired_certificate_format);
  }
  CHECK(std::string(retired_certificate_format) == "gyrores-certificate/1");
  check_refusal_line(retired_certificate_message());
  // Not JSON, no format, a format that is not a string: not /1 (the checker calls them malformed).
  CHECK(certificate_format_of("not json").empty());
  CHECK(certificate_format_of(R"({"tau": 6})").empty());
  CHECK(certificate_format_of(R"({"format": 1})").empty());
}

TEST_CASE("gyrores check refuses the malicious /1 files within a second, exit 2", "[cli][retired]") {
  if (!test::cli_available()) return;
  test::temp_dir dir("retired");
  for (const auto& f : retired_files()) {
    INFO(f.name);
    const std::string path = dir / f.name;
    std::ofstream(path) << f.text;
    // A regression that runs the cover again would take minutes: `timeout` stops it (status 124,
    // not the refusal's 2) rather than hanging the suite.
    const auto r = test::cli_run("check " + path, "timeout 60");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(test::count_lines(r.err) == 1);
    CHECK(r.err.rfind("gyrores check: ", 0) == 0);
    check_refusal_line(r.err.substr(0, r.err.find('\n')));
  }
}

TEST_CASE("the /1 producer is gone; a /1 file without its format is malformed, not read as /1", "[cli][retired]") {
  if (!test::cli_available()) return;
  test::check_rejected("certify 6 5 --digits 20 --cover", 2, "--cover");
  test::temp_dir dir("retired_noformat");
  std::string text = retired_files().front().text;
  const std::string format_field = R"("format": "gyrores-certificate/1", )";
  text.erase(text.find(format_field), format_field.size());
  const std::string path = dir / "no_format.json";
  std::ofstream(path) << text;
  test::check_rejected("check " + path, 2, "malformed");
}
