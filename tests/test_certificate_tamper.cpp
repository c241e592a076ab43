// The tamper catalogue of the cover reference's certificates (tests/reference/, the retired format
// /1): every field of a certificate's JSON (docs/formats.md) is changed in turn, in a way that
// makes the certificate false or inconsistent, written to a file, read back
// (reference/certificate_json.hpp, io/files.hpp) and checked; the checker must refuse each one (a
// failing verdict, or "malformed"). Pairs: small (6, 5), x -> 1 (1000, 1), huge (10^30+1, 10^30)
// and (2^64+1, 2^64), degenerate (11, 9), and (10^9, 1), which is not proved (r_res <= hi only).
// The obligations' `statement` texts are prose for the reader and are not part of the claim.
#include <catch2/catch.hpp>

#include <gyrores/io/files.hpp>

#include <functional>
#include <string>
#include <vector>

#include "reference/certificate_json.hpp"
#include "reference/certify.hpp"
#include "reference/check.hpp"
#include "testing/cli_run.hpp"

using namespace gyrores;

namespace {

using tamper = std::function<void(json&)>;

// "d.ddd...e+XX" moved by delta units of its last digit (delta > 0: up, towards +infinity), by
// changing one digit (the previous one when the last would leave 0..9): an inward move of a lower
// end for delta = 1, of an upper end for delta = -1.
std::string bump_last_digit(std::string s, int delta) {
  if (!s.empty() && s[0] == '-') delta = -delta;  // the digits are the magnitude
  auto e = s.find('e');
  std::size_t i = (e == std::string::npos ? s.size() : e) - 1;
  int d = s[i] - '0' + delta;
  if (d < 0 || d > 9) {  // move the previous digit instead of carrying
    --i;
    if (s[i] == '.') --i;
    d = s[i] - '0' + delta;
  }
  s[i] = char('0' + (d + 10) % 10);
  return s;
}

json& obligation(json& j, const std::string& id) {
  for (auto& o : j["obligations"])
    if (o["id"] == id) return o;
  throw std::runtime_error("no obligation " + id);
}

std::string plus_one(const json& v) { return (big_int(v.get<std::string>()) + 1).str(); }

// The catalogue for one certificate: (what, change).
std::vector<std::pair<std::string, tamper>> catalogue(const certificate& c) {
  std::vector<std::pair<std::string, tamper>> t;
  auto add = [&](std::string what, tamper f) { t.push_back({std::move(what), std::move(f)}); };
  add("format", [](json& j) { j["format"] = "gyrores-certificate/0"; });
  add("tau + 2", [](json& j) { j["tau"] = json_integer((big_int(json_dump(j["tau"], -1)) + 2).str()); });
  add("sigma + 2", [](json& j) { j["sigma"] = json_integer((big_int(json_dump(j["sigma"], -1)) + 2).str()); });
  add("tau as a string", [](json& j) { j["tau"] = json_dump(j["tau"], -1); });
  add("digits x 3", [](json& j) { j["digits"] = j["digits"].get<unsigned>() * 3; });
  add("working_bits 16", [](json& j) { j["working_bits"] = 16; });
  add("cover_bits 16", [](json& j) { j["cover_bits"] = 16; });
  add("degenerate flipped", [](json& j) { j["degenerate"] = !j["degenerate"].get<bool>(); });
  add("global_minimality flipped", [](json& j) { j["global_minimality"] = !j["global_minimality"].get<bool>(); });
  add("note", [](json& j) { j["global_minimality_note"] = "proved (by assertion)"; });
  add("obligations removed", [](json& j) { j["obligations"] = json::array(); });
  add("claims removed", [](json& j) { j.erase("claims"); });
  if (c.degenerate) {
    add("r_res not zero", [](json& j) { j["claims"]["r_res"][1] = "1e-40"; });
    add("theta_first lo up", [](json& j) { j["claims"]["theta_first"][0] = bump_last_digit(j["claims"]["theta_first"][0], 1); });
    add("t_first hi down", [](json& j) { j["claims"]["t_first"][1] = bump_last_digit(j["claims"]["t_first"][1], -1); });
    add("minimiser_count", [](json& j) { j["minimiser_count"] = 4; });
    for (const char* key : {"delta_mod4", "tau_mod4", "sigma_mod4"})
      add(std::string("degenerate.") + key, [key](json& j) { obligation(j, "degenerate")["data"][key] = "7"; });
    return t;
  }
  add("r_res hi down", [](json& j) { j["claims"]["r_res"][1] = bump_last_digit(j["claims"]["r_res"][1], -1); });
  if (c.global_minimality) {
    add("r_res lo up", [](json& j) { j["claims"]["r_res"][0] = bump_last_digit(j["claims"]["r_res"][0], 1); });
    add("theta_first lo up", [](json& j) { j["claims"]["theta_first"][0] = bump_last_digit(j["claims"]["theta_first"][0], 1); });
    add("theta_first hi down", [](json& j) { j["claims"]["theta_first"][1] = bump_last_digit(j["claims"]["theta_first"][1], -1); });
    add("t_first lo up", [](json& j) { j["claims"]["t_first"][0] = bump_last_digit(j["claims"]["t_first"][0], 1); });
    add("t_first hi down", [](json& j) { j["claims"]["t_first"][1] = bump_last_digit(j["claims"]["t_first"][1], -1); });
    add("minimiser_count + 1", [](json& j) { j["minimiser_count"] = j["minimiser_count"].get<unsigned>() + 1; });
    add("cover.lobes + 1", [](json& j) { obligation(j, "cover")["data"]["lobes"] = plus_one(obligation(j, "cover")["data"]["lobes"]); });
    add("cover.boxes + 1", [](json& j) { obligation(j, "cover")["data"]["boxes"] = plus_one(obligation(j, "cover")["data"]["boxes"]); });
    add("cover.strategy", [](json& j) { obligation(j, "cover")["data"]["strategy"] = "no-cover"; });
  } else {
    add("r_res lo not 0", [](json& j) { j["claims"]["r_res"][0] = "1e-300"; });
    add("theta_first claimed", [](json& j) { j["claims"]["theta_first"] = json::array({"0", "7"}); });
  }
  add("local-root.k + 1", [](json& j) { obligation(j, "local-root")["data"]["k"] = plus_one(obligation(j, "local-root")["data"]["k"]); });
  add("local-root.j + 1", [](json& j) { obligation(j, "local-root")["data"]["j"] = plus_one(obligation(j, "local-root")["data"]["j"]); });
  add("local-root.m + 1", [](json& j) { obligation(j, "local-root")["data"]["m"] = plus_one(obligation(j, "local-root")["data"]["m"]); });
  // The root box moved off the root: collapsed onto either end (a one-digit inward move may still
  // hold the root, which the checker then rightly accepts: where the root sits in the box
  // depends on the producer's last bits).
  add("local-root.X_lo up to X_hi", [](json& j) { auto& d = obligation(j, "local-root")["data"]; d["X_lo"] = d["X_hi"]; });
  add("local-root.X_hi down to X_lo", [](json& j) { auto& d = obligation(j, "local-root")["data"]; d["X_hi"] = d["X_lo"]; });
  add("basin.Y_hi below X", [](json& j) {
    auto& y = obligation(j, "basin")["data"];
    y["Y_hi"] = obligation(j, "local-root")["data"]["X_lo"];
  });
  add("basin.bits + 1", [](json& j) { obligation(j, "basin")["data"]["bits"] = plus_one(obligation(j, "basin")["data"]["bits"]); });
  add("cover.bits + 1", [](json& j) { obligation(j, "cover")["data"]["bits"] = plus_one(obligation(j, "cover")["data"]["bits"]); });
  add("cover.bound up", [](json& j) { auto& d = obligation(j, "cover")["data"]; d["bound"] = bump_last_digit(d["bound"], 1); });
  add("symmetry.images + 1", [](json& j) { obligation(j, "symmetry")["data"]["images"] = plus_one(obligation(j, "symmetry")["data"]["images"]); });
  if (find_obligation(c, "rayleigh"))
    add("rayleigh.t far too small", [](json& j) { obligation(j, "rayleigh")["data"]["t"] = "1e-30"; });
  for (const char* id : {"local-root", "basin", "symmetry", "cover"})
    add(std::string("drop ") + id, [id](json& j) {
      auto& o = j["obligations"];
      for (std::size_t i = 0; i < o.size(); ++i)
        if (o[i]["id"] == id) o.erase(i);
    });
  return t;
}

// Written to a file and read back, as `gyrores check` reads it.
check_verdict check_through_file(const json& j, const std::string& path) {
  write_file_atomically(path, json_dump(j) + "\n");
  try {
    return check_certificate(certificate_from_text(read_file(path)));
  } catch (const usage_error& e) {
    return {false, std::string("malformed: ") + e.what()};
  } catch (const compute_error& e) {  // the checker could not compute its own enclosures: not accepted
    return {false, std::string("not re-proved: ") + e.what()};
  }
}

}  // namespace

TEST_CASE("tamper catalogue: every field changed is refused, through the files", "[certificate][tamper]") {
  test::temp_dir dir("tamper");
  struct row {
    const char* tau;
    const char* sigma;
  };
  for (auto r : {row{"6", "5"}, row{"1000", "1"}, row{"1000000000000000000000000000001", "1000000000000000000000000000000"},
                 row{"18446744073709551617", "18446744073709551616"}, row{"11", "9"}, row{"1000000000", "1"}}) {
    const resonant_pair<big_int> p{big_int(r.tau), big_int(r.sigma)};
    const certificate c = certify_pair(p, 20);
    const json good = certificate_to_json(c);
    INFO(p.str());
    {
      auto v = check_through_file(good, dir / "good.json");
      INFO(v.failure);
      REQUIRE(v.holds);
    }
    for (const auto& [what, change] : catalogue(c)) {
      json bad = good;
      change(bad);
      auto v = check_through_file(bad, dir / "bad.json");
      INFO(what << " -> " << v.failure);
      CHECK_FALSE(v.holds);
    }
  }
}
