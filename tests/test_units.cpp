// Consistent flags and physical units (docs/units.md): --qdot0 on coupling (energies times
// qdot0^2, radii times qdot0, times unchanged, an absolute level at that impulse), --pair with
// --tolerance, and a physical plant (--mass, --stiffness, --gyro, --velocity): energies in J and
// times in s, also over the band of its --tolerance. The references are independent of the code under test: the dimensionless answers
// scaled by hand at 200 bits (Boost's MPFR type), and a direct RK4 simulation of the dimensional
// equations m q'' + g z' + k q = 0, m z'' - g q' + k z = 0.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <boost/multiprecision/mpfr.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "cli_checks.hpp"
#include "testing/cli_run.hpp"

using gyrores::test::check_rejected;
using gyrores::test::cli_available;
using gyrores::test::cli_json;
using gyrores::test::cli_run;
using big_real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>>;

namespace {

big_real real_of(const std::string& text) {
  big_real v;
  v.precision(70);
  v = big_real(text);
  return v;
}

// `shown` (a correct rounding to `digits` digits) is within half a unit of its last digit of `exact`.
bool rounds_from(const std::string& shown, const big_real& exact, int digits) {
  const big_real s = real_of(shown);
  if (exact == 0) return s == 0;
  const big_real e = floor(log10(abs(exact)));
  const big_real half_ulp = pow(big_real(10), e - (digits - 1)) / 2;
  return abs(s - exact) <= half_ulp * big_real("1.0000001");
}

// The rows "t H_q H_z" of index 0 of an energy figure's data file.
std::vector<std::vector<double>> energy_rows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) break;  // the end of index 0
    if (line[0] == '#') continue;
    std::istringstream is(line);
    double t = 0, hq = 0, hz = 0;
    if (is >> t >> hq >> hz) rows.push_back({t, hq, hz});
  }
  return rows;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// The dimensional plant integrated by RK4 with step dt over [0, T_s]: the least energy of mode q,
// (m q'^2 + k q^2)/2, and the first time it is attained (sampled at the steps).
struct simulated {
  double e_min = 0, t_min = 0;
};
simulated simulate(double m, double k, double g, double V, double Ts, double dt) {
  double s[4] = {0, V, 0, 0};  // q, q', z, z'
  const auto f = [&](const double* x, double* d) {
    d[0] = x[1];
    d[1] = -(g * x[3] + k * x[0]) / m;
    d[2] = x[3];
    d[3] = (g * x[1] - k * x[2]) / m;
  };
  simulated out{m * V * V / 2, 0};
  const long steps = long(std::llround(Ts / dt));
  for (long i = 1; i <= steps; ++i) {
    double k1[4], k2[4], k3[4], k4[4], t[4];
    f(s, k1);
    for (int j = 0; j < 4; ++j) t[j] = s[j] + dt / 2 * k1[j];
    f(t, k2);
    for (int j = 0; j < 4; ++j) t[j] = s[j] + dt / 2 * k2[j];
    f(t, k3);
    for (int j = 0; j < 4; ++j) t[j] = s[j] + dt * k3[j];
    f(t, k4);
    for (int j = 0; j < 4; ++j) s[j] += dt / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    const double e = (m * s[1] * s[1] + k * s[0] * s[0]) / 2;
    if (e < out.e_min) out = {e, double(i) * dt};
  }
  return out;
}

}  // namespace

