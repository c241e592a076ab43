// include/gyrores/core/verified_digits.hpp
#include "reference/verified_digits.hpp"

#include <algorithm>
#include <optional>

#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>

namespace gyrores {
namespace {

constexpr int verification_rounds = 5;
constexpr unsigned check_extra_bits = 64;
constexpr int ziv_lost_bits = 12;  // bits the check run is assumed to have lost (Ziv's test)

constexpr int diagnostic_rounds = 2;  // rounds after which an unsettled diagnostic is accepted as partial

// The fields' values are mpfr_real of their run's precision, read here through MPFR's C API
// only: Boost's operators on them would set the process-wide default precision (core/real.hpp).

// True when a and b round to the same `digits` digits and b passes Ziv's test.
bool value_settled(const mpfr_real& a, const mpfr_real& b, mpfr_srcptr rel, unsigned digits) {
  return format_scientific(a, digits) == format_scientific(b, digits) && digits_settled(b.backend().data(), rel, digits);
}

// The D-digit strings of field `name` (values va of the plan's run, vb of the check run), or
// nullopt with `problem` saying how it failed.
std::optional<std::vector<std::string>> settled_field(const std::string& name, const std::vector<mpfr_real>& va,
                                                      const std::vector<mpfr_real>* vb, unsigned digits,
                                                      unsigned check_bits, mpfr_srcptr rel, std::string& problem) {
  if (!vb || vb->size() != va.size()) {
    problem = name + " has a different number of values at " + std::to_string(check_bits) + " bits";
    return std::nullopt;
  }
  std::vector<std::string> strs;
  for (std::size_t i = 0; i < va.size(); ++i) {
    if (!value_settled(va[i], (*vb)[i], rel, digits)) {
      problem = name + " is not settled to " + std::to_string(digits) + " digits (" + format_scientific(va[i], digits) +
                " vs " + format_scientific((*vb)[i], digits) + ")";
      return std::nullopt;
    }
    strs.push_back(format_scientific(va[i], digits));
  }
  return strs;
}

// The most digits (< D) on which a and b agree and settle, or 0.
unsigned partial_digits(const mpfr_real& a, const mpfr_real& b, mpfr_srcptr rel, unsigned digits) {
  if (digits <= 1) return 0;
  // Start near -log10 of the larger of the runs' relative difference and Ziv's error.
  unsigned top = digits - 1;
  mpfr_srcptr av = a.backend().data(), bv = b.backend().data();
  if (!mpfr_zero_p(bv)) {
    fixed_mpfr diff(std::max(mpfr_get_prec(av), mpfr_get_prec(bv)));
    mpfr_sub(diff, av, bv, MPFR_RNDN);
    mpfr_abs(diff, diff, MPFR_RNDN);
    mpfr_div(diff, diff, bv, MPFR_RNDN);
    mpfr_abs(diff, diff, MPFR_RNDN);
    if (mpfr_less_p(diff, rel)) mpfr_set(diff, rel, MPFR_RNDN);
    mpfr_log10(diff, diff, MPFR_RNDN);
    const double lg = -mpfr_get_d(diff, MPFR_RNDN);
    if (lg + 2 < double(top)) top = lg + 2 < 1 ? 1u : unsigned(lg + 2);
  }
  for (unsigned d = top; d >= 1; --d)
    if (value_settled(a, b, rel, d)) return d;
  return 0;
}

// A diagnostic that did not settle: its values with the digits that did (the fewest over its
// values), or estimated bounds on |value| (max(|a|, |b|) + |a - b|, 2 digits rounded up).
std::vector<std::string> partial_field(const std::vector<mpfr_real>& va, const std::vector<mpfr_real>& vb,
                                       mpfr_srcptr rel, unsigned digits, unsigned& settled) {
  settled = digits;
  for (std::size_t i = 0; i < va.size(); ++i) settled = std::min(settled, partial_digits(va[i], vb[i], rel, digits));
  std::vector<std::string> strs;
  for (std::size_t i = 0; i < va.size(); ++i) {
    if (settled > 0) {
      strs.push_back(format_scientific(va[i], settled));
      continue;
    }
    mpfr_srcptr a = va[i].backend().data(), b = vb[i].backend().data();
    const mpfr_prec_t prec = std::max(mpfr_get_prec(a), mpfr_get_prec(b)) + 2;
    fixed_mpfr bound(prec), diff(prec);
    mpfr_sub(diff, a, b, MPFR_RNDU);
    mpfr_abs(diff, diff, MPFR_RNDU);
    if (mpfr_cmpabs(a, b) >= 0) mpfr_abs(bound, a, MPFR_RNDU);
    else mpfr_abs(bound, b, MPFR_RNDU);
    mpfr_add(bound, bound, diff, MPFR_RNDU);
    strs.push_back(format_scientific(bound, 2, MPFR_RNDU));
  }
  return strs;
}

// The check run of `plan`: MPFR with 64 bits beyond what the plan's run holds (an MPFR plan runs
// on a rung of the ladder, with up to twice its bits: core/precision.hpp), so that the two runs
// always differ; nullopt beyond the ladder.
std::optional<precision_plan> check_plan(const precision_plan& plan) {
  if (plan.kind == real_kind::mpfr && plan.bits > mpfr_ladder_max_bits) return std::nullopt;
  const unsigned bits = plan_working_bits(plan) + check_extra_bits;
  if (bits > mpfr_ladder_max_bits) return std::nullopt;
  return precision_plan{real_kind::mpfr, bits};
}

// One round's verdict: every main field settled (the run), or nullopt with `problem`. A
// diagnostic that fails makes `diagnostics_pending` true; with accept_partial it is reported
// partially instead (verified_run::unsettled).
std::optional<verified_run> confirmed_fields(const real_fields& a, const real_fields& b, unsigned digits,
                                             unsigned check_bits, const diagnostic_predicate& is_diagnostic,
                                             bool accept_partial, bool& diagnostics_pending, std::string& problem) {
  fixed_mpfr rel(2);  // 2^-(check_bits - 12): Ziv's relative error for the check run
  mpfr_set_si_2exp(rel, 1, -long(check_bits) + ziv_lost_bits, MPFR_RNDN);
  verified_run out;
  diagnostics_pending = false;
  for (const auto& [name, va] : a) {
    auto it = b.find(name);
    const std::vector<mpfr_real>* vb = it == b.end() ? nullptr : &it->second;
    std::string why;
    if (auto strs = settled_field(name, va, vb, digits, check_bits, rel, why)) {
      out.fields[name] = std::move(*strs);
      continue;
    }
    const bool diagnostic = is_diagnostic && is_diagnostic(name);
    if (!diagnostic) {
      problem = why;
      return std::nullopt;
    }
    if (!vb || vb->size() != va.size()) continue;  // a diagnostic the check run could not compute: left out
    diagnostics_pending = true;
    unsigned settled = 0;
    out.fields[name] = partial_field(va, *vb, rel, digits, settled);
    out.unsettled[name] = settled;
  }
  if (diagnostics_pending && !accept_partial) problem = "diagnostics not settled";
  return out;
}

}  // namespace

void check_verified_digits(unsigned digits) {
  if (digits < 1 || digits > verified_digits_max)
    throw usage_error("digits must be in [1, " + std::to_string(verified_digits_max) + "], got " + std::to_string(digits));
}

verified_run compute_verified(unsigned digits, bool needs_mpfr,
                              const std::function<real_fields(const precision_plan&)>& compute,
                              const diagnostic_predicate& is_diagnostic) {
  precision_plan plan = plan_for_digits(digits, needs_mpfr);
  std::string last_problem;
  std::optional<verified_run> main_settled;  // the first round whose main fields all settled
  for (int round = 0; round < verification_rounds; ++round) {
    const auto check = check_plan(plan);
    if (!check) {  // no further round: as after the last one
      if (main_settled) return std::move(*main_settled);
      last_problem = "the precision would exceed the largest working type (" + std::to_string(mpfr_ladder_max_bits) +
                     " bits)";
      break;
    }
    real_fields a = compute(plan), b = compute(*check);
    bool pending = false;
    const bool accept_partial = round + 1 >= diagnostic_rounds || round + 1 == verification_rounds;
    if (auto run = confirmed_fields(a, b, digits, check->bits, is_diagnostic, accept_partial, pending, last_problem)) {
      run->plan = plan;
      if (!pending || accept_partial) return std::move(*run);
      if (!main_settled) main_settled = std::move(*run);
    } else if (main_settled) {
      return std::move(*main_settled);  // a later round failed a main field: keep the settled one
    }
    plan = {real_kind::mpfr, 2 * plan.bits};
  }
  throw compute_error("could not settle " + std::to_string(digits) + " digits: " + last_problem);
}

}  // namespace gyrores
