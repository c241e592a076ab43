// The band theorem (theorem/band.hpp, proofs/band-theorem.md) against independent references:
// the minimum over [0, T] at each coupling by the plain loop over every lobe, sampled densely over
// the band and at the resonant couplings of small denominators (tests/reference/band_reference),
// and, for long horizons, the least-odd-denominator pair's own minimum by the high-precision
// reference of src/testing (no lobe frames, no theorem).
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <random>
#include <vector>

#include <gyrores/model/fractions.hpp>
#include <gyrores/design/design.hpp>
#include <gyrores/design/tolerance.hpp>
#include <gyrores/theorem/band.hpp>

#include "reference/band_reference.hpp"
#include "testing/high_precision_reference.hpp"
#include "testing/test_support.hpp"

using gyrores::test::hp::hp_reference;
using gyrores::test::hp::hp_result;

using namespace gyrores;

namespace {

double to_double(const big_rational& v) { return v.convert_to<double>(); }
double n_of(const band_coupling& c) { return std::sqrt(to_double(c.spec.n2)); }

// The couplings a test samples in [n1, n2]: a uniform grid, and every coupling x = p/q with q <= 60
// inside (the peaks and zeros of the lobes' offsets, where the extremes of the band live).
std::vector<double> samples(double n1, double n2, int grid) {
  std::vector<double> out;
  for (int i = 0; i <= grid; ++i) out.push_back(n1 + (n2 - n1) * i / grid);
  const double x1 = n1 / std::sqrt(n1 * n1 + 4), x2 = n2 / std::sqrt(n2 * n2 + 4);
  for (int q = 2; q <= 60; ++q)
    for (int p = int(std::ceil(x1 * q)); p <= int(std::floor(x2 * q)); ++p) {
      const double x = double(p) / q;
      if (x > x1 && x < x2) out.push_back(2 * x / std::sqrt(1 - x * x));
    }
  return out;
}

struct band_case {
  double n1, n2, T;
  unsigned digits;
};

// Every sampled minimum lies under the absorption guarantee and above the containment guarantee;
// each guarantee is settled and attained at its coupling (the reference's minimum there rounds
// to the printed value).
void check_against_samples(const band_case& c) {
  INFO("band [" << c.n1 << ", " << c.n2 << "], T = " << c.T << ", " << c.digits << " digits");
  const big_rational n1 = parse_rational(std::to_string(c.n1), "n1"), n2 = parse_rational(std::to_string(c.n2), "n2");
  const horizon_time T(parse_rational(std::to_string(c.T), "T"));
  band_options opt;
  opt.digits = c.digits;
  const band_extreme W = prove_band_absorption(n1, n2, T, opt), B = prove_band_containment(n1, n2, T, opt);
  REQUIRE(W.settled);
  REQUIRE(B.settled);
  const double w_hi = to_double(W.value.hi_rational()), b_lo = to_double(B.value.lo_rational());
  double sampled_max = 0, sampled_min = INFINITY;
  for (double n : samples(to_double(n1), to_double(n2), 1500)) {
    const double m = reference::band_minimum(n, to_double(T.value));
    sampled_max = std::max(sampled_max, m);
    sampled_min = std::min(sampled_min, m);
  }
  CHECK(sampled_max <= w_hi * (1 + 1e-8));
  CHECK(sampled_min >= b_lo * (1 - 1e-8));
  for (const band_extreme* e : {&W, &B}) {
    const double at = reference::band_minimum(n_of(e->at), to_double(T.value));
    const double lo = to_double(e->value.lo_rational()), hi = to_double(e->value.hi_rational());
    if (hi == 0) CHECK(at < 1e-12);  // an exact zero: the reference comes close to it
    else CHECK((at >= lo * (1 - 1e-8) && at <= hi * (1 + 1e-8)));
  }
}

}  // namespace

