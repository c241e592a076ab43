// Coupling certificates ("gyrores-coupling-certificate/1", certify/horizon_certificate.hpp) and
// their independent checker (src/checker/horizon_checker.hpp):
//   * random couplings (n as decimals, n^2 as fractions, resonant and not) and horizons from
//     T < 1 to 10^100: every certificate is accepted, and its lobe is the plain loop's smallest
//     argmin of ||k x - 1/2|| over the admissible lobes (an oracle independent of both the
//     producer's and the checker's O(log K) recursions) whenever K_T is small;
//   * the tamper catalogue: every field changed in turn, each refused with one line naming it;
//   * wrong but self-consistent: a genuine other lobe (with its own true j, side and bracket), a
//     tie of a resonant coupling's mirror lobes (same h_min) that is not the first: refused.
#include <catch2/catch.hpp>

#include <gyrores/app/coupling.hpp>
#include <gyrores/certify/horizon_certificate.hpp>
#include <gyrores/core/decimal.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/model/rotation.hpp>

#include <functional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "horizon_checker.hpp"

using namespace gyrores;

namespace {

gyrores_checker::verdict check(const json& j) { return gyrores_checker::check_coupling_certificate(json_dump(j)); }

// The entry of one lobe k >= 0 as horizon_certificate_of writes a lobe (its j, side and root
// bracket; theorem/horizon.hpp, certified_lobe_root), for the tests that build a wrong lobe on purpose.
certificate_lobe certificate_lobe_of(const coupling_spec& c, const big_int& k, unsigned digits) {
  const lobe_root r = certified_lobe_root(c, k, digits);
  return {k, (coupling_rotation_number(c) * quadratic_number(k)).floor(), k == 0 ? 1 : r.lobe.side,
          r.bracket.ends.is_exact() ? decimal_bracket{"0", "0"} : r.bracket.ends.outward(certificate_digits(digits))};
}

json certificate_json(const coupling_spec& c, const big_rational& T, unsigned digits) {
  return certificate_to_json(certify_horizon_minimum(c, T, digits));
}

// The certificate file of min H_q over [0, T] and, with a level, the first time below it.
std::string certificate_text(const coupling_spec& c, const big_rational& T, const std::optional<big_rational>& level,
                             unsigned digits) {
  horizon_certificate cert = certify_horizon_minimum(c, T, digits);
  if (level) cert.below = below_certificate_of(c, prove_first_below(c, *level, {digits, {}}, proof_use::certificate), digits);
  return gyrores::certificate_text(cert);
}

// The plain loop: the smallest argmin of ||k x - 1/2|| over 0 <= k <= K (exact comparisons).
big_int loop_argmin(const quadratic_number& x, const big_int& K) {
  big_int best = 0;
  quadratic_number v = distance_to_half(x, 0);
  for (big_int k = 1; k <= K; ++k) {
    const quadratic_number w = distance_to_half(x, k);
    if (w < v) {
      v = w;
      best = k;
    }
  }
  return best;
}

struct case_spec {
  std::string name;
  coupling_spec c;
  big_rational T;
};

std::vector<case_spec> cases() {
  std::vector<case_spec> out;
  auto dec = [](const std::string& s) { return parse_rational(s, "n"); };
  // Named: resonant (n^2 = 1/12: (4,3), x = 1/7; n = 3/2: W1/W2 = 4; n^2 = 4/99: (11,9), degenerate),
  // not resonant (n = 2, 0.1832, 0.001, 30), horizons inside lobe 0 and cut lobes.
  for (const auto& [n2, T] : std::vector<std::pair<std::string, std::string>>{
           {"1/12", "2.5"}, {"1/12", "40"}, {"4/99", "200"}, {"4/99", "0.3"}, {"9/4", "7"}, {"9/4", "1e30"}})
    out.push_back({"n^2 = " + n2 + ", T = " + T, coupling_spec::from_n2(dec(n2)), dec(T)});
  for (const auto& [n, T] : std::vector<std::pair<std::string, std::string>>{
           {"2", "0.5"}, {"2", "37"}, {"2", "1e100"}, {"0.1832", "1000"}, {"0.001", "5000"}, {"30", "12.75"},
           {"0.2886751345948", "1e12"}})
    out.push_back({"n = " + n + ", T = " + T, coupling_spec::from_n(dec(n)), dec(T)});
  std::mt19937_64 rng(20261125);
  for (int i = 0; i < 24; ++i) {
    const big_rational T = big_rational(long(rng() % 100000) + 1, long(rng() % 997) + 1);
    if (i % 2 == 0) {
      const big_rational n2(long(rng() % 5000) + 1, long(rng() % 500) + 1);
      out.push_back({"random n^2 = " + rational_str(n2) + ", T = " + rational_str(T), coupling_spec::from_n2(n2), T});
    } else {
      const big_rational n(long(rng() % 30000) + 1, 1000);
      out.push_back({"random n = " + rational_str(n) + ", T = " + rational_str(T), coupling_spec::from_n(n), T});
    }
  }
  return out;
}

}  // namespace

