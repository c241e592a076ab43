// The certified sweep's filter: the theorem in double-double balls (theorem/minimum_dd_ball.hpp,
// theorem/paper.hpp, core/dd_ball.hpp) and the rows' roundings of its balls (sweep/testing.hpp):
// every ball holds the exact result (MPFR at 400 bits), every bracket the high-precision root, an
// undecided sign or rounding is never taken as decided, and certified sweeps print the same bytes
// with the filter as without it. tests/mutants/CMakeLists.txt breaks each step and requires a
// case here to fail.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <random>

#include <gyrores/core/dd_ball.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/app/sweep.hpp>
#include <gyrores/io/sweep_files.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/sweep/testing.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum_dd_ball.hpp>
#include <gyrores/theorem/paper.hpp>

#include "testing/cli_run.hpp"
#include "sweep_summary_core.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using namespace gyrores::sweep_testing;
using gyrores::ddb::exact;

namespace {

constexpr int hp_digits = 120;  // 400 bits

mpfr_real hp(const double_double& v) { return mpfr_real(v.hi) + mpfr_real(v.lo); }
// Is the exact value v inside the ball?
bool holds(const dd_ball& b, const mpfr_real& v) { return abs(v - hp(b.m)) <= mpfr_real(b.r); }

resonant_pair<std::int64_t> pair_of(std::int64_t tau, std::int64_t sigma) {
  return resonant_pair<std::int64_t>(tau, sigma, known_coprime);
}

// Newton in MPFR for an increasing f with derivative fp, from u.
template <class F, class FP> mpfr_real newton_hp(mpfr_real u, F f, FP fp) {
  for (int i = 0; i < 200; ++i) {
    const mpfr_real step = f(u) / fp(u);
    u -= step;
    if (step == 0 || abs(step) < abs(u) * pow(mpfr_real(2), -380)) break;
  }
  return u;
}
// u* = H^{-1}(pi m/(2a)); u_a: u + tan u = s.
mpfr_real theorem_root_hp(std::int64_t a, std::int64_t b, std::int64_t m) {
  const mpfr_real x = mpfr_real(b) / a, mu = boost::math::constants::pi<mpfr_real>() * m / (2 * a);
  return newton_hp(mpfr_real(std::min(1.5, double(mu / (2 * x)))),
                   [&](const mpfr_real& u) { return x * u + atan(x * tan(u)) - mu; },
                   [&](const mpfr_real& u) {
                     const mpfr_real t = tan(u);
                     return x + x * (1 + t * t) / (1 + x * x * t * t);
                   });
}
mpfr_real paper_root_hp(const mpfr_real& s) {
  return newton_hp(s / 2, [&](const mpfr_real& u) { return u + tan(u) - s; },
                   [&](const mpfr_real& u) { return 2 + tan(u) * tan(u); });
}

// Random coprime pairs with orders up to max_order (and a few of the extremes).
std::vector<resonant_pair<std::int64_t>> sample_pairs(std::int64_t max_order, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<resonant_pair<std::int64_t>> out{pair_of(2, 1), pair_of(5, 3), pair_of(6, 5), pair_of(3, 1),
                                               pair_of(500001, 500000), pair_of(1000000, 1)};
  while (int(out.size()) < count) {
    const std::int64_t a = 3 + std::int64_t(rng() % std::uint64_t(max_order - 2));
    const std::int64_t sigma = 1 + std::int64_t(rng() % std::uint64_t((a - 1) / 2));
    const std::int64_t tau = a - sigma;
    if (tau > sigma && std::gcd(tau, sigma) == 1) out.push_back(pair_of(tau, sigma));
  }
  return out;
}

sweep_config certified(std::int64_t max_order, bool filter) {
  sweep_config c;
  c.max_order = max_order;
  c.certified = true;
  c.certified_filter = filter;
  return c;
}

}  // namespace

