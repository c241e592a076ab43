// The scalar equations of the lattice theorem (proofs/lattice-theorem.md) and of the paper, solved
// as points in double (the fast paths: sweep rows, the design catalogue, figures) and as proved
// enclosures at an explicit precision (everything printed, the certificates, certified sweeps).
//
//   theorem  H(u) = x u + arctan(x tan u) = mu, unique root in (0, pi/2) for 0 < mu <= pi/2:
//            a pair's u* (x = b/a, mu = pi m/(2a)) and the paper's lobe roots, and any coupling's
//            lobe roots H^{-1}(pi nu) (x = n/sqrt(n^2 + 4), nu in (0, 1/2]; theorem/horizon.hpp);
//   paper    u + tan u = s, unique root in (-pi/2, pi/2) (the x -> 0 limit, divided by x).
//
// Enclosures (nothing here reads a process-wide precision: every object carries its own, so
// all of it runs on any number of threads). One solver for every x and mu, prove_theorem_root:
//  1. A point by one Newton ladder (newton_ladder below): levels of precision planned from the
//     top, each at most 4 times the accuracy of the level before, the last centre accurate to
//     half the precision and 16 bits. Near a centre c every tangent comes from tan c (and
//     tan(mu - x c)) and the addition formula tan(c + d) = (tan c + tan d)/(1 - tan c tan d),
//     tan d = d + d^3/3 + r (tan_shift). At the last centre, at full precision, tan c and
//     tan(mu - x c) are Arb enclosures, the equation's value there is enclosed from them, and one
//     Newton step from them gives the point (doubling the centre's accuracy). Where u* lies within
//     2^-L of pi/2 (a coupling's x -> 0 with mu not small: tan u* ~ 2^L), every level carries L
//     bits more (root_enclosure::pole_bits), which tan loses there; a pair never comes near
//     (u* <= pi/4: L = 0).
//  2. A bracket [lo, hi] about the point, proved. Theorem: for 0 < u < pi/2 the angle
//     w = mu - x u lies in (-pi/2, pi/2) (mu <= pi/2, x u < pi/2), where tan increases, so
//     H(u) < mu iff f(u) = x tan u - tan w < 0 (for a pair b tan u - a tan w, by integer
//     products). Paper: g(u) = u + tan u - s increases on (-pi/2, pi/2). f (or g) at each end is
//     enclosed by the mean value form about the centre,
//     f(v) = f(c) + f'(xi) (v - c) with xi between c and v: f(c) from the centre's enclosures at
//     full precision, f' over the hull of c and the ends from the addition formula with the
//     remainder |r| <= |d|^5/7 for |d| <= 1/4 (tan's Taylor coefficients are positive, so
//     0 <= r <= d^5 (tan(1/4) - 1/4 - 1/192) 4^5 < 0.137 d^5 for d >= 0; r is odd), at the bits
//     its product with v - c (about 2^-(prec/2) of c) needs. No tangent is evaluated at an end.
//     For a certificate the ends' outward roundings to D decimal digits, within e (a unit in the
//     D-th digit) beyond lo and hi, bracket the root too, H being increasing, wherever they stay
//     in (0, pi/2); so the decimals written are proved without being read back.
//  3. From the bracket: T = tan([lo, hi]) by the same mean value form (1 + tan^2 over the hull),
//     and for the theorem sqrt(G(u)) = x sqrt(1-x^2) t^2/sqrt((1 + t^2)(1 + x^2 t^2)), t = tan u,
//     increasing in t: r_res = v sqrt(G(u*)) over T (theorem_radius).
#pragma once
#include <gyrores/core/double_double.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/core/status.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// ---- points in double ----

// H^{-1}(mu) for 0 < x < 1, 0 < mu < (1 + x) pi/2, by safeguarded Newton on [0, pi/2] (TOMS 748
// if it does not converge); accurate to about an ulp. compute_error if neither converges.
double theorem_root_double(double x, double mu);

