// The one precision loop. Every proved value is computed at a precision that starts from what
// the digits asked need and doubles until the proof holds and every rounding is decided, up to a
// documented cap; a requested stop (Ctrl-C, the Python module) is honoured before each
// precision. Refinements (the pair report, the horizon theorem, certificates, bands) call it
// instead of writing their own loop, so the caps and the failure message are the same everywhere.
//
//   attempt(bits, status) -> std::optional<R>: R when everything held at `bits` bits; otherwise
//   none, with `status` saying why (core/status.hpp; the last reason goes into the message).
#pragma once
#include <mpfr.h>

#include <optional>
#include <string>
#include <type_traits>

#include <gyrores/core/error.hpp>
#include <gyrores/core/status.hpp>
#include <gyrores/core/stop.hpp>

namespace gyrores {

// The precision caps (bits). A proof that needs more than its cap gives up with compute_error:
//   report_bits_cap  pairs, couplings and certificates at any digits (2^20 bits ~ 315,000 digits:
//                    far beyond report_digits_max, reached only by a tie no precision settles);
//   tie_bits_cap(s)  proofs that only a tie can stall (the horizon end point equal to a lobe's
//                    minimum, a level equal to one): 64 times their start, at least 2^16.
inline constexpr mpfr_prec_t report_bits_cap = mpfr_prec_t(1) << 20;
constexpr mpfr_prec_t tie_bits_cap(mpfr_prec_t start) { return start << 6 > (mpfr_prec_t(1) << 16) ? start << 6 : mpfr_prec_t(1) << 16; }

struct precision_plan {
  mpfr_prec_t start = 64;  // the first precision (bits)
  mpfr_prec_t cap = report_bits_cap;
};

// Runs attempt at plan.start, 2 plan.start, ... while <= plan.cap; returns the first value.
// Throws `interrupted` when stop is requested, compute_error("<what> was not decided within
// <cap> bits (<last reason>)") when the cap is passed.
template <class Attempt>
auto refine(const precision_plan& plan, const stop_token& stop, const std::string& what, Attempt&& attempt)
    -> typename std::invoke_result_t<Attempt&, mpfr_prec_t, proof_status&>::value_type {
  proof_status last = proof_status::undecided("no precision was tried");
  for (mpfr_prec_t bits = plan.start; bits <= plan.cap; bits *= 2) {
    stop.throw_if_requested();
    proof_status status;
    if (auto value = attempt(bits, status)) return std::move(*value);
    last = status;
  }
  throw compute_error(what + " was not decided within " + std::to_string(plan.cap) + " bits (" + last.reason() + ")");
}

}  // namespace gyrores