TEST_CASE("filter balls hold the exact results of their operations", "[filter][ball]") {
  scoped_digits sd(hp_digits);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1.9, 1.9), R(0, 1);
  auto point = [&] { return dd::add(double_double(U(rng)), double_double(U(rng) * 0x1p-54)); };
  for (int i = 0; i < 2000; ++i) {
    const double_double xm = point(), ym = point();
    const dd_ball x{xm, R(rng) * 0x1p-70}, y{ym, R(rng) * 0x1p-70};
    // The exact operands at the balls' ends and centres.
    for (int ex = -1; ex <= 1; ++ex)
      for (int ey = -1; ey <= 1; ++ey) {
        const mpfr_real X = hp(xm) + ex * mpfr_real(x.r), Y = hp(ym) + ey * mpfr_real(y.r);
        CHECK(holds(ddb::add(x, y), X + Y));
        CHECK(holds(ddb::sub(x, y), X - Y));
        CHECK(holds(ddb::mul(x, y), X * Y));
        dd_ball q;
        if (ddb::div(q, x, y)) CHECK(holds(q, X / Y));
        dd_ball r;
        if (ddb::sqrt(r, x)) CHECK(holds(r, sqrt(X)));
      }
    dd_ball s, c;
    ddb::sin_cos(exact(xm), s, c);  // a point: only dd_sin_cos_accurate's own error
    CHECK(holds(s, sin(hp(xm))));
    CHECK(holds(c, cos(hp(xm))));
    ddb::sin_cos(x, s, c);
    CHECK(holds(s, sin(hp(xm) + mpfr_real(x.r))));
    CHECK(holds(c, cos(hp(xm) - mpfr_real(x.r))));
  }
  // pi, and a sign is decided only where the ball excludes 0.
  CHECK(holds(ddb::pi(), boost::math::constants::pi<mpfr_real>()));
  CHECK_FALSE(ddb::positive(dd_ball{double_double(1e-20), 1e-20}));
  CHECK_FALSE(ddb::negative(dd_ball{double_double(-1e-20), 1e-20}));
  CHECK(ddb::positive(dd_ball{double_double(1e-20), 0.99e-20}));
}

TEST_CASE("filter: sin y - y cos y by its alternating series", "[filter][series]") {
  scoped_digits sd(hp_digits);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> Y(0, 0.49);
  for (int i = 0; i < 2000; ++i) {
    const double_double y = dd::add(double_double(Y(rng)), double_double(Y(rng) * 0x1p-55));
    dd_ball P;
    REQUIRE(sin_minus_y_cos(P, exact(y)));
    const mpfr_real v = hp(y);
    CHECK(holds(P, sin(v) - v * cos(v)));
    CHECK(P.r < 0x1p-70 * P.m.hi);  // and narrow
  }
  dd_ball P;
  CHECK_FALSE(sin_minus_y_cos(P, exact(0.6)));  // outside |y| < 1/2
}

TEST_CASE("filter roundings: decided only when the whole enclosure rounds alike", "[filter][rounding]") {
  const double h = 1.2345, up = std::nextafter(h, 2.0), dn = std::nextafter(h, 0.0);
  const double half = (up - h) / 2;
  double out = 0;
  // An exact double: to nearest and downward it is itself; upward too (v <= h).
  const dd_ball point = exact(h);
  CHECK((round_nearest(point, out) && out == h));
  CHECK((round_up(point, out) && out == h));
  CHECK((round_down(point, out) && out == h));
  // Just above h: up to next(h), down to h; straddling h: neither.
  const dd_ball above{double_double(h, half / 4), half / 8};
  CHECK((round_up(above, out) && out == up));
  CHECK((round_down(above, out) && out == h));
  const dd_ball around{double_double(h, 0), half / 8};
  CHECK_FALSE(round_up(around, out));
  CHECK_FALSE(round_down(around, out));
  CHECK((round_nearest(around, out) && out == h));
  // Just below h: down to prev(h).
  const dd_ball below{double_double(h, -half / 4), half / 8};
  CHECK((round_down(below, out) && out == dn));
  CHECK((round_up(below, out) && out == h));
  // Straddling the midpoint h + half: undecided to nearest.
  const dd_ball mid{double_double(h, half * (1 - 0x1p-20)), half * 0x1p-10};
  CHECK_FALSE(round_nearest(mid, out));
}

