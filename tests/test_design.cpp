// Design problems and the Pareto front (paper §IV-V; include/gyrores/design.hpp).
//
// The paper's Section V reasoning, with exact first-hit times, and where it goes wrong:
//  - Case A, delta = 2, beat >= 10: (11, 9); t_first = sqrt(99) pi/2 = pi/n exactly (delta = 2).
//  - Case A, delta = 6, beat >= 10: the paper says the smallest coprime pair is (41, 35); it is
//    (35, 29) (gcd 1, beat 64/6 >= 10). (41, 35)'s "T_min ~ 19.8" is its proxy pi/n; its exact
//    first zero is t_first = 3 pi/n = 59.50 (for delta = 2 mod 4, t_first = (delta/2) pi/n).
//  - Case B, delta = 1, beat >= 10: (6, 5); "T_min ~ 17.2" is the proxy; the exact first minimum
//    is earlier, t_first = 16.351 (the mirror minimiser theta = 2.985 comes before 3.298).
//  - Design with the exact time vs the proxy: containment at T_max = 17 picks (6, 5) (exact) but
//    (23, 19) with the proxy; absorption with the proxy ranks degenerate pairs whose exact first
//    zero is far beyond T_max (e.g. (101, 83): pi/n = 15.98, t_first = 143.8).
// Answers are checked against an independent oracle: the global search (all critical points,
// no lattice structure assumed) over every pair that passes the beat filter.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>

#include <gyrores/design/design.hpp>
#include <gyrores/gyrores.hpp>
#include "reference/global_search.hpp"

#include "cli_checks.hpp"
#include "testing/cli_run.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using gyrores::test::cli_available;
using gyrores::test::check_rejected;
using gyrores::test::cli_json;
using gyrores::test::cli_run;

namespace {

const std::vector<design_point>& catalogue200() {
  static const auto c = design_catalogue(200);
  return c;
}

design_options opts(design_problem p, design_time t, const char* tmax, std::optional<std::int64_t> delta = {}) {
  design_options o;
  o.problem = p;
  o.time = t;
  o.tmax = parse_rational(tmax, "tmax");
  o.filter.beat_min = big_rational(10);
  o.filter.delta = delta;
  o.candidates = 5;
  return o;
}

bool is(const design_point& p, std::int64_t t, std::int64_t s) { return p.tau == t && p.sigma == s; }

// Independent oracle: every pair with beat >= 10 and order <= 200 by the global search.
struct oracle_point {
  std::int64_t tau, sigma;
  double r, t, proxy;
};
const std::vector<oracle_point>& oracle() {
  static const auto v = [] {
    std::vector<oracle_point> out;
    for (std::int64_t a = 3; a <= 200; ++a)
      for (std::int64_t s = 1; 2 * s < a; ++s) {
        if (std::gcd(a, s) != 1) continue;
        std::int64_t t = a - s, b = t - s;
        if (a < 10 * b) continue;
        auto g = inscribed_global<double>(resonant_pair<std::int64_t>(t, s), 1.0);
        out.push_back({t, s, g.r_res, g.t_first, M_PI * std::sqrt(double(t) * double(s)) / double(b)});
      }
    return out;
  }();
  return v;
}

// The oracle's answer: best r (min or max), ties by smaller time, then order.
oracle_point oracle_best(bool absorb, bool proxy, double T) {
  const oracle_point* best = nullptr;
  for (const auto& p : oracle()) {
    double time = proxy ? p.proxy : p.t;
    if (time > T) continue;
    if (!best) {
      best = &p;
      continue;
    }
    double bt = proxy ? best->proxy : best->t;
    bool better = absorb ? p.r < best->r : p.r > best->r;
    if (p.r == best->r) better = time < bt;
    if (better) best = &p;
  }
  REQUIRE(best != nullptr);
  return *best;
}

}  // namespace

