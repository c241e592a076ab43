// include/gyrores/core/dd_ball.hpp: the ball operations, each the double-double operation on the
// midpoints plus the propagated radius and the operation's bound (the header's list).
#include <gyrores/core/dd_ball.hpp>

#include <cmath>

namespace gyrores::ddb {

// Not cloned (it needs no FMA), so that the operations below inline it.
double up(double v) { return v * (1 + 0x1p-48) + 0x1p-1000; }

GYRORES_DD_FAST dd_ball add(const dd_ball& x, const dd_ball& y) {
  const double_double m = dd::add(x.m, y.m);
  return {m, up(x.r + y.r + add_bound * std::fabs(m.hi))};
}
GYRORES_DD_FAST dd_ball sub(const dd_ball& x, const dd_ball& y) {
  const double_double m = dd::sub(x.m, y.m);
  return {m, up(x.r + y.r + add_bound * std::fabs(m.hi))};
}
// |x y - mx my| <= |mx| ry + |my| rx + rx ry (|mx| <= |mx.hi| (1 + 2^-53): up's slack).
GYRORES_DD_FAST dd_ball mul(const dd_ball& x, const dd_ball& y) {
  const double_double m = dd::mul(x.m, y.m);
  return {m, up(mag(x) * y.r + mag(y) * x.r + x.r * y.r + mul_bound * std::fabs(m.hi))};
}
// den: a double at most |my| - ry (|my| >= |my.hi| (1 - 2^-53)); qa at least |mx/my|.
GYRORES_DD_FAST bool div(dd_ball& out, const dd_ball& x, const dd_ball& y) {
  const double den = std::fabs(y.m.hi) * (1 - 0x1p-50) - y.r * (1 + 0x1p-50);
  if (!(den > 0)) return false;
  const double_double q = dd::div(x.m, y.m);
  const double qa = std::fabs(q.hi) * (1 + 0x1p-50);
  out = {q, up((x.r + qa * y.r) / (den * (1 - 0x1p-50)) + div_bound * std::fabs(q.hi))};
  return true;
}
// |sqrt(v) - sqrt(m)| = |v - m|/(sqrt(v) + sqrt(m)) <= r/sqrt(m - r), low at most m - r.
GYRORES_DD_FAST bool sqrt(dd_ball& out, const dd_ball& x) {
  const double low = x.m.hi * (1 - 0x1p-50) - x.r * (1 + 0x1p-50);
  if (!(low > 0)) return false;
  const double_double s = dd::sqrt(x.m);
  out = {s, up(x.r / (std::sqrt(low) * (1 - 0x1p-50)) + sqrt_bound * std::fabs(s.hi))};
  return true;
}
// dd_sin_cos_accurate is within 2^-101 |sin m| and 2^-101 of sin m, cos m; |sin m| <= |s.hi| (1 + 2^-52).
GYRORES_DD_FAST void sin_cos(const dd_ball& x, dd_ball& s, dd_ball& c) {
  dd_sin_cos_accurate(x.m, s.m, c.m);
  s.r = up(sin_bound * std::fabs(s.m.hi) + x.r);
  c.r = up(cos_bound + x.r);
}
// m >= m.hi (1 - 2^-53) for m.hi > 0; the product, rounded, is at most that.
GYRORES_DD_FAST bool positive(const dd_ball& x) { return x.m.hi > 0 && x.m.hi * (1 - 0x1p-52) > x.r; }
GYRORES_DD_FAST bool negative(const dd_ball& x) { return x.m.hi < 0 && -x.m.hi * (1 - 0x1p-52) > x.r; }
GYRORES_DD_FAST double upper_abs(const dd_ball& x) { return up(std::fabs(x.m.hi) * (1 + 0x1p-52) + x.r); }

}  // namespace gyrores::ddb
