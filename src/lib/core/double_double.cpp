// include/gyrores/core/double_double.hpp: sin and cos of a double-double for the balls.
#include <gyrores/core/double_double.hpp>

#include <mpfr.h>

namespace gyrores {

sin_cos_table::sin_cos_table() {
  mpfr_t v, sn, cs, r;
  mpfr_inits2(192, v, sn, cs, r, static_cast<mpfr_ptr>(nullptr));
  auto to_dd = [&](mpfr_srcptr a) {
    const double hi = mpfr_get_d(a, MPFR_RNDN);
    mpfr_sub_d(r, a, hi, MPFR_RNDN);
    return double_double(hi, mpfr_get_d(r, MPFR_RNDN));
  };
  for (int i = 0; i < 256; ++i) {  // c_i = i/128 for |x| < 2
    mpfr_set_si_2exp(v, i, -7, MPFR_RNDN);  // exact
    mpfr_sin_cos(sn, cs, v, MPFR_RNDN);
    s[std::size_t(i)] = to_dd(sn);
    c[std::size_t(i)] = to_dd(cs);
  }
  mpfr_clears(v, sn, cs, r, static_cast<mpfr_ptr>(nullptr));
}

// Formed on first use (thread-safe static initialisation): about 0.3 ms, once per process.
const sin_cos_table& dd_sin_cos_table() {
  static const sin_cos_table t;
  return t;
}

}  // namespace gyrores

// ---- dd_sin_cos_accurate (include/gyrores/core/double_double.hpp) ----
//
// The reduction (dd_table_reduce): x = c + d exactly, c = i 2^-7, |d| <= 2^-7 (1 + 2^-45) (d < 0 only
// when |x|.hi = c, then |d| <= 2^-53), and the table's S_i, C_i within 2^-106 relatively. With
// u = 2^-53 the double-double operations err relatively by at most (Joldes, Muller and Popescu,
// the header's comment): (+) 3u^2 = 2^-104.41 (2u^2 with a double), (x) 7u^2 = 2^-103.19. Let
// e = d (x) d, so e = d^2 (1 + 7u^2 at most), |e| <= 2^-14 (1 + 2^-44), and h = e.hi = e (1 + u
// at most). k_n is 1/n! rounded to double-double (within 2^-106 relatively) or to double (u).
//
// sin d = d + d^3 S(d^2) + R, S(e) = -1/3! + e/5! - e^2/7! + e^3/9! - e^4/11!, |R| <= |d|^13/13!
// < 2^-116.5 |d| (alternating series, decreasing terms). By Horner from the inside, each step
// within the stated absolute error of the exact polynomial at the computed e:
//   t  = h (k9 - h k11) (doubles)   e (1/9! - e/11!)    4.1u 2^-32.47 < 2^-83
//   A3 = -k7 (+) t                  -1/7! + ...         2^-83 (1 + 2^-30)
//   A2 = k5 (+) e (x) A3            1/5! - ...          2^-97 + 2^-111.3 (k5, the add) < 2^-96.9
//   A1 = -k3 (+) e (x) A2           S(e)                2^-110.9 + 2^-108.58 (k3) + 2^-106.99 (the
//                                                       add) < 2^-106.5, and |S| > 1/6.01: 2^-103.9 |S|
//   sd = d (+) (d (x) e) (x) A1: the product is d e S(e) (|.| <= 2^-16.58 |d|) within two muls and
//   A1's error, 2^-101.8 relatively, < 2^-118.4 |d|; d e S(e) is d^3 S(d^2) within 7u^2 2^-16.58
//   |d| < 2^-119.7 |d| (e's error); the add errs by 3u^2 |sd|. With R and |d| <= |sin d| (1 +
//   2^-16.5): |sd - sin d| < 0.047 2^-100 |sin d| < 2^-104.4 |sin d|.
// cos d = 1 + e C0(e) + R', C0 = -1/2 + e/4! - e^2/6! + e^3/8! - e^4/10!, |R'| <= d^12/12! <
// 2^-112.8:
//   t' = h (k8 - h k10) (doubles)   e (1/8! - e/10!)    4.1u 2^-29.3 < 2^-80.2
//   B2 = -k6 (+) t'                 -1/6! + ...         2^-80.2 (1 + 2^-30)
//   B1 = k4 (+) e (x) B2            1/4! - ...          2^-94.2 + 2^-109 < 2^-94.1
//   B0 = -1/2 (+) e (x) B1          C0(e), |C0| < 1/2   2^-108.1 + 2^-105.41 (the add) < 2^-105.2
//   cd = 1 (+) e (x) B0: the product is e C0(e) within 2^-119.2 + 2^-118.2 (its mul); e C0(e) is
//   d^2 C0(d^2) within 7u^2 2^-15 < 2^-118.1 (e's error); the add errs by 3u^2 |cd| <= 3u^2. So
//   |cd - cos d| < 2^-104.41 + 2^-112.7 < 2^-104.3.
// For i = 0, s = sd and c = cd. For i >= 1, s = S_i (x) cd (+) C_i (x) sd: the products are
// sin c cos d and cos c sin d within 2^-106 (the table) + 2^-104.3 (1 + 2^-14) (cd, sd; cos d > 1 -
// 2^-15) + 7u^2 (the mul) < 0.18 2^-100 of their magnitudes, and these sum to at most 1.11
// |sin x|: for c < pi/2 both terms have sin x's sign (but for |cos c sin d| <= 2^-52 when d < 0,
// and |sin x| > sin(2^-7) > 2^-7.01); for c > pi/2 (i >= 202) |sin x| > sin 2 > 0.909 while the
// sum is at most 1 + 0.41 sin(2^-7) < 1.0033. With the add's 3u^2 (1 + 2^-99) |sin x|, s errs
// by < (0.18 1.11 + 0.047) 2^-100 |sin x| < 2^-102 |sin x|. c = C_i (x) cd (-) S_i (x) sd errs
// by < 0.18 2^-100 (|cos c| + sin(2^-7)) + 3u^2 (1 + 2^-99) < 0.23 2^-100 < 2^-102. The stated
// 2^-101 keeps a factor 2 over this for the first-order sums above.
// Underflow: for |d| < 2^-538, e = 0 and sd = d, cd = 1 exactly (within d^2/6 |d| and d^2/2,
// below 2^-1076). Otherwise an operation that underflows works on quantities below 2^-900 that
// enter the result multiplied by at most 1, so each adds at most 2^-1074 absolutely, a few
// 2^-1074 in all: the balls' 2^-1000 (core/dd_ball.hpp, `up`) covers them.
// tests/test_double_double.cpp checks the bounds against MPFR.