TEST_CASE("design: Case A with delta = 2 chooses (11, 9); t_first equals the proxy exactly", "[design]") {
  for (auto t : {design_time::first_hit, design_time::proxy}) {
    auto r = design_solve(catalogue200(), opts(design_problem::absorb, t, "1000", 2));
    REQUIRE(r.feasible_any());
    CHECK(is(r.ranked[0], 11, 9));
  }
  auto p = design_point_of(resonant_pair<std::int64_t>(11, 9));
  const double exact = std::sqrt(99.0) * M_PI / 2;  // theta_first = pi/2 (degenerate)
  CHECK(p.r_res == 0);
  CHECK(p.t_first == Approx(exact).epsilon(1e-14));
  CHECK(p.t_proxy == Approx(exact).epsilon(1e-14));
  CHECK(p.n == Approx(0.201).margin(0.0005));  // paper: n = 0.201
  CHECK(p.t_first == Approx(15.6).margin(0.05));  // paper: T_min ~ 15.6 s
}

TEST_CASE("design: Case A with delta = 6: the smallest valid pair is (35, 29), not the paper's (41, 35)", "[design]") {
  // Independent: the first coprime (sigma + 6, sigma) with (2 sigma + 6)/6 >= 10.
  std::int64_t s = 1;
  while (!(std::gcd(s + 6, s) == 1 && 2 * s + 6 >= 60)) ++s;
  CHECK(s + 6 == 35);
  CHECK(s == 29);
  CHECK(std::gcd(35, 29) == 1);
  for (auto t : {design_time::first_hit, design_time::proxy}) {
    auto r = design_solve(catalogue200(), opts(design_problem::absorb, t, "1000", 6));
    REQUIRE(r.ranked.size() >= 3);
    CHECK(is(r.ranked[0], 35, 29));
    CHECK(is(r.ranked[1], 37, 31));
    CHECK(is(r.ranked[2], 41, 35));
  }
  // Degenerate pairs: t_first = sqrt(tau sigma) pi/2 = (delta/2) pi/n: three times the proxy.
  for (auto [t, sg] : {std::pair{35, 29}, std::pair{41, 35}}) {
    auto p = design_point_of(resonant_pair<std::int64_t>(t, sg));
    CHECK(p.t_first == Approx(3 * p.t_proxy).epsilon(1e-13));
  }
  auto p41 = design_point_of(resonant_pair<std::int64_t>(41, 35));
  CHECK(p41.t_proxy == Approx(19.8).margin(0.05));   // the paper's 19.8 is the proxy
  CHECK(p41.t_first == Approx(59.504).margin(0.001)); // the exact first zero
  auto p35 = design_point_of(resonant_pair<std::int64_t>(35, 29));
  CHECK(p35.t_proxy == Approx(16.681).margin(0.001));
  CHECK(p35.t_first == Approx(50.044).margin(0.001));
  // (11, 9) still wins against every delta = 6 pair, with either time.
  auto p11 = design_point_of(resonant_pair<std::int64_t>(11, 9));
  CHECK(p11.t_first < p35.t_first);
  CHECK(p11.t_proxy < p35.t_proxy);
}

TEST_CASE("design: larger delta does not deteriorate under the proxy (paper's claim holds for exact times only)", "[design]") {
  // (57, 47): delta = 10, beat 10.4, proxy below (35, 29)'s although its exact first zero is 5 pi/n.
  auto p57 = design_point_of(resonant_pair<std::int64_t>(57, 47));
  auto p35 = design_point_of(resonant_pair<std::int64_t>(35, 29));
  REQUIRE(p57.degenerate);
  CHECK(p57.t_proxy < p35.t_proxy);
  CHECK(p57.t_first > p35.t_first);
  CHECK(p57.t_first == Approx(5 * p57.t_proxy).epsilon(1e-13));
}

TEST_CASE("design: Case B with delta = 1 chooses (6, 5); the exact first minimum precedes the proxy", "[design]") {
  auto r = design_solve(catalogue200(), opts(design_problem::contain, design_time::first_hit, "1000", 1));
  REQUIRE(r.feasible_any());
  CHECK(is(r.ranked[0], 6, 5));
  auto p = design_point_of(resonant_pair<std::int64_t>(6, 5));
  CHECK(p.n == Approx(0.183).margin(0.0005));         // paper: n = 0.183
  CHECK(p.t_proxy == Approx(17.2).margin(0.05));      // paper: T_min ~ 17.2 s (the proxy)
  CHECK(p.t_first == Approx(16.3510779751).margin(1e-9));
  CHECK(p.t_first < p.t_proxy);
  CHECK(p.r_res == Approx(5.075e-2).margin(0.0005e-2));  // paper: r_min = 5.075e-2
  // theta_first is the mirror image of the paper's theta ~ 3.30: 2 pi - 3.2979 = 2.9853.
  auto g = inscribed_global<double>(resonant_pair<std::int64_t>(6, 5), 1.0);
  REQUIRE(g.minimisers.size() == 2);
  CHECK(g.minimisers[0] + g.minimisers[1] == Approx(2 * M_PI).epsilon(1e-12));
  CHECK(g.minimisers[0] == Approx(2.98528474884).margin(1e-9));
}

