// Band certificates ("gyrores-band-certificate/1", certify/band_certificate.hpp) and their
// independent checker (src/checker/band_checker.hpp):
//   * certificates of a few bands (1% around n = 2 at T = 10 and 10^6; 0.343:0.357 at 10^30; a band
//     holding the degenerate coupling n^2 = 4/99, x = 1/10, at T = 20, containment 0; 2:2.4 at T = 4
//     and 0.3:3 at T = 5, where the end point decides many intervals; 7.6:8.4 at T = 3, with
//     line_turning intervals), written
//     from the app's band run (record_cover): every one is accepted;
//   * the tamper catalogue: every key of the format removed, and every field changed in turn
//     (format, theorem, ends, horizon, digits, claims, the attaining coupling, each interval's
//     ends, kind, K, k, flags and bound, the order of the intervals, a removed one, a gap): each
//     refused with one line naming it;
//   * each kind of the absorption cover changed to every other kind, and a line's k moved: refused
//     (to end_point: refused unless the end point proves the same bound, a true statement);
//   * the work bounds: too many intervals, too long a number, too many digits: refused;
//   * the CLI: `coupling --band ... --certificate FILE`, then `check FILE` exits 0, a tampered file 1.
#include <catch2/catch.hpp>

#include <gyrores/app/band.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/model/inputs.hpp>

#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "band_checker.hpp"
#include "testing/cli_run.hpp"

using namespace gyrores;

namespace {

using checker_json = nlohmann::json;

// The certificate of the band [n1, n2] over [0, T] from the app's band run (both guarantees).
const checker_json& certificate(const std::string& n1, const std::string& n2, const std::string& T) {
  static std::map<std::string, checker_json> cache;
  const std::string key = n1 + ":" + n2 + "@" + T;
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  app::band_request q;
  q.n1 = parse_rational(n1, "n1");
  q.n2 = parse_rational(n2, "n2");
  q.horizon = horizon_time(parse_rational(T, "T"));
  q.digits = 6;
  q.certificate = true;
  const app::band_result r = app::run_band(q);
  REQUIRE(r.certificate);
  return cache[key] = checker_json::parse(certificate_text(*r.certificate));
}

gyrores_checker::verdict check(const checker_json& j) { return gyrores_checker::check_band_certificate(j.dump()); }

// A tampered copy must be refused (status 1 or 2) with a one-line message holding `why`.
void refused(const checker_json& j, const std::string& why, int status = 1) {
  const auto v = check(j);
  INFO(why << " -> " << v.message);
  CHECK(v.status == status);
  CHECK(v.message.find(why) != std::string::npos);
  CHECK(v.message.find('\n') == std::string::npos);
}

// The index of the interval with the largest (absorption) or smallest positive (containment) bound.
std::size_t extreme_interval(const checker_json& cover, bool absorption) {
  std::size_t best = 0;
  double v = absorption ? -1 : 1e300;
  for (std::size_t i = 0; i < cover.size(); ++i) {
    const double b = std::stod(cover[i]["bound"].get<std::string>());
    if (absorption ? b > v : (b > 0 && b < v)) v = b, best = i;
  }
  return best;
}

}  // namespace