TEST_CASE("band: the guarantees enclose every sampled minimum and are attained, fixed bands", "[band]") {
  for (const band_case& c : {band_case{0.5, 0.6, 20, 6}, band_case{0.2, 0.21, 40, 6}, band_case{1.9, 2.1, 300, 8},
                             band_case{0.18, 0.19, 20, 10}, band_case{0.5, 1.5, 300, 6}, band_case{0.5, 3, 1, 12},
                             band_case{1.98, 2.02, 1000, 6}, band_case{2.5, 2.6, 50, 20}, band_case{7.0, 7.5, 30, 6},
                             band_case{0.05, 0.051, 2, 30}, band_case{12, 14, 3, 8}})
    check_against_samples(c);
}

TEST_CASE("band: random bands, relative widths 1e-6 to 50%, digits 6 to 30", "[band][random]") {
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> log_n(-1.3, 1.1), log_w(-6, std::log10(0.5)), log_T(0, 3);
  std::uniform_int_distribution<unsigned> digits(6, 30);
  const int count = 12 * test::multiplier();
  for (int i = 0; i < count; ++i) {
    const double n0 = std::pow(10, log_n(rng)), w = std::pow(10, log_w(rng)), T = std::round(std::pow(10, log_T(rng)) * 100) / 100;
    check_against_samples({n0 * (1 - w), n0 * (1 + w), T, digits(rng)});
  }
}

TEST_CASE("band: over long horizons the absorption guarantee is the least odd denominator pair's minimum", "[band]") {
  // x in [x1, x2]: the fraction p/q of least odd denominator inside is the resonant pair
  // ((q + p)/2, (q - p)/2) (p odd) or (q + p, q - p) (p even); its all-time minimum of H_q is
  // r_res^2/2, by the high-precision reference.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> log_n(-1.2, 1.0), log_w(-5, -0.5);
  for (int i = 0; i < 6; ++i) {
    const double n0 = std::pow(10, log_n(rng)), w = std::pow(10, log_w(rng));
    const big_rational n1 = parse_rational(std::to_string(n0 * (1 - w)), "n1"), n2 = parse_rational(std::to_string(n0 * (1 + w)), "n2");
    for (const char* T : {"1e12", "1e30", "1e100"}) {
      INFO("band [" << rational_str(n1) << ", " << rational_str(n2) << "], T = " << T);
      band_options opt;
      opt.digits = 10;
      const band_extreme W = prove_band_absorption(n1, n2, horizon_time(parse_rational(T, "T")), opt);
      REQUIRE(W.settled);
      const fraction odd = least_of_parity_in(band_coupling::of_n(n1).x, band_coupling::of_n(n2).x, 1);
      const big_int tau = odd.p % 2 != 0 ? big_int((odd.q + odd.p) / 2) : big_int(odd.q + odd.p);
      const big_int sigma = odd.p % 2 != 0 ? big_int((odd.q - odd.p) / 2) : big_int(odd.q - odd.p);
      const hp_result ref = hp_reference(tau, sigma, 30);
      const double h_min = ref.radius_sq.convert_to<double>() / 2;
      CHECK(std::fabs(to_double(W.value.lo_rational()) - h_min) <= 1e-9 * h_min);
      CHECK(W.at.x == odd.value());
    }
  }
}

TEST_CASE("band: the containment guarantee is 0 exactly at a degenerate pair whose zero comes before T", "[band]") {
  // [0.2, 0.21]: x = 1/10 is the pair (11, 9), its zero at t = 15.629 (the golden band_json).
  const big_rational n1(1, 5), n2(21, 100);
  const band_extreme before = prove_band_containment(n1, n2, horizon_time(big_rational(40)));
  CHECK(before.value.hi_rational() == 0);
  CHECK(before.at.x == quadratic_number(1, 10));
  const band_extreme after = prove_band_containment(n1, n2, horizon_time(big_rational(15)));
  CHECK(after.value.lo_rational() > 0);
}

