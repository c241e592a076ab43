// Lazy enumeration of resonant pairs by order (enumerate.hpp).
//
// Oracle: an independent, materialised enumeration by nested loops with std::gcd, sorted by the
// documented key (order ascending, then sigma ascending), and Euler's phi computed by counting.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <gyrores/model/enumerate.hpp>

#include "reference/coprime_count.hpp"
#include "testing/test_support.hpp"

using gyrores::coprime_pairs;
using pr = std::pair<std::int64_t, std::int64_t>;  // (tau, sigma)

namespace {
// All coprime tau > sigma >= 1 with lo <= tau + sigma <= hi, built independently and sorted by
// (tau + sigma, sigma).
std::vector<pr> brute_pairs(std::int64_t lo, std::int64_t hi) {
  std::vector<pr> out;
  for (std::int64_t t = 2; t < hi; ++t)
    for (std::int64_t s = 1; s < t; ++s)
      if (t + s >= lo && t + s <= hi && std::gcd(t, s) == 1) out.push_back({t, s});
  std::sort(out.begin(), out.end(), [](const pr& x, const pr& y) {
    return std::make_tuple(x.first + x.second, x.second) < std::make_tuple(y.first + y.second, y.second);
  });
  return out;
}

std::vector<pr> library_pairs(const coprime_pairs& range) {
  std::vector<pr> out;
  for (auto p : range) out.push_back({p.tau(), p.sigma()});
  return out;
}

// Euler's phi by counting (independent of the library's factorisation).
std::int64_t phi_by_count(std::int64_t n) {
  std::int64_t c = 0;
  for (std::int64_t k = 1; k <= n; ++k)
    if (std::gcd(k, n) == 1) ++c;
  return c;
}
}  // namespace

TEST_CASE("enumeration starts with the documented small pairs", "[enumerate]") {
  const std::vector<pr> expect = {{2, 1}, {3, 1}, {4, 1}, {3, 2}, {5, 1}, {6, 1}, {5, 2}, {4, 3},
                                  {7, 1}, {5, 3}, {8, 1}, {7, 2}, {5, 4}, {9, 1}, {7, 3}};
  std::vector<pr> got;
  for (auto p : coprime_pairs(1, 10)) got.push_back({p.tau(), p.sigma()});
  CHECK(got == expect);
}

TEST_CASE("enumeration equals the independent sorted enumeration", "[enumerate]") {
  for (std::int64_t hi : {3, 4, 5, 17, 64, 151, 400}) {
    INFO("max order " << hi);
    auto lib = library_pairs(coprime_pairs(3, hi));
    auto ref = brute_pairs(3, hi);
    REQUIRE(lib.size() == ref.size());
    CHECK(lib == ref);
    // Strictly increasing in the documented key, every pair valid.
    for (std::size_t i = 0; i < lib.size(); ++i) {
      auto [t, s] = lib[i];
      REQUIRE(t > s);
      REQUIRE(s >= 1);
      REQUIRE(std::gcd(t, s) == 1);
      if (i > 0) {
        auto [t0, s0] = lib[i - 1];
        REQUIRE(std::make_tuple(t0 + s0, s0) < std::make_tuple(t + s, s));
      }
    }
  }
}

TEST_CASE("counts equal the sum of phi(a)/2", "[enumerate]") {
  // coprime_pairs_of_order against phi counted by brute force.
  for (std::int64_t a = 0; a <= 2000; ++a) {
    INFO("order " << a);
    std::int64_t want = a < 3 ? 0 : phi_by_count(a) / 2;
    REQUIRE(gyrores::coprime_pairs_of_order(a) == want);
  }
  // Prime powers and large orders (phi known in closed form).
  CHECK(gyrores::coprime_pairs_of_order(1024) == 256);
  CHECK(gyrores::coprime_pairs_of_order(1000003) == 500001);          // prime
  CHECK(gyrores::coprime_pairs_of_order(1000000) == 200000);          // 2^6 5^6: phi = 400000
  CHECK(gyrores::coprime_pairs_of_order(999999999989LL) == 499999999994LL);  // prime
  // The length of the enumeration, per order and in total.
  for (std::int64_t m : {3, 10, 100, 1000}) {
    std::int64_t total = 0, want = 0;
    std::vector<std::int64_t> per_order(std::size_t(m + 1), 0);
    for (auto p : coprime_pairs(3, m)) {
      ++total;
      ++per_order[std::size_t(p.tau() + p.sigma())];
    }
    for (std::int64_t a = 3; a <= m; ++a) {
      want += phi_by_count(a) / 2;
      INFO("max " << m << ", order " << a);
      REQUIRE(per_order[std::size_t(a)] == phi_by_count(a) / 2);
    }
    CHECK(total == want);
  }
  // Known value: sum_{a=3}^{100} phi(a)/2 = (sum_{a=1}^{100} phi(a) - 2)/2 = (3044 - 2)/2.
  std::int64_t n100 = 0;
  for (auto p : coprime_pairs(3, 100)) { (void)p; ++n100; }
  CHECK(n100 == 1521);
}

