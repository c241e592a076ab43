// The double path's accuracy (core/double_double.hpp, theorem/root.hpp theorem_root_refined,
// theorem/minimum.hpp theorem_minimum_double) against MPFR computed here at 200 bits and the
// proved enclosures of prove_pair_values: sines and cosines within their stated bounds, u* within
// 2^-60, and r_res, theta_first, t_first within one ulp of the exact value for every pair tried.
#include <catch2/catch.hpp>

#include <mpfr.h>

#include <cmath>
#include <random>
#include <atomic>
#include <thread>
#include <vector>

#include <gyrores/core/thread_caches.hpp>
#include <gyrores/gyrores.hpp>

#include "reference/dd_sin_cos.hpp"
#include "reference/lattice.hpp"  // minimiser_lobes_modular

using namespace gyrores;

namespace {

struct mp {
  mpfr_t v;
  mp() { mpfr_init2(v, 200); }
  explicit mp(const double_double& x) : mp() {
    mpfr_set_d(v, x.hi, MPFR_RNDN);
    mpfr_add_d(v, v, x.lo, MPFR_RNDN);
  }
  ~mp() { mpfr_clear(v); }
  mp(const mp&) = delete;
  mp& operator=(const mp&) = delete;
  operator mpfr_ptr() { return v; }
};

// |x - ref| as a multiple of 2^e |scale| (a double, enough to compare with bounds).
double error_in(const double_double& x, mpfr_ptr ref, double scale) {
  mp d(x);
  mpfr_sub(d, d, ref, MPFR_RNDN);
  return std::fabs(mpfr_get_d(d, MPFR_RNDN)) / scale;
}

// |value - ref| in ulps of ref (ref the exact value to 200 bits).
double ulps(double value, mpfr_ptr ref) {
  mp d;
  mpfr_set_d(d, value, MPFR_RNDN);
  mpfr_sub(d, d, ref, MPFR_RNDN);
  const double r = mpfr_get_d(ref, MPFR_RNDN);
  return std::fabs(mpfr_get_d(d, MPFR_RNDN)) / (std::nextafter(std::fabs(r), INFINITY) - std::fabs(r));
}

void set_decimal(mpfr_ptr out, const std::string& text) { mpfr_set_str(out, text.c_str(), 10, MPFR_RNDN); }

// s, c against MPFR's sin x, cos x: required within 2^-63 |sin x| and 2^-63; the worst errors
// seen (in those units) kept in worst_s, worst_c.
void require_sin_cos_2_63(const double_double& x, const double_double& s, const double_double& c, double& worst_s,
                          double& worst_c) {
  mp X(x), S, C;
  mpfr_sin_cos(S, C, X, MPFR_RNDN);
  const double es = error_in(s, S, 0x1p-63 * std::fabs(mpfr_get_d(S, MPFR_RNDN)));
  const double ec = error_in(c, C, 0x1p-63);
  worst_s = std::max(worst_s, es);
  worst_c = std::max(worst_c, ec);
  INFO("x = " << x.hi << " + " << x.lo);
  REQUIRE(es <= 1);
  REQUIRE(ec <= 1);
}

}  // namespace

TEST_CASE("double_double: sin and cos within 2^-63 for |x| < 2", "[double_double]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-2, 2), tiny(-40, 0);
  double worst_s = 0, worst_c = 0;
  for (int i = 0; i < 20000; ++i) {
    double_double x;
    if (i % 4 == 3) x = double_double(std::copysign(std::pow(2.0, tiny(rng)), unit(rng)));  // down to 2^-40
    else if (i % 4 == 2) x = double_double(std::floor(unit(rng) * 128) / 128, 0x1p-60 * unit(rng));  // at the table's points
    else x = dd::two_sum(unit(rng), 0x1p-54 * unit(rng));
    if (std::fabs(x.hi) >= 2) continue;
    double_double s, c;
    dd_sin_cos(x, s, c);
    require_sin_cos_2_63(x, s, c, worst_s, worst_c);
  }
  // The bounds are not vacuous: the worst case uses a fair part of them, and 2^-90 would fail.
  CHECK(worst_s > 0x1p-30);
  CHECK(worst_c > 0x1p-30);
  WARN("worst sin error " << worst_s << " x 2^-63 |sin x|, cos " << worst_c << " x 2^-63");
}

