// Choosing the working precision from the digits the user asks for, and proving the digits.
//
// Plan: D <= 11 digits: double; D <= 15: long double; D <= 29: float128; beyond: MPFR with
// ceil(D log2 10) + 24 bits. Pairs beyond double's exponent range always use MPFR.
// Verification (every printed digit right): the report is computed twice, in the plan's type
// and in MPFR with 64 more bits; a real field is printed only if both round to the same D
// digits and the second passes Ziv's rounding test with a relative error of 2^-(bits - 12).
// Otherwise the precision is doubled and both runs repeat (at most 5 times, then exit 3).
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores::cli {

enum class real_kind { f64, f80, f128, mpfr };

struct precision_plan {
  real_kind kind;
  unsigned bits;  // significand bits of the working type
  std::string name() const {
    switch (kind) {
      case real_kind::f64: return "double";
      case real_kind::f80: return "long double";
      case real_kind::f128: return "float128";
      case real_kind::mpfr: return "mpfr";
    }
    return "?";
  }
};

inline precision_plan plan_for_digits(unsigned digits, bool needs_mpfr) {
  if (!needs_mpfr) {
    if (digits <= 11) return {real_kind::f64, 53};
    if (digits <= 15) return {real_kind::f80, 64};
    if (digits <= 29) return {real_kind::f128, 113};
  }
  return {real_kind::mpfr, unsigned(digits * 3.3219280948873623) + 25};
}

// Run f(T{}) in the plan's type (MPFR precision set for the call).
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

// The real-valued fields of a report, as exact MPFR copies, by name (arrays allowed).
using real_fields = std::map<std::string, std::vector<mpfr_real>>;

// Formatted fields once verified.
using verified_fields = std::map<std::string, std::vector<std::string>>;

struct verified_run {
  verified_fields fields;
  precision_plan plan;  // the plan whose run produced the printed digits
};

// compute(plan) -> real_fields. Returns the D-digit strings proven by the two-run test.
inline verified_run compute_verified(unsigned digits, bool needs_mpfr,
                                     const std::function<real_fields(const precision_plan&)>& compute) {
  precision_plan plan = plan_for_digits(digits, needs_mpfr);
  std::string last_problem;
  for (int round = 0; round < 5; ++round) {
    precision_plan check{real_kind::mpfr, plan.bits + 64};
    real_fields a = compute(plan), b = compute(check);
    verified_fields out;
    bool ok = true;
    mpfr_real rel;
    {
      scoped_digits d(30);
      rel = ldexp(mpfr_real(1), -int(check.bits) + 12);
    }
    for (auto& [name, va] : a) {
      auto it = b.find(name);
      if (it == b.end() || it->second.size() != va.size()) {
        ok = false;
        last_problem = name + " has a different number of values at " + std::to_string(check.bits) + " bits";
        break;
      }
      std::vector<std::string> strs;
      for (std::size_t i = 0; i < va.size(); ++i) {
        std::string sa = format_scientific(va[i], digits), sb = format_scientific(it->second[i], digits);
        if (sa != sb || !digits_settled(it->second[i], rel, digits)) {
          ok = false;
          last_problem = name + " is not settled to " + std::to_string(digits) + " digits (" + sa + " vs " + sb + ")";
          break;
        }
        strs.push_back(sa);
      }
      if (!ok) break;
      out[name] = strs;
    }
    if (ok) return {out, plan};
    plan = {real_kind::mpfr, 2 * plan.bits};
  }
  throw compute_error("could not settle " + std::to_string(digits) + " digits: " + last_problem);
}

}  // namespace gyrores::cli