TEST_CASE("band certificates of a few bands are accepted", "[band][certificate]") {
  struct band {
    std::string n1, n2, T;
  };
  const auto around2 = parse_tolerance_band(big_rational(2), "1%", "--tolerance");
  for (const band& b : {band{rational_str(around2.first), rational_str(around2.second), "10"},
                        band{rational_str(around2.first), rational_str(around2.second), "1000000"},
                        band{"343/1000", "357/1000", "1000000000000000000000000000000"}, band{"1/5", "101/500", "20"},
                        band{"2", "12/5", "4"}, band{"3/10", "3", "5"}, band{"38/5", "42/5", "3"}}) {
    const checker_json& j = certificate(b.n1, b.n2, b.T);
    const auto v = check(j);
    INFO(b.n1 << ":" << b.n2 << " T = " << b.T << ": " << v.message);
    CHECK(v.status == 0);
    CHECK(v.message.find("certificate holds (band-theorem/1)") != std::string::npos);
    CHECK(j["format"] == "gyrores-band-certificate/1");
    CHECK(!j["absorption"]["cover"].empty());
  }
  // The kinds these covers exercise, every one (line_turning needs x^2 > 1/2: n > 2, here 8 -+ 5% at T = 3).
  std::set<std::string> kinds;
  for (const band& b : {band{rational_str(around2.first), rational_str(around2.second), "1000000"}, band{"2", "12/5", "4"},
                        band{"3/10", "3", "5"}, band{"38/5", "42/5", "3"}})
    for (const std::string side : {"absorption", "containment"})
      for (const auto& J : certificate(b.n1, b.n2, b.T)[side]["cover"])
        kinds.insert(side + " " + J["kind"].get<std::string>() + (J["unreached"].get<bool>() ? " unreached" : "") +
                     (J["reached"].get<bool>() ? " reached" : ""));
  for (const std::string k : {"absorption lobes", "absorption lobes reached", "absorption line_falling", "absorption line_rising",
                              "absorption line_turning", "absorption line_unproved", "absorption end_point",
                              "containment lobes", "containment end_point unreached"}) {
    INFO(k);
    CHECK(kinds.count(k) == 1);
  }
  // The band holding x = 1/10 (n^2 = 4/99, a centre of lobe 5): containment exactly 0, attained there.
  const checker_json& z = certificate("1/5", "101/500", "20");
  CHECK(z["containment"]["value"][0] == "0");
  CHECK(z["containment"]["value"][1] == "0");
  CHECK(z["containment"]["at"]["n2"] == "4/99");
}