TEST_CASE("double_double: the first quadrant's sin and cos within 2^-63 for 0 <= x <= 3/2", "[double_double]") {
  // dd_sin_cos_first_quadrant (the theorem root's Newton step) on the same kinds of arguments:
  // random double-doubles with a full low part (its first-order term), the table's points and
  // just below them (d near 2^-7), and tiny ones.
  const sin_cos_table& table = dd_sin_cos_table();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1.5), sign(-1, 1), tiny(-40, 0);
  double worst_s = 0, worst_c = 0;
  for (int i = 0; i < 40000; ++i) {
    double_double x;
    if (i % 4 == 3) x = dd::two_sum(std::pow(2.0, tiny(rng)), 0);
    else if (i % 4 == 2) x = dd::two_sum(std::nextafter(std::ceil(unit(rng) * 128) / 128, 0), 0x1p-54 * sign(rng));
    else x = dd::two_sum(unit(rng), 0x1p-53 * sign(rng));
    x = dd::fast_two_sum(x.hi, x.lo);
    if (x.hi < 0 || x.hi > 1.5) continue;
    double_double s, c;
    dd_sin_cos_first_quadrant(table, x, s, c);
    REQUIRE(std::fabs(s.lo) <= 0x1p-53 * std::fabs(s.hi));  // normalised
    REQUIRE(std::fabs(c.lo) <= 0x1p-53 * std::fabs(c.hi));
    require_sin_cos_2_63(x, s, c, worst_s, worst_c);
  }
  CHECK(worst_s > 0x1p-30);
  CHECK(worst_c > 0x1p-30);
  WARN("first quadrant: worst sin error " << worst_s << " x 2^-63 |sin x|, cos " << worst_c << " x 2^-63");
}

TEST_CASE("double_double: the arithmetic's error bounds", "[double_double]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.5, 2);
  for (int i = 0; i < 20000; ++i) {
    const double_double a = dd::two_sum(u(rng), 0x1p-53 * u(rng)), b = dd::two_sum(u(rng), 0x1p-54 * u(rng));
    mp A(a), B(b), r;
    mpfr_mul(r, A, B, MPFR_RNDN);
    REQUIRE(error_in(dd::mul(a, b), r, 7 * 0x1p-106 * mpfr_get_d(r, MPFR_RNDN)) <= 1);
    mpfr_div(r, A, B, MPFR_RNDN);
    REQUIRE(error_in(dd::div(a, b), r, 16 * 0x1p-106 * mpfr_get_d(r, MPFR_RNDN)) <= 1);
    mpfr_add(r, A, B, MPFR_RNDN);
    REQUIRE(error_in(dd::add(a, b), r, 3 * 0x1p-106 * mpfr_get_d(r, MPFR_RNDN)) <= 1);
    mpfr_sqrt(r, A, MPFR_RNDN);
    REQUIRE(error_in(dd::sqrt(a), r, 4 * 0x1p-106 * mpfr_get_d(r, MPFR_RNDN)) <= 1);
    const double n = std::floor(u(rng) * 1e15), d = std::floor(u(rng) * 1e15) + 1;
    mpfr_set_d(r, n, MPFR_RNDN);
    mpfr_div_d(r, r, d, MPFR_RNDN);
    REQUIRE(error_in(dd::quotient(n, d), r, 0x1p-104 * mpfr_get_d(r, MPFR_RNDN)) <= 1);
  }
  mp p;
  mpfr_const_pi(p, MPFR_RNDN);
  CHECK(error_in(dd::pi, p, 0x1p-106) <= 1);
  const std::int64_t big = (std::int64_t(1) << 62) + 12345;
  const double_double b = dd::of_int(big);
  CHECK(int128(b.hi) + int128(b.lo) == big);
}

TEST_CASE("double_double: integers exactly below 2^106, within 2^-106 (1 + 2^-20) below 2^126", "[double_double]") {
  std::mt19937_64 rng(13);
  for (int i = 0; i < 20000; ++i) {
    const int bits = 1 + int(rng() % 125);
    const auto raw = (static_cast<unsigned __int128>(rng()) << 64) | rng();
    int128 v = int128(raw >> (128 - bits));
    if (i % 3 == 0) v = -v;
    const double_double x = dd::of_int(v);
    INFO("bits " << bits << ", v = " << to_big(v).str());
    REQUIRE(std::fabs(x.lo) <= 0.5 * (std::nextafter(std::fabs(x.hi), INFINITY) - std::fabs(x.hi)));  // normalised
    // hi and lo are integers here (|lo| >= 1 or 0), so the integer sum is the value.
    const big_int sum = to_big(int128(x.hi)) + to_big(int128(x.lo)), err = abs(sum - to_big(v));
    if (bits <= 106) REQUIRE(err == 0);
    else REQUIRE(err.convert_to<double>() <= 0x1p-106 * (1 + 0x1p-20) * std::fabs(x.hi));
  }
}