TEST_CASE("design: chosen pairs with and without --proxy agree with a global-search oracle", "[design]") {
  struct row {
    design_problem prob;
    design_time time;
    const char* T;
    std::int64_t tau, sigma;
  };
  const std::vector<row> rows = {
      {design_problem::absorb, design_time::first_hit, "16", 11, 9},
      {design_problem::absorb, design_time::proxy, "16", 11, 9},
      {design_problem::contain, design_time::first_hit, "16", 17, 14},
      {design_problem::contain, design_time::proxy, "16", 28, 23},
      {design_problem::contain, design_time::first_hit, "17", 6, 5},   // exact: (6, 5) fits, t_first = 16.35
      {design_problem::contain, design_time::proxy, "17", 23, 19},     // proxy: (6, 5) excluded, pi/n = 17.21
      {design_problem::contain, design_time::first_hit, "18", 6, 5},
      {design_problem::contain, design_time::proxy, "18", 6, 5},
  };
  for (const auto& w : rows) {
    INFO(design_problem_name(w.prob) << " " << design_time_name(w.time) << " T = " << w.T);
    auto r = design_solve(catalogue200(), opts(w.prob, w.time, w.T));
    REQUIRE(r.feasible_any());
    CHECK(is(r.ranked[0], w.tau, w.sigma));
    auto o = oracle_best(w.prob == design_problem::absorb, w.time == design_time::proxy, std::stod(w.T));
    CHECK(o.tau == w.tau);
    CHECK(o.sigma == w.sigma);
    // Every reported pair meets every constraint.
    for (const auto& p : r.ranked) {
      CHECK(10 * p.delta() <= p.order());
      CHECK(design_time_of(p, w.time) <= std::stod(w.T));
    }
  }
}

TEST_CASE("design: the proxy admits pairs whose exact first-hit time violates T_max", "[design]") {
  auto r = design_solve(catalogue200(), opts(design_problem::absorb, design_time::proxy, "16"));
  REQUIRE(r.ranked.size() >= 2);
  CHECK(is(r.ranked[1], 101, 83));  // degenerate, pi/n = 15.98 <= 16
  CHECK(r.ranked[1].t_proxy <= 16);
  CHECK(r.ranked[1].t_first == Approx(143.82).margin(0.01));
  CHECK_FALSE(design_time_within(r.ranked[1], design_time::first_hit, big_rational(16)));
}

TEST_CASE("design: infeasible constraints choose nothing", "[design]") {
  // The fastest pair with beat >= 10 is (11, 9) at 15.629...: below it nothing qualifies.
  for (auto t : {design_time::first_hit, design_time::proxy})
    for (auto p : {design_problem::absorb, design_problem::contain}) {
      auto r = design_solve(catalogue200(), opts(p, t, "15.6"));
      CHECK_FALSE(r.feasible_any());
      CHECK(r.feasible == 0);
    }
  CHECK_THROWS_AS(design_solve(catalogue200(), opts(design_problem::absorb, design_time::first_hit, "0")), usage_error);
  CHECK_THROWS_AS(design_catalogue(2), usage_error);
}

TEST_CASE("design: --exclude-low removes the paper's low-order set", "[design]") {
  auto o = opts(design_problem::absorb, design_time::first_hit, "16");
  o.filter.exclude_low = 20;  // removes (11, 9), order 20
  auto r = design_solve(catalogue200(), o);
  REQUIRE(r.feasible_any());
  CHECK(is(r.ranked[0], 105, 86));
  for (const auto& p : r.ranked) CHECK(p.order() > 20);
}

