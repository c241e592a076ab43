// Exact numbers of a real quadratic field Q(sqrt d): (p + q sqrt d)/r with integers p, q, r
// (r > 0, gcd(p, q, r) = 1) and d > 0 not a perfect square, or plain rationals (q = 0, d = 0).
//
// Why: for any coupling with n^2 = P/Q rational, x = n/sqrt(n^2 + 4) = sqrt(D)/(P + 4Q) with
// D = P (P + 4Q) (model/coupling.hpp), and the rotation by x (model/rotation.hpp) only adds,
// multiplies, inverts and takes integer parts. Each of these is exact here, so every comparison
// that decides a lobe is decided exactly, never by rounding.
//
// Signs and integer parts are exact (proofs/horizon-theorem.md): sign(p + q sqrt d) compares p^2
// with q^2 d when p and q differ in sign (never equal: d is not a square), and
// floor((p + q sqrt d)/r) = floor((p + s)/r) with s = floor(q sqrt d) from an integer square root,
// because p + s is an integer and q sqrt d - s lies in (0, 1).
#pragma once
#include <string>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/rational.hpp>

namespace gyrores {

class quadratic_number {
 public:
  // 0 (a rational).
  quadratic_number() = default;
  // The rational p/r.
  quadratic_number(const big_int& p, const big_int& r = 1);
  quadratic_number(long p, long r = 1) : quadratic_number(big_int(p), big_int(r)) {}
  explicit quadratic_number(const big_rational& v);
  // (p + q sqrt d)/r; d must be > 0 and not a perfect square when q != 0 (usage_error otherwise).
  quadratic_number(const big_int& p, const big_int& q, const big_int& r, const big_int& d);

  const big_int& p() const { return p_; }
  const big_int& q() const { return q_; }
  const big_int& r() const { return r_; }
  const big_int& d() const { return d_; }
  bool is_rational() const { return q_ == 0; }

  int sign() const;
  // floor and the fractional part {v} = v - floor(v) in [0, 1).
  big_int floor() const;
  big_int ceil() const;
  quadratic_number frac() const;

  // Field arithmetic. Operands must share d (or be rational): usage_error otherwise.
  friend quadratic_number operator+(const quadratic_number& a, const quadratic_number& b);
  friend quadratic_number operator-(const quadratic_number& a, const quadratic_number& b);
  friend quadratic_number operator*(const quadratic_number& a, const quadratic_number& b);
  // compute_error-free: division by zero is a usage_error.
  friend quadratic_number operator/(const quadratic_number& a, const quadratic_number& b);
  quadratic_number operator-() const;

  friend bool operator==(const quadratic_number& a, const quadratic_number& b) { return (a - b).sign() == 0; }
  friend bool operator<(const quadratic_number& a, const quadratic_number& b) { return (a - b).sign() < 0; }
  friend bool operator<=(const quadratic_number& a, const quadratic_number& b) { return (a - b).sign() <= 0; }
  friend bool operator>(const quadratic_number& a, const quadratic_number& b) { return b < a; }
  friend bool operator>=(const quadratic_number& a, const quadratic_number& b) { return b <= a; }

  // The exact value as text: "p/r" or "(p + q*sqrt(d))/r".
  std::string str() const;
  // The double nearest the value (for messages and estimates; decisions use the exact order).
  double approx() const;

 private:
  // (p + q sqrt d)/r for a d taken from an operand (already checked and reduced): normalised only.
  static quadratic_number in_field(big_int p, big_int q, big_int r, const big_int& d);
  void normalise();
  big_int p_ = 0, q_ = 0, r_ = 1, d_ = 0;
};

// The sign of u - v for numbers of any two fields (the field operators need one d), exactly.
int compare(const quadratic_number& u, const quadratic_number& v);

}  // namespace gyrores