TEST_CASE("band certificates: the tamper catalogue", "[band][certificate]") {
  // A band whose covers hold several intervals of the kinds lobes and end_point, the containment
  // bounds positive.
  const checker_json& good = certificate("2", "12/5", "4");
  REQUIRE(check(good).status == 0);

  SECTION("every key removed") {
    for (const std::string key : {"format", "theorem", "n1", "n2", "horizon", "digits", "absorption", "containment"}) {
      checker_json j = good;
      j.erase(key);
      refused(j, "missing field '" + key + "'", 2);
    }
    for (const std::string side : {"absorption", "containment"})
      for (const std::string key : {"value", "at", "cover"}) {
        checker_json j = good;
        j[side].erase(key);
        const auto v = check(j);
        INFO(side << "." << key << ": " << v.message);
        CHECK(v.status != 0);
      }
    for (const std::string key : {"a", "b", "kind", "K", "k", "reached", "unreached", "bound"}) {
      checker_json j = good;
      j["absorption"]["cover"][0].erase(key);
      refused(j, "missing field '" + key + "'", 2);
    }
    checker_json j = good;
    j["absorption"]["cover"][0]["extra"] = "1";
    refused(j, "unknown field 'extra'", 2);
  }

  SECTION("the head fields") {
    struct tamper {
      const char* field;
      std::string value;
      const char* needle;
      int status;
    };
    for (const auto& t : {tamper{"format", "gyrores-band-certificate/2", "format is not", 2},
                          tamper{"theorem", "band-theorem/2", "theorem is not band-theorem/1", 1},
                          tamper{"n1", "197/100", "is not n1^2", 1},
                          tamper{"n2", "13/5", "is not n2^2", 1},
                          tamper{"horizon", "11", "its horizon is not the certificate's", 1},
                          tamper{"digits", "6", "digits must be an integer", 2},
                          tamper{"n1", good["n2"].get<std::string>(), "n1 < n2", 1}}) {
      checker_json j = good;
      j[t.field] = t.value;
      refused(j, t.needle, t.status);
    }
  }

  SECTION("the claims and the attaining couplings") {
    // One field of `good` forged, and what the verdict must say.
    using forgery = std::pair<const char*, std::function<void(checker_json&)>>;
    for (const auto& [why, forge] : std::vector<forgery>{
             {"above 2 hi", [](checker_json& j) { j["absorption"]["value"][1] = j["absorption"]["value"][0]; }},
             {"lo is above the attaining coupling's minimum",
              [](checker_json& j) { j["absorption"]["value"][0] = j["absorption"]["value"][1]; }},
             {"hi is below the attaining coupling's minimum",
              [](checker_json& j) { j["containment"]["value"][1] = j["containment"]["value"][0]; }},
             {"below 2 lo", [](checker_json& j) { j["containment"]["value"][0] = j["containment"]["value"][1]; }},
             {"0 <= lo <= hi", [](checker_json& j) { j["absorption"]["value"][0] = "1"; }},
             {"not in the band", [](checker_json& j) { j["absorption"]["at"]["n2"] = "100"; }},
             {"its horizon is not the certificate's",
              [](checker_json& j) { j["containment"]["at"]["horizon"] = "11"; }},
             {"absorption.at: FAILS", [](checker_json& j) { j["absorption"]["at"]["minimum"]["cut_lobe"] = "0"; }},
         }) {
      checker_json j = good;
      forge(j);
      refused(j, why);
    }
    checker_json j = good;
    j["absorption"]["at"] = j["containment"]["at"];
    CHECK(check(j).status != 0);
  }

  SECTION("every interval field, in both covers") {
    for (const std::string side : {"absorption", "containment"}) {
      const bool absorption = side == "absorption";
      const checker_json& cover = good[side]["cover"];
      REQUIRE(cover.size() >= 2);
      const std::size_t i = extreme_interval(cover, absorption);
      const std::string where = side + ".cover[" + std::to_string(i) + "]";
      const auto with = [&](const std::string& key, const checker_json& value) {
        checker_json j = good;
        j[side]["cover"][i][key] = value;
        return j;
      };
      const checker_json& J = cover[i];
      for (const std::string kind : {"lobes", "line_falling", "line_rising", "line_turning", "line_unproved", "end_point"})
        if (kind != J["kind"]) {
          const auto v = check(with("kind", kind));
          INFO(where << " kind " << kind << ": " << v.message);
          CHECK(v.status != 0);
        }
      refused(with("kind", "peak"), "not a known kind", 2);
      const long K = std::stol(J["K"].get<std::string>());
      refused(with("K", std::to_string(K + 1)), where + ": K is not");
      refused(with("K", std::to_string(K - 1)), where + ": K is not");
      refused(with("K", "x1"), "not an integer", 2);
      {
        const auto v = check(with("k", std::to_string(std::stol(J["k"].get<std::string>()) + 1)));
        INFO(where << " k + 1: " << v.message);
        CHECK(v.status == 1);
      }
      {
        const auto v = check(with("reached", !J["reached"].get<bool>()));
        INFO(where << " reached flipped: " << v.message);
        CHECK(v.status == 1);
      }
      {
        const auto v = check(with("unreached", !J["unreached"].get<bool>()));
        INFO(where << " unreached flipped: " << v.message);
        CHECK(v.status == 1);
      }
      // The bound on the unsafe side of the recomputed one (still on the claim's side).
      // (M <= R(0) = 1 everywhere: a containment bound 1 is false.)
      if (absorption) refused(with("bound", "0"), where + ": bound is below the recomputed upper bound");
      else {
        checker_json j = with("bound", "1");
        j[side]["value"][0] = "0";
        refused(j, where + ": bound is above the recomputed lower bound");
      }
      refused(with("bound", "-1"), where + ".bound must be >= 0");
      refused(with("bound", "1/2"), "bound", 2);
      // Ends: a gap, an overlap, the band's ends, the order.
      if (i > 0) refused(with("a", cover[i - 1]["a"]), "a gap or an overlap");
      if (i + 1 < cover.size()) refused(with("b", cover[i + 1]["b"]), "a gap or an overlap");
      refused(with("b", J["a"]), "a must be < b");
      checker_json j = good;
      j[side]["cover"].erase(j[side]["cover"].begin() + long(cover.size() / 2));
      if (cover.size() >= 3) refused(j, "a gap or an overlap");
      else CHECK(check(j).status == 1);
      j = good;
      j[side]["cover"].erase(j[side]["cover"].end() - 1);
      refused(j, "does not reach the band's end");
      j = good;
      j[side]["cover"].erase(j[side]["cover"].begin());
      refused(j, "does not start at the band's end");
      j = good;
      std::swap(j[side]["cover"][0], j[side]["cover"][1]);
      CHECK(check(j).status == 1);
    }
  }

  SECTION("wrong but self-consistent: every bound and the claim moved together") {
    // Absorption: every upper bound and hi scaled by 0.9 (each interval's bound then too low);
    // containment: every lower bound and lo scaled by 1.1 (too high). Only recomputation can tell.
    for (const std::string side : {"absorption", "containment"}) {
      const bool absorption = side == "absorption";
      checker_json j = good;
      const double f = absorption ? 0.9 : 1.1;
      for (auto& J : j[side]["cover"]) {
        char text[64];
        std::snprintf(text, sizeof text, "%.12e", std::stod(J["bound"].get<std::string>()) * f);
        J["bound"] = text;
      }
      if (absorption) j[side]["value"][1] = "1";  // any hi: the bounds' side holds
      else j[side]["value"][0] = "0";
      const auto v = check(j);
      INFO(side << ": " << v.message);
      CHECK(v.status == 1);
      CHECK(v.message.find(absorption ? "bound is below the recomputed upper bound" : "bound is above the recomputed lower bound") !=
            std::string::npos);
    }
  }

  SECTION("the work bounds") {
    checker_json j = good;
    checker_json& cover = j["absorption"]["cover"];
    while (cover.size() <= gyrores_checker::band_max_intervals) cover.push_back(cover[0]);
    refused(j, "work bound: absorption.cover has more than");
    j = good;
    j["digits"] = gyrores_checker::band_max_digits + 1;
    refused(j, "work bound: digits above");
    j = good;
    j["absorption"]["cover"][0]["K"] = std::string(gyrores_checker::band_max_field_chars + 1, '7');
    refused(j, "work bound: absorption.cover[0].K has more than");
    j = good;
    j["n1"] = std::string(gyrores_checker::band_max_field_chars, '1') + "/3";
    refused(j, "work bound: n1 has more than");
  }
}