TEST_CASE("coupling certificates of random couplings and horizons are accepted", "[certificate][horizon]") {
  for (const auto& k : cases()) {
    INFO(k.name);
    const horizon_certificate cert = certify_horizon_minimum(k.c, k.T, 20);
    const auto v = check(certificate_to_json(cert));
    INFO(v.message);
    CHECK(v.status == 0);
    // The lobe against the plain loop over k (independent of both recursions).
    const big_int K_T = cert.cut_lobe_reached ? cert.cut_lobe : big_int(cert.cut_lobe - 1);
    CHECK(cert.lobe.has_value() == (K_T >= 0));
    if (cert.lobe && K_T <= 20000) CHECK(cert.lobe->k == loop_argmin(coupling_rotation_number(k.c), K_T));
  }
}

TEST_CASE("the certificate text for the CLI; T <= 0 is refused", "[certificate][horizon]") {
  const auto c = coupling_spec::from_n(parse_rational("2", "n"));
  const std::string text = certificate_text(c, parse_rational("37", "T"), std::nullopt, 15);
  CHECK(text.back() == '\n');
  CHECK(gyrores_checker::check_coupling_certificate(text).status == 0);
  const std::string with_level = certificate_text(c, 37, big_rational(1, 100), 15);
  CHECK(gyrores_checker::check_coupling_certificate(with_level).status == 0);
  CHECK(with_level.find("\"case\": \"lobe\"") != std::string::npos);
  CHECK_THROWS_AS(certify_horizon_minimum(c, 0, 15), usage_error);
}

TEST_CASE("the coupling request certifies the proofs its report rounded", "[certificate][horizon]") {
  // One computation (app/coupling.hpp): the certificate's claims are the report's enclosures,
  // rounded outward, and the checker accepts them; for a lobe and for the horizon's end.
  for (const auto& [n, T] : std::vector<std::pair<std::string, std::string>>{{"2", "37"}, {"2", "2.2"}, {"0.31", "1e20"}}) {
    app::coupling_request request;
    request.spec = coupling_spec::from_n(parse_rational(n, "n"));
    request.options.horizon = horizon_time(parse_rational(T, "T"));
    request.options.below = big_rational(1, 1000000);
    request.options.digits = 15;
    request.options.convergents = 0;
    request.certificate = true;
    const app::coupling_result r = app::run_coupling(request);
    INFO("n = " << n << ", T = " << T);
    REQUIRE(r.certificate);
    CHECK(gyrores_checker::check_coupling_certificate(gyrores::certificate_text(*r.certificate)).status == 0);
    CHECK(r.certificate->h_min == r.report.horizon.h_min.enclosure);
    CHECK(r.certificate->t_min == r.report.horizon.t_min.enclosure);
    CHECK(r.certificate->below->t_below == r.report.below->t_below.enclosure);
    CHECK(r.certificate->cut_lobe == r.report.horizon.proof.cut_lobe);
    CHECK(r.certificate->at_horizon_end == r.report.horizon.proof.at_horizon_end);
    // The report without a certificate prints the same digits.
    request.certificate = false;
    const app::coupling_result plain = app::run_coupling(request);
    CHECK(plain.report.horizon.h_min.value == r.report.horizon.h_min.value);
    CHECK(plain.report.below->t_below.value == r.report.below->t_below.value);
  }
}