TEST_CASE("min and max order bounds", "[enumerate]") {
  CHECK(library_pairs(coprime_pairs(10, 20)) == brute_pairs(10, 20));
  CHECK(library_pairs(coprime_pairs(20, 20)) == brute_pairs(20, 20));
  CHECK(library_pairs(coprime_pairs(97, 150)) == brute_pairs(97, 150));
  // min below 3 is treated as 3.
  CHECK(library_pairs(coprime_pairs(-5, 12)) == brute_pairs(3, 12));
  CHECK(library_pairs(coprime_pairs(0, 12)) == brute_pairs(3, 12));
  // Empty ranges.
  CHECK(library_pairs(coprime_pairs(3, 2)).empty());
  CHECK(library_pairs(coprime_pairs(1, 1)).empty());
  CHECK(library_pairs(coprime_pairs(21, 20)).empty());
  // A single order.
  CHECK(library_pairs(coprime_pairs(3, 3)) == std::vector<pr>{{2, 1}});
  auto o12 = library_pairs(coprime_pairs(12, 12));
  CHECK(o12 == std::vector<pr>{{11, 1}, {7, 5}});
  // Every pair respects the bounds, for a window in the middle.
  for (auto p : coprime_pairs(500, 520)) {
    REQUIRE(p.tau() + p.sigma() >= 500);
    REQUIRE(p.tau() + p.sigma() <= 520);
  }
  // Far from the origin: the first pairs of order 10^12 and 10^12 + 1.
  std::vector<pr> far;
  for (auto p : coprime_pairs(1000000000000LL, 1000000000001LL)) {
    far.push_back({p.tau(), p.sigma()});
    if (far.size() == 4) break;
  }
  const std::int64_t T = 1000000000000LL;
  CHECK(far == std::vector<pr>{{T - 1, 1}, {T - 3, 3}, {T - 7, 7}, {T - 9, 9}});
}

TEST_CASE("shards I/N are disjoint and cover the enumeration", "[enumerate][shard]") {
  const std::int64_t lo = 3, hi = 300;
  auto full = library_pairs(coprime_pairs(lo, hi));
  REQUIRE(full == brute_pairs(lo, hi));
  for (std::int64_t n : {1, 2, 3, 7, 64, 100000}) {
    std::set<pr> seen;
    std::size_t total = 0;
    for (std::int64_t i = 0; i < n && i < 200; ++i) {
      INFO("shard " << i << "/" << n);
      std::vector<pr> shard;
      coprime_pairs range(lo, hi, i, n);
      for (auto it = range.begin(); it != range.end(); ++it) {
        // The position is the index in the unsharded enumeration, congruent to i mod n.
        REQUIRE(it.position() % n == i);
        REQUIRE(std::size_t(it.position()) < full.size());
        pr p{(*it).tau(), (*it).sigma()};
        REQUIRE(full[std::size_t(it.position())] == p);
        shard.push_back(p);
      }
      // Within a shard, the documented order is kept.
      for (std::size_t k = 1; k < shard.size(); ++k)
        REQUIRE(std::make_tuple(shard[k - 1].first + shard[k - 1].second, shard[k - 1].second) <
                std::make_tuple(shard[k].first + shard[k].second, shard[k].second));
      for (const auto& p : shard) REQUIRE(seen.insert(p).second);  // disjoint
      total += shard.size();
    }
    if (n <= 200) {
      CHECK(total == full.size());  // cover
      CHECK(seen == std::set<pr>(full.begin(), full.end()));
    }
  }
  // Shards of a range with a min order: positions count from the first pair of the range.
  auto part = library_pairs(coprime_pairs(50, 80));
  std::vector<pr> merged;
  for (std::int64_t i = 0; i < 3; ++i)
    for (auto p : coprime_pairs(50, 80, i, 3)) merged.push_back({p.tau(), p.sigma()});
  std::sort(merged.begin(), merged.end());
  std::sort(part.begin(), part.end());
  CHECK(merged == part);
}

TEST_CASE("invalid shards are rejected", "[enumerate][shard][errors]") {
  CHECK_THROWS_AS(coprime_pairs(3, 10, 0, 0), gyrores::usage_error);
  CHECK_THROWS_AS(coprime_pairs(3, 10, 2, 2), gyrores::usage_error);
  CHECK_THROWS_AS(coprime_pairs(3, 10, -1, 2), gyrores::usage_error);
  CHECK_NOTHROW(coprime_pairs(3, 10, 1, 2));
}

TEST_CASE("enumeration is lazy: huge ranges cost only the steps taken", "[enumerate][lazy]") {
  // A materialising range would never return (the suite's timeout catches it).
  // max order 10^6 holds ~3 10^11 pairs; 10^18 holds ~3 10^35. Materialising either never ends.
  for (std::int64_t hi : {1000000LL, 1000000000000000000LL}) {
    INFO("max order " << hi);
    coprime_pairs range(3, hi);
    std::vector<pr> first;
    for (auto p : range) {
      first.push_back({p.tau(), p.sigma()});
      if (first.size() == 5) break;
    }
    CHECK(first == std::vector<pr>{{2, 1}, {3, 1}, {4, 1}, {3, 2}, {5, 1}});
    // begin() is cheap and repeatable: a second pass starts over.
    auto it = range.begin();
    CHECK((*it).tau() == 2);
    ++it;
    ++it;
    CHECK((*it).tau() == 4);
    CHECK(it.position() == 2);
  }
  // A shard of a huge range also starts at once: shard 5/7 begins at position 5.
  coprime_pairs sh(3, 1000000, 5, 7);
  auto it = sh.begin();
  CHECK(it.position() == 5);
  CHECK((*it).tau() == 6);  // positions 0..5: (2,1) (3,1) (4,1) (3,2) (5,1) (6,1)
  CHECK((*it).sigma() == 1);
  ++it;
  CHECK(it.position() == 12);  // (5,4)
  CHECK((*it).tau() == 5);
  CHECK((*it).sigma() == 4);
  // The iterator holds a few integers, not a container.
  CHECK(sizeof(coprime_pairs::iterator) <= 8 * sizeof(std::int64_t));
}