TEST_CASE("double_double: u* of theorem_root_refined within 2^-60 of the root, sin w* within 2^-59.7", "[double_double]") {
  // The root by bisection in MPFR at 200 bits on x u + atan(x tan u) = pi m/(2a).
  std::mt19937_64 rng(5);
  for (int i = 0; i < 300; ++i) {
    const std::int64_t a = 3 + std::int64_t(rng() % (i < 150 ? 1000 : (std::uint64_t(1) << 60)));
    std::int64_t b = 1 + std::int64_t(rng() % std::uint64_t(a - 1));
    if ((a - b) % 2) ++b;  // tau, sigma integers: a and b of one parity
    if (b >= a) b -= 2;
    if (b < 1 || std::gcd(a, b) > 2) continue;
    const int m = theorem_m_min(a);
    if (m == 0) continue;
    const double_double x = dd::div(dd::of_int(b), dd::of_int(a));
    const double_double mu = dd::div(dd::mul(dd::pi, double(m)), dd::of_int(2 * a));
    const root_double_double r = theorem_root_refined(x, mu);
    mp X, MU, lo, hi, mid, f, t;
    mpfr_set_si(X, b, MPFR_RNDN);
    mpfr_div_si(X, X, a, MPFR_RNDN);
    mpfr_const_pi(MU, MPFR_RNDN);
    mpfr_mul_si(MU, MU, m, MPFR_RNDN);
    mpfr_div_si(MU, MU, 2 * a, MPFR_RNDN);
    mpfr_set_ui(lo, 0, MPFR_RNDN);
    mpfr_const_pi(hi, MPFR_RNDN);
    mpfr_div_ui(hi, hi, 2, MPFR_RNDN);
    for (int k = 0; k < 190; ++k) {
      mpfr_add(mid, lo, hi, MPFR_RNDN);
      mpfr_div_ui(mid, mid, 2, MPFR_RNDN);
      mpfr_tan(t, mid, MPFR_RNDN);
      mpfr_mul(t, t, X, MPFR_RNDN);
      mpfr_atan(t, t, MPFR_RNDN);
      mpfr_mul(f, X, mid, MPFR_RNDN);
      mpfr_add(f, f, t, MPFR_RNDN);
      if (mpfr_cmp(f, MU) < 0) mpfr_set(lo, mid, MPFR_RNDN);
      else mpfr_set(hi, mid, MPFR_RNDN);
    }
    INFO("a = " << a << ", b = " << b);
    REQUIRE(error_in(r.u, lo, 0x1p-60 * mpfr_get_d(lo, MPFR_RNDN)) <= 1);
    mpfr_sin_cos(f, t, lo, MPFR_RNDN);
    REQUIRE(error_in(r.sin_u, f, 0x1p-60 * mpfr_get_d(f, MPFR_RNDN)) <= 1);
    REQUIRE(error_in(r.cos_u, t, 0x1p-60) <= 1);
    // sin w* = sin(mu - x u*) within 2^-59.7 (theorem/root.hpp; r_res is formed from it).
    mpfr_mul(t, X, lo, MPFR_RNDN);
    mpfr_sub(t, MU, t, MPFR_RNDN);
    mpfr_sin(f, t, MPFR_RNDN);
    REQUIRE(error_in(r.sin_w, f, std::exp2(-59.7) * mpfr_get_d(f, MPFR_RNDN)) <= 1);
  }
}

namespace {

// r_res, theta_first, t_first of theorem_minimum_double within one ulp of the proved 25-digit
// values (whose own error is below 10^-24 relative, far below an ulp).
template <class M> void check_minimum(const M& m, const resonant_pair<big_int>& p, double& worst) {
  const pair_report pr = prove_pair_values(p, 25);
  mp ref;
  INFO(p.str());
  for (auto [value, text] : {std::pair{m.r_res, pr.r_res.value}, std::pair{m.theta_first, pr.theta_first.value},
                             std::pair{m.t_first, pr.t_first.value}}) {
    set_decimal(ref, text);
    if (mpfr_zero_p(ref.v)) {
      REQUIRE(value == 0);
      continue;
    }
    const double e = ulps(value, ref);
    worst = std::max(worst, e);
    REQUIRE(e <= 1);
  }
}

void check_pair(const resonant_pair<std::int64_t>& p, double& worst) {
  check_minimum(theorem_minimum_double(p), resonant_pair<big_int>(big_int(p.tau()), big_int(p.sigma())), worst);
}

}  // namespace