TEST_CASE("design: ties in r_res = 0 are broken by time, then order", "[design]") {
  auto o = opts(design_problem::absorb, design_time::first_hit, "30", 2);
  auto r = design_solve(catalogue200(), o);
  REQUIRE(r.ranked.size() >= 4);
  for (std::size_t i = 1; i < r.ranked.size(); ++i) {
    CHECK(r.ranked[i].r_res == 0);
    CHECK(r.ranked[i - 1].t_first < r.ranked[i].t_first);
  }
}

TEST_CASE("design: the time constraint is decided at 256 bits near the boundary", "[design]") {
  // T_max = t_first of (11, 9) rounded to 20 digits, just below and just above.
  auto p = design_point_of(resonant_pair<std::int64_t>(11, 9));
  scoped_digits d(60);
  auto c = resonant_constants_of<mpfr_real>(resonant_pair<std::int64_t>(11, 9), mpfr_real(1));
  mpfr_real exact = c.sqrt_ts * c.pi / 2;  // 15.629226114...
  std::string s = exact.str(25, std::ios_base::fixed);
  // s has 25 decimals; bump the last digit down/up for strict bounds.
  big_rational T = parse_rational(s, "T");
  big_rational tiny(big_int(1), boost::multiprecision::pow(big_int(10), 24));
  CHECK(design_time_within(p, design_time::first_hit, T + tiny));
  CHECK_FALSE(design_time_within(p, design_time::first_hit, T - tiny));
}

TEST_CASE("pareto: the front is exactly the non-dominated set (brute force), both orientations", "[pareto]") {
  auto cat = design_catalogue(60);
  for (auto o : {pareto_orientation::absorb, pareto_orientation::contain}) {
    const bool absorb = o == pareto_orientation::absorb;
    auto front = pareto_front(cat, o, design_time::first_hit);
    auto dominates = [&](const design_point& x, const design_point& y) {
      bool r_ge = absorb ? x.r_res <= y.r_res : x.r_res >= y.r_res;
      bool r_gt = absorb ? x.r_res < y.r_res : x.r_res > y.r_res;
      return r_ge && x.t_first <= y.t_first && (r_gt || x.t_first < y.t_first);
    };
    std::set<std::pair<std::int64_t, std::int64_t>> on;
    for (auto& p : front) on.insert({p.tau, p.sigma});
    for (const auto& y : cat) {
      bool dominated = false;
      for (const auto& x : cat)
        if (dominates(x, y)) {
          dominated = true;
          break;
        }
      INFO(y.tau << "," << y.sigma);
      CHECK(dominated == !on.count({y.tau, y.sigma}));
    }
  }
}

TEST_CASE("pareto: absorb front up to order 60 runs from (5, 1) to (3, 1); values match the global search", "[pareto]") {
  auto cat = design_catalogue(60);
  auto front = pareto_front(cat, pareto_orientation::absorb, design_time::first_hit);
  REQUIRE(front.size() >= 3);
  CHECK(is(front.front(), 5, 1));
  CHECK(is(front.back(), 3, 1));
  CHECK(front.back().r_res == 0);
  CHECK(front.back().t_first == Approx(std::sqrt(3.0) * M_PI / 2).epsilon(1e-14));
  for (const auto& p : front) {
    if (p.degenerate) continue;
    auto g = inscribed_global<double>(p.pair(), 1.0);
    CHECK(p.r_res == Approx(g.r_res).epsilon(1e-9));
    CHECK(p.t_first == Approx(g.t_first).epsilon(1e-9));
  }
  // Times ascend and radii descend along the front.
  for (std::size_t i = 1; i < front.size(); ++i) {
    CHECK(front[i - 1].t_first <= front[i].t_first);
    CHECK(front[i - 1].r_res > front[i].r_res);
  }
  auto cfront = pareto_front(cat, pareto_orientation::contain, design_time::first_hit);
  CHECK(is(cfront.back(), 2, 1));  // the largest r_res of all pairs
}

// ------------------------------------------------------------------------------------ CLI

