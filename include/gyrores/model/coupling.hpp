// Any coupling n given exactly: n^2 rational, the exact resonance test, the continued fraction
// of W1/W2 and the exact rotation number x = n/sqrt(n^2 + 4) (docs/mathematics.md §1).
//
// Resonance (exact, rational arithmetic on n^2). With r = n^2 = P/Q in lowest terms and
// s = sqrt(n^2 + 4), the frequency ratio is W1/W2 = (s + n)^2/4 = (r + 2 + n s)/2, so it is
// rational iff n s = sqrt(r (r + 4)) is, i.e. iff r (r + 4) = P (P + 4Q)/Q^2 is a rational square,
// i.e. iff the integer D = P (P + 4Q) is a perfect square. Then
//     W1/W2 = (P + 2Q + sqrt(D)) / (2Q)   (reduced: the pair (tau, sigma)).
// Examples: n^2 = 1/12: D = 49, W1/W2 = 32/24 = 4/3; n^2 = 4/99: D = 1600, W1/W2 = 11/9;
// n = 2: D = 32, not a square, so n = 2 is not resonant; n = 3/2: D = 225, W1/W2 = 4.
// A decimal close to a resonant value (0.2886751345948 for 1/sqrt(12)) is an exact rational
// whose D is not a square: not resonant. Only n^2 matters (the sign of n mirrors the motion).
//
// Continued fraction of W1/W2 = (m + sqrt(D))/d with m = P + 2Q, d = 2Q: d divides D - m^2 =
// -4Q^2, so the classical recurrence for quadratic irrationals runs in exact integers
// (a = floor((m + isqrt(D))/d), m' = a d - m, d' = (D - m'^2)/d). The convergents p_k/q_k are
// the best rational approximations of W1/W2; each (p_k, q_k) with p_k > q_k is a resonant pair.
//
// The rotation number. x^2 = n^2/(n^2 + 4) = P/(P + 4Q), so x = sqrt(D)/(P + 4Q) with the same D:
// x is rational exactly when the coupling is resonant (then x = b/a of its pair), and otherwise a
// quadratic irrational of Q(sqrt D), on which core/quadratic.hpp computes exactly.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/core/quadratic.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// A coupling given exactly: n^2 (always rational here) and, when known, n itself (rational).
// n = 0 is rejected (no coupling: H_q is constant). The sign of n is kept for messages only.
struct coupling_spec {
  big_rational n2;                 // n^2 > 0, exact
  std::optional<big_rational> n;   // n when given as a rational (its sign as given)

  // Throw usage_error for n = 0, n^2 <= 0.
  static coupling_spec from_n(const big_rational& n);
  static coupling_spec from_n2(const big_rational& n2);
  big_int P() const;  // numerator of n^2
  big_int Q() const;  // denominator of n^2
  // D = P (P + 4Q): W1/W2 is rational iff D is a perfect square.
  big_int discriminant() const;

  // |n| in T: |num|/den for a rational n, else sqrt(P/Q) (correctly rounded parts).
  template <class T> T abs_n() const {
    using std::sqrt;
    if (n) {
      big_int num = boost::multiprecision::numerator(*n), den = boost::multiprecision::denominator(*n);
      if (num < 0) num = -num;
      return real_from_int<T>(num) / real_from_int<T>(den);
    }
    return sqrt(real_from_int<T>(P()) / real_from_int<T>(Q()));
  }
};

// The resonant pair of a coupling, decided exactly; std::nullopt when W1/W2 is irrational.
std::optional<resonant_pair<big_int>> coupling_resonant_pair(const coupling_spec& c);

// One convergent p/q of W1/W2 with its resonant pair (p > q) and the partial quotient a_k.
struct ratio_convergent {
  big_int partial_quotient;
  big_int p, q;  // the convergent p/q (coprime)
};

// The first `max_terms` convergents of W1/W2 (all of them when the ratio is rational, i.e. the
// coupling is resonant: the last is then W1/W2 itself). Exact integer arithmetic throughout.
std::vector<ratio_convergent> coupling_convergents(const coupling_spec& c, std::size_t max_terms);

// x = n/sqrt(n^2 + 4) = sqrt(D)/(P + 4Q), exactly (rational when the coupling is resonant).
quadratic_number coupling_rotation_number(const coupling_spec& c);

}  // namespace gyrores
