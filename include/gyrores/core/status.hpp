// The outcome of one proof attempt: proved, or why not. Every step that proves something at a
// given precision (a root's bracket, a sign, the rounding of an enclosure) answers with a
// proof_status instead of a bare bool, so that a computation that gives up can say which step
// failed and why (the precision loop of core/refine.hpp puts the last reason in its message).
//
// The reasons are static texts (no allocation on the hot paths of sweeps and filters):
//   undecided      an inequality or a rounding straddles at this precision (more bits may settle it);
//   out_of_domain  an argument lies where the step does not apply (e.g. a bracket end past pi/2);
//   no_convergence an iteration did not settle within its budget.
#pragma once
#include <functional>

namespace gyrores {

class proof_status {
 public:
  enum class outcome : unsigned char { proved, undecided, out_of_domain, no_convergence };

  constexpr proof_status() = default;  // proved
  static constexpr proof_status proved() { return {}; }
  static constexpr proof_status undecided(const char* why) { return {outcome::undecided, why}; }
  static constexpr proof_status out_of_domain(const char* why) { return {outcome::out_of_domain, why}; }
  static constexpr proof_status no_convergence(const char* why) { return {outcome::no_convergence, why}; }

  constexpr bool ok() const { return kind_ == outcome::proved; }
  constexpr explicit operator bool() const { return ok(); }
  constexpr outcome kind() const { return kind_; }
  constexpr const char* reason() const { return reason_; }

 private:
  constexpr proof_status(outcome k, const char* why) : kind_(k), reason_(why) {}
  outcome kind_ = outcome::proved;
  const char* reason_ = "proved";
};

// Returns the status of `expr` from the enclosing function unless it is proved (a chain of steps:
// the first failure is the answer).
#define GYRORES_TRY_PROOF(expr)                      \
  do {                                               \
    const ::gyrores::proof_status status_ = (expr);  \
    if (!status_) return status_;                    \
  } while (false)

// What a refinement of a proof must reach: `digits` sets where the precision starts (the
// relative accuracy 10^-digits the proof aims at); `accept`, when given, is asked of each proof
// that held, and the precision keeps doubling until it holds too (a report's roundings decided,
// a double decided, a certificate's claims narrow enough).
template <class Proof> struct refine_goal {
  unsigned digits = 17;
  std::function<proof_status(const Proof&)> accept;
  proof_status accepts(const Proof& p) const { return accept ? accept(p) : proof_status::proved(); }
};

}  // namespace gyrores
