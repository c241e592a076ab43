// model/fractions.hpp against plain searches over every denominator, and the peak lemma
// (proofs/band-theorem.md, item 3) against the maximum of min_k ||k x - 1/2|| over every fraction.
#include <catch2/catch.hpp>

#include <random>

#include <gyrores/model/fractions.hpp>
#include <gyrores/model/rotation.hpp>

using namespace gyrores;

namespace {

// The least q (with q % 2 == parity, or any q for parity -1) having p/q strictly inside (a, b).
fraction plain_least(const quadratic_number& a, const quadratic_number& b, int parity) {
  for (big_int q = 1;; ++q) {
    if (parity >= 0 && int(q % 2) != parity) continue;
    for (big_int p = (a * quadratic_number(q)).floor() + 1; quadratic_number(p, q) < b; ++p)
      if (boost::multiprecision::gcd(p, q) == 1) return {p, q};
  }
}

}  // namespace

TEST_CASE("simplest_in and least_of_parity_in against the plain search", "[fractions]") {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> num(1, 99999), width(1, 5000), scale(3, 7);
  for (int trial = 0; trial < 400; ++trial) {
    const quadratic_number a(big_int(num(rng)), big_int(100003));
    big_int ten = 1;
    for (int i = scale(rng); i > 0; --i) ten *= 10;
    const quadratic_number b = a + quadratic_number(big_int(width(rng)), ten);
    if (b >= quadratic_number(1)) continue;
    const simplest_fraction s = simplest_in(a, b);
    CHECK(s.simplest == plain_least(a, b, -1));
    CHECK(s.left.q * s.simplest.p - s.left.p * s.simplest.q == 1);
    CHECK(s.simplest.q * s.right.p - s.simplest.p * s.right.q == 1);
    CHECK(least_of_parity_in(a, b, 0) == plain_least(a, b, 0));
    CHECK(least_of_parity_in(a, b, 1) == plain_least(a, b, 1));
  }
  // Ends in two quadratic fields, as a band's: x = n/sqrt(n^2 + 4) at n = 2 (sqrt(2)/2) and
  // n = 2.2 (11 sqrt(221)/221).
  const quadratic_number a(0, 1, 2, 2), b(0, 11, 221, 221);
  REQUIRE(a.approx() < b.approx());
  CHECK(simplest_in(a, b).simplest == fraction{5, 7});
  CHECK(least_of_parity_in(a, b, 0) == fraction{13, 18});
  CHECK(least_of_parity_in(a, b, 1) == fraction{5, 7});
}

TEST_CASE("the peak lemma: the piece of a peak and the maximum over it", "[fractions]") {
  // For every K <= 24 and every odd Q <= 2K - 1: the piece's centres have determinant 1 against
  // P/Q, no centre of the lobes 1..K lies strictly between them and P/Q, and
  // max over [c1, c2] of min_k ||k x - 1/2|| is 1/(2Q), at P/Q.
  for (int K = 1; K <= 24; ++K)
    for (int Q = 1; Q <= 2 * K - 1; Q += 2)
      for (int P = 1; P < Q; ++P) {
        if (boost::multiprecision::gcd(big_int(P), big_int(Q)) != 1) continue;
        const peak_piece piece = peak_piece_of({P, Q}, K);
        const quadratic_number c1 = piece.left.value(), c2 = piece.right.value(), v(P, Q);
        REQUIRE(c1 < v);
        REQUIRE(v < c2);
        CHECK(piece.left.q * P - piece.left.p * Q == 1);
        CHECK(piece.right.p * Q - P * piece.right.q == 1);
        for (int k = 1; k <= K; ++k) {  // no centre (2j+1)/(2k) strictly inside (c1, c2)
          const big_int j = (quadratic_number(2 * k) * c1).floor();
          for (big_int o = j; o <= j + 2; ++o)
            if (o % 2 != 0) {
              const quadratic_number c(o, 2 * k);
              CHECK_FALSE((c1 < c && c < c2));
            }
        }
        CHECK(min_distance_to_half(v, K).value == quadratic_number(1, 2 * Q));
      }
}
