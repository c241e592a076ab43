// The paper's lobe in the proof programs verify_error_bound and verify_section5: for a fast node
// k (lobe frame (k, 0), m = a - 2 k b, |m| <= b when x < 1/2), the exact root u_c of q' and the
// paper's u_asy, the root of u + tan u = s, s = pi m/(2b), both enclosed by interval Newton
// (tests/reference/interval_newton.hpp) from floating-point guesses.
#pragma once
#include <cstdint>
#include <optional>

#include "reference/lobe_intervals.hpp"

namespace gyrores::proofs {

using I = proof::I;
using P = proof::P;

// The frame quantities of the lobe with offset m: mu = pi m/(2a) and s = pi m/(2b) = mu/x.
struct paper_lobe {
  I mu, s;
};
paper_lobe paper_lobe_of(const proof::constants& K, const big_int& m);

// Double-precision guesses of u_c (lobe_equation_root) and u_asy (u_plus_tan_u_root) for the
// lobe with offset m of the pair of order a and delta b (tests/reference/asymptotic.hpp; x < 1/2).
struct lobe_guesses {
  double u_c, u_asy;
};
lobe_guesses double_guesses(std::int64_t a, std::int64_t b, std::int64_t m);

// u_asy: interval Newton (60 steps) on h(u) = u + tan u - s, h' = 2 + tan^2 u >= 2 (so the root
// is unique on (-pi/2, pi/2)), from a point guess; scale |guess|, or 1 for a guess of 0.
// nullopt if not proved.
std::optional<I> certify_u_plus_tan(const I& s, const P& guess);

}  // namespace gyrores::proofs
