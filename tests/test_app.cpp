// The application layer's design, Pareto and figure requests (include/gyrores/app/design.hpp,
// pareto.hpp, figures.hpp), which the CLI and the Python module share: what each request computes
// beyond the library calls it makes (the ranks a tolerance walks against the pairs it lists, the
// checks Python relies on, the Pareto figure's thinning, a resonant coupling drawn as its pair).
// The printed forms are tested through the CLI (test_design, test_figures, tests/golden/).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <gyrores/app/design.hpp>
#include <gyrores/app/figures.hpp>
#include <gyrores/app/pareto.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>

using namespace gyrores;

namespace {

app::design_request absorb_request() {
  app::design_request r;
  r.options.problem = design_problem::absorb;
  r.options.tmax = 20;
  r.options.candidates = 2;
  r.tmax_text = "20";
  r.digits = 8;
  return r;
}

std::string usage_message(const app::design_request& r) {
  try {
    app::run_design(r);
  } catch (const usage_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("app design: a tolerance walks more ranks than are listed, up to the first that meets", "[app][design]") {
  app::design_request r = absorb_request();
  const app::design_outcome plain = app::run_design(r);
  CHECK(plain.result.ranked.size() == 3);
  CHECK(plain.values.size() == 3);
  r.tolerance = app::design_tolerance{big_rational(1, 100), big_rational(1, 200), std::nullopt};
  const app::design_outcome out = app::run_design(r);
  REQUIRE(out.tolerance);
  CHECK(out.values.size() == 3);  // the listed pairs: candidates + 1
  CHECK(out.result.ranked.size() == std::min<std::size_t>(out.result.feasible, 21));
  for (std::size_t i = 0; i < 3; ++i) CHECK(out.result.ranked[i].pair().str() == plain.result.ranked[i].pair().str());
  const tolerance_result& t = *out.tolerance;
  REQUIRE(t.chosen);
  CHECK(*t.chosen + 1 == t.checked.size());
  for (std::size_t i = 0; i < t.checked.size(); ++i) {
    CHECK(t.checked[i].point.pair().str() == out.result.ranked[i].pair().str());
    CHECK((t.checked[i].verdict == tolerance_verdict::meets) == (i == *t.chosen));
  }
}

TEST_CASE("app design and pareto: parameters out of range are usage errors naming them", "[app][design]") {
  auto with = [](auto change) {
    app::design_request r = absorb_request();
    change(r);
    return usage_message(r);
  };
  CHECK_THAT(with([](auto& r) { r.digits = 0; }), Catch::Contains("digits must be in [1, 1000]"));
  CHECK_THAT(with([](auto& r) { r.options.candidates = 1001; }), Catch::Contains("candidates"));
  CHECK_THAT(with([](auto& r) { r.options.filter.delta = 0; }), Catch::Contains("delta must be >= 1"));
  CHECK_THAT(with([](auto& r) { r.options.filter.exclude_low = -1; }), Catch::Contains("exclude_low"));
  CHECK_THAT(with([](auto& r) { r.options.filter.beat_min = big_rational(0); }), Catch::Contains("beat must be > 0"));
  CHECK_THAT(with([](auto& r) { r.options.max_order = 2; }), Catch::Contains("max_order"));
  CHECK_THAT(with([](auto& r) {
               r.options.time = design_time::proxy;
               r.tolerance = app::design_tolerance{big_rational(1, 100), 0, std::nullopt};
             }),
             Catch::Contains("exact first-hit time"));
  CHECK_THAT(with([](auto& r) { r.tolerance = app::design_tolerance{big_rational(1, 100), 0, horizon_time(30)}; }),
             Catch::Contains("horizon is for contain"));
  app::design_request none = absorb_request();
  none.options.tmax = big_rational(1, 1000);
  CHECK_THROWS_AS(app::run_design(none), compute_error);
  app::pareto_request p;
  p.max_order = 10;
  p.filter.beat_min = big_rational(100);
  CHECK_THROWS_AS(app::run_pareto(p), compute_error);
  CHECK_THROWS_AS(app::parse_pareto_orientation("sideways", "orientation"), usage_error);
  CHECK_THROWS_AS(app::parse_design_problem("middle"), usage_error);
}

TEST_CASE("app pareto: the front's values in its order; a figure's front without them", "[app][pareto]") {
  app::pareto_request r;
  r.max_order = 40;
  r.digits = 6;
  std::vector<std::string> stages;
  r.progress = [&](const std::string& s) { stages.push_back(s); };
  const app::pareto_outcome p = app::run_pareto(r);
  REQUIRE(p.values.size() == p.front.size());
  for (std::size_t i = 0; i < p.front.size(); ++i)
    CHECK(std::fabs(std::stod(p.values[i].t_first.value) - p.front[i].t_first) <= 1e-5 * p.front[i].t_first);
  CHECK(stages.size() == 2);
  r.values = false;
  const app::pareto_outcome q = app::run_pareto(r);
  CHECK(q.values.empty());
  CHECK(q.front.size() == p.front.size());
}

TEST_CASE("app figures: above the limit the scatter keeps one pair per cell, the front complete", "[app][figures]") {
  // A synthetic set: 300 x 250 pairs on a log grid of (time, r_res), and 200 pairs with r_res = 0.
  std::vector<design_point> all, front;
  for (int i = 0; i < 300; ++i)
    for (int j = 0; j < 250; ++j) {
      design_point p;
      p.tau = 1000 + i, p.sigma = j + 1;
      p.t_first = std::pow(10.0, i / 100.0), p.r_res = std::pow(10.0, -j / 50.0);
      all.push_back(p);
      if (i == j) front.push_back(p);
    }
  for (int i = 0; i < 200; ++i) {
    design_point p;
    p.tau = 5000 + i, p.sigma = 1, p.t_first = 1 + i, p.degenerate = true;
    all.push_back(p);
  }
  front.push_back(all.back());
  const int w = 200, h = 120;
  const auto f = app::pareto_figure_points_of(all, front, design_time::first_hit, w, h);
  REQUIRE(all.size() > app::pareto_thin_above);
  CHECK(f.pairs == all.size());
  CHECK(f.t_lo == 1);
  CHECK(f.t_hi == std::pow(10.0, 299 / 100.0));
  CHECK(f.positive.size() <= std::size_t(w / 2) * std::size_t(h / 2));
  CHECK(f.positive.size() > std::size_t(w / 2) * std::size_t(h / 2) / 2);  // thinned, not emptied
  CHECK(f.zeros.size() <= std::size_t(w / 2));
  for (const auto& p : f.positive) CHECK(p.r_res > 0);
  for (const auto& p : f.zeros) CHECK(p.r_res == 0);
  CHECK(f.front_positive.size() + 1 == front.size());  // the front is never thinned
  REQUIRE(f.front_zeros.size() == 1);
  CHECK(f.front_zeros[0].tau == front.back().tau);
  REQUIRE(!f.labelled.empty());
  CHECK(f.labelled.front().tau == front.front().tau);
  for (std::size_t k = 1; k < f.labelled.size(); ++k)  // steps of at least half a decade in r_res
    CHECK(std::fabs(std::log10(f.labelled[k].r_res) - std::log10(f.labelled[k - 1].r_res)) >= 0.5 - 1e-12);
  // Below the limit every pair is drawn.
  std::vector<design_point> few(all.begin(), all.begin() + 1000);
  CHECK(app::pareto_figure_points_of(few, {}, design_time::first_hit, w, h).positive.size() == few.size());
}

TEST_CASE("app figures: a resonant coupling is drawn as its pair, any other as its |n|", "[app][figures]") {
  const auto s = app::figure_subject_of(coupling_spec::from_n2(big_rational(1, 12)));
  REQUIRE(s.pair);
  CHECK(s.pair->str() == "(4, 3)");
  const auto c = app::figure_subject_of(coupling_spec::from_n(big_rational(-2)));
  CHECK_FALSE(c.pair);
  CHECK(c.n == 2);
  // A coupling's default spans: 200 pi/n for the phase portrait, 8 pi/n for the energy.
  CHECK(app::phase_figure(c).t_span == 200 * real_pi<double>() / 2);
  CHECK(app::energy_figure(c).t_end == 8 * real_pi<double>() / 2);
  CHECK(app::phase_figure(s).resonant);
}
