// A proved real value: an enclosure [lo, hi] with exact binary ends (each end an MPFR number of
// its own precision, copied exactly), and optionally the exact rational it encloses. The theorem
// layer returns enclosures; they become text only at the edge (report/, certify/, io/), through
// the three roundings below, so a proved value never loses its proof to a round trip through a
// decimal string:
//   rounded(D)       the correct rounding to nearest with D significant digits, when every value
//                    of [lo, hi] rounds alike (else none: refine the enclosure); an exact rational
//                    is rounded once, ties to even (an exact tie no enclosure could settle);
//   nearest_double() the double nearest to the value, when every value of [lo, hi] rounds to it;
//   outward(D)       D-digit decimal ends rounded outward: lo rounded down, hi rounded up (an
//                    exact rational: its own D-digit decimal at both ends when that is exact).
// The report digit limits (report_digits_max) live here: every real the tool prints goes through
// rounded() with digits in [1, report_digits_max].
#pragma once
#include <mpfi.h>
#include <mpfr.h>

#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include <gyrores/core/rational.hpp>

namespace gyrores {

// The most significant digits a report gives and a certificate states.
inline constexpr unsigned report_digits_max = 10000;

// usage_error ("digits must be in [1, 10000], got D") outside [1, report_digits_max].
void check_report_digits(unsigned digits);

// An MPFR number that owns its limbs and keeps its own precision when copied (Boost's mpfr_real
// copies at the process-wide default precision in places; this never reads it).
class exact_binary {
 public:
  exact_binary() : exact_binary(2) {}
  explicit exact_binary(mpfr_prec_t prec) { mpfr_init2(v_, prec), mpfr_set_zero(v_, 1); }
  explicit exact_binary(mpfr_srcptr v) { mpfr_init2(v_, mpfr_get_prec(v)), mpfr_set(v_, v, MPFR_RNDN); }
  exact_binary(const exact_binary& o) : exact_binary(static_cast<mpfr_srcptr>(o.v_)) {}
  exact_binary& operator=(const exact_binary& o) {
    if (this != &o) mpfr_set_prec(v_, mpfr_get_prec(o.v_)), mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  ~exact_binary() { mpfr_clear(v_); }
  operator mpfr_srcptr() const { return v_; }
  mpfr_ptr get() { return v_; }

 private:
  mpfr_t v_;
};

// A proved real as a report prints it: the correct rounding to nearest with the digits asked,
// and (when asked) the enclosure rounded outward to digits + 3 digits (report/).
struct proved_real {
  std::string value;                              // correctly rounded, `digits` significant digits
  std::pair<std::string, std::string> enclosure;  // holds the exact value; outward, digits + 3 digits (when asked)
  double nearest = 0;  // the double nearest the exact value, decided by the same enclosure (when asked)
  operator const std::string&() const { return value; }  // where text is wanted, the value
};
inline std::ostream& operator<<(std::ostream& os, const proved_real& r) { return os << r.value; }

// The exact rational value of a finite MPFR number.
big_rational rational_of(mpfr_srcptr v);

// The double nearest every value of [lo, hi]: rounding to nearest is monotone, so ends that round
// to one double decide it (beyond double's range an infinity or a zero, as strtod reads such a
// decimal); none when they round to two.
std::optional<double> nearest_double(mpfr_srcptr lo, mpfr_srcptr hi);
// The double nearest an exact rational (rounded once, ties to even).
double nearest_double(const big_rational& v);

class enclosure {
 public:
  enclosure() : exact_(big_rational(0)) {}  // [0, 0], exact 0
  // [lo, hi] from two MPFR numbers (copied exactly). Precondition (not checked): lo <= hi, finite.
  enclosure(mpfr_srcptr lo, mpfr_srcptr hi) : lo_(lo), hi_(hi) {}
  explicit enclosure(mpfi_srcptr v) : lo_(&v->left), hi_(&v->right) {}
  // An exact rational; its binary ends lo(), hi() are v rounded outward to `bits` bits (the
  // enclosure an interval computation at that precision would hold).
  static enclosure exact(const big_rational& v, mpfr_prec_t bits = 128);

  mpfr_srcptr lo() const { return lo_; }
  mpfr_srcptr hi() const { return hi_; }
  bool is_exact() const { return exact_.has_value(); }

  std::optional<std::string> rounded(unsigned digits) const;
  std::optional<double> nearest_double() const;
  std::pair<std::string, std::string> outward(unsigned digits) const;
  // rounded(D) with outward(D + 3), as a report prints it (proved_real above); none while the
  // rounding is undecided.
  std::optional<proved_real> report(unsigned digits) const;

  // The ends as exact rationals (lo <= value <= hi).
  big_rational lo_rational() const;
  big_rational hi_rational() const;

 private:
  exact_binary lo_, hi_;
  std::optional<big_rational> exact_;
};

}  // namespace gyrores
