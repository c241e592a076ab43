// include/gyrores/core/verified_digits.hpp
#include <gyrores/core/verified_digits.hpp>

#include <optional>

#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

constexpr int verification_rounds = 5;
constexpr unsigned check_extra_bits = 64;
constexpr int ziv_lost_bits = 12;  // bits the check run is assumed to have lost (Ziv's test)

// The D-digit strings of the plan's run, if the check run confirms every field; else nullopt,
// with `problem` saying which field failed and how.
std::optional<verified_fields> confirmed_fields(const real_fields& a, const real_fields& b, unsigned digits,
                                                unsigned check_bits, std::string& problem) {
  mpfr_real rel;
  {
    scoped_digits d(30);
    rel = ldexp(mpfr_real(1), -int(check_bits) + ziv_lost_bits);
  }
  verified_fields out;
  for (const auto& [name, va] : a) {
    auto it = b.find(name);
    if (it == b.end() || it->second.size() != va.size()) {
      problem = name + " has a different number of values at " + std::to_string(check_bits) + " bits";
      return std::nullopt;
    }
    std::vector<std::string> strs;
    for (std::size_t i = 0; i < va.size(); ++i) {
      std::string sa = format_scientific(va[i], digits), sb = format_scientific(it->second[i], digits);
      if (sa != sb || !digits_settled(it->second[i], rel, digits)) {
        problem = name + " is not settled to " + std::to_string(digits) + " digits (" + sa + " vs " + sb + ")";
        return std::nullopt;
      }
      strs.push_back(sa);
    }
    out[name] = strs;
  }
  return out;
}

}  // namespace

void check_verified_digits(unsigned digits) {
  if (digits < 1 || digits > verified_digits_max)
    throw usage_error("digits must be in [1, " + std::to_string(verified_digits_max) + "], got " + std::to_string(digits));
}

verified_run compute_verified(unsigned digits, bool needs_mpfr,
                              const std::function<real_fields(const precision_plan&)>& compute) {
  precision_plan plan = plan_for_digits(digits, needs_mpfr);
  std::string last_problem;
  for (int round = 0; round < verification_rounds; ++round) {
    const precision_plan check{real_kind::mpfr, plan.bits + check_extra_bits};
    real_fields a = compute(plan), b = compute(check);
    if (auto fields = confirmed_fields(a, b, digits, check.bits, last_problem)) return {std::move(*fields), plan};
    plan = {real_kind::mpfr, 2 * plan.bits};
  }
  throw compute_error("could not settle " + std::to_string(digits) + " digits: " + last_problem);
}

}  // namespace gyrores