TEST_CASE("band certificates: each kind tampered", "[band][certificate]") {
  // In three bands, the first absorption interval of each kind: its kind changed to every other
  // kind and (a line) its k moved by one; each refused.
  std::set<std::string> seen;
  for (const auto& [n1, n2, T] : {std::tuple<std::string, std::string, std::string>{"38/5", "42/5", "3"}, {"3/10", "3", "5"}, {"1", "3", "10"}}) {
    const checker_json& good = certificate(n1, n2, T);
    REQUIRE(check(good).status == 0);
    const checker_json& cover = good["absorption"]["cover"];
    for (std::size_t i = 0; i < cover.size(); ++i) {
      const std::string kind = cover[i]["kind"];
      if (!seen.insert(kind).second) continue;
      for (const std::string other : {"lobes", "line_falling", "line_rising", "line_turning", "line_unproved", "end_point"}) {
        if (other == kind) continue;
        checker_json j = good;
        j["absorption"]["cover"][i]["kind"] = other;
        const auto v = check(j);
        INFO(n1 << ":" << n2 << " " << kind << " -> " << other << ": " << v.message);
        // The end point proved on the checker's halved pieces can be tighter than the producer's
        // one mean-value form: a lobe bound it also proves is then a true statement of that kind.
        if (other == "end_point") CHECK(v.status != 2);
        else CHECK(v.status == 1);
      }
      if (kind.rfind("line_", 0) == 0)
        for (const long d : {-1L, 1L}) {
          checker_json j = good;
          j["absorption"]["cover"][i]["k"] = std::to_string(std::stol(cover[i]["k"].get<std::string>()) + d);
          const auto v = check(j);
          INFO(n1 << ":" << n2 << " " << kind << " k " << d << ": " << v.message);
          CHECK(v.status == 1);
        }
    }
  }
  for (const std::string kind : {"lobes", "line_falling", "line_rising", "line_turning", "line_unproved", "end_point"}) {
    INFO(kind);
    CHECK(seen.count(kind) == 1);
  }
}

