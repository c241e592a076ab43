// The working precision for a number of significant decimal digits, and running a generic
// computation in the real type it names.
//
// Plan for D digits: D <= 11: double; D <= 15: long double; D <= 29: float128; beyond (or when the
// caller says the inputs need MPFR, e.g. integers beyond double's exponent range): MPFR with
// ceil(D log2 10) + 24 bits. The margins (11 digits in 53 bits, ...) leave room for the rounding
// errors of the computations; whether the digits are right is decided by verified_digits.hpp, not
// by the plan.
//
// MPFR plans run in a type whose precision is part of the type, never at Boost's process-wide
// default precision (core/real.hpp: so with_real_type may run on any thread): the smallest rung
// of a ladder of fixed-precision types mpfr_fixed<D>, D = 40, 80, 160, ..., 20480 decimal digits
// (134 to 68034 bits), that holds the plan's bits. A plan thus runs with up to twice its bits
// (plan_working_bits says how many). The top rung holds the check run of 10000 digits
// (verified_digits.hpp); each rung costs about 2 s of compiling wherever a computation is
// instantiated for the ladder, so it stops there.
#pragma once
#include <limits>
#include <string>

#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores {

enum class real_kind { f64, f80, f128, mpfr };

struct precision_plan {
  real_kind kind = real_kind::f64;
  unsigned bits = 53;  // significand bits asked for (MPFR: the type it runs in holds at least as many)
  // "double", "long double", "float128" or "mpfr".
  std::string name() const;
};

// The plan for `digits` significant digits (see the header comment). needs_mpfr forces MPFR.
precision_plan plan_for_digits(unsigned digits, bool needs_mpfr);

// The MPFR ladder: rung k is mpfr_fixed<mpfr_ladder_digits(k)>, k < mpfr_ladder_rungs.
inline constexpr unsigned mpfr_ladder_rungs = 10;  // 40 .. 20480 digits
constexpr unsigned mpfr_ladder_digits(unsigned k) { return 40u << k; }
// The significand bits of rung k (Boost's digits10_2_2: D digits hold floor(D/log10 2) + 1 or + 2 bits).
constexpr unsigned mpfr_ladder_bits(unsigned k) {
  const unsigned long d = mpfr_ladder_digits(k);
  return unsigned(d * 1000ul / 301ul + ((d * 1000ul) % 301ul ? 2u : 1u));
}
// The most bits an MPFR plan may ask for (the top rung's).
inline constexpr unsigned mpfr_ladder_max_bits = mpfr_ladder_bits(mpfr_ladder_rungs - 1);

// The significand bits with_real_type runs `plan` with: 53, 64, 113, or the bits of the smallest
// rung holding plan.bits. usage_error for an MPFR plan beyond mpfr_ladder_max_bits.
unsigned plan_working_bits(const precision_plan& plan);

namespace detail {
[[noreturn]] void throw_beyond_mpfr_ladder(unsigned bits);

template <unsigned K, class F> auto with_mpfr_rung(unsigned bits, F& f) {
  using T = mpfr_fixed<mpfr_ladder_digits(K)>;
  static_assert(unsigned(std::numeric_limits<T>::digits) == mpfr_ladder_bits(K));
  if (bits > mpfr_ladder_bits(K)) {
    if constexpr (K + 1 < mpfr_ladder_rungs) return with_mpfr_rung<K + 1>(bits, f);
    else throw_beyond_mpfr_ladder(bits);
  }
  return f(T{});
}
}  // namespace detail

// Runs f(T{}) with T the plan's real type and returns its result: double, long double, float128,
// or for MPFR the smallest rung of the ladder holding plan.bits (see the header comment; no
// process-wide state is read or written, so f may run on any thread). f must return the same
// type for every T; it is instantiated for every rung. usage_error for an MPFR plan beyond
// mpfr_ladder_max_bits.
template <class F> auto with_real_type(const precision_plan& plan, F&& f) {
  switch (plan.kind) {
    case real_kind::f64: return f(double{});
    case real_kind::f80: return f((long double){});
    case real_kind::f128: return f(float128{});
    case real_kind::mpfr: break;
  }
  return detail::with_mpfr_rung<0>(plan.bits, f);
}

}  // namespace gyrores
