// `gyrores check FILE` on coupling certificates (src/cli/cmd_certify.cpp dispatches on the format
// to src/checker/horizon_checker.hpp): a certificate written by the library holds (exit 0, one
// line on stdout); a tampered one fails (exit 1) and a malformed one is refused (exit 2), each
// with one line on stderr; a lattice-theorem certificate still goes to its own checker.
#include <catch2/catch.hpp>

#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/io/horizon_certificate_json.hpp>

#include <fstream>

#include "testing/cli_run.hpp"

using namespace gyrores;

TEST_CASE("gyrores check dispatches coupling certificates to their checker", "[cli][certificate][horizon]") {
  if (!test::cli_available()) return;
  test::temp_dir dir("coupling_certificate");
  const auto c = coupling_spec::from_n2(4);
  horizon_certificate cert = certify_horizon_minimum(c, 37, 15);
  cert.below = certify_first_below(c, big_rational(1, 1000000), 15);
  const std::string text = coupling_certificate_text(cert);
  const std::string good = dir / "good.json", bad = dir / "bad.json", broken = dir / "broken.json",
                    lattice = dir / "lattice.json";
  std::ofstream(good) << text;
  json j = json::parse(text);
  j["minimum"]["lobe"]["k"] = "2";
  std::ofstream(bad) << json_dump(j);
  j.erase("theorem");
  std::ofstream(broken) << json_dump(j);
  std::ofstream(lattice) << json_dump(certificate_to_json(certify_by_theorem(resonant_pair<big_int>(6, 5), 15)));

  auto r = test::cli_run("check " + good);
  CHECK(r.status == 0);
  CHECK(r.out.find("certificate holds (horizon-theorem/1)") != std::string::npos);
  CHECK(test::count_lines(r.out) == 1);
  r = test::cli_run("check " + bad);
  CHECK(r.status == 1);
  CHECK(r.err.find("lobe.k is 2") != std::string::npos);
  CHECK(test::count_lines(r.err) == 1);
  r = test::cli_run("check " + broken);
  CHECK(r.status == 2);
  CHECK(r.err.find("missing field 'theorem'") != std::string::npos);
  r = test::cli_run("check " + lattice);
  CHECK(r.status == 0);
  CHECK(r.out.find("lattice-theorem/1") != std::string::npos);
}
