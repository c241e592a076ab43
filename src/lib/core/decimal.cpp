// include/gyrores/core/decimal.hpp: decimal output by MPFR, Ziv's test, decimal integers.
#include <gyrores/core/decimal.hpp>

#include <cstdio>

#include <gyrores/core/fixed_precision.hpp>

namespace gyrores {

std::string format_scientific(const mpfr_real& v, unsigned digits, mpfr_rnd_t rnd) {
  return format_scientific(v.backend().data(), digits, rnd);
}

std::string format_scientific(mpfr_srcptr v, unsigned digits, mpfr_rnd_t rnd) {
  if (digits < 1) digits = 1;
  mpfr_exp_t exp = 0;
  char* raw = mpfr_get_str(nullptr, &exp, 10, digits, v, rnd);
  if (!raw) throw compute_error("format_scientific: MPFR could not format the value");
  std::string s(raw);
  mpfr_free_str(raw);
  const bool neg = !s.empty() && s[0] == '-';
  if (neg) s.erase(0, 1);
  if (mpfr_zero_p(v)) return scientific_text(false, s, 0);  // -0 (an interval's end) prints as 0
  return scientific_text(neg, s, long(exp) - 1);
}

bool enclosure_rounding(mpfr_srcptr lo, mpfr_srcptr hi, unsigned digits, std::string& out) {
  std::string a = format_scientific(lo, digits);
  if (mpfr_equal_p(lo, hi)) {
    out = std::move(a);
    return true;
  }
  // "-0.0e+00" and "0.0e+00" are different texts of one rounding: an interval around 0 is never
  // decided (its values have no common sign), so the texts are compared as they are.
  if (a != format_scientific(hi, digits)) return false;
  out = std::move(a);
  return true;
}

std::string scientific_text(bool negative, const std::string& digits, long e10) {
  // Appended piece by piece (GCC 12 reports a false -Wstringop-overflow on "." + std::string&&).
  std::string out;
  if (negative) out += '-';
  out += digits[0];
  if (digits.size() > 1) {
    out += '.';
    out.append(digits, 1, std::string::npos);
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "e%c%02ld", e10 < 0 ? '-' : '+', e10 < 0 ? -e10 : e10);
  out += buf;
  return out;
}

bool digits_settled(mpfr_srcptr v, mpfr_srcptr rel_err, unsigned digits) {
  if (mpfr_zero_p(v)) return true;
  // |v| rel_err exactly (the product of a p-bit and a q-bit number has p + q bits), the ends outward.
  const mpfr_prec_t prec = mpfr_get_prec(v) + mpfr_get_prec(rel_err);
  fixed_mpfr d(prec), lo(prec), hi(prec);
  mpfr_mul(d, v, rel_err, MPFR_RNDN);
  mpfr_abs(d, d, MPFR_RNDN);
  mpfr_sub(lo, v, d, MPFR_RNDD);
  mpfr_add(hi, v, d, MPFR_RNDU);
  return format_scientific(lo, digits) == format_scientific(hi, digits);
}

bool digits_settled(const mpfr_real& v, const mpfr_real& rel_err, unsigned digits) {
  return digits_settled(v.backend().data(), rel_err.backend().data(), digits);
}

big_int parse_big_int(const std::string& text, const std::string& what) {
  std::size_t i = 0;
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) i = 1;
  if (i == text.size()) throw usage_error(what + " must be an integer, got '" + text + "'");
  for (std::size_t k = i; k < text.size(); ++k)
    if (text[k] < '0' || text[k] > '9') throw usage_error(what + " must be an integer, got '" + text + "'");
  // Strip leading zeros: GMP would read "011" as octal.
  const std::size_t first = text.find_first_not_of('0', i);
  const std::string digits = first == std::string::npos ? "0" : text.substr(first);
  return big_int(text[0] == '-' ? "-" + digits : digits);
}

}  // namespace gyrores
