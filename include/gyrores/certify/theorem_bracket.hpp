// The proof of a bracket of u*, the root of the lattice theorem (proofs/lattice-theorem.md:
// H(u) = x u + arctan(x tan u) = mu = pi m_min/(2a), 0 < u* < pi/2), at an explicit precision:
// shared by the certificates (certify/theorem_certificate.hpp) and the certified sweep
// (sweep/certified.hpp). Nothing here reads Boost's process-wide MPFR precision for pairs of
// order below 2^900, so it runs on the sweep's threads.
//
//  1. u* by Newton on f(u) = tan(mu - x u) - x tan u, whose root in (0, pi/2) is the root of
//     H(u) = mu (below). Near a centre c every tangent comes from tan c, tan(mu - x c) and the
//     addition formula tan(c + d) = (tan c + tan d)/(1 - tan c tan d), tan d = d + d^3/3 + r:
//     two tangents per centre (MPFR on the way, Arb balls at the last), the centres on a ladder of precisions (each level at most 4
//     times the accuracy of its centre, so |d|^5 is below it).
//  2. A bracket [lo, hi] proved: H(lo) < mu < H(hi). For 0 < u < pi/2 the angle w = mu - x u
//     lies in (-pi/2, pi/2) (mu = pi m/(2a) <= pi/3, x u < pi/2) where tan increases, so
//     H(u) < mu iff arctan(x tan u) < w iff x tan u < tan w. Both sides are enclosed in MPFI
//     from enclosures of tan c and tan(mu - x c), the addition formula, and the remainder
//     |r| <= |d|^5/7 for |d| <= 1/4 (tan's Taylor coefficients are positive, so
//     0 <= r <= d^5 (tan(1/4) - 1/4 - 1/192) 4^4 < 0.137 d^5 for d >= 0; r is odd).
//  3. r_res = sqrt(G(u*)) with sqrt(G) = x sqrt(1-x^2) t^2/sqrt((1 + t^2)(1 + x^2 t^2)),
//     t = tan u, increasing in t: enclosed over tan([lo, hi]) = [tan lo, tan hi] from step 2.
#pragma once
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// The pair's constants as intervals at one precision.
struct theorem_constants {
  explicit theorem_constants(mpfr_prec_t p) : prec(p), a(p), x(p), x2(p), s1mx2(p), sqrt_ts(p), pi(p), mu(p) {}
  mpfr_prec_t prec;
  // a, x = b/a, x^2, sqrt(1-x^2) = 2 sqrt(tau sigma)/a, sqrt(tau sigma), pi, mu = pi m_min/(2a)
  fixed_mpfi a, x, x2, s1mx2, sqrt_ts, pi, mu;
};
void set_theorem_constants(theorem_constants& K, const resonant_pair<big_int>& p);

// Step 1 for a pair with m_min >= 1: u (approximately u*) and the centre c with enclosures of
// tan c and tan(mu - x c). False if the enclosures could not be formed.
struct theorem_centre {
  explicit theorem_centre(mpfr_prec_t p) : u(p), c(p), tc(p), wc(p) {}
  fixed_mpfr u, c;
  fixed_mpfi tc, wc;
};
bool theorem_centre_of(theorem_centre& z, const theorem_constants& K, const resonant_pair<big_int>& p);

// Step 2: true if H(lo) < mu < H(hi) is proved for every lo in LO and hi in HI (then u* lies in
// (lo, hi)); T receives an enclosure of tan([lo, hi]). False (nothing proved) unless
// 0 < LO, HI < pi/2 and both lie within 2^-10 of the centre.
bool prove_theorem_bracket(const theorem_constants& K, const theorem_centre& z, const fixed_mpfi& LO,
                           const fixed_mpfi& HI, fixed_mpfi& T);

// Step 3: r = sqrt(G) over T = tan(U).
void theorem_radius(fixed_mpfi& r, const theorem_constants& K, const fixed_mpfi& T);

}  // namespace gyrores