TEST_CASE("units: --qdot0 scales energies by qdot0^2 and radii by qdot0, not times", "[units][cli]") {
  if (!cli_available()) return;
  const auto unit = cli_json("coupling 2 --horizon 37 --below 1e-3 --digits 40 --json --convergents 0");
  const auto q = cli_json("coupling 2 --horizon 37 --qdot0 3/7 --below 9/49000 --digits 20 --json --convergents 0");
  const big_real v = real_of("3") / 7;
  CHECK(rounds_from(q["h_min_horizon"], real_of(unit["h_min_horizon"]) * v * v, 20));
  CHECK(rounds_from(q["r_min_horizon"], real_of(unit["r_min_horizon"]) * v, 20));
  CHECK(rounds_from(q["t_min_horizon"], real_of(unit["t_min_horizon"]), 20));
  // The level 9/49000 at qdot0 = 3/7 is 1e-3 at the unit impulse: the same first time.
  CHECK(rounds_from(q["t_below"], real_of(unit["t_below"]), 20));
  CHECK(q["qdot0"] == "3/7");
  CHECK(q["below"]["level"] == "1/1000");
  // Must fail: the energy scaled by qdot0 (not its square) is another number.
  CHECK_FALSE(rounds_from(q["h_min_horizon"], real_of(unit["h_min_horizon"]) * v, 20));
  // A percentage is a share of H_q(0) at every impulse: the same first time.
  const auto p1 = cli_json("coupling 2 --horizon 37 --below 1% --json --convergents 0");
  const auto p2 = cli_json("coupling 2 --horizon 37 --below 1% --qdot0 5 --json --convergents 0");
  CHECK(p1["t_below"] == p2["t_below"]);
  // qdot0 = 1 given is the default, byte for byte.
  CHECK(cli_run("coupling --n2 1/12 --qdot0 1").out == cli_run("coupling --n2 1/12").out);
  // A resonant coupling's pair values take the impulse too (as gyrores pair --qdot0).
  const auto r = cli_json("coupling --n2 1/30 --qdot0 2 --json --convergents 0");
  const auto pr = cli_json("pair 6 5 --qdot0 2 --json --digits 12");
  CHECK(r["pair_analysis"]["r_res"] == pr["r_res"]);
  check_rejected("coupling 2 --qdot0 0", 2, "--qdot0");
  check_rejected("coupling 2 --qdot0 -1", 2, "--qdot0");
  check_rejected("coupling 2 --qdot0 2 --certificate c.json", 2, "--certificate");
}

TEST_CASE("units: --qdot0 with a band scales its guarantees by qdot0^2", "[units][cli]") {
  if (!cli_available()) return;
  const auto a = cli_json("coupling --band 0.5:0.6 --horizon 20 --json --digits 30");
  const auto b = cli_json("coupling --band 0.5:0.6 --horizon 20 --json --qdot0 2 --digits 12");
  CHECK(rounds_from(b["band"]["absorption"]["h_min"], real_of(a["band"]["absorption"]["h_min"]) * 4, 12));
  CHECK(rounds_from(b["band"]["containment"]["h_min"], real_of(a["band"]["containment"]["h_min"]) * 4, 12));
}

TEST_CASE("units: --pair with --tolerance is the band around the pair's exact coupling", "[units][cli]") {
  if (!cli_available()) return;
  // (6, 5): n^2 = 1/30 exactly.
  const auto p = cli_json("coupling --pair 6 5 --tolerance 1% --horizon 20 --json --convergents 0 --quiet");
  const auto n = cli_json("coupling --n2 1/30 --tolerance 1% --horizon 20 --json --convergents 0 --quiet");
  CHECK(p["n2"] == "1/30");
  CHECK(p["band"]["n1"] == n["band"]["n1"]);
  CHECK(p["band"]["n2"] == n["band"]["n2"]);
  CHECK(p["band"]["absorption"]["h_min"] == n["band"]["absorption"]["h_min"]);
  CHECK(p["input"]["pair"] == nlohmann::json::array({"6", "5"}));
  check_rejected("coupling --pair 6 --tolerance 1%", 2, "--pair");
  check_rejected("coupling --pair 6 4 --tolerance 1%", 2);
  check_rejected("coupling 0.2 --pair 6 5", 2, "exactly one");
}

