// Exact rationals (GMP): parsing decimals and fractions exactly, printing them, perfect squares.
// A decimal such as "0.2886751345948" is the exact rational 2886751345948/10^13, never a double.
#pragma once
#include <boost/multiprecision/gmp.hpp>
#include <optional>
#include <string>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores {

using big_rational = boost::multiprecision::mpq_rational;

// Parse an exact rational: an integer, a fraction "P/Q" (integers, Q != 0) or a decimal
// ("0.25", "-1.5e-3", "2E+4"; exponents up to 6 digits, |shift| <= 100000). Throws usage_error
// naming `what` for anything else.
big_rational parse_rational(const std::string& text, const std::string& what);

// Exact text of a rational: "P/Q", or "P" when Q = 1.
std::string rational_str(const big_rational& r);

// q in scientific notation d.ddd...e+XX with `digits` significant digits (at least 1), rounded
// once from the exact value, to nearest with ties to even (the rule of format_scientific,
// core/decimal.hpp, for binary values). Zero prints as 0.000...e+00. This is how exact
// quantities (beat ratio, qdot0, ...) are printed: an exact tie such as 2305843009213693950 at
// 18 digits has no floating Ziv test that could ever settle it. `exact`, when given, receives
// whether the text is q itself (no rounding happened).
std::string format_rational_scientific(const big_rational& q, unsigned digits, bool* exact = nullptr);

// q rounded to `digits` significant digits down (dir -1) or up (+1), as an exact rational: the
// value of format_scientific's directed roundings (core/decimal.hpp), with no text.
big_rational decimal_rounded(const big_rational& q, unsigned digits, int dir);

// True when v >= 0 is a perfect square; root receives floor(sqrt(v)).
bool int_is_square(const big_int& v, big_int& root);

// floor(sqrt(y)) for a rational y >= 0: floor(sqrt(floor(y))), an integer root.
big_int floor_sqrt(const big_rational& y);

// sqrt(r) when r >= 0 is the square of a rational (numerator and denominator perfect squares,
// r being in lowest terms), else none: the exact case of every square root of an input.
std::optional<big_rational> rational_sqrt(const big_rational& r);

}  // namespace gyrores
