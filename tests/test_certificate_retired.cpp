// The retired cover certificate ("gyrores-certificate/1", docs/formats.md): `gyrores check` and
// gyrores.check refuse a /1 file at once, whatever it says, with exit 2 and one line saying how to
// re-certify. The fixture tests/fixtures/certificate_v1_rayleigh_overflow.json is such a file as
// an attacker would write it: (10^30+1, 10^30) with the Rayleigh parameter t = "1e20", for which
// the old checker converted floor(t/3) to a long, ran the slow-node cover over no lobe at all and
// answered "certificate holds" (exit 0). `gyrores certify --cover`, which wrote /1, is gone too.
#include <catch2/catch.hpp>

#include <gyrores/io/certificate_json.hpp>

#include <fstream>
#include <string>

#include "cli_checks.hpp"
#include "testing/cli_run.hpp"

using namespace gyrores;

namespace {

const std::string fixture = std::string(GYRORES_TEST_FIXTURES) + "/certificate_v1_rayleigh_overflow.json";

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
  CHECK(certificate_format_of(test::read_text(fixture)) == retired_certificate_format);
  CHECK(std::string(retired_certificate_format) == "gyrores-certificate/1");
  check_refusal_line(retired_certificate_message());
  // Not JSON, no format, a format that is not a string: not /1 (the checker calls them malformed).
  CHECK(certificate_format_of("not json").empty());
  CHECK(certificate_format_of(R"({"tau": 6})").empty());
  CHECK(certificate_format_of(R"({"format": 1})").empty());
}

TEST_CASE("gyrores check refuses a /1 file within a second, exit 2", "[cli][retired]") {
  if (!test::cli_available()) return;
  // A regression that runs the old cover again would never end: `timeout` stops it (status 124,
  // not the refusal's 2) rather than hanging the suite.
  const auto r = test::cli_run("check " + fixture, "timeout 60");
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(test::count_lines(r.err) == 1);
  CHECK(r.err.rfind("gyrores check: ", 0) == 0);
  check_refusal_line(r.err.substr(0, r.err.find('\n')));
}

TEST_CASE("the /1 producer is gone; a /1 file without its format is malformed, not read as /1", "[cli][retired]") {
  if (!test::cli_available()) return;
  test::check_rejected("certify 6 5 --digits 20 --cover", 2, "--cover");
  test::temp_dir dir("retired_noformat");
  std::string text = test::read_text(fixture);
  const std::string format_field = "  \"format\": \"gyrores-certificate/1\",\n";
  REQUIRE(text.find(format_field) != std::string::npos);
  text.erase(text.find(format_field), format_field.size());
  const std::string path = dir / "no_format.json";
  std::ofstream(path) << text;
  test::check_rejected("check " + path, 2, "malformed");
}