TEST_CASE("band: a late lobe's minimiser entering [0, T] near its centre", "[band]") {
  // (11, 9) has its zero (x = 1/10, lobe 5) at t = 15.629..., just after T = 15.6, so the band
  // holds no degenerate pair with its zero in [0, T]; but nearby couplings reach lobe 5's
  // minimiser before T, with a tiny ||5 x - 1/2||: the containment guarantee is where that starts
  // (about n = 0.2017544), 3.4e-9. A bound that took the lobe's value only at the interval's ends,
  // or dropped the lobe, would miss it.
  check_against_samples({0.2, 0.202, 15.6, 8});
  const band_extreme B = prove_band_containment(big_rational(1, 5), big_rational(202, 1000), horizon_time(big_rational(156, 10)));
  CHECK(B.value.hi_rational() < big_rational(1, 100000000));
  CHECK(B.value.lo_rational() > 0);
  // Densely around where it is attained.
  const double at = n_of(B.at);
  for (int i = -500; i <= 500; ++i) CHECK(reference::band_minimum(at + i * 2e-10, 15.6) >= to_double(B.value.lo_rational()) * (1 - 1e-8));
}

TEST_CASE("band: a resonant pair at the band's edge gives the extreme exactly", "[band]") {
  // (9, 4): n = 5/6, x = 5/13, H_min = V(1/26) from lobes 4 (offset -1/26) and 9 (+1/26), the
  // mirror lobes (k, a - k). Over [0, 20] lobe 4 is in and lobe 9 is not: moving n down lowers
  // lobe 4's value, moving up raises it; so the absorption guarantee of [5/6 - 10^-4, 5/6] and the
  // containment one of [5/6, 5/6 + 10^-4] are M(5/6) = H_min. Over [0, 200] both mirror lobes are
  // in and 5/6 is the peak of both one-sided bands and of the two-sided band.
  const hp_result ref = hp_reference(9, 4, 30);
  const double h_min = ref.radius_sq.convert_to<double>() / 2;
  const big_rational n(5, 6), d(1, 10000);
  band_options opt;
  opt.digits = 9;
  struct one_side {
    int T;
    big_rational a, b;
    bool absorption;
  };
  for (const one_side& c : {one_side{20, n - d, n, true}, one_side{20, n, n + d, false}, one_side{200, n - d, n, true},
                            one_side{200, n, n + d, true}, one_side{200, n - d, n + d, true}}) {
    INFO("T = " << c.T << " band [" << rational_str(c.a) << ", " << rational_str(c.b) << "]");
    const band_extreme e = c.absorption ? prove_band_absorption(c.a, c.b, horizon_time(big_rational(c.T)), opt)
                                        : prove_band_containment(c.a, c.b, horizon_time(big_rational(c.T)), opt);
    REQUIRE(e.settled);
    CHECK(e.at.x == quadratic_number(5, 13));
    CHECK(std::fabs(to_double(e.value.lo_rational()) - h_min) <= 1e-9 * h_min);
  }
}

TEST_CASE("band: T = 0 and a horizon inside lobe 0", "[band]") {
  // T = 0: H_q = 1/2 for every n. T = 1/2: before lobe 0's minimiser for these n, so
  // M(n) = H_q(T), decreasing in n here: the absorption guarantee at n1, the containment one at n2.
  const band_extreme z = prove_band_absorption(big_rational(1, 2), big_rational(1), horizon_time(big_rational(0)));
  CHECK(z.value.lo_rational() == big_rational(1, 2));
  CHECK(z.value.hi_rational() == big_rational(1, 2));
  check_against_samples({0.5, 1, 0.5, 12});
  const band_extreme W = prove_band_absorption(big_rational(1, 2), big_rational(1), horizon_time(big_rational(1, 2)));
  CHECK(W.at.spec.n2 == big_rational(1, 4));
  CHECK_THROWS_AS(prove_band_absorption(big_rational(2), big_rational(1), horizon_time(big_rational(1))), usage_error);
}

