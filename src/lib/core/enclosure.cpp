// include/gyrores/core/enclosure.hpp: proved values and their three roundings.
#include <gyrores/core/enclosure.hpp>

#include <cmath>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>

namespace gyrores {

big_rational rational_of(mpfr_srcptr v) {
  if (mpfr_zero_p(v)) return big_rational(0);  // (mpfr_get_z_2exp gives 0 the exponent emin)
  big_int m;
  const long e = long(mpfr_get_z_2exp(m.backend().data(), v));
  if (e >= 0) return big_rational(big_int(m << static_cast<unsigned>(e)));
  return big_rational(m, big_int(1) << static_cast<unsigned>(-e));
}

void check_report_digits(unsigned digits) {
  if (digits < 1 || digits > report_digits_max)
    throw usage_error("digits must be in [1, " + std::to_string(report_digits_max) + "], got " + std::to_string(digits));
}

enclosure enclosure::exact(const big_rational& v, mpfr_prec_t bits) {
  enclosure e;
  exact_binary lo(bits), hi(bits);
  mpfr_set_q(lo.get(), v.backend().data(), MPFR_RNDD);
  mpfr_set_q(hi.get(), v.backend().data(), MPFR_RNDU);
  e.lo_ = lo;
  e.hi_ = hi;
  e.exact_ = v;
  return e;
}

std::optional<std::string> enclosure::rounded(unsigned digits) const {
  if (exact_) return format_rational_scientific(*exact_, digits);
  std::string out;
  if (!enclosure_rounding(lo_, hi_, digits, out)) return std::nullopt;
  return out;
}

std::optional<double> nearest_double(mpfr_srcptr lo, mpfr_srcptr hi) {
  const double a = mpfr_get_d(lo, MPFR_RNDN), b = mpfr_get_d(hi, MPFR_RNDN);
  if (a != b) return std::nullopt;
  return a;
}

double nearest_double(const big_rational& v) {
  exact_binary t(53);  // to nearest at 53 bits: the double itself
  mpfr_set_q(t.get(), v.backend().data(), MPFR_RNDN);
  return mpfr_get_d(t, MPFR_RNDN);
}

std::optional<double> enclosure::nearest_double() const {
  if (exact_) return gyrores::nearest_double(*exact_);
  const auto d = gyrores::nearest_double(lo_, hi_);
  if (d && !std::isfinite(*d)) return std::nullopt;
  return d;
}

std::pair<std::string, std::string> enclosure::outward(unsigned digits) const {
  if (!exact_) return {format_scientific(lo_, digits, MPFR_RNDD), format_scientific(hi_, digits, MPFR_RNDU)};
  // An exact rational: its own decimal when it has at most D digits, else its ends through
  // 64 + 4 D bits.
  bool exact = false;
  const std::string e = format_rational_scientific(*exact_, digits, &exact);
  if (exact) return {e, e};
  exact_binary lo(64 + 4 * mpfr_prec_t(digits)), hi(64 + 4 * mpfr_prec_t(digits));
  mpfr_set_q(lo.get(), exact_->backend().data(), MPFR_RNDD);
  mpfr_set_q(hi.get(), exact_->backend().data(), MPFR_RNDU);
  return {format_scientific(lo, digits, MPFR_RNDD), format_scientific(hi, digits, MPFR_RNDU)};
}

std::optional<proved_real> enclosure::report(unsigned digits) const {
  auto value = rounded(digits);
  if (!value) return std::nullopt;
  return proved_real{std::move(*value), outward(digits + 3)};
}

big_rational enclosure::lo_rational() const { return exact_ ? *exact_ : rational_of(lo_); }
big_rational enclosure::hi_rational() const { return exact_ ? *exact_ : rational_of(hi_); }

}  // namespace gyrores
