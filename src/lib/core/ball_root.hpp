// THE proved root in Arb balls, for the horizon theorem's equations other than H(u) = mu (which
// theorem/root.hpp solves): G(u) = 2E and the crossing R = 2E (proofs/horizon-theorem.md, item
// 5). Private to src/lib, like the kit it extends (ball.hpp).
//
// prove_ball_root(g, dg, lo, hi, prec, D, out): for a g negative before its root in (lo, hi) and
// positive after it (the callers prove this sign pattern), safeguarded Newton on exact midpoints,
// then a tiny bracket [a, b] about the point whose end signs are decided in balls: g(a) < 0 <
// g(b) proves a < root < b. With D > 0 the ends' outward roundings to D digits are brackets too
// when they stay in [lo, hi] (within e, a unit in the D-th digit, beyond a and b, where the sign
// pattern holds): a certificate states them without proving them again; `decimals` says whether
// they stayed. Undecided when this precision cannot tell (the caller raises it).
#pragma once
#include <functional>

#include <gyrores/core/status.hpp>

#include "ball.hpp"

namespace gyrores::arb_support {

using ball_fn = std::function<void(arb_t, const arb_t)>;

struct ball_root {
  enclosure bracket;      // [a, b], exact binary ends
  unsigned decimals = 0;  // D when their outward decimals to D digits are brackets too
  ball value;             // holds [a, b] (and those decimals)
};

proof_status prove_ball_root(const ball_fn& g, const ball_fn& dg, const arb_t lo, const arb_t hi, slong prec,
                             unsigned decimal_digits, ball_root& out);

// e = 2^(E - k), |v| < 2^E for both ends, 2^-k > 10^(1-D): at least a unit in the D-th digit.
void decimal_unit(arb_t out, const arf_t a, const arf_t b, unsigned decimal_digits);

}  // namespace gyrores::arb_support