TEST_CASE("cli design: JSON schema; integers as integers, reals as strings", "[design][cli]") {
  if (!cli_available()) return;
  auto j = cli_json("design contain --tmax 17 --beat 10 --json --digits 8");
  CHECK(j["problem"] == "contain");
  CHECK(j["tmax"] == "17");
  for (const auto* k : {"chosen", "candidates"}) REQUIRE(j.contains(k));
  auto check_shape = [](const nlohmann::json& p) {
    CHECK(p["tau"].is_number_integer());
    CHECK(p["sigma"].is_number_integer());
    for (const auto* k : {"n", "r_res", "h_min", "t_first", "t_min_paper"}) {
      REQUIRE(p.contains(k));
      CHECK(p[k].is_string());
    }
  };
  check_shape(j["chosen"]);
  CHECK(j["chosen"]["tau"] == 6);
  CHECK(j["chosen"]["sigma"] == 5);
  CHECK(j["chosen"]["r_res"] == "5.0745806e-02");
  CHECK(j["chosen"]["t_first"] == "1.6351078e+01");
  CHECK(j["chosen"]["t_min_paper"] == "1.7207212e+01");
  REQUIRE(j["candidates"].size() == 5);
  for (auto& c : j["candidates"]) check_shape(c);

  auto p = cli_run("design contain --tmax 17 --beat 10 --proxy --json");
  REQUIRE(p.status == 0);
  auto jp = nlohmann::json::parse(p.out);
  CHECK(jp["chosen"]["tau"] == 23);
  CHECK(jp["chosen"]["sigma"] == 19);
}

TEST_CASE("cli design: proxy choice that violates the exact time is flagged", "[design][cli]") {
  if (!cli_available()) return;
  // delta = 6 with T_max = 20: the proxy accepts (35, 29) (pi/n = 16.68), whose first zero is at 50.04.
  auto j = cli_json("design absorb --tmax 20 --beat 10 --delta 6 --proxy --json");
  CHECK(j["chosen"]["tau"] == 35);
  CHECK(j["chosen_t_first_exceeds_tmax"] == true);
  // exact: no delta = 6 pair reaches zero by t = 20
  check_rejected("design absorb --tmax 20 --beat 10 --delta 6", 3, "no resonant pair");
  // --delta 0 and negative deltas are refused, not ignored.
  check_rejected("design absorb --tmax 20 --delta 0", 2, "--delta must be >= 1");
  check_rejected("design absorb --tmax 20 --delta -3", 2, "--delta must be >= 1");
}

TEST_CASE("cli design: infeasible exits 3, bad input exits 2, nothing on stdout", "[design][cli]") {
  if (!cli_available()) return;
  check_rejected("design absorb --tmax 15 --beat 10", 3);
  for (const char* bad : {"design absorb --tmax abc", "design maximise --tmax 10", "design absorb --tmax -1",
                          "design absorb --tmax 10 --beat 1/0", "design absorb --tmax 10 --max-order 2",
                          "design absorb"})
    check_rejected(bad);
}

TEST_CASE("cli pareto: CSV and JSON", "[pareto][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir dir("pareto");
  auto r = cli_run("pareto --max-order 40 --out " + dir / "front.csv" + " --json --digits 6");
  REQUIRE(r.status == 0);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j["orientation"] == "absorb");
  REQUIRE(j["front"].size() >= 3);
  CHECK(j["front"][0]["tau"] == 5);
  CHECK(j["front"][0]["sigma"] == 1);
  CHECK(j["front"].back()["tau"] == 3);
  std::ifstream in(dir / "front.csv");
  std::string head;
  std::getline(in, head);
  CHECK(head == "tau,sigma,order,delta,degenerate,n,r_res,t_first,t_min_paper");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  CHECK(rows == int(j["front"].size()));
  auto bad = cli_run("pareto --max-order 40 --orientation sideways");
  CHECK(bad.status == 2);
  CHECK(bad.out.empty());
}

TEST_CASE("cli design --tolerance: a proved band verdict per ranked pair, and refusals", "[design][cli]") {
  if (!cli_available()) return;
  const auto j = cli_json("design absorb --tmax 20 --tolerance 1% --level 1% --json");
  REQUIRE(j["tolerance"]["chosen"].is_object());
  CHECK(j["tolerance"]["theorem"] == "band-theorem/1");
  CHECK(j["tolerance"]["checked"].back()["verdict"] == "meets");
  for (const char* bad : {"design absorb --tmax 20 --tolerance 1%", "design absorb --tmax 20 --tolerance 1 --level 1%",
                          "design absorb --tmax 20 --level 1%", "design absorb --tmax 20 --tolerance 1% --level 1% --horizon 5",
                          "design contain --tmax 20 --tolerance 150% --level 1%"})
    check_rejected(bad);
}
