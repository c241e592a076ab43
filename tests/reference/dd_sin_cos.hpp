// dd_sin_cos: sin and cos of a double-double, |x| < 2, sin within 2^-63 |sin x| and cos within
// 2^-63, by the product's table step (core/double_double.hpp: dd_table_reduce, dd_table_step)
// and short Taylor polynomials: the cheaper sibling of dd_sin_cos_accurate, which the product no
// longer uses; tests/test_double_double.cpp keeps its bounds checked against MPFR.
//
// With x = c + d (the table step's reduction), S_i, C_i the double-double roundings of sin c,
// cos c (relative error <= 2^-106), and e = d^2:
//   sin d = d + d p,  p = -e/6 + e^2/120 - e^3/5040 + e^4/9!      (next term < 2^-95 d),
//   cos d = 1 - d^2/2 + q,  q = e^2/24 - e^3/720 + e^4/8! - e^5/10!  (next term < 2^-110).
// d^2/2 is a double-double (the exact product of the high parts plus d.hi d.lo); p
// (|p| < 2^-15) and q (|q| < 2^-32) are doubles, formed from e = d.hi^2 with relative errors
// below 2^-50, so sin d is within 2^-64 d and cos d within 2^-81. The double-double products
// and sums add relative errors of at most 7u^2 each (u = 2^-53). For i = 0, sin x = sin d.
// For i >= 1, |sin x| > sin(2^-7) > 2^-7.01 (|x| < 2), the error of C_i sin d is below 2^-71 and
// that of S_i cos d below 2^-80. So cos x is within 2^-63 and sin x within 2^-63 |sin x|.
#pragma once
#include <gyrores/core/double_double.hpp>

namespace gyrores {

inline void dd_sin_cos(const double_double& x, double_double& s, double_double& c) {
  const dd_table_reduction r = dd_table_reduce(x);
  const double_double& d = r.d;
  const double e = d.hi * d.hi;
  const double p = e * (-1.0 / 6 + e * (1.0 / 120 - e * (1.0 / 5040 - e * (1.0 / 362880))));
  const double q = e * e * (1.0 / 24 - e * (1.0 / 720 - e * (1.0 / 40320 - e * (1.0 / 3628800))));
  const double_double sd = dd::add(d, d.hi * p);
  const double_double half_d2 = dd::add(dd::scale(dd::two_prod(d.hi, d.hi), 0.5), d.hi * d.lo);
  dd_table_step(r, sd, dd::add(dd::add(double_double(1.0), dd::neg(half_d2)), q), s, c);
}

}  // namespace gyrores
