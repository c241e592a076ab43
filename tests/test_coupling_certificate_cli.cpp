// `gyrores check FILE` on coupling certificates (src/cli/cmd_certify.cpp dispatches on the format
// to src/checker/horizon_checker.hpp): a certificate written by the library holds (exit 0, one
// line on stdout); a tampered one fails (exit 1) and a malformed one is refused (exit 2), each
// with one line on stderr; a lattice-theorem certificate still goes to its own checker.
#include <catch2/catch.hpp>

#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/io/certificate_json.hpp>

#include <fstream>

#include "testing/cli_run.hpp"

using namespace gyrores;

TEST_CASE("gyrores check dispatches coupling certificates to their checker", "[cli][certificate][horizon]") {
  if (!test::cli_available()) return;
  test::temp_dir dir("coupling_certificate");
  const auto c = coupling_spec::from_n2(4);
  horizon_certificate cert = certify_horizon_minimum(c, 37, 15);
  cert.below = below_certificate_of(c, prove_first_below(c, big_rational(1, 1000000), {15, {}}, proof_use::certificate), 15);
  const std::string text = certificate_text(cert);
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

TEST_CASE("gyrores check refuses a never certificate with its unused fields filled in", "[cli][certificate][horizon]") {
  // The forgery of issue 36: the (6, 5) coupling (n^2 = 1/30) never goes below 1e-4 (its minimum
  // is 0.0012876...); its certificate says "never", and t_below, crossing and root are unused.
  if (!test::cli_available()) return;
  test::temp_dir dir("coupling_certificate_forged");
  const std::string good = dir / "c.json", forged = dir / "forged.json", wrapped = dir / "wrapped.json";
  auto r = test::cli_run("coupling --n2 1/30 --horizon 100 --below 1e-4 --certificate " + good);
  REQUIRE(r.status == 0);
  std::ifstream in(good);
  json j = json::parse(in);
  REQUIRE(j["below"]["case"] == "never");
  REQUIRE(test::cli_run("check " + good).status == 0);
  json f = j;
  f["below"]["t_below"] = json::array({"4.5", "4.6"});
  f["below"]["crossing"] = json::array({"1", "1.1"});
  f["below"]["root"] = json::array({"0.5", "0.6"});
  std::ofstream(forged) << json_dump(f);
  r = test::cli_run("check " + forged);
  CHECK(r.status == 2);
  CHECK(r.err.find("must be null: case never does not use it") != std::string::npos);
  CHECK(test::count_lines(r.err) == 1);
  // Only t_below planted (the first step): refused too, naming it.
  f = j;
  f["below"]["t_below"] = json::array({"4.5", "4.6"});
  std::ofstream(forged) << json_dump(f);
  r = test::cli_run("check " + forged);
  CHECK(r.status == 2);
  CHECK(r.err.find("below.t_below must be null") != std::string::npos);
  // A lobe side of 2^64 - 1 (not -1) in the minimum.
  f = j;
  f["minimum"]["lobe"]["side"] = json::parse("18446744073709551615");
  std::ofstream(wrapped) << json_dump(f);
  r = test::cli_run("check " + wrapped);
  CHECK(r.status == 2);
  CHECK(r.err.find("lobe.side must be an integer in [-1, 1]") != std::string::npos);
}