TEST_CASE("band: --band 1:2e8 --horizon 1 answers (couplings up to x = 1 - 5e-17)", "[band]") {
  // The containment guarantee is at n2 = 2e8, where every lobe's value carries 1 - x^2 = 1e-16.
  const band_extreme B = prove_band_containment(big_rational(1), big_rational(200000000), horizon_time(big_rational(1)));
  REQUIRE(B.settled);
  CHECK(B.at.spec.n2 == big_rational(40000000000000000));
  CHECK(std::fabs(to_double(B.value.lo_rational()) - reference::band_minimum(2e8, 1)) <= 1e-6 * to_double(B.value.lo_rational()));
  const band_extreme W = prove_band_absorption(big_rational(1), big_rational(200000000), horizon_time(big_rational(1)));
  REQUIRE(W.settled);
}

TEST_CASE("design with tolerance: each verdict agrees with a dense sample of the band", "[band][design]") {
  // Absorb to E = 1% (0.005) before T = 20 and contain E = 1e-4 over [0, 50]: for every checked
  // pair, 'meets' means every sampled coupling meets it.
  const auto catalogue = design_catalogue(60);
  for (auto problem : {design_problem::absorb, design_problem::contain}) {
    design_options o;
    o.problem = problem;
    o.tmax = problem == design_problem::absorb ? big_rational(20) : big_rational(17);
    o.candidates = 6;
    const auto res = design_solve(catalogue, o);
    tolerance_options t;
    t.fraction = big_rational(1, 100);
    t.level = problem == design_problem::absorb ? big_rational(1, 200) : big_rational(1, 10000);
    t.horizon = horizon_time(problem == design_problem::absorb ? big_rational(20) : big_rational(50));
    t.max_pairs = 6;
    const tolerance_result r = design_with_tolerance(res.ranked, problem, t);
    REQUIRE(r.chosen);  // both problems have a pair that meets the guarantee here
    for (const auto& c : r.checked) {
      INFO(c.point.pair().str() << " " << tolerance_verdict_name(c.verdict));
      if (c.verdict != tolerance_verdict::meets) continue;
      for (double n : samples(to_double(c.n1), to_double(c.n2), 200)) {
        const double m = reference::band_minimum(n, to_double(t.horizon.value));
        if (problem == design_problem::absorb) CHECK(m <= to_double(t.level) * (1 + 1e-9));
        else CHECK(m >= to_double(t.level) * (1 - 1e-9));
      }
    }
  }
}

TEST_CASE("design with tolerance: a stop returns the checks so far and the bracket reached", "[band][design]") {
  design_options o;
  o.problem = design_problem::absorb;
  o.tmax = big_rational(20);
  const auto res = design_solve(design_catalogue(60), o);
  std::atomic<bool> stopped{false};  // set as soon as the first band proof reports progress
  tolerance_options t;
  t.fraction = big_rational(1, 100);
  t.horizon = horizon_time(big_rational(20));
  // A level at the first pair's own guarantee (its proved lower end): far from decided at once.
  const auto [n1, n2] = tolerance_band(res.ranked[0], t.fraction);
  band_options twelve;
  twelve.digits = 12;
  t.level = prove_band_absorption(n1, n2, t.horizon, twelve).value.lo_rational();
  t.band.stop = stop_token(&stopped);
  t.band.progress = [&stopped](const band_progress&) { stopped = true; };
  const tolerance_result r = design_with_tolerance(res.ranked, design_problem::absorb, t);
  CHECK(r.interrupted);
  CHECK_FALSE(r.chosen);
  REQUIRE(r.checked.size() == 1);
  CHECK(r.checked[0].guarantee.interrupted);
  CHECK(r.checked[0].verdict == tolerance_verdict::undecided);
  // The bracket is proved even so: the nominal pair's own minimum lies in it.
  const double m = reference::band_minimum(to_double(r.checked[0].n1), 20.0);
  CHECK(to_double(r.checked[0].guarantee.value.hi_rational()) >= m * (1 - 1e-9));
}

