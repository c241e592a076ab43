// include/gyrores/core/decimal.hpp: decimal output (directed: exact integers; to nearest: MPFR)
// and decimal integers.
#include <gyrores/core/decimal.hpp>

#include <gmp.h>

#include <cmath>

#include <gyrores/core/fixed_precision.hpp>

namespace gyrores {

namespace {

// The integers of the directed conversions, kept per thread: a certificate writes eight ends in
// a row, and the scratch and the last power of ten (its ends share k) are reused, not
// reallocated and recomputed each time.
struct decimal_scratch {
  mpz_t F, rem, pow;
  long pow_k = -1;  // pow = 10^pow_k (none yet)
  decimal_scratch() { mpz_inits(F, rem, pow, nullptr); }
  ~decimal_scratch() { mpz_clears(F, rem, pow, nullptr); }
  decimal_scratch(const decimal_scratch&) = delete;
  decimal_scratch& operator=(const decimal_scratch&) = delete;
  mpz_srcptr power_of_ten(long k) {
    if (k != pow_k) mpz_ui_pow_ui(pow, 10, (unsigned long)k), pow_k = k;
    return pow;
  }
};

// floor(|v| 10^k) in S.F (v = M 2^E exactly, M an integer: integer arithmetic, nothing rounded);
// true if it is exact. A power of two divides by a shift.
bool floor_scaled(decimal_scratch& S, mpfr_srcptr v, long k) {
  const long E = long(mpfr_get_z_2exp(S.F, v));
  mpz_abs(S.F, S.F);
  if (k >= 0) mpz_mul(S.F, S.F, S.power_of_ten(k));
  if (E >= 0) mpz_mul_2exp(S.F, S.F, (mp_bitcnt_t)E);
  if (k < 0) {
    if (E < 0) {  // divide by 10^-k 2^-E
      mpz_mul_2exp(S.rem, S.power_of_ten(-k), (mp_bitcnt_t)-E);
      mpz_fdiv_qr(S.F, S.rem, S.F, S.rem);
    } else {
      mpz_fdiv_qr(S.F, S.rem, S.F, S.power_of_ten(-k));
    }
    return mpz_sgn(S.rem) == 0;
  }
  if (E >= 0) return true;
  const bool exact = mpz_divisible_2exp_p(S.F, (mp_bitcnt_t)-E) != 0;
  mpz_fdiv_q_2exp(S.F, S.F, (mp_bitcnt_t)-E);
  return exact;
}

// The `digits` significant digits of |v| (v finite, nonzero) rounded down in magnitude, or up
// when `up`, and the decimal exponent e10 of the first: exactly, from floor(|v| 10^k) with
// k = digits - 1 - e10. e10 is estimated from log10 |v| and corrected until that floor has
// exactly `digits` digits (then it is the truncation); rounding up adds one unit in the last
// place when the floor was not exact, a carry out of the first digit moving e10.
void directed_digits(mpfr_srcptr v, unsigned digits, bool up, std::string& out, long& e10) {
  long e2 = 0;
  const double m = mpfr_get_d_2exp(&e2, v, MPFR_RNDN);  // |v| = |m| 2^e2, |m| in [1/2, 1]
  e10 = long(std::floor(std::log10(std::fabs(m)) + double(e2) * 0.30102999566398120));
  thread_local decimal_scratch S;
  bool exact = false;
  for (int tries = 0;; ++tries) {
    if (tries == 8) throw compute_error("format_scientific: the decimal exponent did not settle");
    exact = floor_scaled(S, v, long(digits) - 1 - e10);
    if (mpz_sgn(S.F) == 0) {  // |v| 10^k < 1: e10 far too high
      --e10;
      continue;
    }
    out.resize(mpz_sizeinbase(S.F, 10) + 2);
    mpz_get_str(out.data(), 10, S.F);
    out.resize(std::char_traits<char>::length(out.c_str()));
    if (out.size() == digits) break;
    e10 += long(out.size()) - long(digits);  // the estimate was off (near a power of 10)
  }
  if (!up || exact) return;
  std::size_t i = digits;
  while (i > 0 && out[i - 1] == '9') out[--i] = '0';
  if (i > 0) {
    ++out[i - 1];
  } else {  // 99...9 + 1: 10...0, one place up
    out[0] = '1';
    ++e10;
  }
}

}  // namespace

std::string format_scientific(const mpfr_real& v, unsigned digits, mpfr_rnd_t rnd) {
  return format_scientific(v.backend().data(), digits, rnd);
}

std::string format_scientific(mpfr_srcptr v, unsigned digits, mpfr_rnd_t rnd) {
  if (digits < 1) digits = 1;
  // Directed roundings (the ends of enclosures, the certificates' hot path) exactly by integers;
  // to nearest by MPFR. So do binary exponents beyond 2^16: the integers grow with the exponent
  // (10^k for k ~ |exponent| log10 2), MPFR's conversion does not.
  if (rnd != MPFR_RNDN && !mpfr_zero_p(v) && mpfr_number_p(v) && std::labs(long(mpfr_get_exp(v))) < (1L << 16)) {
    const bool neg = mpfr_sgn(v) < 0;
    // Up in magnitude: away from zero, or toward the infinity on v's side.
    const bool up = rnd == MPFR_RNDA || (rnd == MPFR_RNDU && !neg) || (rnd == MPFR_RNDD && neg);
    std::string d;
    long e10 = 0;
    directed_digits(v, digits, up, d, e10);
    return scientific_text(neg, d, e10);
  }
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
  // The exponent by hand (snprintf cost more than the digits at 30 of them): sign, >= 2 digits.
  out += 'e';
  out += e10 < 0 ? '-' : '+';
  unsigned long e = e10 < 0 ? 0UL - (unsigned long)e10 : (unsigned long)e10;
  char buf[24];
  int n = 0;
  do {
    buf[n++] = char('0' + e % 10);
    e /= 10;
  } while (e);
  if (n < 2) buf[n++] = '0';
  while (n) out += buf[--n];
  return out;
}

big_int parse_big_int(const std::string& text, const std::string& what) {
  std::size_t i = 0;
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) i = 1;
  if (i == text.size()) throw usage_error(what + " must be an integer, got '" + shown_input(text) + "'");
  for (std::size_t k = i; k < text.size(); ++k)
    if (text[k] < '0' || text[k] > '9') throw usage_error(what + " must be an integer, got '" + shown_input(text) + "'");
  // Strip leading zeros: GMP would read "011" as octal.
  const std::size_t first = text.find_first_not_of('0', i);
  const std::string digits = first == std::string::npos ? "0" : text.substr(first);
  return big_int(text[0] == '-' ? "-" + digits : digits);
}

}  // namespace gyrores