TEST_CASE("filter balls hold u* and u_c - u_a; signs at the roots are undecided", "[filter][bracket]") {
  scoped_digits sd(hp_digits);
  int decided = 0, nondegenerate = 0, asy = 0, asy_decided = 0;
  const auto pairs = sample_pairs(3000000, 300, 13);
  for (const auto& p : pairs) {
    const std::int64_t a = std::int64_t(p.order()), b = p.delta();
    dd_ball_constants K;
    REQUIRE(dd_ball_constants_of(K, p));
    const int m_min = theorem_m_min(a);
    if (m_min != 0) {
      ++nondegenerate;
      dd_ball U;
      if (theorem_root_dd_ball(U, K, m_min)) {
        ++decided;
        const mpfr_real u = theorem_root_hp(a, b, m_min);
        CHECK(holds(U, u));
        CHECK(U.r < double(u) * 0x1p-59);  // and narrow
        // F at the double-double nearest u*: its ball holds 0.
        const double_double un = dd::add(double_double(double(u)), double_double(double(u - mpfr_real(double(u)))));
        dd_ball mu;
        REQUIRE(ddb::div(mu, ddb::scale(K.pi, 0.5 * m_min), exact(K.a)));
        const dd_ball F = theorem_F_dd_ball(K, mu, dd_trig_at(un), nullptr);
        CHECK_FALSE(ddb::positive(F));
        CHECK_FALSE(ddb::negative(F));
      }
    }
    if (2 * b < a) {
      const auto node = paper_fast_node(a, b);
      const std::int64_t m = a - 2 * node.k * b, am = m < 0 ? -m : m;
      if (am == 0) continue;
      ++asy;
      dd_ball s;
      REQUIRE(ddb::div(s, ddb::mul(K.pi, exact(double(am))), exact(2 * K.b)));
      dd_ball D;
      if (!paper_difference_dd_ball(D, K, s)) continue;
      ++asy_decided;
      const mpfr_real S = boost::math::constants::pi<mpfr_real>() * am / (2 * b);
      const mpfr_real ua = paper_root_hp(S), uc = theorem_root_hp(a, b, am);
      CHECK(holds(D, uc - ua));
      CHECK(D.r < double(uc - ua) * 0x1p-58);  // and narrow: the cancellation is avoided
    }
  }
  // The filter decides almost every pair (a property of its design, not a timing).
  CHECK(decided >= int(0.95 * nondegenerate));
  CHECK(asy_decided >= int(0.95 * asy));
}

TEST_CASE("certified sweeps: the same rows and summary with the filter as without", "[filter][rows]") {
  test::temp_dir d("test_certified_filter");
  sweep_engine_options e;
  e.threads = 2;
  std::string text[2], summary[2];
  for (int f = 0; f < 2; ++f) {
    sweep_files files;
    files.rows_path = d / (f ? "filter.csv" : "plain.csv");
    files.summary_path = d / (f ? "filter.json" : "plain.json");
    REQUIRE(app::sweep_to_files<double>(certified(400, f == 1), files, e).complete);
    text[f] = test::read_text(files.rows_path);
    text[f] = text[f].substr(0, text[f].rfind("# end"));  // the end line holds the seconds
    summary[f] = sweep_summary_core(json::parse(test::read_text(files.summary_path))).dump();
  }
  CHECK(text[0].size() > 1000000);
  CHECK(text[0] == text[1]);
  CHECK(summary[0] == summary[1]);
  // The filter itself decided most of these rows (the rest fell back).
  int decided = 0, total = 0;
  for (std::int64_t a = 3; a <= 400; ++a)
    for (std::int64_t sigma = 1; 2 * sigma < a; ++sigma)
      if (std::gcd(a, sigma) == 1) {
        const auto p = pair_of(a - sigma, sigma);
        sweep_row<double> r;
        decided += certified_filter_row(r, p, certified(400, true)) ? 1 : 0;
        ++total;
      }
  WARN("filter decided " << decided << " of " << total << " pairs to order 400");
  // With sines and cosines to 2^-101 (dd_sin_cos_accurate) the balls are about 2^-95 wide, so a
  // 17-digit rounding is left undecided about once in 2^40: the filter decides (nearly) all.
  CHECK(decided >= int(0.999 * total));
}

