// include/gyrores/sweep/certified.hpp: the per-pair proofs of a certified sweep, in MPFI at an
// explicit precision (the sweep runs them on several threads; Boost's MPFR wrappers keep one
// process-wide default precision, so they are not used here).
#include <gyrores/sweep/certified.hpp>

#include <mpfi.h>

#include <algorithm>
#include <cmath>

#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/inscribed/asymptotic.hpp>  // u_plus_tan_u_root (the scout of u_a)
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

namespace {

// The pair's constants as intervals at one precision: the theorem's (theorem/root.hpp)
// and 1 - x^2.
struct constants : theorem_constants {
  explicit constants(mpfr_prec_t p) : theorem_constants(p), one_m_x2(p) {}
  fixed_mpfi one_m_x2;
};

void set_constants(constants& K, const resonant_pair<big_int>& p) {
  set_theorem_constants(K, p);
  mpfi_sqr(K.one_m_x2, K.s1mx2);
}

// out = pi n/d, n, d integers.
void pi_ratio(fixed_mpfi& out, const constants& K, std::int64_t n, std::int64_t d) {
  mpfi_mul_si(out, K.pi, n);
  mpfi_div_si(out, out, d);
}

// tan u for the double u in (0, pi/2): the interval [down, up] from one MPFR call rounded in
// direction rnd (the other end is the neighbouring float, which lies on the other side of the
// exact value).
void tan_at(fixed_mpfi& out, double u, mpfr_rnd_t rnd, mpfr_prec_t prec) {
  fixed_mpfr t(prec), o(prec);
  mpfr_set_d(t, u, MPFR_RNDN);  // exact: prec >= 53
  mpfr_tan(t, t, rnd);
  mpfr_set(o, t, MPFR_RNDN);
  if (rnd == MPFR_RNDU) mpfr_nextbelow(o);
  else mpfr_nextabove(o);
  if (rnd == MPFR_RNDU) mpfi_interv_fr(out, o, t);
  else mpfi_interv_fr(out, t, o);
}

// A bracket [lo, hi] of u_a, the root of u + tan u = s in (0, pi/2) near the double u0, proved
// by lo + tan lo < s < hi + tan hi (g increases); relative half-widths 2^-46, 2^-36, 2^-26 are
// tried. On success T holds tan([lo, hi]). False when none is proved.
bool bracket_u_asy(const constants& K, double u0, const fixed_mpfi& s, double& lo, double& hi, fixed_mpfi& T) {
  fixed_mpfi tlo(K.prec), thi(K.prec);
  fixed_mpfr g(K.prec);
  const double half_pi = K.pi.lo() / 2;
  for (int e : {46, 36, 26}) {
    lo = u0 - std::ldexp(u0, -e);
    hi = u0 + std::ldexp(u0, -e);
    if (!(lo > 0) || !(hi < half_pi)) continue;
    tan_at(tlo, lo, MPFR_RNDU, K.prec);
    mpfr_add_d(g, tlo.right(), lo, MPFR_RNDU);
    if (!(mpfr_cmp(g, s.left()) < 0)) continue;
    tan_at(thi, hi, MPFR_RNDD, K.prec);
    mpfr_add_d(g, thi.left(), hi, MPFR_RNDD);
    if (!(mpfr_cmp(g, s.right()) > 0)) continue;
    mpfi_interv_fr(T, tlo.left(), thi.right());
    return true;
  }
  return false;
}

// r_res and theta_first of a non-degenerate pair (theorem/root.hpp): a bracket of
// relative half-width 2^-(prec-16) about the approximate u*, proved. False if not proved.
bool enclose_minimum(sweep_proof& pr, const constants& K, const resonant_pair<big_int>& p, std::int64_t a) {
  root_enclosure z(K.prec);
  if (!prove_theorem_root(z, K, big_int(p.strand_offset_min()))) return false;
  fixed_mpfi r(K.prec), th(K.prec);
  theorem_radius(r, K, z.T);
  const auto& f = pr.lobes.front();
  minimiser_theta(th, K, big_int(a), lobe_frame<big_int>{to_big(f.k), to_big(f.j), to_big(f.m)}, z.U);
  if (!fixed_narrow(r, 40) || !fixed_narrow(th, 40)) return false;
  pr.r_lo = r.lo();
  pr.r_hi = r.hi();
  pr.theta_lo = th.lo();
  pr.theta_hi = th.hi();
  // r_res^2 <= R(pi/2) = N/(4 a^2).
  fixed_mpfi R(K.prec);
  mpfi_set_z(R, to_big(pr.quarter_R_scaled).backend().data());
  mpfi_div_si(R, R, a);
  mpfi_div_si(R, R, a);
  mpfi_div_ui(R, R, 4);
  mpfi_sqr(r, r);
  pr.r_below_R_half_pi = mpfr_cmp(r.right(), R.left()) <= 0;
  return true;
}

// f'(u) = 1 + (1 + t^2)/(1 + x^2 t^2) and f''(u) = 2 t (1 - x^2)(1 + t^2)/(1 + x^2 t^2)^2,
// t = tan u, over the interval t (u in [0, pi/2)).
void f_derivatives(fixed_mpfi& d1, fixed_mpfi* d2, const constants& K, const fixed_mpfi& t) {
  fixed_mpfi t2(K.prec), num(K.prec), den(K.prec);
  mpfi_sqr(t2, t);
  mpfi_add_ui(num, t2, 1);
  mpfi_mul(den, K.x2, t2);
  mpfi_add_ui(den, den, 1);
  mpfi_div(d1, num, den);
  mpfi_add_ui(d1, d1, 1);
  if (d2) {
    mpfi_mul(*d2, t, K.one_m_x2);
    mpfi_mul(*d2, *d2, num);
    mpfi_mul_ui(*d2, *d2, 2);
    mpfi_sqr(den, den);
    mpfi_div(*d2, *d2, den);
  }
}

// D = t - arctan(x t)/x >= 0 over T = tan(U_a): by the alternating series
// x^2 t^3 sum_n (-1)^n (x t)^(2n)/(2n+3) when x t < 1/16 (no cancellation), directly otherwise.
void d_of(fixed_mpfi& D, const constants& K, const fixed_mpfi& T) {
  fixed_mpfi y(K.prec), y2(K.prec), c(K.prec), rem(K.prec);
  mpfi_mul(y, K.x, T);
  if (y.hi() < 1.0 / 16) {
    mpfi_sqr(y2, y);
    const int terms = int(K.prec / 8) + 2;  // y^(2 terms) < 2^-(8 terms) < 2^-prec
    // Horner for sum_{n < terms} (-1)^n y2^n/(2n+3); the tail is at most y2^terms/(2 terms + 3).
    mpfi_set_ui(c, 1);
    mpfi_div_ui(c, c, unsigned(2 * (terms - 1) + 3));
    for (int n = terms - 2; n >= 0; --n) {
      mpfi_mul(c, c, y2);
      mpfi_neg(c, c);
      mpfi_set_ui(rem, 1);
      mpfi_div_ui(rem, rem, unsigned(2 * n + 3));
      mpfi_add(c, c, rem);
    }
    mpfi_set(rem, y2);
    for (int n = 1; n < terms; ++n) mpfi_mul(rem, rem, y2);
    mpfi_div_ui(rem, rem, unsigned(2 * terms + 3));
    const double tail = rem.hi();
    mpfi_interv_d(rem, -tail, tail);  // |tail| <= that (directed: hi() rounds up)
    mpfi_add(c, c, rem);
    mpfi_mul(D, c, y2);
    mpfi_mul(D, D, T);
  } else {
    mpfi_atan(D, y);
    mpfi_div(D, D, K.x);
    mpfi_sub(D, T, D);
  }
}

// The paper's error in the lobe k = round(a/(2b)) (x < 1/2): false if not proved at this precision.
bool enclose_asy_error(sweep_proof& pr, const constants& K, std::int64_t a, std::int64_t b) {
  const std::int64_t twob = 2 * b, rem = int_mod(a, twob);
  const std::int64_t k = rem == b ? (a - b) / twob : int_floor_div(a + b, twob);
  const std::int64_t m = a - 2 * k * b, am = m < 0 ? -m : m;
  fixed_mpfi d(K.prec);
  if (am == 0) {
    mpfi_set_ui(d, 0);  // s = 0: u_a = u_c = 0 exactly
  } else {
    fixed_mpfi s(K.prec);
    pi_ratio(s, K, am, twob);
    const double u0 = u_plus_tan_u_root(double(M_PI) * double(am) / double(twob));
    double lo = 0, hi = 0;
    fixed_mpfi T(K.prec), D(K.prec), F1(K.prec), F2(K.prec), TXi(K.prec), d1(K.prec), t(K.prec);
    if (!bracket_u_asy(K, u0, s, lo, hi, T)) return false;
    d_of(D, K, T);
    if (!fixed_narrow(D, 20)) return false;
    // First order: d = D/f'(xi), xi in Xi = [u_a, u_a + D/2] (f' >= 2); tan(Xi) is [tan lo, tan(hi + D/2)].
    f_derivatives(F1, nullptr, K, T);
    const double xi_hi = std::nextafter(hi + D.hi() / 2, 2.0);  // >= hi + D/2 despite the rounding of the sum
    if (!(xi_hi < K.pi.lo() / 2)) return false;
    tan_at(t, xi_hi, MPFR_RNDU, K.prec);
    mpfi_interv_fr(TXi, T.left(), t.right());
    fixed_mpfi F1xi(K.prec);
    f_derivatives(F1xi, &F2, K, TXi);
    mpfi_div(d1, D, F1xi);
    // Second order: d = (D - f''(eta) d^2/2)/f'(u_a), eta in Xi; intersected with the first.
    mpfi_sqr(t, d1);
    mpfi_mul(t, t, F2);
    mpfi_div_ui(t, t, 2);
    mpfi_sub(d, D, t);
    mpfi_div(d, d, F1);
    mpfi_intersect(d, d, d1);
    if (mpfi_is_empty(d)) return false;  // cannot happen: both enclose u_c - u_a
  }
  // error = 2 d/a, bound = pi^3 x^2/a, ratio = 2 d/(pi^3 x^2), constant = 2 d/x^2.
  fixed_mpfi e(K.prec), bound(K.prec), ratio(K.prec), cst(K.prec);
  mpfi_mul_ui(e, d, 2);
  mpfi_div_si(e, e, a);
  mpfi_sqr(bound, K.pi);
  mpfi_mul(bound, bound, K.pi);
  mpfi_mul(bound, bound, K.x2);
  mpfi_div_si(bound, bound, a);
  mpfi_div(ratio, e, bound);
  mpfi_mul_ui(cst, d, 2);
  mpfi_div(cst, cst, K.x2);
  pr.asy_error_hi = e.hi();
  pr.asy_bound_lo = bound.lo();
  pr.asy_ratio_lo = ratio.lo();
  pr.asy_ratio_hi = ratio.hi();
  pr.asy_constant_hi = cst.hi();
  return true;
}

// sqrt(2) sin(k pi/4) and sqrt(2) cos(k pi/4) for odd k; sin, cos for even k (all in {0, +-1}).
int sin_quarter(std::int64_t k) {
  static const int t[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  return t[int_mod(k, std::int64_t(8))];
}
int cos_quarter(std::int64_t k) {
  static const int t[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  return t[int_mod(k, std::int64_t(8))];
}

}  // namespace

// With alpha = a pi/4, beta = b pi/4 (theta = pi/2) and v = 1: q = sqrt(1-x^2) sin alpha cos beta,
// q' = cos alpha cos beta - x sin alpha sin beta (docs/mathematics.md §1), so
// 4 a^2 R = 4 (a^2 - b^2) (sA cB)^2 + 4 (a cA cB - b sA sB)^2. For odd a (b odd too) every
// sine and cosine is +-1/sqrt(2), each product is (+-1)/2; for even a they are 0 or +-1.
int128 sweep_quarter_R_scaled(std::int64_t a, std::int64_t b) {
  const int sa = sin_quarter(a), ca = cos_quarter(a), sb = sin_quarter(b), cb = cos_quarter(b);
  const int128 A = a, B = b, diff = A * A - B * B;
  const int128 q = A * (ca * cb) - B * (sa * sb);
  if (a % 2 != 0) return diff + q * q;
  return 4 * diff * (sa * cb) * (sa * cb) + 4 * q * q;
}

sweep_proof sweep_prove_pair(const resonant_pair<std::int64_t>& p, bool asy) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  sweep_proof pr;
  pr.quarter_R_scaled = sweep_quarter_R_scaled(a, b);
  const int amod = int(int_mod(a, std::int64_t(4)));
  pr.m_min = std::min(amod, 4 - amod);
  pr.lobes = minimiser_lobes(int128(a), int128(b));
  pr.has_asy = asy && 2 * b < a;
  const resonant_pair<big_int> pb(big_int(p.tau()), big_int(p.sigma()));
  bool done_r = false, done_asy = !pr.has_asy;
  for (mpfr_prec_t prec = 64; prec <= 512 && !(done_r && done_asy); prec *= 2) {
    constants K(prec);
    set_constants(K, pb);
    if (!done_r) {
      if (pr.m_min == 0) {
        fixed_mpfi th(prec);  // theta_first = 2 k pi/a, u* = 0; r_res = 0 exactly
        mpfi_mul_si(th, K.pi, long(pr.lobes.front().k));
        mpfi_mul_ui(th, th, 2);
        mpfi_div_si(th, th, a);
        pr.theta_lo = th.lo();
        pr.theta_hi = th.hi();
        done_r = true;
      } else {
        done_r = enclose_minimum(pr, K, pb, a);
      }
    }
    if (!done_asy) done_asy = enclose_asy_error(pr, K, a, b);
  }
  pr.enclosed = done_r;
  pr.asy_enclosed = pr.has_asy && done_asy;
  if (!done_r) pr.note = "not proved: the bracket of u* was not decided within 512 bits";
  if (pr.has_asy && !done_asy)
    pr.note += std::string(pr.note.empty() ? "" : "; ") + "not proved: the asy error was not enclosed within 512 bits";
  return pr;
}

}  // namespace gyrores