TEST_CASE("band: the band-wide first time below a level encloses every sampled coupling's", "[band]") {
  struct below_case {
    double n1, n2;
    const char* level;
  };
  for (const below_case& c : {below_case{1.96, 2.04, "10%"}, below_case{1.9, 2.1, "1e-4"}, below_case{0.5, 0.6, "1e-3"},
                              below_case{0.18, 0.19, "2%"}}) {
    INFO("band [" << c.n1 << ", " << c.n2 << "], E = " << c.level);
    const big_rational E = parse_energy_level(c.level, "E");
    band_options opt;
    opt.digits = 8;
    const band_first_below r = prove_band_first_below(parse_rational(std::to_string(c.n1), "n1"),
                                                      parse_rational(std::to_string(c.n2), "n2"), E, opt);
    REQUIRE(r.settled);
    REQUIRE_FALSE(r.never);
    const double hi = to_double(r.time.hi_rational()), lo = to_double(r.time.lo_rational());
    double latest = 0;
    for (double n : samples(c.n1, c.n2, 300)) latest = std::max(latest, reference::band_first_below(n, to_double(E), hi * 1.01));
    CHECK(latest <= hi * (1 + 1e-7));
    // The coupling where it is attained: its own first time is the lower end.
    CHECK(std::fabs(reference::band_first_below(n_of(r.at), to_double(E), hi * 1.01) - lo) <= 1e-6 * lo);
    // What a bisection on the horizon finds: the absorption guarantee W(T) is above E just before
    // the time and at most E just after it (band-theorem.md: the least T with W(T) <= E).
    const big_rational n1 = parse_rational(std::to_string(c.n1), "n1"), n2 = parse_rational(std::to_string(c.n2), "n2");
    band_options versus;
    versus.versus = E;
    const band_extreme before = prove_band_absorption(n1, n2, horizon_time(r.time.lo_rational() * (1 - big_rational(1, 1000000))), versus);
    const band_extreme after = prove_band_absorption(n1, n2, horizon_time(r.time.hi_rational() * (1 + big_rational(1, 1000000))), versus);
    REQUIRE(before.decided);
    REQUIRE(after.decided);
    CHECK(before.value.lo_rational() > E);
    CHECK(after.value.hi_rational() <= E);
  }
  // A pair of the band that never drains: (6, 1) at x = 5/7 keeps H_q >= 7.5e-5.
  const band_first_below never = prove_band_first_below(big_rational(19, 10), big_rational(21, 10), big_rational(1, 1000000));
  CHECK(never.never);
  CHECK(never.at.x == quadratic_number(5, 7));
}

TEST_CASE("band: each interval's bound (item 4) holds every sampled minimum of the interval", "[band]") {
  // Intervals of x with rational ends across the couplings and horizons where each bound decides:
  // wide ones (the peaks and centres of item 3), narrow ones (the lines of item 4), near x -> 1
  // (a rising line's composite can turn there), short horizons (the end point decides).
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> den(20, 4000);
  std::uniform_real_distribution<double> where(0.05, 0.98), frac(0.0005, 0.2);
  int checked = 0;
  for (const double T : {1.5, 4.0, 12.0, 60.0, 400.0}) {
    for (int i = 0; i < 14; ++i) {
      const int q = den(rng);
      const int p1 = std::max(1, int(where(rng) * q)), p2 = std::min(q - 1, p1 + std::max(1, int(frac(rng) * q)));
      if (p2 <= p1) continue;
      const band_coupling a = band_coupling::of_x(p1, q), b = band_coupling::of_x(p2, q);
      INFO("x in [" << p1 << "/" << q << ", " << p2 << "/" << q << "], T = " << T);
      const horizon_time Tt(parse_rational(std::to_string(T), "T"));
      const double upper = to_double(band_interval_bound(a, b, Tt, true).bound) / 2;
      const double lower = to_double(band_interval_bound(a, b, Tt, false).bound) / 2;
      for (double n : samples(n_of(a), n_of(b), 300)) {
        const double m = reference::band_minimum(n, T);
        CHECK(m <= upper * (1 + 1e-8) + 1e-300);
        CHECK(m >= lower * (1 - 1e-8));
      }
      ++checked;
    }
  }
  CHECK(checked >= 50);
}