TEST_CASE("filter: what it must leave to the fallback, and the rows agree", "[filter][fallback]") {
  const sweep_config with = certified(3, true), without = certified(3, false);
  // Beyond its range (order >= 2^31): declined, and the fallback's row is not an error.
  for (const auto& p : {pair_of(std::int64_t(1) << 31, (std::int64_t(1) << 31) - 1), pair_of(3000000001, 2)}) {
    sweep_row<double> r;
    CHECK_FALSE(certified_filter_row(r, p, with));
    const auto row = sweep_evaluate<double>(p, with);
    CHECK_FALSE(row.failed);
    CHECK(row.r_res == sweep_evaluate<double>(p, without).r_res);
  }
  // Degenerate pairs (m_min = 0) and tiny x: whatever the filter decides equals the fallback.
  for (const auto& p : {pair_of(5, 3), pair_of(1001, 999), pair_of(500001, 500000), pair_of(1000000001, 1000000000),
                        pair_of(7, 1), pair_of(1000000, 1)}) {
    const auto r1 = sweep_evaluate<double>(p, with), r0 = sweep_evaluate<double>(p, without);
    CHECK_FALSE(r1.failed);
    CHECK(r1.r_res == r0.r_res);
    CHECK(r1.theta_first == r0.theta_first);
    CHECK(r1.t_first == r0.t_first);
    CHECK(r1.t_min_paper == r0.t_min_paper);
    CHECK(r1.t_ratio == r0.t_ratio);
    CHECK(r1.asy_error == r0.asy_error);
    CHECK(r1.asy_bound == r0.asy_bound);
    CHECK(r1.asy_ratio == r0.asy_ratio);
    CHECK(r1.asy_constant == r0.asy_constant);
    CHECK(r1.status == r0.status);
  }
}


TEST_CASE("filter: sin and cos over a ball from the balls at a nearby point", "[filter][near]") {
  scoped_digits sd(hp_digits);
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> Upoint(0.001, 1.5), R(0, 1), sign(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    const double u0 = Upoint(rng);
    const dd_trig_point P = dd_trig_at(double_double(u0));
    // U's centre 2^-10 to 2^-60 from u0 (the remainder t^2/2 from 2^-21 down to far below the
    // balls' radii), radius up to the offset.
    const double offset = std::ldexp(sign(rng), -10 - i % 51), radius = std::fabs(offset) * R(rng);
    const dd_ball U{dd::add(double_double(u0), double_double(offset)), radius};
    dd_ball s, c;
    dd_sin_cos_near(P, U, s, c);
    for (int e = -1; e <= 1; ++e) {
      const mpfr_real v = hp(U.m) + e * mpfr_real(U.r);
      INFO("u0 = " << u0 << ", offset " << offset << ", radius " << radius << ", end " << e);
      CHECK(holds(s, sin(v)));
      CHECK(holds(c, cos(v)));
    }
    // Narrow as the ball sin_cos for near points: U's radius (sin, cos are 1-Lipschitz), and
    // t^2/2 and the operations' errors beyond it.
    if (std::fabs(offset) < 0x1p-50) {
      CHECK(s.r < radius * (1 + 0x1p-40) + 0x1p-96);
      CHECK(c.r < radius * (1 + 0x1p-40) + 0x1p-96);
    }
  }
}
