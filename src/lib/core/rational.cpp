// include/gyrores/core/rational.hpp
#include <gyrores/core/rational.hpp>

#include <cctype>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

// The value of a decimal "[+-]digits[.digits][(e|E)[+-]digits]" as p/10^k, exactly.
big_rational parse_decimal_exact(const std::string& text, const std::string& what) {
  auto bad = [&]() { return usage_error(what + " must be a decimal or a fraction P/Q, got '" + shown_input(text) + "'"); };
  std::size_t i = 0;
  bool neg = false;
  if (text[i] == '+' || text[i] == '-') neg = text[i++] == '-';
  std::string digits;
  long frac = 0;
  bool seen_dot = false;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    const char ch = text[i];
    if (ch == '.' && !seen_dot) {
      seen_dot = true;
    } else if (std::isdigit((unsigned char)ch)) {
      digits += ch;
      if (seen_dot) ++frac;
    } else {
      throw bad();
    }
  }
  if (digits.empty()) throw bad();
  long exp10 = 0;
  if (i < text.size()) {
    const std::string e = text.substr(i + 1);
    const std::size_t k = !e.empty() && (e[0] == '+' || e[0] == '-') ? 1 : 0;
    if (k == e.size() || e.size() - k > 6) throw bad();
    for (std::size_t j = k; j < e.size(); ++j)
      if (!std::isdigit((unsigned char)e[j])) throw bad();
    exp10 = std::stol(e);
  }
  const long shift = exp10 - frac;
  if (shift > 100000 || shift < -100000) throw usage_error(what + ": exponent out of range in '" + shown_input(text) + "'");
  big_int num = parse_big_int(digits, what), den(1);
  const big_int ten_pow = boost::multiprecision::pow(big_int(10), unsigned(shift < 0 ? -shift : shift));
  if (shift >= 0) num *= ten_pow;
  else den = ten_pow;
  if (neg) num = -num;
  return big_rational(num, den);
}

}  // namespace

big_rational parse_rational(const std::string& text, const std::string& what) {
  if (text.empty()) throw usage_error(what + " must be a decimal or a fraction P/Q, got ''");
  const auto slash = text.find('/');
  if (slash == std::string::npos) return parse_decimal_exact(text, what);
  const std::string p = text.substr(0, slash), q = text.substr(slash + 1);
  const big_int num = parse_big_int(p, what + " (numerator)");
  if (q.empty() || q[0] == '+' || q[0] == '-')
    throw usage_error(what + " must be a decimal or a fraction P/Q, got '" + shown_input(text) + "'");
  const big_int den = parse_big_int(q, what + " (denominator)");
  if (den == 0) throw usage_error(what + ": denominator is zero in '" + shown_input(text) + "'");
  return big_rational(num, den);
}

std::string rational_str(const big_rational& r) {
  const big_int q = boost::multiprecision::denominator(r);
  const std::string s = boost::multiprecision::numerator(r).str();
  return q == 1 ? s : s + "/" + q.str();
}

namespace {

big_int pow10(long e) { return boost::multiprecision::pow(big_int(10), unsigned(e)); }

long decimal_length(const big_int& v) { return long(v.str().size()); }

// |q| = n 10^(e10 - digits + 1), n of `digits` digits, rounded in magnitude: to nearest with ties
// to even (dir 0), down (-1) or up (+1); `exact` when no rounding happened. q != 0.
big_int decimal_digits_of(const big_rational& q, unsigned digits, int dir, long& e10, bool& exact) {
  const long d = long(digits);
  big_int num = boost::multiprecision::numerator(q), den = boost::multiprecision::denominator(q);
  if (num < 0) num = -num;
  // e10 = floor(log10 |q|): 10^e10 <= num/den < 10^(e10+1); the length difference is within 1.
  e10 = decimal_length(num) - decimal_length(den);
  auto at_least = [&](long e) { return e >= 0 ? num >= den * pow10(e) : num * pow10(-e) >= den; };
  if (!at_least(e10)) --e10;
  const long s = d - 1 - e10;
  big_int top = s >= 0 ? big_int(num * pow10(s)) : num, bottom = s >= 0 ? den : big_int(den * pow10(-s));
  big_int n = top / bottom, rem = top - n * bottom;
  exact = rem == 0;
  const int cmp = big_int(2 * rem).compare(bottom);
  if (dir > 0 ? !exact : dir == 0 && (cmp > 0 || (cmp == 0 && (n & 1) != 0))) ++n;
  if (n == pow10(d)) {  // rounded up to 10^d: one more decade, d digits 100...0
    n = pow10(d - 1);
    ++e10;
  }
  return n;
}

}  // namespace

std::string format_rational_scientific(const big_rational& q, unsigned digits, bool* exact) {
  if (digits < 1) digits = 1;
  if (exact) *exact = true;
  if (q == 0) return scientific_text(false, std::string(std::size_t(digits), '0'), 0);
  long e10 = 0;
  bool is_exact = false;
  const big_int n = decimal_digits_of(q, digits, 0, e10, is_exact);
  if (exact) *exact = is_exact;
  return scientific_text(q < 0, n.str(), e10);
}

big_rational decimal_rounded(const big_rational& q, unsigned digits, int dir) {
  if (q == 0) return q;
  long e10 = 0;
  bool exact = false;
  const big_int n = decimal_digits_of(q, digits, q < 0 ? -dir : dir, e10, exact);
  const long s = long(digits) - 1 - e10;
  const big_rational v = s >= 0 ? big_rational(n, pow10(s)) : big_rational(big_int(n * pow10(-s)));
  return q < 0 ? big_rational(-v) : v;
}

bool int_is_square(const big_int& v, big_int& root) {
  if (v < 0) return false;
  root = boost::multiprecision::sqrt(v);
  return root * root == v;
}

big_int floor_sqrt(const big_rational& y) {
  return boost::multiprecision::sqrt(big_int(numerator(y) / denominator(y)));
}

std::optional<big_rational> rational_sqrt(const big_rational& r) {
  big_int p, q;
  if (int_is_square(big_int(numerator(r)), p) && int_is_square(big_int(denominator(r)), q)) return big_rational(p, q);
  return std::nullopt;
}

}  // namespace gyrores