TEST_CASE("units: a plant in joules and seconds, against a simulation of the dimensional equations", "[units][cli]") {
  if (!cli_available()) return;
  struct plant_case {
    const char* m;
    const char* k;
    const char* g;
    const char* V;
    const char* Ts;
    bool exact_horizon;
  };
  for (const auto& c : {plant_case{"0.5", "200", "4", "0.1", "2", true}, plant_case{"0.3", "200", "3", "0.2", "1.5", false}}) {
    const std::string plant = std::string("--mass ") + c.m + " --stiffness " + c.k + " --gyro " + c.g + " --velocity " + c.V;
    INFO(plant);
    const auto j = cli_json("coupling " + plant + " --horizon-s " + c.Ts + " --json --convergents 0");
    const double m = std::stod(c.m), k = std::stod(c.k), g = std::stod(c.g), V = std::stod(c.V);
    CHECK(j["horizon_exact"] == c.exact_horizon);
    const simulated s = simulate(m, k, g, V, std::stod(c.Ts), 1e-6);
    const double e = std::stod(j["h_min_horizon"].get<std::string>()), t = std::stod(j["t_min_horizon"].get<std::string>());
    CHECK(std::abs(e - s.e_min) <= 1e-6 * m * V * V);
    CHECK(std::abs(t - s.t_min) <= 2e-6);
    // The scaling by hand at 200 bits: t_s = t sqrt(m/k), E = m V^2 H_q, amplitude V sqrt(m/k) r.
    const auto u = cli_json("coupling --n2 " + j["n2"].get<std::string>() + " --horizon " + j["horizon"].get<std::string>() +
                            " --json --digits 40 --convergents 0");
    const big_real bm = real_of(c.m), bk = real_of(c.k), bV = real_of(c.V);
    CHECK(rounds_from(j["t_min_horizon"], real_of(u["t_min_horizon"]) * sqrt(bm / bk), 12));
    CHECK(rounds_from(j["h_min_horizon"], real_of(u["h_min_horizon"]) * bm * bV * bV, 12));
    CHECK(rounds_from(j["r_min_horizon"], real_of(u["r_min_horizon"]) * bV * sqrt(bm / bk), 12));
    CHECK(rounds_from(j["t_min_paper"], real_of(u["t_min_paper"]) * sqrt(bm / bk), 12));
    // Must fail: time scaled by sqrt(k/m) instead.
    CHECK_FALSE(rounds_from(j["t_min_horizon"], real_of(u["t_min_horizon"]) * sqrt(bk / bm), 12));
    CHECK(j["plant"]["units"]["time"] == "s");
  }
  // n^2 = g^2/(m k) exactly; omega0 = 20 rad/s, 1/omega0 = 0.05 s, H_q(0) = m V^2/2 = 1/400 J.
  const auto j = cli_json("coupling --mass 0.5 --stiffness 200 --gyro 4 --velocity 0.1 --json --convergents 0");
  CHECK(j["n2"] == "4/25");
  CHECK(j["plant"]["omega0"] == "2.00000000000e+01");
  CHECK(j["plant"]["time_scale"] == "5.00000000000e-02");
  CHECK(j["plant"]["h_q0"] == "1/400");
  // --below in joules: 1e-5 J is the unit-impulse level 1e-5 / (m V^2) = 1/500.
  const auto b = cli_json("coupling --mass 0.5 --stiffness 200 --gyro 4 --velocity 0.1 --below 1e-5 --json --convergents 0");
  CHECK(b["below"]["level"] == "1/500");
  const auto ub = cli_json("coupling --n2 4/25 --below 1/500 --json --convergents 0 --digits 40");
  CHECK(rounds_from(b["t_below"], real_of(ub["t_below"]) / 20, 12));
  // The text says the units.
  const auto text = cli_run("coupling --mass 0.5 --stiffness 200 --gyro 4 --velocity 0.1 --horizon-s 2").out;
  CHECK(text.find(" rad/s") != std::string::npos);
  CHECK(text.find(" J  (") != std::string::npos);
  CHECK(text.find("first at t =  ") != std::string::npos);
  CHECK(text.find(" s\n") != std::string::npos);
  // A percentage level is a share of H_q(0), without a unit; an absolute one is in J.
  const auto share = cli_run("coupling --mass 0.5 --stiffness 200 --gyro 4 --velocity 0.1 --below 1% --convergents 0").out;
  CHECK(share.find("first time H_q <= 1%:\n") != std::string::npos);
  CHECK(share.find("first time H_q <= 1% J") == std::string::npos);
}

