// Balls of double-double numbers: the exact value lies within r of m (the exact sum m.hi + m.lo).
// Each operation takes the double-double operation of core/double_double.hpp on the midpoints
// and adds to the propagated radius that operation's proved relative error bound, so a ball
// always holds the exact result of the exact operation on any values in its operands' balls.
// The theorem in these balls (theorem/minimum_dd_ball.hpp), the certified sweep's filter, proves
// its brackets and values in them.
//
// Bounds used (u = 2^-53; core/double_double.hpp, Joldes, Muller and Popescu 2017), each taken
// relative to |m.hi| with slack for |exact| <= |m.hi| (1 + 2^-52):
//   add 3u^2 -> 2^-104, mul 7u^2 -> 2^-103, div 15u^2 + 56u^3 -> 2^-102, sqrt 4u^2 -> 2^-103,
//   sin within 2^-101 |sin x| -> 2^-100.99 |s.hi|, cos within 2^-101 (absolute) (dd_sin_cos_accurate),
//   dd::pi within 2^-106 (its low part is the double nearest pi - hi, of ulp 2^-105) -> 2^-104.
// Radii are doubles formed in round-to-nearest from nonnegative terms in at most 12 operations,
// then `up`: (1 + u)^13 < 1 + 2^-49, so multiplying by 1 + 2^-48 (itself rounded) and adding
// 2^-1000 (for any underflow, each below 2^-1074) never rounds a radius below its exact value.
// The operations are compiled in src/lib/core/dd_ball.cpp (FMA clones, GYRORES_DD_FAST).
// Preconditions (not checked): finite values of magnitude below 2^500, sin/cos arguments with
// |m.hi| + r < 2 (dd_sin_cos_accurate's range), divisors whose ball excludes 0 (div returns false).
#pragma once
#include <cmath>

#include <gyrores/core/double_double.hpp>

namespace gyrores {

struct dd_ball {
  double_double m;
  double r = 0;
};

namespace ddb {

double up(double v);  // v (1 + 2^-48) + 2^-1000, rounded: above the exact value of a radius sum
inline double mag(const dd_ball& x) { return x.m.hi < 0 ? -x.m.hi : x.m.hi; }

inline constexpr double add_bound = 0x1p-104, mul_bound = 0x1p-103, div_bound = 0x1p-102, sqrt_bound = 0x1p-103;
inline constexpr double sin_bound = 0x1.0002p-101, cos_bound = 0x1p-101, pi_radius = 0x1p-104;

inline dd_ball exact(double v) { return {double_double(v), 0}; }
inline dd_ball exact(const double_double& v) { return {v, 0}; }
inline dd_ball pi() { return {dd::pi, pi_radius}; }
inline dd_ball neg(const dd_ball& x) { return {dd::neg(x.m), x.r}; }
// x times a power of two f: exact.
inline dd_ball scale(const dd_ball& x, double f) { return {dd::scale(x.m, f), x.r * (f < 0 ? -f : f)}; }

dd_ball add(const dd_ball& x, const dd_ball& y);
dd_ball sub(const dd_ball& x, const dd_ball& y);
dd_ball mul(const dd_ball& x, const dd_ball& y);
// x/y: |x/y - mx/my| <= (rx + |mx/my| ry)/(|my| - ry). False if y's ball may hold 0.
bool div(dd_ball& out, const dd_ball& x, const dd_ball& y);
// sqrt over a ball of positive values: |sqrt(v) - sqrt(m)| <= r/sqrt(m - r). False if it may hold 0.
bool sqrt(dd_ball& out, const dd_ball& x);
// sin and cos over the ball (both 1-Lipschitz).
void sin_cos(const dd_ball& x, dd_ball& s, dd_ball& c);

// Every value of the ball is > 0 (< 0).
bool positive(const dd_ball& x);
bool negative(const dd_ball& x);
// An upper bound of every |value| in the ball.
double upper_abs(const dd_ball& x);

}  // namespace ddb
}  // namespace gyrores