TEST_CASE("a certificate is written only from a proof made for it, at its digits", "[certificate][horizon]") {
  const auto c = coupling_spec::from_n(big_rational(2));
  const horizon_time T(big_rational(37));
  const auto for_report = prove_horizon_minimum(c, T, {20, {}}, proof_use::report);
  CHECK_THROWS_AS(horizon_certificate_of(c, for_report, 20), compute_error);  // its decimals are not proved
  const auto for_certificate = prove_horizon_minimum(c, T, {12, {}}, proof_use::certificate);
  CHECK_THROWS_AS(horizon_certificate_of(c, for_certificate, 20), compute_error);  // made for 12 digits
  CHECK(gyrores_checker::check_coupling_certificate(gyrores::certificate_text(horizon_certificate_of(c, for_certificate, 12)))
            .status == 0);
}

TEST_CASE("certificates the format cannot state are refused, before any work or at once", "[certificate][horizon]") {
  app::coupling_request request;
  request.spec = coupling_spec::from_n(big_rational(2));
  request.certificate = true;
  request.options.horizon = horizon_time(big_rational(100), true);  // 100 pi: the report accepts it
  CHECK_THROWS_WITH(app::run_coupling(request), Catch::Contains("multiple of pi"));
  request.options.horizon = horizon_time(big_rational(0));
  CHECK_THROWS_AS(app::run_coupling(request), usage_error);
  // A coupling so small that its lobe roots lie within 10^-27 of pi/2: the report answers, the
  // certificate is refused at once (compute_error naming why), not after a long refinement.
  request.spec = coupling_spec::from_n(parse_rational("1e-20", "n"));
  request.options.horizon = horizon_time(big_rational(100));
  request.options.convergents = 0;
  CHECK_THROWS_WITH(app::run_coupling(request), Catch::Contains("pi/2"));
  request.certificate = false;
  CHECK_NOTHROW(app::run_coupling(request));
  // x = 1 - 2 10^-30: near delta the lobes' ||k x - 1/2|| lie 2 10^-30 apart, closer than a unit
  // of delta's 27th digit, so no decimal of delta decides the first lobe below E = 10^-40.
  request.spec = coupling_spec::from_n(parse_rational("1e15", "n"));
  request.options.horizon = horizon_time(big_rational(1000));
  request.options.below = parse_rational("1e-40", "E");
  CHECK_NOTHROW(app::run_coupling(request));
  request.certificate = true;
  CHECK_THROWS_WITH(app::run_coupling(request), Catch::Contains("delta"));
}