TEST_CASE("units: a plant's --tolerance is the band of its n, guarantees in J and times in s", "[units][cli]") {
  if (!cli_available()) return;
  // n^2 = 3/20 (n irrational: ends rounded outward); sqrt(k/m) irrational: the model horizon T'.
  const std::string plant = "coupling --mass 0.3 --stiffness 200 --gyro 3 --velocity 0.2 --horizon-s 1.5 ";
  const auto j = cli_json(plant + "--tolerance 1% --below 1e-4 --json --convergents 0 --quiet");
  CHECK(j["horizon_exact"] == false);
  CHECK(j["below"]["level"] == "1/120");  // 1e-4 J / (m V^2 = 0.012 J)
  // The reference: the dimensionless band of n^2 = 3/20 over the same model horizon at the unit
  // level, at 30 digits, scaled by hand at 200 bits: E = m V^2 H_q, t_s = t sqrt(m/k).
  const auto u = cli_json("coupling --n2 3/20 --tolerance 1% --horizon " + j["horizon"].get<std::string>() +
                          " --below 1/120 --json --convergents 0 --band-digits 30 --quiet");
  const auto& b = j["band"];
  const auto& ub = u["band"];
  CHECK(b["n1"] == ub["n1"]);
  CHECK(b["n2"] == ub["n2"]);
  const big_real mV2 = real_of("0.3") * real_of("0.2") * real_of("0.2"), ts = sqrt(real_of("0.3") / 200);
  for (const char* g : {"absorption", "containment"}) {
    INFO(g);
    CHECK(b[g]["settled"] == true);
    CHECK(rounds_from(b[g]["h_min"], real_of(ub[g]["h_min"]) * mV2, 12));
    CHECK(rounds_from(b[g]["at"]["t_min"], real_of(ub[g]["at"]["t_min"]) * ts, 12));
    CHECK(b[g]["at"]["n2"] == ub[g]["at"]["n2"]);
    // Must fail: the energy scaled by m V (not m V^2).
    CHECK_FALSE(rounds_from(b[g]["h_min"], real_of(ub[g]["h_min"]) * real_of("0.3") * real_of("0.2"), 12));
  }
  CHECK(b["first_below"]["settled"] == true);
  CHECK(rounds_from(b["first_below"]["t_below"], real_of(ub["first_below"]["t_below"]) * ts, 12));
  CHECK(rounds_from(b["first_below"]["at"]["t_below"], real_of(ub["first_below"]["at"]["t_below"]) * ts, 12));
  // Must fail: the time scaled by sqrt(k/m).
  CHECK_FALSE(rounds_from(b["first_below"]["t_below"], real_of(ub["first_below"]["t_below"]) / ts, 12));
  // n = g/sqrt(m k) = 2/5 rational: the exact band n (1 -+ 1%); the text in J and s.
  const auto e = cli_json("coupling --mass 0.5 --stiffness 200 --gyro 4 --velocity 0.1 --tolerance 1% --horizon-s 2 --json --quiet");
  CHECK(e["band"]["n1"] == "99/250");
  CHECK(e["band"]["n2"] == "101/250");
  const auto text = cli_run(plant + "--tolerance 1% --below 1e-4 --quiet").out;
  CHECK(text.find("band n in [") != std::string::npos);
  CHECK(text.find("over [0, 1.5 s]:") != std::string::npos);
  CHECK(text.find(" J  (") != std::string::npos);
  CHECK(text.find(" s: every n of the band has H_q <= E by then") != std::string::npos);
  check_rejected(plant + "--band 0.3:0.5", 2, "--band");
  check_rejected(plant + "--tolerance 1% --certificate c.json", 2, "--certificate");
  check_rejected(plant + "--tolerance 1% --qdot0 2", 2, "--qdot0");
}