TEST_CASE("double_double: theorem_minimum_double within an ulp for every pair up to order 200 and large pairs",
          "[double_double]") {
  double worst = 0;
  int n = 0;
  for (const auto& p : coprime_pairs(3, 200)) check_pair(p, worst), ++n;
  std::mt19937_64 rng(3);
  for (int i = 0; i < 400; ++i) {
    const int bits = 10 + int(rng() % 51);  // orders up to 2^61
    const std::int64_t tau = std::int64_t(rng() >> (64 - bits)) + 2;
    const std::int64_t sigma = 1 + std::int64_t(rng() % std::uint64_t(i % 3 == 0 ? 10 : tau - 1));
    if (std::gcd(tau, sigma) != 1 || sigma >= tau) continue;
    check_pair(resonant_pair<std::int64_t>(tau, sigma), worst), ++n;
  }
  CHECK(n > 6000);
  WARN(n << " pairs, worst " << worst << " ulp");
}

// The done-when of the double path: every row of `gyrores sweep --max-order 3000` in double
// (1.37e6 pairs) within one ulp of the --certified row's proved value (the midpoint of an
// enclosure of relative width below 2^-80, so the correctly rounded double or next to it).
// About a minute on 2 cores: run by ctest only with -DGYRORES_LONG_TESTS=ON (label long).
TEST_CASE("double_double: sweep rows to order 3000 within an ulp of the certified rows", "[.long]") {
  sweep_config plain, certified;
  plain.max_order = certified.max_order = 3000;
  certified.certified = true;
  std::atomic<std::int64_t> pairs{0}, over{0};
  auto work = [&](std::int64_t shard, std::int64_t shards) {
    coprime_pairs all(3, 3000, shard, shards);
    for (const auto& p : all) {
      const sweep_row<double> d = sweep_evaluate<double>(p, plain), c = sweep_evaluate<double>(p, certified);
      ++pairs;
      for (auto [x, y] : {std::pair{d.r_res, c.r_res}, std::pair{d.theta_first, c.theta_first},
                          std::pair{d.t_first, c.t_first}}) {
        if (x == y) continue;
        if (std::fabs(x - y) > std::nextafter(std::fabs(y), INFINITY) - std::fabs(y)) ++over;
      }
    }
    release_thread_caches();
  };
  const unsigned n = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (unsigned i = 0; i < n; ++i) threads.emplace_back(work, i, n);
  for (auto& t : threads) t.join();
  CHECK(pairs == 1368093);
  CHECK(over == 0);
}

namespace {

// A random coprime pair of order below 2^bits (bits <= 119): tau up to 2^(bits-1), sigma either
// small or of tau's size (x tiny and x near 1 both), as big_int.
resonant_pair<big_int> random_wide_pair(std::mt19937_64& rng, int bits, int i) {
  for (;;) {
    auto draw = [&](int n) {  // uniform below 2^n
      unsigned __int128 v = (unsigned __int128)(rng()) << 64 | rng();
      return int128(v >> (128 - n));
    };
    const int128 tau = draw(bits - 1) + 2;
    const int128 sigma = i % 3 == 0 ? 1 + int128(rng() % 10) : 1 + draw(bits - 1) % (tau - 1);
    const big_int t = to_big(tau), s = to_big(sigma);
    if (s < t && int_gcd(t, s) == 1) return resonant_pair<big_int>(t, s);
  }
}

}  // namespace

