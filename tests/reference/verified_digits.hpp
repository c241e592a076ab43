// Verified decimal digits: accepting a computed real only with digits that two independent
// precisions agree on. The CLI printed such digits before the theorems proved every number; this is
// now a reference method for the tests (a consistency check, not a proof).
//
// The computation is a function from a precision plan (core/precision.hpp) to named real
// fields (each a list of values, copied exactly into MPFR). compute_verified runs it twice: in the
// plan for D digits, and in MPFR with 64 more bits than the plan's run holds (plan_working_bits:
// an MPFR plan runs in the smallest type of the precision ladder holding its bits). A field's
// D-digit string is accepted only if
//   1. both runs round every value of the field to the same D significant digits (to nearest), and
//   2. the higher-precision value passes Ziv's rounding test (core/decimal.hpp, digits_settled)
//      for a relative error of 2^-(bits - 12), bits being the precision that run asked for (its
//      type may hold more): every value that close rounds to the same string.
// If any field fails, the plan becomes MPFR with twice the bits and both runs repeat, at most 5
// rounds in all (fewer if the check run would exceed the ladder, mpfr_ladder_max_bits); then
// compute_error ("could not settle D digits: <field> ...").
//
// Threads: nothing here reads or writes Boost's process-wide default precision (the fields'
// values carry their own and are read through MPFR's C API; compute_verified_per_type runs in
// fixed-precision types), so compute_verified may run on any thread if `compute` may.
//
// Diagnostics (fields the caller names as such, e.g. the relative error of a closed form, nearly
// all cancellation) never block the main answer: once every main field has settled, a
// diagnostic that has not settled by the second round is reported with the digits that did
// settle (fewer than D), or, when not one did, as an estimated bound on its magnitude; the
// result lists it in `unsettled`; a diagnostic the check run does not have is left out of the
// result. compute_error is kept for the main fields.
//
// What this guarantees, and what not: it is a strong consistency check, an *estimate* of the
// error, not a proof. Test 2 assumes that the MPFR run has lost at most 12 bits, which is not
// proved; and two runs can round the same way and both be wrong (an error that does not shrink
// with the precision: a wrong branch taken, a missed minimiser, a tolerance in an iteration). It
// catches the usual failures of floating point (too few bits, cancellation, a value on a rounding
// boundary). For results that are proved, use certificates (certify/theorem_certificate.hpp:
// interval arithmetic, re-checked by an independent checker).
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <gyrores/core/decimal.hpp>
#include "reference/precision.hpp"
#include <gyrores/core/real.hpp>

namespace gyrores {

// The real-valued fields of a result, by name, as exact MPFR copies (a field may hold several
// values, e.g. all minimisers), each with the precision of the run that computed it.
using real_fields = std::map<std::string, std::vector<mpfr_real>>;

// The accepted D-digit strings ("d.ddd...e+XX"), by field name, in the same order.
using verified_fields = std::map<std::string, std::vector<std::string>>;

struct verified_run {
  verified_fields fields;
  precision_plan plan;  // the plan whose run produced the accepted digits (the first of the pair)
  // Diagnostic fields that did not settle to D digits, with the digits that did (the fewest over
  // the field's values): d in [1, D) means its strings have d significant digits; 0 means not
  // one digit settled and its strings are estimated bounds on |value| (2 digits, rounded up).
  std::map<std::string, unsigned> unsettled;
};

// Which fields are diagnostics (see the header comment); none by default.
using diagnostic_predicate = std::function<bool(const std::string&)>;

// Largest number of digits the verified APIs of gyrores accept.
inline constexpr unsigned verified_digits_max = 10000;

// Throws usage_error ("digits must be in [1, 10000], got D") outside [1, verified_digits_max].
void check_verified_digits(unsigned digits);

// Stores x (any supported real) exactly as the single value of field `name`.
template <class T> void put_field(real_fields& f, const std::string& name, const T& x) {
  f[name] = {real_to_mpfr(x)};
}

// The two-run test described in the header comment. compute(plan) must return the same field
// names with the same number of values at every precision (a field missing or with another count
// in the check run fails the round); fields the check run has in addition are ignored. Every
// field of the first run is in the result. Precondition: digits >= 1 (not checked). Throws
// compute_error after 5 rounds in which a main field failed; exceptions from compute pass through.
verified_run compute_verified(unsigned digits, bool needs_mpfr,
                              const std::function<real_fields(const precision_plan&)>& compute,
                              const diagnostic_predicate& is_diagnostic = {});

// The same, for a generic computation written once for every real type: per_type(T{}) returns
// the real_fields computed in T (with_real_type, core/precision.hpp: double, long double,
// float128 and every rung of the MPFR ladder, mpfr_fixed<D>).
template <class F> verified_run compute_verified_per_type(unsigned digits, bool needs_mpfr, F&& per_type) {
  return compute_verified(digits, needs_mpfr,
                          [&](const precision_plan& plan) { return with_real_type(plan, per_type); });
}

}  // namespace gyrores
