// Fractions in an interval, exactly (proofs/band-theorem.md, item 3 and its proof): the fraction
// of least denominator in an open interval and its Stern-Brocot parents, the least denominator of
// a given parity, and the piece of the lobes 1..K around a peak. The ends may be any numbers of one
// quadratic field (model/coupling.hpp: the band's ends are x = n/sqrt(n^2 + 4)), so every
// comparison is exact (core/quadratic.hpp). Each search descends the Stern-Brocot tree by runs
// (the continued fractions of the ends): O(log) steps of exact arithmetic.
//
// Why: in a band of couplings x in [x1, x2], the lobes' offsets ||k x - 1/2|| vanish at the
// fractions of even denominator (the centres, degenerate pairs) and peak at fractions of odd
// denominator; the band theorem reduces the extremes over an interval to these fractions.
#pragma once
#include <gyrores/core/integer.hpp>
#include <gyrores/core/quadratic.hpp>

namespace gyrores {

// A fraction p/q in lowest terms (q >= 1), as integers.
struct fraction {
  big_int p, q;
  quadratic_number value() const { return quadratic_number(p, q); }
  friend bool operator==(const fraction& a, const fraction& b) { return a.p == b.p && a.q == b.q; }
};

// The fraction of least denominator strictly inside (a, b) and its two Stern-Brocot parents
// (left < simplest < right, each with determinant 1 against it).
// Precondition: 0 <= a < b <= 1 (a and b may lie in different fields: a < b is not checked
// exactly, usage_error when the search does not end).
struct simplest_fraction {
  fraction simplest, left, right;
};
simplest_fraction simplest_in(const quadratic_number& a, const quadratic_number& b);

// The fraction of least denominator q with q % 2 == parity strictly inside (a, b) (unique).
// Precondition: 0 <= a < b <= 1.
fraction least_of_parity_in(const quadratic_number& a, const quadratic_number& b, int parity);

// The piece of a peak (band-theorem item 3): for an odd Q <= 2K - 1 and P coprime to Q, the
// consecutive centres c1 = p1/q1 < P/Q < c2 = p2/q2 of the lobes 1..K (q1, q2 even <= 2K, the
// largest with q1 P - p1 Q = 1 and p2 Q - P q2 = 1). usage_error unless Q is odd, Q <= 2K - 1 and
// gcd(P, Q) = 1.
struct peak_piece {
  fraction left, right;
};
peak_piece peak_piece_of(const fraction& peak, const big_int& K);

}  // namespace gyrores