TEST_CASE("band certificates: a bogus value in every field a kind leaves unused is refused", "[band][certificate]") {
  // Each case (the claim's side, the interval's kind and flags; the first interval of each in four
  // bands) leaves some fields unused: the line's k (0 unless a line kind), unreached in absorption,
  // reached in containment (false); `at.below` (null: the band reads only the minimum). A plausible
  // bogus value planted there must be refused, naming the interval and the field.
  const auto around2 = parse_tolerance_band(big_rational(2), "1%", "--tolerance");
  std::map<std::string, std::size_t> unused_of;  // case -> unused fields planted
  std::size_t planted = 0;
  for (const auto& [n1, n2, T] : {std::tuple<std::string, std::string, std::string>{rational_str(around2.first), rational_str(around2.second), "1000000"},
                                  {"2", "12/5", "4"}, {"3/10", "3", "5"}, {"38/5", "42/5", "3"}}) {
    const checker_json& good = certificate(n1, n2, T);
    REQUIRE(check(good).status == 0);
    for (const std::string side : {"absorption", "containment"}) {
      const bool absorption = side == "absorption";
      // at.below: a true statement (E = 1/2 is reached at t = 0 by every coupling), but unused.
      checker_json j = good;
      j[side]["at"]["below"] = checker_json{{"level", "1/2"}, {"case", "start"}, {"lobe", nullptr}, {"level_root", nullptr},
                                            {"delta", nullptr}, {"root", nullptr}, {"crossing", nullptr}, {"t_below", {"0", "0"}}};
      refused(j, side + ".at.below must be null", 2);
      unused_of[side + " at"] = 1;
      const checker_json& cover = good[side]["cover"];
      for (std::size_t i = 0; i < cover.size(); ++i) {
        const checker_json& J = cover[i];
        const std::string kind = J["kind"].get<std::string>(), name = side + " " + kind + (J["reached"].get<bool>() ? " reached" : "") +
                                                                   (J["unreached"].get<bool>() ? " unreached" : "");
        if (unused_of.count(name)) continue;
        std::vector<std::pair<std::string, checker_json>> plants;
        const bool line = kind.rfind("line_", 0) == 0;
        CHECK(J["k"] == (line ? J["k"] : checker_json("0")));  // the producer writes the unused k as 0
        if (!line) plants.push_back({"k", "1"}), plants.push_back({"k", J["K"].get<std::string>() == "0" ? "2" : J["K"]});
        if (absorption) plants.push_back({"unreached", true});
        else plants.push_back({"reached", true});
        const std::string where = side + ".cover[" + std::to_string(i) + "]";
        std::set<std::string> fields;
        for (const auto& [key, value] : plants) {
          checker_json t = good;
          t[side]["cover"][i][key] = value;
          const auto v = check(t);
          INFO(name << ": " << where << "." << key << " = " << value.dump() << " -> " << v.message);
          CHECK(v.status == 1);
          CHECK(v.message.find(where + ": " + key + " must be") != std::string::npos);
          fields.insert(key);
        }
        unused_of[name] = fields.size();
      }
    }
  }
  for (const auto& [name, n] : unused_of) planted += n;
  WARN("band certificate unused-field pass: " << planted << " fields over " << unused_of.size() << " cases");
  // The nine cases of the kinds test above, and at.below on both sides.
  CHECK(unused_of.size() == 9 + 2);
  CHECK(planted == 2 + 2 + 4 + 2 + 2 + 2 + 2);
}

TEST_CASE("gyrores coupling --band --certificate, then gyrores check", "[cli][band][certificate]") {
  if (!test::cli_available()) return;
  test::temp_dir dir("band_certificate");
  const std::string file = dir / "band.json", bad = dir / "bad.json", pi = dir / "pi.json";
  auto r = test::cli_run("coupling 2 --tolerance 1% --horizon 10 --certificate " + file);
  REQUIRE(r.status == 0);
  r = test::cli_run("check " + file);
  CHECK(r.status == 0);
  CHECK(r.out.find("certificate holds (band-theorem/1)") != std::string::npos);
  std::ifstream in(file);
  checker_json j = checker_json::parse(in);
  j["absorption"]["cover"][0]["K"] = "12345";
  std::ofstream(bad) << j.dump();
  r = test::cli_run("check " + bad);
  CHECK(r.status == 1);
  CHECK(r.err.find("K is not") != std::string::npos);
  // A horizon in multiples of pi is refused before the work, and no file is written.
  r = test::cli_run("coupling --band 1.98:2.02 --horizon 10pi --certificate " + pi);
  CHECK(r.status != 0);
  CHECK(r.err.find("multiple of pi") != std::string::npos);
  CHECK(!std::ifstream(pi).good());
  // A path that cannot be written is refused before the work too.
  r = test::cli_run("coupling --band 1.98:2.02 --horizon 10 --certificate " + (dir / "no/such/dir/x.json"));
  CHECK(r.status == 2);
  CHECK(r.out.empty());
}