TEST_CASE("double_double: the lobes by one Euclid are the theorem's lobes", "[double_double]") {
  for (const auto& p : coprime_pairs(3, 300)) {
    const std::int64_t a = std::int64_t(p.order()), b = p.delta();
    const auto fast = minimiser_lobes(a, b), ref = minimiser_lobes_modular(a, b);
    REQUIRE(fast.size() == ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i) {
      INFO(p.str() << " lobe " << i);
      REQUIRE(fast[i].k == ref[i].k);
      REQUIRE(fast[i].j == ref[i].j);
      REQUIRE(fast[i].m == ref[i].m);
    }
  }
  std::mt19937_64 rng(17);
  for (int i = 0; i < 500; ++i) {
    const auto p = random_wide_pair(rng, 63 + i % 57, i);
    const big_int a = p.order(), b = big_int(p.delta());
    const auto fast = minimiser_lobes(to_int128(a), to_int128(b));
    const auto ref = minimiser_lobes_modular(a, b);
    INFO(p.str());
    REQUIRE(fast.size() == ref.size());
    for (std::size_t i2 = 0; i2 < ref.size(); ++i2) {
      REQUIRE(to_big(fast[i2].k) == ref[i2].k);
      REQUIRE(to_big(fast[i2].j) == ref[i2].j);
      REQUIRE(to_big(fast[i2].m) == ref[i2].m);
    }
  }
  CHECK_THROWS_AS(minimiser_lobes(std::int64_t(15), std::int64_t(3)), usage_error);  // (9, 6)
  // minimiser_lobes_big (int64 Euclid below order 2^62) against the big-integer modular inverse.
  auto same_big = [](const big_int& a, const big_int& b) {
    const auto fast = minimiser_lobes_big(a, b), ref = minimiser_lobes_modular(a, b);
    INFO("a = " << a << ", b = " << b);
    REQUIRE(fast.size() == ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i)
      REQUIRE((fast[i].k == ref[i].k && fast[i].j == ref[i].j && fast[i].m == ref[i].m));
  };
  for (const auto& p : coprime_pairs(3, 300)) same_big(to_big(p.order()), big_int(p.delta()));
  for (int i = 0; i < 300; ++i) {
    const auto p = random_wide_pair(rng, 40 + i % 24, i);  // orders 2^40 to 2^64: both sides of 2^62
    same_big(p.order(), big_int(p.delta()));
  }
}

// The int128 double path (orders 2^62 to 2^120): r_res, theta_first, t_first within one ulp of
// the proved 25-digit values, as for the int64 path.
TEST_CASE("double_double: theorem_minimum_double within an ulp for pairs of order up to 2^120", "[double_double]") {
  std::mt19937_64 rng(29);
  double worst = 0;
  int n = 0;
  auto check = [&](const resonant_pair<big_int>& p) {
    check_minimum(theorem_minimum_double(p), p, worst);
    ++n;
  };
  const big_int e30("1000000000000000000000000000000");
  check(resonant_pair<big_int>(e30 + 1, e30));
  for (int i = 0; i < 300; ++i) check(random_wide_pair(rng, 62 + i % 58, i));
  // An int64 pair of order between 2^62 and 2^63 takes the int128 arithmetic and agrees.
  const std::int64_t big = (std::int64_t(1) << 62) - 1;
  const auto narrow = theorem_minimum_double(resonant_pair<std::int64_t>(big, big - 2));
  const auto wide = theorem_minimum_double(resonant_pair<big_int>(big_int(big), big_int(big - 2)));
  CHECK(narrow.r_res == wide.r_res);
  CHECK(narrow.theta_first == wide.theta_first);
  CHECK(narrow.t_first == wide.t_first);
  CHECK(int128(narrow.lobes[0].k) == wide.lobes[0].k);
  CHECK_THROWS_AS(theorem_minimum_double(resonant_pair<big_int>(big_int(1) << 120, big_int(1))), usage_error);
  WARN(n << " pairs of order 2^62 to 2^120, worst " << worst << " ulp");
}

