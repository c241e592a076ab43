// THE proved root in Arb balls, for the equations of the horizon theorem other than H(u) = mu
// (which theorem/root.hpp solves for every caller): G(u) = 2E and the crossing R = 2E
// (proofs/horizon-theorem.md, item 5). Private to src/lib, like the kit it extends (ball.hpp).
//
// prove_ball_root(g, dg, lo, hi, prec, D, out): for a g that is negative before its root in
// (lo, hi) and positive after it (g need not be monotone elsewhere; the callers prove the sign
// pattern), safeguarded Newton on exact midpoints at `prec` bits, then the ends of a tiny
// bracket [a, b] about the point are decided in balls: g(a) < 0 < g(b) proves a < root < b.
// With D > 0 the ends' outward roundings to D decimal digits are brackets too when they stay in
// [lo, hi]: they lie in [a - e, a] and [b, b + e] (e at least a unit in the D-th digit), on the
// root's sides, where the sign pattern holds; so a certificate can state those decimals without
// proving them again. `decimals` says whether they are (0 when they would leave [lo, hi]). The result's bracket holds a and b exactly; its ball holds the bracket (and the
// decimals). Undecided when this precision cannot tell (the caller raises it): the ends of
// [lo, hi] without the expected signs (closer than the precision can tell, or where g is
// steep), or no bracket about the point decided.
#pragma once
#include <functional>

#include <gyrores/core/status.hpp>

#include "ball.hpp"

namespace gyrores::arb_support {

using ball_fn = std::function<void(arb_t, const arb_t)>;

struct ball_root {
  enclosure bracket;      // [a, b], exact binary ends
  unsigned decimals = 0;  // D when the ends' outward decimals to D digits are proved too
  ball value;             // holds [a, b] (and those decimals)
};

proof_status prove_ball_root(const ball_fn& g, const ball_fn& dg, const arb_t lo, const arb_t hi, slong prec,
                             unsigned decimal_digits, ball_root& out);

// e = 2^(E - k) with |v| < 2^E for both ends v and 2^-k > 10^(1-D): at least a unit in the D-th
// significant digit of either end (the widening for decimals, here and in theorem/root.cpp).
void decimal_unit(arb_t out, const arf_t a, const arf_t b, unsigned decimal_digits);

}  // namespace gyrores::arb_support