namespace {

using tamper = std::function<void(json&)>;

std::string plus_one(const json& v) { return (big_int(v.get<std::string>()) + 1).str(); }

// One end of a bracket replaced by the other end moved by 10^-6 across it (lo above hi, or hi
// below lo): the bracket is then reversed, or no longer holds its value.
void swap_in(json& bracket, int end) {
  const big_rational other = parse_rational(bracket[1 - end].get<std::string>(), "end");
  const big_rational step = other == 0 ? big_rational(1, 1000000) : abs(other) / 1000000;
  const big_rational moved = end == 0 ? big_rational(other + step) : big_rational(other - step);
  bracket[end] = format_rational_scientific(moved, 30);
}

// Every field of the certificate, changed in turn, with the word the refusal must name.
std::vector<std::tuple<std::string, std::string, tamper>> catalogue(const json& cert) {
  std::vector<std::tuple<std::string, std::string, tamper>> t;
  auto add = [&](std::string what, std::string names, tamper f) { t.emplace_back(std::move(what), std::move(names), std::move(f)); };
  add("format", "format", [](json& j) { j["format"] = "gyrores-coupling-certificate/2"; });
  add("theorem", "theorem", [](json& j) { j["theorem"] = "horizon-theorem/2"; });
  add("n2 numerator + 1", "", [](json& j) {
    const big_rational n2 = parse_rational(j["n2"].get<std::string>(), "n2") * big_rational(1000001, 1000000);
    j["n2"] = rational_str(n2);
  });
  add("horizon x 2", "", [](json& j) {
    j["horizon"] = rational_str(parse_rational(j["horizon"].get<std::string>(), "T") * 2);
  });
  add("horizon not a rational", "horizon", [](json& j) { j["horizon"] = "1e5"; });
  add("digits + 8", "wider", [](json& j) { j["digits"] = j["digits"].get<int>() + 8; });
  add("cut_lobe + 1", "cut_lobe", [](json& j) { j["minimum"]["cut_lobe"] = plus_one(j["minimum"]["cut_lobe"]); });
  add("cut_lobe_reached flipped", "cut_lobe_reached",
      [](json& j) { j["minimum"]["cut_lobe_reached"] = !j["minimum"]["cut_lobe_reached"].get<bool>(); });
  add("cut_root[0] = cut_root[1]", "cut_root", [](json& j) { swap_in(j["minimum"]["cut_root"], 0); });
  add("cut_root[1] = cut_root[0]", "cut_root", [](json& j) { swap_in(j["minimum"]["cut_root"], 1); });
  add("at_horizon_end flipped", "at_horizon_end",
      [](json& j) { j["minimum"]["at_horizon_end"] = !j["minimum"]["at_horizon_end"].get<bool>(); });
  add("h_min[0] = h_min[1]", "h_min", [](json& j) { swap_in(j["minimum"]["h_min"], 0); });
  add("h_min[1] = h_min[0]", "h_min", [](json& j) { swap_in(j["minimum"]["h_min"], 1); });
  add("t_min[0] = t_min[1]", "t_min", [](json& j) { swap_in(j["minimum"]["t_min"], 0); });
  add("t_min[1] = t_min[0]", "t_min", [](json& j) { swap_in(j["minimum"]["t_min"], 1); });
  add("unknown field", "unknown field", [](json& j) { j["minimum"]["note"] = "x"; });
  add("missing field", "missing field", [](json& j) { j.erase("digits"); });
  if (!cert["minimum"]["lobe"].is_null()) {
    add("lobe.k + 1", "lobe.k", [](json& j) { j["minimum"]["lobe"]["k"] = plus_one(j["minimum"]["lobe"]["k"]); });
    add("lobe.j + 1", "lobe.j", [](json& j) { j["minimum"]["lobe"]["j"] = plus_one(j["minimum"]["lobe"]["j"]); });
    add("lobe.side changed", "lobe.side",
        [](json& j) { j["minimum"]["lobe"]["side"] = j["minimum"]["lobe"]["side"].get<int>() == 1 ? -1 : 1; });
    add("lobe null", "lobe", [](json& j) { j["minimum"]["lobe"] = nullptr; j["minimum"]["root"] = nullptr; });
    add("root[0] = root[1]", "root", [](json& j) { swap_in(j["minimum"]["root"], 0); });
    add("root[1] = root[0]", "root", [](json& j) { swap_in(j["minimum"]["root"], 1); });
    add("root moved above u0", "root", [](json& j) {
      const std::string hi = j["minimum"]["root"][1].get<std::string>();
      j["minimum"]["root"] = json::array({hi, format_rational_scientific(parse_rational(hi, "u") * 2, 40)});
    });
  } else {
    add("a lobe where none is admissible", "lobe", [](json& j) {
      j["minimum"]["lobe"] = json{{"k", "0"}, {"j", "0"}, {"side", 1}};
      j["minimum"]["root"] = j["minimum"]["cut_root"];
    });
  }
  return t;
}

}  // namespace

TEST_CASE("the tamper catalogue: every field changed is refused with one line naming it", "[certificate][horizon]") {
  // A lobe minimum (n = 2, T = 37), the end point (the cut lobe not reached, R(T) lower), no
  // admissible lobe (T inside lobe 0's descent), a resonant coupling, a huge horizon.
  for (const auto& [n2, T] : std::vector<std::pair<std::string, std::string>>{
           {"4", "37"}, {"4", "2.2"}, {"4", "0.5"}, {"1/12", "40"}, {"9/4", "1e30"}}) {
    const json cert = certificate_json(coupling_spec::from_n2(parse_rational(n2, "n2")), parse_rational(T, "T"), 20);
    INFO("n^2 = " << n2 << ", T = " << T << ", end " << cert["minimum"]["at_horizon_end"]);
    REQUIRE(check(cert).status == 0);
    for (const auto& [what, names, change] : catalogue(cert)) {
      json j = cert;
      change(j);
      const auto v = check(j);
      INFO(what << ": " << v.message);
      CHECK(v.status != 0);
      CHECK(v.message.find('\n') == std::string::npos);
      // Changing the coupling or the horizon makes some derived field false; the others are named.
      if (!names.empty()) CHECK(v.message.find(names) != std::string::npos);
    }
  }
}