// dd_sin_cos_accurate (the certified sweep's balls, core/dd_ball.hpp) against MPFR at 320 bits:
// sin within 2^-101 |sin x|, cos within 2^-101, where its reduction and polynomials are weakest:
// near 0 and down to the subnormals, at and just below each table point i 2^-7 (d near 0 and
// near 2^-7), near |x| = 2, negatives, and low parts at every scale.
namespace {

struct accurate_worst {
  double s = 0, c = 0;  // the largest errors seen, in units of the stated bounds
};

// |x.hi + x.lo - ref| / (2^-101 scale), in MPFR (scale may be subnormal or 0).
double in_units(const double_double& x, mpfr_srcptr ref, mpfr_srcptr scale) {
  mpfr_t d, s;
  mpfr_inits2(320, d, s, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(d, x.hi, MPFR_RNDN);
  mpfr_add_d(d, d, x.lo, MPFR_RNDN);
  mpfr_sub(d, d, ref, MPFR_RNDN);
  mpfr_abs(d, d, MPFR_RNDN);
  mpfr_mul_2si(s, scale, -101, MPFR_RNDN);
  mpfr_abs(s, s, MPFR_RNDN);
  double out;
  if (mpfr_zero_p(s)) out = mpfr_zero_p(d) ? 0 : INFINITY;
  else {
    mpfr_div(d, d, s, MPFR_RNDU);
    out = mpfr_get_d(d, MPFR_RNDU);
  }
  mpfr_clears(d, s, static_cast<mpfr_ptr>(nullptr));
  return out;
}

void check_accurate(const double_double& x, accurate_worst& w) {
  double_double s, c;
  dd_sin_cos_accurate(x, s, c);
  mpfr_t X, S, C, one;
  mpfr_inits2(320, X, S, C, one, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(X, x.hi, MPFR_RNDN);
  mpfr_add_d(X, X, x.lo, MPFR_RNDN);  // exact: the parts are at most 107 bits apart
  mpfr_sin_cos(S, C, X, MPFR_RNDN);
  mpfr_set_ui(one, 1, MPFR_RNDN);
  const double es = in_units(s, S, S), ec = in_units(c, C, one);
  mpfr_clears(X, S, C, one, static_cast<mpfr_ptr>(nullptr));
  w.s = std::max(w.s, es);
  w.c = std::max(w.c, ec);
  INFO("x = " << x.hi << " + " << x.lo << " (" << std::hexfloat << x.hi << " + " << x.lo << std::defaultfloat
              << "): sin error " << es << ", cos error " << ec << " x 2^-101");
  REQUIRE(es <= 1);
  REQUIRE(ec <= 1);
}

// x and -x, with low parts l and -l (|l| within half an ulp of x).
void check_both_signs(double hi, double lo, accurate_worst& w) {
  for (double sign : {1.0, -1.0})
    for (double l : {lo, -lo}) {
      const double_double x = dd::two_sum(sign * hi, sign * l);
      if (std::fabs(x.hi) < 2) check_accurate(x, w);
    }
}

}  // namespace

TEST_CASE("double_double: dd_sin_cos_accurate within 2^-101 for |x| < 2", "[double_double][sin_cos_accurate]") {
  accurate_worst w;
  check_accurate(double_double(0.0), w);
  check_accurate(double_double(-0.0), w);
  std::mt19937_64 rng(101);
  std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
  // Tiny and small arguments: 2^-p for p = 1..1074, with and without low parts.
  for (int p = 1; p <= 1074; ++p) {
    const double v = std::ldexp(1 + unit(rng), -p);
    check_both_signs(v, 0, w);
    if (p < 960) check_both_signs(v, std::ldexp(signed_unit(rng), -p - 54), w);
  }
  // Around each table point c = i 2^-7: d at 0 (exactly, and just below or above through the low
  // part), small d, and d just below 2^-7 (next point's reach).
  for (int i = 1; i < 256; ++i) {
    const double c = i * 0x1p-7;
    check_both_signs(c, 0, w);
    check_both_signs(c, 0x1p-60 * signed_unit(rng), w);
    for (int k = 9; k <= 60; k += 3) check_both_signs(c + std::ldexp(unit(rng), -k), std::ldexp(signed_unit(rng), -k - 54), w);
    const double below_next = std::nextafter((i + 1) * 0x1p-7, 0.0);
    check_both_signs(below_next, 0x1p-55 * unit(rng) * std::fabs(below_next), w);
    check_both_signs(c + 0x1p-7 * (1 - unit(rng) * 0x1p-10), 0x1p-56 * signed_unit(rng), w);
  }
  // Near |x| = 2.
  for (int k = 1; k <= 53; ++k) check_both_signs(2 - std::ldexp(1, -k), 0x1p-55 * unit(rng), w);
  check_both_signs(std::nextafter(2.0, 0.0), 0x1p-54 * unit(rng), w);
  // Uniform over (-2, 2), with low parts.
  for (int n = 0; n < 40000; ++n) {
    const double hi = 2 * signed_unit(rng);
    check_both_signs(hi, 0x1p-53 * std::fabs(hi) * signed_unit(rng), w);
  }
  // Not vacuous: the worst error uses a fair part of each bound (dd_sin_cos, at 2^-63, would
  // exceed it by 2^30), and the bound is within a factor 2^6 of what is reached.
  CHECK(w.s > 0x1p-6);
  CHECK(w.c > 0x1p-6);
  WARN("dd_sin_cos_accurate: worst sin error " << w.s << " x 2^-101 |sin x|, cos " << w.c << " x 2^-101");
}
