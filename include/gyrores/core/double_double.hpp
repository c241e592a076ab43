// Double-double numbers: an unevaluated sum hi + lo of two doubles, |lo| <= ulp(hi)/2, about
// 106 bits. The double path of the theorem (theorem/minimum.hpp) forms its last Newton step and
// its outputs in them, so that a double it returns is within one ulp of the exact value (the
// rounding of a double-double is hi, and everything before it is accurate to about 2^-100).
//
// The building blocks are the classical error-free transformations: two_sum (Knuth) and
// two_prod (by a fused multiply-add), each exact for doubles away from overflow and underflow. The compound operations are those of
// Joldes, Muller and Popescu, "Tight and rigorous error bounds for basic building blocks of
// double-word arithmetic" (ACM TOMS 44, 2017), with u = 2^-53: add (their DWPlusDW, relative
// error <= 3u^2), mul (DWTimesDW1, <= 7u^2), mul by a double (DWTimesFP1, <= 2u^2), div (DWDivDW2,
// <= 15u^2 + 56u^3), and sqrt by one Newton step from the double square root (relative error
// below 4u^2). Nothing here rounds to a chosen mode or reads global state; inputs are finite.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <gyrores/core/integer.hpp>

// The hot functions built on these operations are compiled twice on x86-64, for processors
// with FMA and without, and the dynamic loader picks one (GCC's and Clang's target_clones; the
// attribute goes on the definition only, so that callers in other files call the resolved symbol).
// The operations are always inlined, so that each clone gets its own code.
#if defined(__x86_64__) && defined(__linux__)
#define GYRORES_DD_FAST __attribute__((target_clones("fma", "default")))
#else
#define GYRORES_DD_FAST
#endif
#if defined(__GNUC__)
#define GYRORES_DD_INLINE inline __attribute__((always_inline))
#else
#define GYRORES_DD_INLINE inline
#endif