TEST_CASE("wrong but self-consistent claims are refused", "[certificate][horizon]") {
  SECTION("a genuine lobe that is not the minimum") {
    const auto c = coupling_spec::from_n2(4);
    json cert = certificate_json(c, 37, 20);
    const big_int k = big_int(cert["minimum"]["lobe"]["k"].get<std::string>());
    const certificate_lobe other = certificate_lobe_of(c, k == 1 ? big_int(2) : big_int(1), 20);
    cert["minimum"]["lobe"] = json{{"k", other.k.str()}, {"j", other.j.str()}, {"side", other.side}};
    cert["minimum"]["root"] = json::array({other.root.first, other.root.second});
    const auto v = check(cert);
    INFO(v.message);
    CHECK(v.status == 1);
    CHECK(v.message.find("lobe.k") != std::string::npos);
  }
  SECTION("a resonant coupling's later tie (the same h_min, a later lobe)") {
    // n^2 = 1/12: x = 1/7, nu_k depends on k mod 7 and nu_k = nu_{7-k}: lobes k and 7 - k tie.
    const auto c = coupling_spec::from_n2(big_rational(1, 12));
    json cert = certificate_json(c, 60, 20);
    const big_int k = big_int(cert["minimum"]["lobe"]["k"].get<std::string>());
    const quadratic_number x = coupling_rotation_number(c);
    big_int later = -1;
    for (big_int m = k + 1; m <= k + 7; ++m)
      if (distance_to_half(x, m) == distance_to_half(x, k)) later = m;
    REQUIRE(later > k);
    const certificate_lobe other = certificate_lobe_of(c, later, 20);
    CHECK(other.root == certificate_lobe_of(c, k, 20).root);  // the same value: only the index lies
    cert["minimum"]["lobe"] = json{{"k", other.k.str()}, {"j", other.j.str()}, {"side", other.side}};
    const auto v = check(cert);
    INFO(v.message);
    CHECK(v.status == 1);
    CHECK(v.message.find("lobe.k") != std::string::npos);
  }
}

namespace {

struct below_case {
  std::string n2, E;
};

// Levels in every case: t = 0 (2E >= 1), lobe 0 (V(1/2) <= 2E < 1), a later lobe, E = 0 on a
// degenerate pair (zero) and on others (never), a resonant coupling whose H_min exceeds E (never).
std::vector<below_case> below_cases() {
  std::vector<below_case> out{{"4", "1/2"},      {"4", "0.3"},       {"4", "1/100"},     {"4", "1e-6"},
                              {"4/99", "0"},     {"1/12", "0"},      {"4", "0"},         {"1/12", "1e-6"},
                              {"1/12", "0.01"},  {"9/4", "0.001"},   {"0.000001", "0.1"}, {"900", "0.001"},
                              {"1/3", "1e-30"},  {"4/99", "1e-9"}};
  std::mt19937_64 rng(23);
  for (int i = 0; i < 16; ++i)
    out.push_back({rational_str(big_rational(long(rng() % 9000) + 1, long(rng() % 900) + 1)),
                   rational_str(big_rational(1, long(rng() % 100000) + 3))});
  return out;
}

json below_json(const std::string& n2, const std::string& E, unsigned digits) {
  const auto c = coupling_spec::from_n2(parse_rational(n2, "n2"));
  return json::parse(certificate_text(c, 10, parse_rational(E, "E"), digits));
}

}  // namespace

TEST_CASE("first time below a level: certificates in every case are accepted", "[certificate][horizon]") {
  for (const auto& b : below_cases()) {
    const json j = below_json(b.n2, b.E, 20);
    const auto v = check(j);
    INFO("n^2 = " << b.n2 << ", E = " << b.E << ": " << json_dump(j["below"], -1) << "\n" << v.message);
    CHECK(v.status == 0);
  }
}


