// Integer types used for resonant pairs, and exact helpers on them.
//
// Two integer types are supported: std::int64_t (fast path) and big_int (GMP, any size).
// Sums and products of pair entries are formed in wide_int<I>: __int128 for int64_t, big_int
// otherwise, so (2^62+1, 2^62-1), whose sum overflows 64 bits, is handled exactly.
#pragma once
#include <boost/multiprecision/gmp.hpp>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <gyrores/core/error.hpp>

namespace gyrores {

using big_int = boost::multiprecision::mpz_int;
using int128 = __int128;

template <class I> struct wide_int_of;
template <> struct wide_int_of<std::int64_t> { using type = int128; };
template <> struct wide_int_of<int128> { using type = big_int; };
template <> struct wide_int_of<big_int> { using type = big_int; };
template <class I> using wide_int = typename wide_int_of<I>::type;

template <class I>
concept pair_integer = std::is_same_v<I, std::int64_t> || std::is_same_v<I, big_int>;

// Decimal text of an integer (std::to_string has no __int128 overload).
inline std::string to_decimal(const big_int& v) { return v.str(); }
inline std::string to_decimal(std::int64_t v) { return std::to_string(v); }
inline std::string to_decimal(int128 v) {
  if (v == 0) return "0";
  bool neg = v < 0;
  unsigned __int128 u = neg ? (unsigned __int128)(-(v + 1)) + 1 : (unsigned __int128)v;
  std::string s;
  while (u) { s.insert(s.begin(), char('0' + int(u % 10))); u /= 10; }
  return neg ? "-" + s : s;
}

inline big_int to_big(const big_int& v) { return v; }
inline big_int to_big(std::int64_t v) { return big_int(v); }
inline big_int to_big(int128 v) {
  if (v >= INT64_MIN && v <= INT64_MAX) return big_int(std::int64_t(v));  // one GMP operation
  bool neg = v < 0;
  unsigned __int128 u = neg ? (unsigned __int128)(-(v + 1)) + 1 : (unsigned __int128)v;
  const std::uint64_t limbs[2] = {std::uint64_t(u), std::uint64_t(u >> 64)};  // least significant first
  big_int r;
  mpz_import(r.backend().data(), 2, -1, sizeof(std::uint64_t), 0, 0, limbs);
  if (neg) mpz_neg(r.backend().data(), r.backend().data());
  return r;
}

// v as int128. Precondition (not checked): |v| < 2^127.
inline int128 to_int128(const big_int& v) {
  mpz_srcptr z = v.backend().data();
  unsigned __int128 u = 0;
  const std::size_t n = mpz_size(z);
  for (std::size_t i = n; i-- > 0;) u = (u << 64) | (unsigned __int128)mpz_getlimbn(z, mp_size_t(i));
  return mpz_sgn(z) < 0 ? -int128(u) : int128(u);
}

// Greatest common divisor of |x| and |y|; gcd(0, 0) = 0.
template <class I> I int_gcd(I x, I y) {
  if (x < 0) x = -x;
  if (y < 0) y = -y;
  while (y != 0) { I t = x % y; x = y; y = t; }
  return x;
}
inline big_int int_gcd(const big_int& x, const big_int& y) { return boost::multiprecision::gcd(x, y); }

// 2-adic valuation: the exponent of 2 in n. Precondition (checked): n != 0.
template <class I> unsigned int_v2(I n) {
  if (n == 0) throw std::domain_error("int_v2: the 2-adic valuation of 0 is undefined");
  unsigned v = 0;
  while ((n & 1) == 0) { n >>= 1; ++v; }
  return v;
}
inline unsigned int_v2(const big_int& n) {
  if (n == 0) throw std::domain_error("int_v2: the 2-adic valuation of 0 is undefined");
  return unsigned(boost::multiprecision::lsb(boost::multiprecision::abs(n)));
}

// n mod m in [0, m) for m > 0 (C++'s % truncates toward zero).
template <class I> I int_mod(const I& n, const I& m) {
  I r = n % m;
  if (r < 0) r += m;
  return r;
}

// Floor division for d > 0.
template <class I> I int_floor_div(const I& n, const I& d) {
  I q = n / d;
  if ((n % d != 0) && (n < 0)) q -= 1;
  return q;
}

// Inverse of x modulo m (m >= 2, gcd(x, m) = 1, checked), in [0, m). Extended Euclid: O(log m).
template <class I> I int_inverse_mod(const I& x, const I& m) {
  I r0 = m, r1 = int_mod(x, m), s0 = 0, s1 = 1;
  while (r1 != 0) {
    I qt = r0 / r1;
    I t = r0 - qt * r1; r0 = r1; r1 = t;
    t = s0 - qt * s1; s0 = s1; s1 = t;
  }
  if (r0 != 1) throw std::domain_error("int_inverse_mod: arguments are not coprime");
  return int_mod(s0, m);
}

}  // namespace gyrores