// u* = H^{-1}(mu) as a double-double, with sin u* and cos u* (the steps are written out, with
// their proofs, in src/lib/theorem/root_refined.hpp): a start from two expansions of H
// (theorem_root_start; within 2^-37 u* for b >= 25, or b = 1 and
// a >= 32), Newton steps in double on tan(H(u) - mu) (no arctangent) from the others, then
// Newton steps in double-double on the equivalent equation
//   F(u) = x sin u cos w - cos u sin w = 0,   w = mu - x u,
// (for 0 < u < pi/2 and 0 < mu < pi/2, |w| < pi/2 and F = cos u cos w (x tan u - tan w) has the
// sign of H(u) - mu), F' = 2x cos u cos w + (1 + x^2) sin u sin w, which is x (cos w/cos u +
// cos u/cos w) >= 2x at the root and >= 2x cos u cos w everywhere. Both terms of F are about
// x sin u cos w near the root, each formed to a relative error below 2^-61.7 (table_step_at: the
// sines and cosines of core/double_double.hpp dd_sin_cos_first_quadrant and double-double
// products; for u, w < 2^-7 small_step_at, Taylor polynomials alone, F to 2^-62.5 x u), so a
// step's error is below 2^-60.7 x sin u cos w/(2x cos u cos w) = 2^-61.7 tan u <= 2^-61.3 u
// (tan u <= (4/pi) u for the steps' u <= mu/(2x) = pi m/(4b) <= pi/4).
// Steps repeat until one is below 2^-35 u (Newton's quadratic term is then below (1 + x^2) tan u
// 2^-70 u^2 <= 2^-68 u: |F''/(2F')| <= (1 + x^2) tan u near the root; for u, w < 2^-7 below
// 2^-30 u, where that term is below 2^-65.9 u). The result is within
// 2^-61 u* of it, and sin u*, cos u* within 2^-60 of theirs (first-order steps, second-order
// terms below 2^-70 u); sin w at the returned u within 2^-62 of sin(w(u)), so within 2^-59.7 of
// sin w* (|w(u) - w*| = x |u - u*| <= 2^-61 x u* <= 2^-61 w*, as x u* <= mu/2 <= w*).
// compute_error after 4 double-double steps (never seen: one suffices for every pair tested).
// Preconditions (not checked): x = b/a and mu = pi m/(2a) of a pair, m = 1 or 2 (m_min).
struct root_double_double {
  double_double u, sin_u, cos_u, sin_w;  // sin_w: sin(mu - x u)
};
root_double_double theorem_root_refined(const double_double& x, const double_double& mu);

// The root of u + tan u = s in (-pi/2, pi/2): Newton on u - arctan(s - u), convex below s, from
// an upper end (TOMS 748 if it does not settle), to a few ulp.
double paper_root_double(double s);

// ---- enclosures at an explicit precision ----

// The constants as intervals at one precision: a pair's a, b (x = b/a), x, x^2, sqrt(1 - x^2),
// sqrt(tau sigma), pi and the integers a, b (ratio = true: the solver multiplies by the integers,
// O(prec) each, where an interval x would cost a full product); any coupling's x and pi only.
struct theorem_constants {
  explicit theorem_constants(mpfr_prec_t p) : prec(p), a(p), b(p), x(p), x2(p), s1mx2(p), sqrt_ts(p), pi(p) {}
  theorem_constants(mpfr_prec_t p, const resonant_pair<big_int>& pair);  // set_theorem_constants(*this, pair)
  mpfr_prec_t prec;
  // a, b, x = b/a, x^2, sqrt(1-x^2) = 2 sqrt(tau sigma)/a, sqrt(tau sigma), pi
  fixed_mpfi a, b, x, x2, s1mx2, sqrt_ts, pi;
  big_int ai, bi;      // a and b as integers (pairs)
  bool ratio = false;  // x = bi/ai exactly
};
void set_theorem_constants(theorem_constants& K, const resonant_pair<big_int>& p);
// Any coupling: x an interval in (0, 1) holding the exact x (for the solver: the rest unset).
void set_theorem_constants(theorem_constants& K, const fixed_mpfi& x);