namespace gyrores {

struct double_double {
  double hi = 0, lo = 0;
  constexpr double_double() = default;
  constexpr double_double(double h) : hi(h), lo(0) {}
  constexpr double_double(double h, double l) : hi(h), lo(l) {}
};

namespace dd {

// s + e = a + b exactly (|a| >= |b| not needed).
GYRORES_DD_INLINE double_double two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
// The same when |a| >= |b| (or a = 0).
GYRORES_DD_INLINE double_double fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
// p + e = a b exactly (no underflow of the low part): e = fma(a, b, -p). In a function compiled
// for FMA (GYRORES_DD_FAST below) it is one instruction; elsewhere a call to the C library's
// fma, which is exact too.
GYRORES_DD_INLINE double_double two_prod(double a, double b) {
  const double p = a * b;
  return {p, __builtin_fma(a, b, -p)};
}

GYRORES_DD_INLINE double_double add(const double_double& x, const double_double& y) {
  const double_double s = two_sum(x.hi, y.hi), t = two_sum(x.lo, y.lo);
  const double_double v = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(v.hi, t.lo + v.lo);
}
GYRORES_DD_INLINE double_double add(const double_double& x, double y) {
  const double_double s = two_sum(x.hi, y);
  return fast_two_sum(s.hi, x.lo + s.lo);
}
GYRORES_DD_INLINE double_double neg(const double_double& x) { return {-x.hi, -x.lo}; }
GYRORES_DD_INLINE double_double sub(const double_double& x, const double_double& y) { return add(x, neg(y)); }

GYRORES_DD_INLINE double_double mul(const double_double& x, const double_double& y) {
  const double_double c = two_prod(x.hi, y.hi);
  const double t = x.hi * y.lo + x.lo * y.hi;
  return fast_two_sum(c.hi, c.lo + t);
}
GYRORES_DD_INLINE double_double mul(const double_double& x, double y) {
  const double_double c = two_prod(x.hi, y);
  return fast_two_sum(c.hi, c.lo + x.lo * y);
}
// x times a power of two f (exact, no overflow or underflow).
GYRORES_DD_INLINE double_double scale(const double_double& x, double f) { return {x.hi * f, x.lo * f}; }

GYRORES_DD_INLINE double_double div(const double_double& x, const double_double& y) {
  const double q1 = x.hi / y.hi;
  const double_double r = sub(x, mul(y, q1));
  const double q2 = r.hi / y.hi;
  const double_double s = sub(r, mul(y, q2));
  const double q3 = s.hi / y.hi;
  return add(fast_two_sum(q1, q2), q3);
}
// n/d for doubles (d != 0): the remainder n - q d is exact, so the quotient is good to 2^-104.
GYRORES_DD_INLINE double_double quotient(double n, double d) {
  const double q = n / d;
  const double_double qd = two_prod(q, d);
  return fast_two_sum(q, ((n - qd.hi) - qd.lo) / d);
}

// sqrt(x), x >= 0.
GYRORES_DD_INLINE double_double sqrt(const double_double& x) {
  if (x.hi <= 0) return {0, 0};
  const double s = std::sqrt(x.hi);
  const double_double r = sub(x, two_prod(s, s));
  return fast_two_sum(s, r.hi / (2 * s));
}

// An integer |v| < 2^126: exactly up to 106 bits, else to 2^-106 (1 + 2^-20) relative. By 64-bit
// conversions only (the C library's int128 ones are calls of about 25 instructions): |v| = H 2^64
// + L1 2^32 + L0 (L1, L0 < 2^32), h = H rounded to a double (|H - h| <= 2^9 for H < 2^62), then
// (H - h) 2^64 + L1 2^32 is an exact double (42 bits), two_sum adds it to h 2^64 exactly, and the
// low part plus L0 is exact unless |v| >= 2^106 (integers below 2^53), where its rounding is below
// 2^-53 (ulp(hi)/2 + 2^32). The last fast_two_sum is exact.
// (Not recursive for the sign: an always-inline function cannot call itself.)
GYRORES_DD_INLINE double_double of_int(int128 v) {
  const int128 m = v < 0 ? -v : v;
  const auto L = std::uint64_t(m);
  const auto H = std::int64_t(m >> 64);
  const double h = double(H);
  const double mid = double(H - std::int64_t(h)) * 0x1p64 + double(std::int64_t(L >> 32)) * 0x1p32;  // exact
  const double_double s = two_sum(h * 0x1p64, mid);
  const double_double r = fast_two_sum(s.hi, s.lo + double(std::int64_t(L & 0xffffffffu)));
  return v < 0 ? neg(r) : r;
}
GYRORES_DD_INLINE double_double of_int(std::int64_t v) {
  if (v < (std::int64_t(1) << 53) && v > -(std::int64_t(1) << 53)) return {double(v), 0};
  return of_int(int128(v));
}

// pi to about 2^-107 (hi = the double nearest pi).
inline constexpr double_double pi{0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};

}  // namespace dd

// The table of the sines and cosines below: s[i], c[i] are the double-double roundings of
// sin(i/128), cos(i/128) (relative error <= 2^-106), i < 256, formed once in MPFR on first use
// (thread-safe), then shared.
struct sin_cos_table {
  std::array<double_double, 256> s, c;
  sin_cos_table();
};
const sin_cos_table& dd_sin_cos_table();

// sin x and cos x, |x| < 2, by the table: |x| = c + d with c = i 2^-7 (i = floor(|x| 2^7) < 256)
// and d = (|x|.hi - c) + |x|.lo (the difference is exact by Sterbenz's lemma, c <= |x|.hi < 2c
// for i >= 1); then from sd = sin d and cd = cos d, sin x = S_i cd + C_i sd and cos x = C_i cd -
// S_i sd (for i = 0, sd and cd), with x's sign on the sine (dd_sin_cos_accurate below).
struct dd_table_reduction {
  bool negative;
  int i;
  double_double d;
};
GYRORES_DD_INLINE dd_table_reduction dd_table_reduce(const double_double& x) {
  const bool negative = x.hi < 0;
  const double_double ax = negative ? dd::neg(x) : x;
  const int i = int(ax.hi * 128);
  return {negative, i, dd::two_sum(ax.hi - i * 0x1p-7, ax.lo)};
}
GYRORES_DD_INLINE void dd_table_step(const dd_table_reduction& r, const double_double& sd, const double_double& cd,
                                     double_double& s, double_double& c) {
  if (r.i == 0) {
    s = sd;
    c = cd;
  } else {
    const sin_cos_table& t = dd_sin_cos_table();
    const double_double& S = t.s[std::size_t(r.i)];
    const double_double& C = t.c[std::size_t(r.i)];
    s = dd::add(dd::mul(S, cd), dd::mul(C, sd));
    c = dd::sub(dd::mul(C, cd), dd::mul(S, sd));
  }
  if (r.negative) s = dd::neg(s);
}

// sin and cos of x = x.hi + x.lo, 0 <= x.hi <= 3/2, |x.lo| <= ulp(x.hi)/2, from the table t
// (= dd_sin_cos_table()): sin within 2^-63 |sin x|, cos within 2^-63, as normalised double-doubles;
// inlined, and one double-double sum where a general reduction forms four products and two
// sums. With c = i/128 <= x.hi < c + 2^-7 (i <= 192, so
// S = sin c >= 0, C = cos c > 0) and d = x.hi - c (exact: Sterbenz's lemma for i >= 1),
//   sin x.hi = S + C d - S g + C d p,   cos x.hi = C - S d - C g - S d p,
// g = 1 - cos d = d^2/2 - d^4/24 + d^6/720 (next term < 2^-71.3), p = sin d/d - 1 = -d^2/6 +
// d^4/120 - d^6/5040 (next < 2^-74.5), both in double from e = d^2 (relative errors about 4u,
// u = 2^-53: |g| < 2^-15 and |p| < 2^-16.5 are then within 2^-65.9 and 2^-67.3). C d and S d are
// exact products (two_prod) and S + C d, C - S d exact sums (two_sum); the low parts of the
// table, the products and the sums, -S g + C d p (or -C g - S d p) and the first-order term of
// x.lo (cos x.hi x.lo, -sin x.hi x.lo, with the approximations C - S d and S + C d, within
// 2^-14.4 of them; x.lo^2 < 2^-104 x.hi^2) are added in double: seven terms of total size below
// 2^-14.9 M, M = S + C d (sine) or C + S d (cosine), so their sum is within 6u 2^-14.9 M. In all,
// within 2^-64.2 M; for the sine M <= (1 + 2^-14.9) sin x.hi (cos d >= 1 - 2^-15, sin d >=
// d (1 - 2^-16.5), all terms >= 0) and x.hi <= (pi/2) sin x.hi, for the cosine M <= 1 + 2^-7.
// The final fast_two_sums are exact (the low sums are below 2^-14 of the high parts: cos x.hi >=
// cos(3/2) > 2^-4). (tests/test_double_double.cpp checks both against MPFR.)
GYRORES_DD_INLINE void dd_sin_cos_first_quadrant(const sin_cos_table& t, const double_double& x, double_double& s,
                                                double_double& c) {
  const int i = int(x.hi * 128);
  const double d = x.hi - i * 0x1p-7, e = d * d;
  const double g = e * (0.5 - e * (1.0 / 24 - e * (1.0 / 720)));
  const double dp = d * (e * (-1.0 / 6 + e * (1.0 / 120 - e * (1.0 / 5040))));  // d p
  const double_double& S = t.s[std::size_t(i)];
  const double_double& C = t.c[std::size_t(i)];
  const double_double cd = dd::two_prod(C.hi, d), sd = dd::two_prod(S.hi, d);
  const double_double sh = dd::two_sum(S.hi, cd.hi), ch = dd::two_sum(C.hi, -sd.hi);
  const double s_lo = sh.lo + cd.lo + S.lo + C.lo * d + (C.hi * dp - S.hi * g) + (C.hi - sd.hi) * x.lo;
  const double c_lo = ch.lo - sd.lo + C.lo - S.lo * d - (C.hi * g + S.hi * dp) - (S.hi + cd.hi) * x.lo;
  s = dd::fast_two_sum(sh.hi, s_lo);
  c = dd::fast_two_sum(ch.hi, c_lo);
}

// sin and cos of x, |x| < 2, to about 2^-101: sin within 2^-101 |sin x|, cos within 2^-101
// (absolute), for the certified sweep's balls (core/dd_ball.hpp): the table above at the multiple
// c of 2^-7 next to x and Taylor polynomials of the rest d, |d| < 2^-7, their leading terms in
// double-double (proof in src/lib/core/double_double.cpp, above the definition).
void dd_sin_cos_accurate(const double_double& x, double_double& s, double_double& c);

}  // namespace gyrores
