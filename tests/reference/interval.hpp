// Interval helpers on mpfi_real with tri-state decisions (docs/architecture.md, "Intervals").
//
// Never use <, ==, sign() on mpfi_real: in Boost 1.74 an ambiguous comparison throws from a
// noexcept function and terminates the process. Every predicate here reads the endpoints:
// "certainly" answers true only when the whole interval satisfies the condition.
//
// Precision: new intervals and points take Boost's default precision of mpfi_real/mpfr_real,
// which the arguments must have (core/real.hpp); these helpers serve the proof programs, which
// set it and run single-threaded. Proved code of the library works
// on fixed_mpfi (core/fixed_precision.hpp) or Arb balls instead.
#pragma once
#include <mpfi.h>

#include <string>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores {

inline mpfr_real interval_lower(const mpfi_real& x) { return boost::multiprecision::lower(x); }
inline mpfr_real interval_upper(const mpfi_real& x) { return boost::multiprecision::upper(x); }

inline bool certainly_positive(const mpfi_real& x) { return mpfi_is_strictly_pos(x.backend().data()) > 0; }
inline bool certainly_negative(const mpfi_real& x) { return mpfi_is_strictly_neg(x.backend().data()) > 0; }
inline bool certainly_nonzero(const mpfi_real& x) { return certainly_positive(x) || certainly_negative(x); }
// a < b for every element of each.
inline bool certainly_less(const mpfi_real& a, const mpfi_real& b) { return interval_upper(a) < interval_lower(b); }
// a is inside the interior of b.
inline bool certainly_inside(const mpfi_real& a, const mpfi_real& b) {
  return interval_lower(b) < interval_lower(a) && interval_upper(a) < interval_upper(b);
}
inline bool certainly_subset(const mpfi_real& a, const mpfi_real& b) {
  return interval_lower(b) <= interval_lower(a) && interval_upper(a) <= interval_upper(b);
}

// The interval [lo, hi] from two point values (precondition lo <= hi; rounded outward).
inline mpfi_real interval_of(const mpfr_real& lo, const mpfr_real& hi) {
  mpfi_real r;
  mpfi_interv_fr(r.backend().data(), lo.backend().data(), hi.backend().data());
  return r;
}
inline mpfi_real interval_point(const mpfr_real& v) { return interval_of(v, v); }

// x^2 with the dependency respected ([-1, 2]^2 = [0, 4], not [-2, 4]).
inline mpfi_real interval_sqr(const mpfi_real& x) {
  mpfi_real r;
  mpfi_sqr(r.backend().data(), x.backend().data());
  return r;
}
inline mpfi_real interval_abs(const mpfi_real& x) {
  mpfi_real r;
  mpfi_abs(r.backend().data(), x.backend().data());
  return r;
}
inline mpfi_real interval_hull(const mpfi_real& a, const mpfi_real& b) {
  mpfi_real r;
  mpfi_union(r.backend().data(), a.backend().data(), b.backend().data());
  return r;
}
inline mpfi_real interval_intersect(const mpfi_real& a, const mpfi_real& b) {
  mpfi_real r;
  mpfi_intersect(r.backend().data(), a.backend().data(), b.backend().data());
  return r;
}
inline mpfi_real interval_mid(const mpfi_real& x) {
  mpfr_real m;
  mpfi_mid(m.backend().data(), x.backend().data());
  return interval_point(m);
}
inline mpfr_real interval_mid_point(const mpfi_real& x) {
  mpfr_real m;
  mpfi_mid(m.backend().data(), x.backend().data());
  return m;
}

// Relative width (absolute where the interval contains 0): the digits an enclosure certifies.
inline mpfr_real interval_rel_width(const mpfi_real& x) {
  mpfr_real w = interval_upper(x) - interval_lower(x);
  if (!certainly_nonzero(x)) return w;
  mpfr_real m = abs(interval_lower(x)) < abs(interval_upper(x)) ? abs(interval_lower(x)) : abs(interval_upper(x));
  return w / m;
}

// Decimal endpoints rounded outward with `digits` significant digits: [down(lo), up(hi)].
inline std::pair<std::string, std::string> interval_to_decimal(const mpfi_real& x, unsigned digits) {
  return {format_scientific(interval_lower(x), digits, MPFR_RNDD),
          format_scientific(interval_upper(x), digits, MPFR_RNDU)};
}

// Parse decimal endpoints into an interval that contains [lo, hi] (outward rounding).
inline mpfi_real interval_from_decimal(const std::string& lo, const std::string& hi) {
  mpfr_real a, b;
  if (mpfr_set_str(a.backend().data(), lo.c_str(), 10, MPFR_RNDD) != 0)
    throw usage_error("not a decimal number: '" + lo + "'");
  if (mpfr_set_str(b.backend().data(), hi.c_str(), 10, MPFR_RNDU) != 0)
    throw usage_error("not a decimal number: '" + hi + "'");
  if (b < a) throw usage_error("interval [" + lo + ", " + hi + "] is empty");
  return interval_of(a, b);
}

}  // namespace gyrores