TEST_CASE("first time below a level: every field tampered is refused, naming it", "[certificate][horizon]") {
  // A later lobe (n = 2, E = 10^-6: lobe 12), lobe 0 (E = 0.3), never (n^2 = 1/12, E = 10^-6),
  // zero (n^2 = 4/99, E = 0), start (E = 1/2).
  for (const auto& [n2, E] : std::vector<std::pair<std::string, std::string>>{
           {"4", "1e-6"}, {"4", "0.3"}, {"1/12", "1e-6"}, {"4/99", "0"}, {"4", "1/2"}, {"9/4", "0.001"}}) {
    const json cert = below_json(n2, E, 20);
    REQUIRE(check(cert).status == 0);
    const json& b = cert["below"];
    std::vector<std::tuple<std::string, std::string, tamper>> t;
    auto add = [&](std::string what, std::string names, tamper f) { t.emplace_back(std::move(what), std::move(names), std::move(f)); };
    add("level / 2", "", [](json& j) {
      const big_rational level = parse_rational(j["below"]["level"].get<std::string>(), "E");
      j["below"]["level"] = rational_str(level == 0 ? big_rational(1, 1000) : level / 2);
    });
    // Another case: its own checks, or a field the new case leaves unused, named with the case.
    add("case changed", "case",
        [](json& j) { j["below"]["case"] = j["below"]["case"] == "never" ? "lobe" : "never"; });
    add("case unknown", "below.case", [](json& j) { j["below"]["case"] = "sometimes"; });
    if (!b["lobe"].is_null()) {
      add("below.lobe.k + 1", "below.lobe", [](json& j) { j["below"]["lobe"]["k"] = plus_one(j["below"]["lobe"]["k"]); });
      add("below.lobe.j + 1", "below.lobe.j", [](json& j) { j["below"]["lobe"]["j"] = plus_one(j["below"]["lobe"]["j"]); });
      add("below.lobe.side changed", "below.lobe.side",
          [](json& j) { j["below"]["lobe"]["side"] = j["below"]["lobe"]["side"].get<int>() == 1 ? -1 : 1; });
    }
    for (const std::string f : {"level_root", "delta", "root", "crossing", "t_below"}) {
      if (b[f].is_null()) continue;
      const std::string name = "below." + f;
      if (b[f][0] == b[f][1]) {  // an exact value (t = 0): any other is refused
        add(name + " moved", name, [f](json& j) { j["below"][f] = json::array({"1e-3", "1e-3"}); });
        continue;
      }
      add(name + "[0] above [1]", name, [f](json& j) { swap_in(j["below"][f], 0); });
      add(name + "[1] below [0]", name, [f](json& j) { swap_in(j["below"][f], 1); });
      add(name + " null", name, [f](json& j) { j["below"][f] = nullptr; });
    }
    for (const auto& [what, names, change] : t) {
      json j = cert;
      change(j);
      const auto v = check(j);
      INFO("n^2 = " << n2 << ", E = " << E << ", " << what << ": " << v.message);
      CHECK(v.status != 0);
      CHECK(v.message.find('\n') == std::string::npos);
      if (!names.empty()) CHECK(v.message.find(names) != std::string::npos);
    }
  }
}

TEST_CASE("first time below a level: a later lobe that also reaches E is refused", "[certificate][horizon]") {
  // n = 2, E = 10^-6: lobe 12 is the first; a later lobe with nu_k <= delta exists (irrational x).
  const auto c = coupling_spec::from_n2(4);
  json cert = below_json("4", "1e-6", 20);
  const big_int first(cert["below"]["lobe"]["k"].get<std::string>());
  const big_rational d_lo = parse_rational(cert["below"]["delta"][0].get<std::string>(), "delta");
  const quadratic_number x = coupling_rotation_number(c);
  big_int later = first + 1;
  while (!(distance_to_half(x, later) <= quadratic_number(d_lo))) ++later;
  const certificate_lobe other = certificate_lobe_of(c, later, 20);
  cert["below"]["lobe"] = json{{"k", other.k.str()}, {"j", other.j.str()}, {"side", other.side}};
  cert["below"]["root"] = json::array({other.root.first, other.root.second});
  const auto v = check(cert);
  INFO("later lobe " << later << ": " << v.message);
  CHECK(v.status == 1);
  CHECK(v.message.find("below.lobe.k") != std::string::npos);
}