// An enclosure of a root: U holds it, T = tan(U). `centre` is the last centre of the ladder,
// tc and wc enclosures of tan(centre) and (theorem only) tan(mu - x centre), fc of the equation
// there (step 2: f(centre) or g(centre)). lo and hi are the proved bracket's ends before the
// widening for decimals (U = [lo, hi] without it).
struct root_enclosure {
  explicit root_enclosure(mpfr_prec_t p) : u(p), centre(p), lo(p), hi(p), U(p), T(p), tc(p), wc(p), mu(p), fc(p) {}
  fixed_mpfr u, centre;   // the ladder's point, the last centre
  fixed_mpfr lo, hi;      // the bracket's ends (their outward decimals proved too when asked)
  fixed_mpfi U, T;        // the proved bracket and tan over it
  fixed_mpfi tc, wc, mu;  // tan(centre), tan(mu - x centre), mu (theorem) or s (paper)
  fixed_mpfi fc;          // f(centre) (theorem) or g(centre) (paper)
  long pole_bits = 0;     // L of step 1: the bits tan loses near pi/2 (0 for pairs and the paper)
  unsigned decimals = 0;  // D when lo, hi are proved with their outward roundings to D digits, else 0
};

// THE proved solver of H(u) = mu (steps 1-2), for any coupling: r.mu holds the exact mu, and
// 0 < mu <= pi/2 exactly (not checked: the caller's integers decide it); K's precision. Proved:
// r.U is a bracket of H^{-1}(mu) about the ladder's point with relative half-width
// 2^-(prec - 16), r.T = tan(r.U). With decimal_digits = D > 0 the ends r.lo, r.hi are then
// proved with their outward roundings to D digits too (r.decimals = D, and r.U holds them), unless
// such a decimal would leave (0, pi/2) (a root within 10^-D of pi/2: r.decimals = 0). Not proved:
// the status says which step failed at this precision (the caller doubles it); never a wrong
// enclosure.
proof_status prove_theorem_root(root_enclosure& r, const theorem_constants& K, unsigned decimal_digits = 0);

// A pair's root for offset 0 < m < a (mu = pi m/(2a) < pi/2; true for m_min and the fast
// node's |m|; usage_error otherwise), as above.
proof_status prove_theorem_root(root_enclosure& r, const theorem_constants& K, const big_int& m,
                                unsigned decimal_digits = 0);

// The ladder alone (step 1): r.u, r.centre, r.tc, r.wc, r.fc for r.mu (the second form sets
// r.mu = pi m/(2a) for a pair's offset m, as prove_theorem_root); not proved if the centre's
// enclosures could not be formed.
proof_status theorem_centre(root_enclosure& r, const theorem_constants& K);
proof_status theorem_centre_of(root_enclosure& r, const theorem_constants& K, const big_int& m);

// Step 2 for the theorem: proved if H(lo) < mu < H(hi) is proved for every lo in LO and hi in HI
// (then the root lies in (lo, hi)); T receives tan([lo, hi]). Refused (out of domain) unless
// 0 < LO, HI < pi/2 and both lie within 2^-10 of r.centre.
proof_status prove_theorem_bracket(const theorem_constants& K, const root_enclosure& r, const fixed_mpfi& LO,
                                   const fixed_mpfi& HI, fixed_mpfi& T);

// The paper's root of u + tan u = s for s = pi m/(2b) (any integer m with |m| <= b): as
// prove_theorem_root. m = 0 gives the exact root 0.
proof_status prove_paper_root(root_enclosure& r, const theorem_constants& K, const big_int& m);

// out = pi m/(2 d) at K's precision (d = K.ai: the theorem's mu; d = K.bi: the paper's s).
void pi_ratio(fixed_mpfi& out, const theorem_constants& K, const big_int& m, const big_int& d);

// The paper's error and bound of a lobe from d = |u_c - u_asy| (enclosures at K's precision):
// error = 2 d/a = |theta_c - theta_asy| (formed from the roots, not from two thetas that cancel),
// bound = pi^3 x^2/a.
void paper_error_bound(fixed_mpfi& error, fixed_mpfi& bound, const theorem_constants& K, const fixed_mpfi& d);

// Step 3: r = sqrt(G) over T = tan(U) (v = 1).
void theorem_radius(fixed_mpfi& r, const theorem_constants& K, const fixed_mpfi& T);

// The addition formula of steps 1-2, as an enclosure at out's precision: out holds tan(c + d) for
// every c with tan c in TC and every d in D, (TC + TD)/(1 - TC TD) with TD = D + D^3/3 +
// [-1, 1] |D|^5/7. Precondition (not checked): |D| <= 1/4 (the remainder bound needs it; the
// brackets use |D| <= 2^-10). Where 1 - TC TD holds 0 (c + d near a pole) out is unbounded.
void tan_shift(fixed_mpfi& out, const fixed_mpfi& tc, const fixed_mpfi& d);

}  // namespace gyrores
