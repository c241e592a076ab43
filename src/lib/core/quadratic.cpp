// include/gyrores/core/quadratic.hpp
#include <gyrores/core/quadratic.hpp>

#include <boost/multiprecision/integer.hpp>
#include <algorithm>
#include <cmath>

#include <gyrores/core/error.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/refine.hpp>

namespace gyrores {
namespace {

// floor(q sqrt d) for d > 0 not a square: q sqrt d is irrational when q != 0.
big_int floor_q_sqrt_d(const big_int& q, const big_int& d) {
  if (q == 0) return 0;
  const big_int root = boost::multiprecision::sqrt(big_int(q * q * d));
  return q > 0 ? root : big_int(-root - 1);
}

std::size_t msb_or_zero(const big_int& v) { return v == 0 ? 0 : boost::multiprecision::msb(v < 0 ? big_int(-v) : v); }

const big_int& common_d(const quadratic_number& a, const quadratic_number& b) {
  if (a.is_rational()) return b.d();
  if (!b.is_rational() && a.d() != b.d()) throw usage_error("quadratic_number: operands from different fields");
  return a.d();
}

}  // namespace

quadratic_number::quadratic_number(const big_int& p, const big_int& r) : p_(p), r_(r) {
  if (r == 0) throw usage_error("quadratic_number: zero denominator");
  normalise();
}

quadratic_number::quadratic_number(const big_rational& v)
    : quadratic_number(big_int(boost::multiprecision::numerator(v)), big_int(boost::multiprecision::denominator(v))) {}

quadratic_number::quadratic_number(const big_int& p, const big_int& q, const big_int& r, const big_int& d)
    : p_(p), q_(q), r_(r), d_(d) {
  if (r == 0) throw usage_error("quadratic_number: zero denominator");
  if (q != 0) {
    big_int root;
    if (d <= 0 || int_is_square(d, root)) throw usage_error("quadratic_number: d = " + d.str() + " is not a positive non-square");
    // Move small square factors of d into q, so that equal fields usually get equal d
    // (sqrt 32 = 4 sqrt 2); operands must still share d exactly.
    for (long f = 2; f <= 97; ++f)
      while (d_ % (f * f) == 0) {
        d_ /= f * f;
        q_ *= f;
      }
  }
  normalise();
}

quadratic_number quadratic_number::in_field(big_int p, big_int q, big_int r, const big_int& d) {
  if (r == 0) throw usage_error("quadratic_number: zero denominator");
  quadratic_number v;
  v.p_ = std::move(p);
  v.q_ = std::move(q);
  v.r_ = std::move(r);
  v.d_ = d;
  v.normalise();
  return v;
}

void quadratic_number::normalise() {
  if (r_ < 0) {
    p_ = -p_;
    q_ = -q_;
    r_ = -r_;
  }
  if (q_ == 0) d_ = 0;
  big_int g = int_gcd(int_gcd(p_ < 0 ? big_int(-p_) : p_, q_ < 0 ? big_int(-q_) : q_), r_);
  if (g > 1) {
    p_ /= g;
    q_ /= g;
    r_ /= g;
  }
}

int quadratic_number::sign() const {
  const int sp = p_ > 0 ? 1 : (p_ < 0 ? -1 : 0), sq = q_ > 0 ? 1 : (q_ < 0 ? -1 : 0);
  if (sq == 0) return sp;
  if (sp == 0 || sp == sq) return sq;
  // Opposite signs: the larger of p^2 and q^2 d wins (they differ: d is not a square).
  return p_ * p_ > q_ * q_ * d_ ? sp : sq;
}

big_int quadratic_number::floor() const { return int_floor_div(big_int(p_ + floor_q_sqrt_d(q_, d_)), r_); }

big_int quadratic_number::ceil() const {
  const big_int f = floor();
  return (*this - quadratic_number(f)).sign() == 0 ? f : big_int(f + 1);
}

quadratic_number quadratic_number::frac() const { return *this - quadratic_number(floor()); }

quadratic_number operator+(const quadratic_number& a, const quadratic_number& b) {
  const big_int& d = common_d(a, b);
  return quadratic_number::in_field(a.p_ * b.r_ + b.p_ * a.r_, a.q_ * b.r_ + b.q_ * a.r_, a.r_ * b.r_, d);
}

quadratic_number quadratic_number::operator-() const {
  quadratic_number v = *this;
  v.p_ = -v.p_;
  v.q_ = -v.q_;
  return v;
}

quadratic_number operator-(const quadratic_number& a, const quadratic_number& b) { return a + (-b); }

quadratic_number operator*(const quadratic_number& a, const quadratic_number& b) {
  const big_int& d = common_d(a, b);
  return quadratic_number::in_field(a.p_ * b.p_ + a.q_ * b.q_ * d, a.p_ * b.q_ + a.q_ * b.p_, a.r_ * b.r_, d);
}

quadratic_number operator/(const quadratic_number& a, const quadratic_number& b) {
  if (b.sign() == 0) throw usage_error("quadratic_number: division by zero");
  // 1/b = r (p - q sqrt d)/(p^2 - q^2 d); the norm is non-zero since d is not a square.
  const big_int norm = b.p_ * b.p_ - b.q_ * b.q_ * b.d_;
  const quadratic_number inv = quadratic_number::in_field(b.r_ * b.p_, -b.r_ * b.q_, norm, b.d_);
  return a * inv;
}

std::string quadratic_number::str() const {
  if (q_ == 0) return r_ == 1 ? p_.str() : p_.str() + "/" + r_.str();
  const big_int aq = q_ < 0 ? big_int(-q_) : q_;
  const std::string root = (aq == 1 ? "" : aq.str() + "*") + "sqrt(" + d_.str() + ")";
  std::string num = p_ == 0 ? (q_ < 0 ? "-" : "") + root : p_.str() + (q_ < 0 ? " - " : " + ") + root;
  if (r_ == 1) return num;
  return (p_ == 0 ? num : "(" + num + ")") + "/" + r_.str();
}

int compare(const quadratic_number& u, const quadratic_number& v) {
  if (u.is_rational() || v.is_rational() || u.d() == v.d()) return (u - v).sign();
  // r_u r_v (u - v) = X - y sqrt(d_v), X = r_v p_u - r_u p_v + r_v q_u sqrt(d_u) in Q(sqrt d_u):
  // X - Y has the sign of X when Y = y sqrt(d_v) has another sign, else that sign times the sign
  // of X^2 - y^2 d_v, which lies in Q(sqrt d_u) again.
  const quadratic_number X(v.r() * u.p() - u.r() * v.p(), v.r() * u.q(), big_int(1), u.d());
  const big_int y = u.r() * v.q();
  const int sx = X.sign(), sy = y.sign();
  if (sx != sy) return sx > sy ? 1 : -1;
  return sx * (X * X - quadratic_number(big_int(y * y * v.d()))).sign();
}

double quadratic_number::approx() const {
  if (is_rational()) return nearest_double(big_rational(p_, r_));
  // An enclosure of (p + q sqrt d)/r at the precisions of the one loop (core/refine), until it
  // decides its nearest double (core/enclosure.hpp). p and q sqrt d may nearly cancel: the start
  // covers their size.
  const std::size_t top = std::max(msb_or_zero(p_), msb_or_zero(q_) + msb_or_zero(d_) / 2 + 1) + 1;
  return refine(precision_plan{mpfr_prec_t(top + 64)}, {}, "the double nearest " + str(),
                [&](mpfr_prec_t bits, proof_status& status) -> std::optional<double> {
                  fixed_mpfi v(bits), t(bits);
                  mpfi_set_z(t, d_.backend().data());
                  mpfi_sqrt(t, t);
                  mpfi_mul_z(t, t, q_.backend().data());
                  mpfi_add_z(v, t, p_.backend().data());
                  mpfi_div_z(v, v, r_.backend().data());
                  const auto d = nearest_double(v.left(), v.right());
                  if (!d) status = proof_status::undecided("the ends of its enclosure round to two doubles");
                  return d;
                });
}

}  // namespace gyrores