namespace {

// ---- Every field of every case (issue 36): for each case of the format, each of its fields
// changed in turn. A field the case leaves unused (null, docs/formats.md) gets plausible bogus
// values planted (the issue's ["4.5", "4.6"], a genuine bracket or lobe copied from elsewhere in
// the certificate); a used field is moved off its true value; integers get values that would wrap
// a machine integer. Each tamper must be refused, and a planted unused field named.
struct format_case {
  std::string name;
  json cert;
  std::set<std::string> unused;  // "minimum.lobe", "below.t_below", ...: null in this case
};

std::vector<format_case> format_cases() {
  const auto minimum = [](const std::string& n2, const std::string& T) {
    return certificate_json(coupling_spec::from_n2(parse_rational(n2, "n2")), parse_rational(T, "T"), 20);
  };
  return {
      {"minimum in a lobe (n^2 = 4, T = 37)", minimum("4", "37"), {}},
      {"minimum at the end, a lobe admissible (n^2 = 4, T = 2.2)", minimum("4", "2.2"), {}},
      {"minimum at the end, no lobe admissible (n^2 = 4, T = 0.5)", minimum("4", "0.5"), {"minimum.lobe", "minimum.root"}},
      {"below start (n^2 = 4, E = 1/2)", below_json("4", "1/2", 20),
       {"below.lobe", "below.level_root", "below.delta", "below.root", "below.crossing"}},
      {"below zero (n^2 = 4/99, E = 0)", below_json("4/99", "0", 20),
       {"below.level_root", "below.delta", "below.root", "below.crossing"}},
      {"below never, E = 0 (n^2 = 4)", below_json("4", "0", 20),
       {"below.lobe", "below.level_root", "below.delta", "below.root", "below.crossing", "below.t_below"}},
      {"below never, E > 0 (n^2 = 1/30, E = 1e-4)", below_json("1/30", "1e-4", 20),
       {"below.lobe", "below.root", "below.crossing", "below.t_below"}},
      {"below lobe 0 (n^2 = 4, E = 0.3)", below_json("4", "0.3", 20), {"below.level_root", "below.delta"}},
      {"below crossing in lobe k >= 1 (n^2 = 4, E = 1e-6)", below_json("4", "1e-6", 20), {}},
  };
}

// A decimal end moved off its value: v -> 1.01 v + 10^-3 (an exact 0 becomes 10^-3).
json moved(const json& bracket) {
  json out = json::array();
  for (const auto& end : bracket)
    out.push_back(format_rational_scientific(parse_rational(end.get<std::string>(), "end") * big_rational(101, 100) +
                                                 big_rational(1, 1000), 30));
  return out;
}

// The tampers of one field of `cert`, each a replacement of the field's value.
std::vector<std::pair<std::string, json>> tampers(const json& cert, const std::string& section, const std::string& key) {
  const json& v = section.empty() ? cert[key] : cert[section][key];
  const std::string wrap = "18446744073709551615";  // 2^64 - 1: -1 in a 64-bit signed integer
  std::vector<std::pair<std::string, json>> t;
  if (v.is_null()) {  // unused: plausible bogus values
    if (key == "lobe") {
      const json& genuine = cert["minimum"]["lobe"];
      t.push_back({"a genuine-looking lobe", genuine.is_null() ? json{{"k", "1"}, {"j", "0"}, {"side", 1}} : genuine});
      t.push_back({"lobe 0", json{{"k", "0"}, {"j", "0"}, {"side", 1}}});
    } else {
      t.push_back({"[\"4.5\", \"4.6\"]", json::array({"4.5", "4.6"})});
      t.push_back({"a genuine bracket (cut_root)", cert["minimum"]["cut_root"]});
      t.push_back({"[\"0\", \"0\"]", json::array({"0", "0"})});
    }
    return t;
  }
  if (v.is_boolean()) t.push_back({"flipped", !v.get<bool>()});
  else if (v.is_number()) {
    t.push_back({"+ 8", v.get<long>() + 8});
    t.push_back({"2^64 - 1", json::parse(wrap)});
    t.push_back({"-1", -1});
  } else if (v.is_array()) t.push_back({"moved", moved(v)});
  else if (v.is_object()) {  // a lobe
    for (const std::string f : {"k", "j"}) {
      json l = v;
      l[f] = (big_int(v[f].get<std::string>()) + 1).str();
      t.push_back({f + " + 1", l});
      l[f] = "-1";
      t.push_back({f + " = -1", l});
      l[f] = wrap;
      t.push_back({f + " = 2^64 - 1", l});
    }
    for (const json side : {json(v["side"].get<int>() == 1 ? -1 : 1), json::parse(wrap), json(2), json(-2)}) {
      json l = v;
      l["side"] = side;
      t.push_back({"side " + side.dump(), l});
    }
  } else if (key == "format") t.push_back({"another format", "gyrores-coupling-certificate/2"});
  else if (key == "theorem") t.push_back({"another theorem", "horizon-theorem/2"});
  else if (key == "case") {
    for (const std::string k : {"start", "zero", "never", "lobe"})
      if (k != v.get<std::string>()) t.push_back({"case " + k, k});
  } else if (key == "cut_lobe") {
    t.push_back({"+ 1", plus_one(v)});
    t.push_back({"-1", "-1"});
  } else {  // the rationals n2, horizon, level (a level raised from 1/2 would still be case start)
    const big_rational q = parse_rational(v.get<std::string>(), key);
    if (key == "n2") t.push_back({"x 1.000001", rational_str(q * big_rational(1000001, 1000000))});
    if (key == "horizon") t.push_back({"x 2", rational_str(q * 2)});
    t.push_back({"/ 2", rational_str(q == 0 ? big_rational(1, 1000) : q / 2)});
  }
  return t;
}

}  // namespace