namespace gyrores {
namespace {

// 1/n! (n = 3..7) rounded to double-double: the nearest double and the double nearest the rest.
constexpr double_double inv_fact3{0x1.5555555555555p-3, 0x1.5555555555555p-57};
constexpr double_double inv_fact4{0x1.5555555555555p-5, 0x1.5555555555555p-59};
constexpr double_double inv_fact5{0x1.1111111111111p-7, 0x1.1111111111111p-63};
constexpr double_double inv_fact6{0x1.6c16c16c16c17p-10, -0x1.f49f49f49f49fp-65};
constexpr double_double inv_fact7{0x1.a01a01a01a01ap-13, 0x1.a01a01a01a01ap-73};
// 1/n! (n = 8..11) rounded to double.
constexpr double inv_fact8 = 0x1.a01a01a01a01ap-16, inv_fact9 = 0x1.71de3a556c734p-19,
                 inv_fact10 = 0x1.27e4fb7789f5cp-22, inv_fact11 = 0x1.ae64567f544e4p-26;

// sin d within 2^-104.4 |sin d| (|d| <= 2^-7 (1 + 2^-45)), given e = d (x) d.
GYRORES_DD_INLINE double_double sin_small(const double_double& d, const double_double& e) {
  const double h = e.hi;
  const double t = h * (inv_fact9 - h * inv_fact11);
  const double_double a3 = dd::add(dd::neg(inv_fact7), t);
  const double_double a2 = dd::add(inv_fact5, dd::mul(e, a3));
  const double_double a1 = dd::add(dd::neg(inv_fact3), dd::mul(e, a2));
  return dd::add(d, dd::mul(dd::mul(d, e), a1));
}

// cos d within 2^-104.3 (|d| <= 2^-7 (1 + 2^-45)), given e = d (x) d.
GYRORES_DD_INLINE double_double cos_small(const double_double& e) {
  const double h = e.hi;
  const double t = h * (inv_fact8 - h * inv_fact10);
  const double_double b2 = dd::add(dd::neg(inv_fact6), t);
  const double_double b1 = dd::add(inv_fact4, dd::mul(e, b2));
  const double_double b0 = dd::add(double_double(-0.5), dd::mul(e, b1));
  return dd::add(double_double(1.0), dd::mul(e, b0));
}

}  // namespace

GYRORES_DD_FAST void dd_sin_cos_accurate(const double_double& x, double_double& s, double_double& c) {
  const dd_table_reduction r = dd_table_reduce(x);
  const double_double e = dd::mul(r.d, r.d);
  dd_table_step(r, sin_small(r.d, e), cos_small(e), s, c);
}

}  // namespace gyrores