TEST_CASE("units: bad plant inputs are refused with one line and exit 2", "[units][cli]") {
  if (!cli_available()) return;
  const std::string ok = " --stiffness 200 --gyro 4 --velocity 0.1";
  check_rejected("coupling --mass -0.5" + ok, 2, "--mass");
  check_rejected("coupling --mass 0" + ok, 2, "--mass");
  check_rejected("coupling --mass 0.5 --stiffness 0 --gyro 4 --velocity 0.1", 2, "--stiffness");
  check_rejected("coupling --mass 0.5 --stiffness 200 --gyro 4", 2, "--velocity is missing");
  check_rejected("coupling 0.4 --mass 0.5" + ok, 2, "drop N");
  check_rejected("coupling --n2 4/25 --mass 0.5" + ok, 2, "drop --n2");
  check_rejected("coupling --mass 0.5" + ok + " --qdot0 2", 2, "--qdot0");
  check_rejected("coupling --mass 0.5" + ok + " --band 0.1:0.2", 2, "--band");
  check_rejected("coupling --mass 0.5" + ok + " --horizon 3 --horizon-s 2", 2, "--horizon-s");
  check_rejected("coupling 0.4 --horizon-s 2", 2, "--horizon-s");
  check_rejected("coupling --mass abc" + ok, 2, "--mass");
}

TEST_CASE("units: plot energy and plot phase take --qdot0 (energies times qdot0^2, radii times qdot0)", "[units][cli]") {
  if (!cli_available()) return;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("gyrores-units-plot-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto out = [&](const std::string& name) { return (dir / name).string(); };
  REQUIRE(cli_run("plot energy 6 5 --out " + out("e1.svg")).status == 0);
  REQUIRE(cli_run("plot energy 6 5 --qdot0 3 --out " + out("e3.svg")).status == 0);
  REQUIRE(cli_run("plot energy 6 5 --qdot0 1 --out " + out("e1b.svg")).status == 0);
  // qdot0 = 1 given is the default, byte for byte.
  CHECK(file_text(out("e1.dat")) == file_text(out("e1b.dat")));
  const auto a = energy_rows(out("e1.dat")), b = energy_rows(out("e3.dat"));
  REQUIRE(a.size() > 100);
  REQUIRE(a.size() == b.size());
  // H_q(0) = qdot0^2/2 = 9/2 and H_q + H_z = 9/2 throughout (the whole energy; an independent value).
  CHECK(b[0][1] == 4.5);
  bool times_same = true, squared = true, linear = true;
  for (std::size_t i = 0; i < a.size(); ++i) {
    times_same = times_same && a[i][0] == b[i][0];
    squared = squared && std::abs(b[i][1] - 9 * a[i][1]) <= 1e-8 * 4.5 && std::abs(b[i][1] + b[i][2] - 4.5) <= 1e-8;
    linear = linear && std::abs(b[i][1] - 3 * a[i][1]) <= 1e-8 * 4.5;
  }
  CHECK(times_same);
  CHECK(squared);
  CHECK_FALSE(linear);  // must fail: the energy scaled by qdot0, not its square
  // The phase portrait: the maximal circle is the radius qdot0 = 3/2 (index 3 of its data).
  REQUIRE(cli_run("plot phase --n 0.3 --qdot0 3/2 --out " + out("p.svg")).status == 0);
  const std::string phase = file_text(out("p.dat"));
  CHECK(phase.find("# index 3: maximal circle, radius qdot0 = 1.5 ") != std::string::npos);
  CHECK(phase.find("qdot0 = 3/2") != std::string::npos);  // in the title
  check_rejected("plot energy 6 5 --qdot0 0 --out " + out("x.svg"), 2, "--qdot0");
  check_rejected("plot phase 6 5 --qdot0 -1 --out " + out("x.svg"), 2, "--qdot0");
  std::filesystem::remove_all(dir);
}