TEST_CASE("every field of every case, changed or planted where unused, is refused", "[certificate][horizon]") {
  std::size_t fields = 0, unused = 0, checks = 0;
  const std::vector<std::string> top{"format", "theorem", "n2", "horizon", "digits"},
      minimum{"cut_lobe", "cut_lobe_reached", "cut_root", "lobe", "root", "at_horizon_end", "h_min", "t_min"},
      below{"level", "case", "lobe", "level_root", "delta", "root", "crossing", "t_below"};
  const auto cases = format_cases();
  for (const auto& fc : cases) {
    INFO(fc.name);
    REQUIRE(check(fc.cert).status == 0);
    std::vector<std::pair<std::string, std::string>> keys;  // (section, key)
    for (const auto& k : top) keys.push_back({"", k});
    for (const auto& k : minimum) keys.push_back({"minimum", k});
    if (!fc.cert["below"].is_null())
      for (const auto& k : below) keys.push_back({"below", k});
    for (const auto& [section, key] : keys) {
      const std::string path = section.empty() ? key : section + "." + key;
      const json& genuine = section.empty() ? fc.cert[key] : fc.cert[section][key];
      // The producer writes null exactly in the fields this case leaves unused (docs/formats.md).
      INFO(path);
      CHECK(genuine.is_null() == (fc.unused.count(path) == 1));
      ++fields;
      unused += genuine.is_null();
      for (const auto& [what, value] : tampers(fc.cert, section, key)) {
        json j = fc.cert;
        (section.empty() ? j[key] : j[section][key]) = value;
        const auto v = check(j);
        INFO(path << " " << what << ": " << v.message);
        CHECK(v.status != 0);
        CHECK(v.message.find('\n') == std::string::npos);
        if (genuine.is_null()) CHECK(v.message.find(key) != std::string::npos);
        ++checks;
      }
    }
  }
  // 3 minimum cases x 13 fields, 6 below cases x 21 fields; 23 of them unused by their case.
  WARN("coupling certificate tamper pass: " << fields << " fields over " << cases.size() << " cases, " << unused
                                            << " unused fields planted, " << checks << " tampers");
  CHECK(cases.size() == 9);
  CHECK(fields == 3 * 13 + 6 * 21);
  CHECK(unused == 2 + 5 + 4 + 6 + 4 + 2);
}

TEST_CASE("the issue's forgery: a never certificate with t_below, crossing, root planted", "[certificate][horizon]") {
  // n^2 = 1/30: the (6, 5) coupling, resonant, never below 1e-4 (its minimum is 0.0012876...).
  json cert = json::parse(certificate_text(coupling_spec::from_n2(big_rational(1, 30)), 100, parse_rational("1e-4", "E"), 12));
  REQUIRE(cert["below"]["case"] == "never");
  REQUIRE(check(cert).status == 0);
  cert["below"]["t_below"] = json::array({"4.5", "4.6"});
  cert["below"]["crossing"] = json::array({"1", "1.1"});
  cert["below"]["root"] = json::array({"0.5", "0.6"});
  const auto v = check(cert);
  INFO(v.message);
  CHECK(v.status == 2);
  CHECK(v.message.find("must be null") != std::string::npos);
}
