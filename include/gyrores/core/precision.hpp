// The working precision for a number of significant decimal digits, and running a generic
// computation in the real type it names.
//
// Plan for D digits: D <= 11: double; D <= 15: long double; D <= 29: float128; beyond (or when the
// caller says the inputs need MPFR, e.g. integers beyond double's exponent range): MPFR with
// ceil(D log2 10) + 24 bits. The margins (11 digits in 53 bits, ...) leave room for the rounding
// errors of the computations; whether the digits are right is decided by verified_digits.hpp, not
// by the plan.
#pragma once
#include <string>

#include <gyrores/core/real.hpp>

namespace gyrores {

enum class real_kind { f64, f80, f128, mpfr };

struct precision_plan {
  real_kind kind = real_kind::f64;
  unsigned bits = 53;  // significand bits of the working type
  // "double", "long double", "float128" or "mpfr".
  std::string name() const;
};

// The plan for `digits` significant digits (see the header comment). needs_mpfr forces MPFR.
precision_plan plan_for_digits(unsigned digits, bool needs_mpfr);

// Runs f(T{}) with T the plan's real type and returns its result; for MPFR the default precision
// is the plan's bits for the duration of the call (scoped_digits). f must return the same type
// for every T.
template <class F> auto with_real_type(const precision_plan& plan, F&& f) {
  switch (plan.kind) {
    case real_kind::f64: return f(double{});
    case real_kind::f80: return f((long double){});
    case real_kind::f128: return f(float128{});
    case real_kind::mpfr: break;
  }
  scoped_digits d(digits10_for_bits(plan.bits));
  return f(mpfr_real{});
}

}  // namespace gyrores
