// Resonant pairs and their exact integer helpers (pair.hpp, integer.hpp).
//
// Oracles: std::gcd (int64), GMP's mpz_gcd through boost::multiprecision::gcd (big_int), known
// answers built as odd * 2^v for the 2-adic valuation, hand-computed tables and exact big-integer
// arithmetic for orders that overflow 64 bits. Random loops use a fixed printed seed and scale with
// GYRORES_TEST_MULTIPLIER.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gyrores/core/decimal.hpp>
#include <gyrores/model/enumerate.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/model/pair.hpp>

#include "testing/test_support.hpp"

using gyrores::big_int;
using gyrores::coprime_pairs;
using gyrores::known_coprime;
using gyrores::resonant_pair;
using gyrores::usage_error;
using p64 = resonant_pair<std::int64_t>;
using pbig = resonant_pair<big_int>;

namespace {
constexpr std::uint64_t kSeed = 20240611u;

big_int pow10(unsigned e) {
  big_int r = 1;
  for (unsigned i = 0; i < e; ++i) r *= 10;
  return r;
}
big_int pow2(unsigned e) { return big_int(1) << e; }

// Membership of the paper's low-order set R_low(M) = {coprime tau > sigma >= 1, tau + sigma <= M}
// (the sweep's enumeration bound, model/enumerate.hpp).
template <gyrores::pair_integer I> bool pair_in_low_order_set(const resonant_pair<I>& p, const big_int& max_order) {
  return gyrores::to_big(p.order()) <= max_order;
}

// The beat ratio (tau + sigma)/(tau - sigma) = 1/x as an exact fraction {numerator, denominator}
// (not reduced: gcd(a, b) is 1 or 2).
template <gyrores::pair_integer I> struct int_fraction {
  gyrores::wide_int<I> num, den;
};
template <gyrores::pair_integer I> int_fraction<I> pair_beat_ratio(const resonant_pair<I>& p) {
  return {p.order(), gyrores::wide_int<I>(p.delta())};
}

// Exception message of a throwing callable ("" if it does not throw usage_error).
template <class F> std::string usage_message(F&& f) {
  try {
    f();
  } catch (const usage_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("int_gcd: table and edge values", "[pair][gcd]") {
  using gyrores::int_gcd;
  CHECK(int_gcd<std::int64_t>(0, 0) == 0);
  CHECK(int_gcd<std::int64_t>(0, 7) == 7);
  CHECK(int_gcd<std::int64_t>(7, 0) == 7);
  CHECK(int_gcd<std::int64_t>(-12, 18) == 6);
  CHECK(int_gcd<std::int64_t>(12, -18) == 6);
  CHECK(int_gcd<std::int64_t>(1, 1) == 1);
  CHECK(int_gcd<std::int64_t>(33, 27) == 3);
  CHECK(int_gcd<std::int64_t>(35, 29) == 1);
  CHECK(int_gcd<std::int64_t>(41, 35) == 1);
  // Consecutive Fibonacci numbers: the worst case of Euclid's algorithm.
  CHECK(int_gcd<std::int64_t>(7540113804746346429LL, 4660046610375530309LL) == 1);
  CHECK(int_gcd<std::int64_t>(std::numeric_limits<std::int64_t>::max(), 7 * 73) == 7 * 73);  // 2^63-1 = 7^2*73*...
  CHECK(int_gcd(big_int(0), big_int(0)) == 0);
  CHECK(int_gcd(pow10(40), pow10(30) * 7) == pow10(30));
  CHECK(int_gcd(pow10(30) + 1, pow10(30)) == 1);
}

TEST_CASE("int_gcd: randomised against std::gcd and mpz_gcd", "[pair][gcd][random]") {
  using gyrores::int_gcd;
  const int iters = 20000 * gyrores::test::multiplier();
  std::mt19937_64 rng(kSeed);
  WARN("int_gcd random test: seed " << kSeed << ", iterations " << iters << " (GYRORES_TEST_MULTIPLIER scales)");
  INFO("seed " << kSeed << ", iterations " << iters);
  for (int it = 0; it < iters; ++it) {
    // Random magnitudes (1..62 bits), a shared random factor half the time, rare edge values.
    auto rnd = [&](int bits) { return std::int64_t(rng() >> (64 - bits)); };
    std::int64_t g = (rng() & 1) ? rnd(1 + int(rng() % 20)) + 1 : 1;
    std::int64_t x = rnd(1 + int(rng() % 40)), y = rnd(1 + int(rng() % 40));
    if (g > 1 && x < (std::int64_t(1) << 40) && y < (std::int64_t(1) << 40)) { x *= g; y *= g; }
    switch (rng() % 1000) {
      case 0: x = 0; break;
      case 1: y = 0; break;
      case 2: x = y; break;
      case 3: x = 1; break;
      default: break;
    }
    if (rng() & 1) x = -x;
    if (rng() & 1) y = -y;
    INFO("x = " << x << ", y = " << y);
    REQUIRE(int_gcd(x, y) == std::gcd(x, y));
    // big_int: multiply by random big factors; gcd scales exactly.
    big_int bx = big_int(x) * pow2(unsigned(rng() % 100)), by = big_int(y) * pow2(unsigned(rng() % 100));
    REQUIRE(int_gcd(bx, by) == boost::multiprecision::gcd(bx, by));
    big_int k = big_int(rng() | 1) * big_int(rng() | 1);
    REQUIRE(int_gcd(big_int(x) * k, big_int(y) * k) == big_int(std::gcd(x, y)) * k);
  }
}

TEST_CASE("int_v2: known answers odd * 2^v, and v2(0) rejected", "[pair][v2][random]") {
  using gyrores::int_v2;
  CHECK(int_v2<std::int64_t>(1) == 0);
  CHECK(int_v2<std::int64_t>(2) == 1);
  CHECK(int_v2<std::int64_t>(12) == 2);
  CHECK(int_v2<std::int64_t>(-8) == 3);
  CHECK(int_v2<std::int64_t>(std::int64_t(1) << 62) == 62);
  CHECK(int_v2<std::int64_t>(std::numeric_limits<std::int64_t>::min()) == 63);
  CHECK(int_v2(pow2(300)) == 300);
  CHECK(int_v2(big_int(-48)) == 4);
  CHECK_THROWS_AS(int_v2<std::int64_t>(0), std::domain_error);
  CHECK_THROWS_AS(int_v2(big_int(0)), std::domain_error);

  const int iters = 20000 * gyrores::test::multiplier();
  std::mt19937_64 rng(kSeed + 1);
  INFO("seed " << (kSeed + 1) << ", iterations " << iters);
  for (int it = 0; it < iters; ++it) {
    unsigned v = unsigned(rng() % 62);
    std::int64_t odd = std::int64_t((rng() >> (v + 2)) | 1);  // odd, and odd * 2^v < 2^62
    std::int64_t n = odd << v;
    if (rng() & 1) n = -n;
    INFO("odd = " << odd << ", v = " << v);
    REQUIRE(int_v2(n) == v);
    unsigned vb = unsigned(rng() % 400);
    big_int nb = (big_int(rng() | 1) * big_int(rng()) * 2 + 1) * pow2(vb);
    INFO("big v = " << vb);
    REQUIRE(int_v2(nb) == vb);
  }
}

TEST_CASE("pair invariants: order, delta, delta mod 4, v2, degeneracy, strand offset", "[pair]") {
  struct row {
    std::int64_t tau, sigma, order, delta;
    int mod4;
    unsigned v2;
    bool degenerate;
    int offset;
  };
  const row rows[] = {
      {2, 1, 3, 1, 1, 0, false, 1},     {3, 1, 4, 2, 2, 1, true, 0},      {5, 1, 6, 4, 0, 2, false, 2},
      {6, 5, 11, 1, 1, 0, false, 1},    {9, 4, 13, 5, 1, 0, false, 1},    {11, 9, 20, 2, 2, 1, true, 0},
      {41, 35, 76, 6, 2, 1, true, 0},   {35, 29, 64, 6, 2, 1, true, 0},   {13, 5, 18, 8, 0, 3, false, 2},
      {7, 4, 11, 3, 3, 0, false, 1},    {1000, 1, 1001, 999, 3, 0, false, 1},
      {17, 1, 18, 16, 0, 4, false, 2},  {101, 100, 201, 1, 1, 0, false, 1},
  };
  for (std::size_t i = 0; i < std::size(rows); ++i) {
    const auto& r = rows[i];
    INFO("row " << i << ": (" << r.tau << ", " << r.sigma << ")");
    p64 p(r.tau, r.sigma);
    CHECK(p.tau() == r.tau);
    CHECK(p.sigma() == r.sigma);
    CHECK(gyrores::to_decimal(p.order()) == std::to_string(r.order));
    CHECK(p.delta() == r.delta);
    CHECK(p.delta_mod4() == r.mod4);
    CHECK(p.v2_delta() == r.v2);
    CHECK(p.degenerate() == r.degenerate);
    CHECK(p.strand_offset_min() == r.offset);
    std::string want_str = "(";  // built by appends: GCC 12 warns falsely (-Wrestrict) on "(" + std::string
    want_str += std::to_string(r.tau);
    want_str += ", ";
    want_str += std::to_string(r.sigma);
    want_str += ")";
    CHECK(p.str() == want_str);
    // The same through big_int.
    pbig q(big_int(r.tau), big_int(r.sigma));
    CHECK(q.order() == big_int(r.order));
    CHECK(q.delta() == big_int(r.delta));
    CHECK(q.delta_mod4() == r.mod4);
    CHECK(q.v2_delta() == r.v2);
    CHECK(q.degenerate() == r.degenerate);
    CHECK(q.strand_offset_min() == r.offset);
    // Beat ratio a/b as an exact (unreduced) fraction.
    auto br = pair_beat_ratio(p);
    CHECK(gyrores::to_decimal(br.num) == std::to_string(r.order));
    CHECK(gyrores::to_decimal(br.den) == std::to_string(r.delta));
  }
}

TEST_CASE("pair invariants: randomised against direct integer arithmetic", "[pair][random]") {
  const int iters = 20000 * gyrores::test::multiplier();
  std::mt19937_64 rng(kSeed + 2);
  INFO("seed " << (kSeed + 2) << ", iterations " << iters);
  int made = 0;
  for (int it = 0; it < iters; ++it) {
    std::int64_t s = std::int64_t(rng() >> (3 + rng() % 60)) + 1;  // < 2^61 + 1: t below never overflows
    std::int64_t t = s + std::int64_t(rng() >> (2 + rng() % 61)) + 1;
    if (t <= s || std::gcd(t, s) != 1) continue;
    ++made;
    INFO("pair (" << t << ", " << s << ")");
    p64 p(t, s);
    std::int64_t d = t - s;
    REQUIRE(p.delta() == d);
    REQUIRE(p.delta_mod4() == int(d % 4));
    REQUIRE(p.degenerate() == (d % 4 == 2));
    REQUIRE(p.v2_delta() == unsigned(__builtin_ctzll(std::uint64_t(d))));
    REQUIRE(gyrores::to_big(p.order()) == big_int(t) + big_int(s));
    int off = p.strand_offset_min();
    // Brute force: min over N of |a - 4N|.
    big_int a = big_int(t) + big_int(s);
    int am = big_int(a % 4).convert_to<int>();
    int brute = std::min(am, 4 - am);
    REQUIRE(off == brute);
  }
  CHECK(made > iters / 10);
}

TEST_CASE("low-order set membership R_low(M)", "[pair]") {
  CHECK(pair_in_low_order_set(p64(2, 1), big_int(3)));
  CHECK_FALSE(pair_in_low_order_set(p64(2, 1), big_int(2)));
  CHECK(pair_in_low_order_set(p64(6, 5), big_int(11)));
  CHECK_FALSE(pair_in_low_order_set(p64(6, 5), big_int(10)));
  CHECK(pair_in_low_order_set(p64(11, 9), big_int(100)));
  std::int64_t big = (std::int64_t(1) << 62);
  p64 wide(big + 1, big - 1);  // order 2^63 does not fit in int64
  CHECK(pair_in_low_order_set(wide, pow2(63)));
  CHECK_FALSE(pair_in_low_order_set(wide, pow2(63) - 1));
  pbig huge(pow10(30) + 1, pow10(30));
  CHECK(pair_in_low_order_set(huge, 2 * pow10(30) + 1));
  CHECK_FALSE(pair_in_low_order_set(huge, 2 * pow10(30)));
  // Membership agrees with the enumeration of R_low(M): every enumerated pair is in, and the count
  // of pairs (tau, sigma) with tau + sigma <= M that are members equals the enumeration's length.
  const std::int64_t M = 60;
  std::int64_t members = 0;
  for (std::int64_t t = 2; t < 2 * M; ++t)
    for (std::int64_t s = 1; s < t; ++s)
      if (std::gcd(t, s) == 1 && pair_in_low_order_set(p64(t, s), big_int(M))) ++members;
  std::int64_t enumerated = 0;
  for (auto p : gyrores::coprime_pairs(3, M)) {
    CHECK(pair_in_low_order_set(p, big_int(M)));
    ++enumerated;
  }
  CHECK(members == enumerated);
}

TEST_CASE("pair_from_ratio: reduction, ordering, rejection of ratio 1", "[pair]") {
  using gyrores::pair_from_ratio;
  CHECK(pair_from_ratio(big_int(6), big_int(5)) == pbig(big_int(6), big_int(5)));
  CHECK(pair_from_ratio(big_int(5), big_int(6)) == pbig(big_int(6), big_int(5)));
  CHECK(pair_from_ratio(big_int(10), big_int(4)) == pbig(big_int(5), big_int(2)));
  CHECK(pair_from_ratio(big_int(4), big_int(10)) == pbig(big_int(5), big_int(2)));
  CHECK(pair_from_ratio(big_int(66), big_int(54)) == pbig(big_int(11), big_int(9)));
  CHECK(pair_from_ratio(big_int(7), big_int(1)) == pbig(big_int(7), big_int(1)));
  CHECK(pair_from_ratio(pow10(31) + 10, pow10(31)) == pbig(pow10(30) + 1, pow10(30)));
  CHECK_THROWS_AS(pair_from_ratio(big_int(3), big_int(3)), usage_error);
  CHECK_THROWS_AS(pair_from_ratio(big_int(12), big_int(12)), usage_error);
  CHECK_THROWS_AS(pair_from_ratio(big_int(0), big_int(3)), usage_error);
  CHECK_THROWS_AS(pair_from_ratio(big_int(3), big_int(0)), usage_error);
  CHECK_THROWS_AS(pair_from_ratio(big_int(-3), big_int(2)), usage_error);

  std::mt19937_64 rng(kSeed + 3);
  const int iters = 5000 * gyrores::test::multiplier();
  INFO("seed " << (kSeed + 3));
  for (int it = 0; it < iters; ++it) {
    std::int64_t x = std::int64_t(rng() % 100000) + 1, y = std::int64_t(rng() % 100000) + 1, k = std::int64_t(rng() % 1000) + 1;
    INFO("ratio " << x * k << "/" << y * k);
    if (x == y) {
      REQUIRE_THROWS_AS(pair_from_ratio(big_int(x * k), big_int(y * k)), usage_error);
      continue;
    }
    auto p = pair_from_ratio(big_int(x * k), big_int(y * k));
    std::int64_t g = std::gcd(x, y);
    REQUIRE(p.tau() == big_int(std::max(x, y) / g));
    REQUIRE(p.sigma() == big_int(std::min(x, y) / g));
  }
}

TEST_CASE("bad pairs are rejected with a message naming the problem", "[pair][errors]") {
  CHECK_THROWS_AS(p64(3, 3), usage_error);
  CHECK_THROWS_AS(p64(2, 3), usage_error);
  CHECK_THROWS_AS(p64(1, 1), usage_error);
  CHECK_THROWS_AS(p64(5, 0), usage_error);
  CHECK_THROWS_AS(p64(5, -1), usage_error);
  CHECK_THROWS_AS(p64(-1, -2), usage_error);
  CHECK_THROWS_AS(pbig(big_int(3), big_int(3)), usage_error);
  CHECK_THROWS_AS(pbig(big_int(4), big_int(0)), usage_error);
  CHECK_THROWS_AS(pbig(pow10(30), pow10(30) + 1), usage_error);

  CHECK_THAT(usage_message([] { p64(5, 0); }), Catch::Contains("sigma must be >= 1"));
  CHECK_THAT(usage_message([] { p64(2, 3); }), Catch::Contains("tau must exceed sigma") && Catch::Contains("(2, 3)"));
  // Non-coprime: the message names the pair, the gcd and the reduced pair.
  std::string m = usage_message([] { p64(6, 4); });
  CHECK_THAT(m, Catch::Contains("(6, 4)") && Catch::Contains("not coprime") && Catch::Contains("reduced pair (3, 2)"));
  m = usage_message([] { p64(33, 27); });
  CHECK_THAT(m, Catch::Contains("gcd 3") && Catch::Contains("reduced pair (11, 9)"));
  m = usage_message([] { pbig(pow10(31) + 10, pow10(31)); });
  CHECK_THAT(m, Catch::Contains("gcd 10") && Catch::Contains("reduced pair (" + (pow10(30) + 1).str() + ", " + pow10(30).str() + ")"));
  std::int64_t big = std::int64_t(1) << 61;
  m = usage_message([&] { p64(3 * big, big); });  // gcd 2^61
  CHECK_THAT(m, Catch::Contains("reduced pair (3, 1)"));
}

TEST_CASE("known_coprime: the same pair without the gcd, the range still checked", "[pair]") {
  // The enumerators build their pairs this way (model/enumerate.hpp, src/lib/sweep/engine.cpp).
  for (auto [t, s] : std::vector<std::pair<std::int64_t, std::int64_t>>{{2, 1}, {6, 5}, {11, 9}, {1000003, 999999}})
    CHECK(resonant_pair<std::int64_t>(t, s, known_coprime) == p64(t, s));
  CHECK(resonant_pair<big_int>(pow10(30) + 1, pow10(30), known_coprime) == pbig(pow10(30) + 1, pow10(30)));
  CHECK_THROWS_AS(resonant_pair<std::int64_t>(3, 3, known_coprime), usage_error);
  CHECK_THROWS_AS(resonant_pair<std::int64_t>(2, 3, known_coprime), usage_error);
  CHECK_THROWS_AS(resonant_pair<std::int64_t>(5, 0, known_coprime), usage_error);
  CHECK_THROWS_AS(resonant_pair<big_int>(big_int(4), big_int(0), known_coprime), usage_error);
  // Every pair of the lazy enumeration is coprime (what its known_coprime relies on).
  for (auto p : coprime_pairs(3, 300)) CHECK(std::gcd(p.tau(), p.sigma()) == 1);
}

TEST_CASE("int64 pairs whose sum overflows 64 bits keep exact order", "[pair][overflow]") {
  const std::int64_t p62 = std::int64_t(1) << 62;
  p64 p(p62 + 1, p62 - 1);  // both odd and 2 apart: coprime
  CHECK(gyrores::to_decimal(p.order()) == "9223372036854775808");  // 2^63 exactly
  CHECK(gyrores::to_big(p.order()) == pow2(63));
  CHECK(p.delta() == 2);
  CHECK(p.delta_mod4() == 2);
  CHECK(p.degenerate());
  const std::int64_t mx = std::numeric_limits<std::int64_t>::max();
  p64 q(mx, mx - 1);
  CHECK(gyrores::to_big(q.order()) == pow2(64) - 3);
  CHECK(gyrores::to_decimal(q.order()) == "18446744073709551613");
  CHECK(q.delta() == 1);
  CHECK(q.strand_offset_min() == 1);  // a = 2^64 - 3 = 1 mod 4
  auto br = pair_beat_ratio(q);
  CHECK(gyrores::to_big(br.num) == pow2(64) - 3);
  // Casting to big_int and back is exact.
  auto qb = gyrores::pair_cast<big_int>(q);
  CHECK(qb.order() == pow2(64) - 3);
  CHECK(gyrores::pair_cast<std::int64_t>(qb) == q);
  CHECK(gyrores::pair_fits_int64(qb));
  CHECK_FALSE(gyrores::pair_fits_int64(pbig(pow2(63) + 1, pow2(63))));
  CHECK_THROWS_AS(gyrores::pair_cast<std::int64_t>(pbig(pow2(63) + 1, pow2(63))), usage_error);
  // to_decimal(int128) at the extremes.
  CHECK(gyrores::to_decimal(gyrores::int128(0)) == "0");
  CHECK(gyrores::to_decimal(-gyrores::int128(p62) * 4) == "-18446744073709551616");
  gyrores::int128 mn = gyrores::int128(1) << 126;
  mn = -mn - mn;  // -2^127, the smallest int128
  CHECK(gyrores::to_decimal(mn) == "-170141183460469231731687303715884105728");
  CHECK(gyrores::to_big(mn) == -pow2(127));
}

TEST_CASE("big_int pairs far beyond 64 bits", "[pair][big]") {
  pbig p(pow10(30) + 1, pow10(30));
  CHECK(p.order() == 2 * pow10(30) + 1);
  CHECK(p.order().str() == "2000000000000000000000000000001");
  CHECK(p.delta() == 1);
  CHECK(p.delta_mod4() == 1);
  CHECK(p.v2_delta() == 0);
  CHECK_FALSE(p.degenerate());
  CHECK(p.strand_offset_min() == 1);
  CHECK(p.str() == "(1000000000000000000000000000001, 1000000000000000000000000000000)");
  CHECK_FALSE(gyrores::pair_fits_int64(p));
  pbig q(pow10(30) + 3, pow10(30) + 1);  // delta 2: odd, 2 apart, coprime
  CHECK(q.degenerate());
  pbig r(pow2(200) + 1, pow2(200) - 3);  // delta 4, both odd, gcd | 4 and odd: coprime
  CHECK(r.delta() == 4);
  CHECK(r.v2_delta() == 2);
  CHECK(r.strand_offset_min() == 2);
  CHECK(r.order() == pow2(201) - 2);
  auto br = pair_beat_ratio(r);
  CHECK(br.num == pow2(201) - 2);
  CHECK(br.den == 4);
}

TEST_CASE("integer helpers: int_mod, int_floor_div, int_inverse_mod, parse_big_int", "[pair][integer][random]") {
  using gyrores::int_floor_div;
  using gyrores::int_inverse_mod;
  using gyrores::int_mod;
  CHECK(int_mod<std::int64_t>(-1, 4) == 3);
  CHECK(int_mod<std::int64_t>(-8, 4) == 0);
  CHECK(int_mod<std::int64_t>(7, 4) == 3);
  CHECK(int_floor_div<std::int64_t>(-7, 2) == -4);
  CHECK(int_floor_div<std::int64_t>(-8, 2) == -4);
  CHECK(int_floor_div<std::int64_t>(7, 2) == 3);
  CHECK(int_inverse_mod<std::int64_t>(3, 10) == 7);
  CHECK_THROWS_AS(int_inverse_mod<std::int64_t>(4, 10), std::domain_error);
  std::mt19937_64 rng(kSeed + 4);
  const int iters = 20000 * gyrores::test::multiplier();
  INFO("seed " << (kSeed + 4));
  for (int it = 0; it < iters; ++it) {
    std::int64_t m = std::int64_t(rng() % 1000000) + 2;
    std::int64_t n = std::int64_t(rng() % 2000000000) - 1000000000;
    INFO("n = " << n << ", m = " << m);
    std::int64_t r = int_mod(n, m);
    REQUIRE(r >= 0);
    REQUIRE(r < m);
    REQUIRE((n - r) % m == 0);
    std::int64_t q = int_floor_div(n, m);
    REQUIRE(q * m <= n);
    REQUIRE(n < (q + 1) * m);
    if (std::gcd(n, m) == 1) {
      std::int64_t inv = int_inverse_mod(n, m);
      REQUIRE(inv >= 0);
      REQUIRE(inv < m);
      REQUIRE(int_mod(gyrores::int128(int_mod(n, m)) * inv, gyrores::int128(m)) == 1);
    } else {
      REQUIRE_THROWS_AS(int_inverse_mod(n, m), std::domain_error);
    }
  }
  CHECK(gyrores::parse_big_int("+123", "tau") == 123);
  CHECK(gyrores::parse_big_int("-1000000000000000000000000000000", "tau") == -pow10(30));
  CHECK_THROWS_AS(gyrores::parse_big_int("12a", "tau"), usage_error);
  CHECK_THROWS_AS(gyrores::parse_big_int("", "tau"), usage_error);
  CHECK_THROWS_AS(gyrores::parse_big_int("-", "tau"), usage_error);
  CHECK_THAT(usage_message([] { gyrores::parse_big_int("1.5", "sigma"); }), Catch::Contains("sigma"));
}
