// include/gyrores/theorem/root.hpp: the theorem's and the paper's roots, points and enclosures.
#include <gyrores/theorem/root.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gyrores/core/error.hpp>
#include <gyrores/core/roots.hpp>

#include "../core/ball.hpp"
#include "root_refined.hpp"

namespace gyrores {

namespace {

using fr = fixed_mpfr;
using iv = fixed_mpfi;

// H(u) - mu and H'(u) = x + x (1 + t^2)/(1 + x^2 t^2), t = tan u.
std::pair<double, double> theorem_h(double x, double mu, double u) {
  const double t = std::tan(u), xt = x * t;
  return {x * u + std::atan(xt) - mu, x + x * (1 + t * t) / (1 + xt * xt)};
}

}  // namespace

double theorem_root_double(double x, double mu) {
  constexpr double h = std::numbers::pi / 2;
  // Start: mu/(2x) (H ~ 2xu for small u and x; H ~ 2u as x -> 1), kept inside the bracket.
  const double u0 = std::min(mu / (2 * x), 0.9 * h);
  newton_result<double> nr;
  auto fdf = [&](double u) { return theorem_h(x, mu, u); };
  if (root_newton_safeguarded(fdf, 0.0, h, -1, u0, mu / 4, nr, 200)) return nr.root;
  auto f = [&](double u) { return theorem_h(x, mu, u).first; };
  return root_bracketed(f, 0.0, h, f(0.0), f(h), default_root_tolerance(mu / 4),
                        "lattice theorem: the root of x u + arctan(x tan u) = mu")
      .root;
}

void detail::root_refined_failed() {
  throw compute_error("lattice theorem: the double-double Newton steps for x u + arctan(x tan u) = mu did not settle");
}

GYRORES_DD_FAST root_double_double theorem_root_refined(const double_double& x, const double_double& mu) {
  return detail::root_refined(x, mu, x.hi, mu.hi / (2 * x.hi));
}

double paper_root_double(double s) {
  if (s == 0) return 0;
  if (s < 0) return -paper_root_double(-s);  // the equation is odd
  constexpr double h = std::numbers::pi / 2;
  // phi(u) = u - arctan(s - u) is increasing (1 < phi' <= 2) and convex below s (phi'' =
  // 2 (s - u)/(1 + (s - u)^2)^2), and the root lies in (0, min(s/2, pi/2)] (phi(s/2) >= 0,
  // phi(pi/2) > 0): Newton from that upper end decreases monotonically onto it.
  auto phi = [&](double u) { return u - std::atan(s - u); };
  double u = std::min(s / 2, h);
  for (int i = 0; i < 60; ++i) {
    const double d = s - u, du = phi(u) / (1 + 1 / (1 + d * d));
    if (!(du > 0)) return u;  // at (or a rounding below) the root
    u -= du;
    if (du <= 0x1p-30 * u) return u;  // the step just made leaves about an ulp
  }
  // TOMS 748 on the same bracket if Newton did not settle (it does for every s tested).
  const double floor = std::min(1.0, std::fabs(s) / 8);
  return root_bracketed(phi, -h, h, phi(-h), phi(h), root_tolerance<double>{4 * 0x1p-52, floor},
                        "paper: the root of u + tan u = s")
      .root;
}

void set_theorem_constants(theorem_constants& K, const resonant_pair<big_int>& p) {
  K.ai = p.order();
  K.bi = big_int(p.delta());
  const big_int ts = big_int(p.tau() * p.sigma()), b2 = big_int(K.bi * K.bi), a2 = big_int(K.ai * K.ai);
  // By integers wherever the formula allows (each such product or quotient costs O(prec)); the
  // one full-precision operation is the square root.
  mpfi_set_z(K.a, K.ai.backend().data());
  mpfi_set_z(K.b, K.bi.backend().data());
  mpfi_div_z(K.x, K.b, K.ai.backend().data());
  mpfi_set_z(K.x2, b2.backend().data());
  mpfi_div_z(K.x2, K.x2, a2.backend().data());
  mpfi_set_z(K.sqrt_ts, ts.backend().data());
  mpfi_sqrt(K.sqrt_ts, K.sqrt_ts);
  mpfi_mul_2ui(K.s1mx2, K.sqrt_ts, 1);
  mpfi_div_z(K.s1mx2, K.s1mx2, K.ai.backend().data());
  mpfi_const_pi(K.pi);
  K.ratio = true;
}

theorem_constants::theorem_constants(mpfr_prec_t p, const resonant_pair<big_int>& pair) : theorem_constants(p) {
  set_theorem_constants(*this, pair);
}

void set_theorem_constants(theorem_constants& K, const iv& x) {
  mpfi_set(K.x, x);
  mpfi_const_pi(K.pi);
  K.ratio = false;
}

void pi_ratio(iv& out, const theorem_constants& K, const big_int& m, const big_int& d) {
  mpfi_mul_z(out, K.pi, m.backend().data());
  mpfi_div_z(out, out, d.backend().data());
  mpfi_div_2ui(out, out, 1);
}

void paper_error_bound(iv& error, iv& bound, const theorem_constants& K, const iv& d) {
  mpfi_mul_2ui(error, d, 1);
  mpfi_div_z(error, error, K.ai.backend().data());
  mpfi_sqr(bound, K.pi);
  mpfi_mul(bound, bound, K.pi);
  mpfi_mul(bound, bound, K.x2);
  mpfi_div_z(bound, bound, K.ai.backend().data());
}

namespace {

// ---- tangents ----

// tan(c + d) from tc = tan c and d, points (Newton: the d^5 remainder is below the precision).
void tan_shift_point(fr& out, mpfr_srcptr tc, mpfr_srcptr d) {
  const mpfr_prec_t p = mpfr_get_prec(out);
  fr td(p), den(p);
  mpfr_sqr(td, d, MPFR_RNDN);
  mpfr_mul(td, td, d, MPFR_RNDN);
  mpfr_div_ui(td, td, 3, MPFR_RNDN);
  mpfr_add(td, td, d, MPFR_RNDN);
  mpfr_mul(den, tc, td, MPFR_RNDN);
  mpfr_ui_sub(den, 1, den, MPFR_RNDN);
  mpfr_add(out, tc, td, MPFR_RNDN);
  mpfr_div(out, out, den, MPFR_RNDN);
}

}  // namespace

void tan_shift(iv& out, const iv& tc, const iv& d) {
  const mpfr_prec_t p = mpfi_get_prec(out);
  iv td(p), r(p), den(p);
  fr m(p), m2(p), mneg(p);
  mpfi_mag(m, d);  // max |d| (exact: an endpoint's absolute value)
  mpfr_sqr(m2, m, MPFR_RNDU);
  mpfr_sqr(m2, m2, MPFR_RNDU);
  mpfr_mul(m, m, m2, MPFR_RNDU);
  mpfr_div_ui(m, m, 7, MPFR_RNDU);
  mpfr_neg(mneg, m, MPFR_RNDN);
  mpfi_interv_fr(r, mneg, m);
  mpfi_sqr(td, d);
  mpfi_mul(td, td, d);
  mpfi_div_ui(td, td, 3);
  mpfi_add(td, td, d);
  mpfi_add(td, td, r);
  mpfi_mul(den, tc, td);
  mpfi_ui_sub(den, 1, den);
  mpfi_add(out, tc, td);
  mpfi_div(out, out, den);
}

namespace {

// Arb's error for a small argument |v| ~ 2^-k is not relative to v: k more bits keep the
// result as accurate, relatively, as the argument (without them the ball of tan(mu - x c) for
// (10^18+1, 10^18), w ~ 2^-61, came out 2^19 times wider, and the proof needed twice the bits).
mpfr_prec_t small_argument_bits(mpfr_srcptr v) {
  return !mpfr_zero_p(v) && mpfr_get_exp(v) < 0 ? -mpfr_get_exp(v) : 0;
}

// out = an enclosure of tan over W (inside (-pi/2, pi/2)): Arb's arb_tan of the ball holding W
// (rigorous, and about 3 times cheaper than one MPFR tangent at these precisions), turned into
// an interval rounded outward, with pole_bits more for a W near pi/2. False if Arb's ball is not
// finite (W too close to a pole).
bool tan_enclosure(iv& out, const iv& W, long pole_bits) {
  const mpfr_prec_t prec = mpfi_get_prec(out);
  const mpfr_prec_t work = prec + 8 + small_argument_bits(W.left()) + pole_bits;
  arb_support::ball w, t;
  arb_set_interval_mpfr(w, W.left(), W.right(), work);
  arb_tan(t, w, work);
  if (!arb_is_finite(t)) return false;
  arb_support::interval_of(out, t);
  return true;
}

// out ~ tan(v) at out's precision, for the ladder's centres (no proof needed there): the
// midpoint of Arb's ball.
void tan_point(fr& out, mpfr_srcptr v, long pole_bits) {
  const mpfr_prec_t work = mpfr_get_prec(out) + 8 + small_argument_bits(v) + pole_bits;
  arb_support::ball w, t;
  arf_set_mpfr(arb_midref(w.get()), v);
  arb_tan(t, w, work);
  arf_get_mpfr(out, arb_midref(t.get()), MPFR_RNDN);
}

// ---- the equations, as Newton steps about a centre ----

// A point of the ladder at precision `prec`: c (the centre), tan c and, for the theorem,
// tan(mu - x c); x and mu (theorem) or s (paper) as points.
struct centre_point {
  explicit centre_point(mpfr_prec_t p, long pole) : c(p), tc(p), tw(p), x(p), mu(p), pole_bits(pole) {}
  fr c, tc, tw, x, mu;
  long pole_bits;  // root_enclosure::pole_bits
};

// One Newton step on the theorem's f(u) = tan(mu - x u) - x tan u about the centre (f' =
// -x (1 + tan^2 w) - x (1 + tan^2 u)), or on the paper's g(u) = u + tan u - s (g' = 2 + tan^2
// u). Returns the step's size relative to u, as a power of 2 (an upper bound of its exponent).
long newton_step(fr& u, const centre_point& z, bool theorem) {
  const mpfr_prec_t p = mpfr_get_prec(u);
  fr d(p), tu(p), f(p), df(p), t(p);
  mpfr_sub(d, u, z.c, MPFR_RNDN);
  tan_shift_point(tu, z.tc, d);
  mpfr_sqr(df, tu, MPFR_RNDN);
  if (theorem) {
    fr e(p), tw(p);
    mpfr_mul(e, z.x, d, MPFR_RNDN);
    mpfr_neg(e, e, MPFR_RNDN);
    tan_shift_point(tw, z.tw, e);
    mpfr_mul(f, z.x, tu, MPFR_RNDN);
    mpfr_sub(f, f, tw, MPFR_RNDN);  // -f
    mpfr_sqr(t, tw, MPFR_RNDN);
    mpfr_add(df, df, t, MPFR_RNDN);
    mpfr_add_ui(df, df, 2, MPFR_RNDN);
    mpfr_mul(df, df, z.x, MPFR_RNDN);  // -f'
  } else {
    mpfr_add(f, u, tu, MPFR_RNDN);
    mpfr_sub(f, f, z.mu, MPFR_RNDN);
    mpfr_add_ui(df, df, 2, MPFR_RNDN);
  }
  mpfr_div(f, f, df, MPFR_RNDN);
  mpfr_sub(u, u, f, MPFR_RNDN);
  if (mpfr_zero_p(f)) return -(1L << 30);
  return long(mpfr_get_exp(f)) - long(mpfr_get_exp(u)) + 1;
}

// Newton from u about the centre z until the step just made leaves an error below
// 2^-(prec - 8) |u|: a step of relative size 2^e leaves about kappa 2^(2e), kappa = |u f''/(2 f')|,
// taken as at most 2^(6 + L), L the pole bits (kappa is below 10 for every root of a pair, and
// about u tan u near pi/2; a root it underestimates may stop a step early, and then its proof
// fails at this precision: never a wrong enclosure).
void newton_about(fr& u, const centre_point& z, bool theorem) {
  const long prec = long(mpfr_get_prec(u));
  for (int it = 0; it < 8; ++it)
    if (2 * newton_step(u, z, theorem) + 6 + z.pole_bits <= -(prec - 8)) return;
}

// The point tangents of a centre at z's precision (the ladder's levels below the last).
void set_point_tangents(centre_point& z, bool theorem) {
  tan_point(z.tc, z.c, z.pole_bits);
  if (theorem) {
    const mpfr_prec_t p = mpfr_get_prec(z.c);
    fr w(p);
    mpfr_mul(w, z.x, z.c, MPFR_RNDN);
    mpfr_sub(w, z.mu, w, MPFR_RNDN);
    tan_point(z.tw, w, z.pole_bits);
  }
}

// The bits a factor needs when it multiplies an offset |d| < 2^e_off from the centre c in a sum
// exact to `prec` bits relative to c: the product is about 2^(e_off - exp c) of the sum, so it
// needs that many bits fewer (and 32 guard bits, and the pole bits, which the sum's terms lose
// to their cancellation near pi/2; at least 64, at most prec).
mpfr_prec_t offset_bits(mpfr_prec_t prec, long e_off, mpfr_srcptr c, long pole_bits) {
  const long drop = std::max(0L, long(mpfr_get_exp(c)) - e_off);
  return std::min<mpfr_prec_t>(prec, std::max<long>(64, long(prec) + 32 + pole_bits - drop));
}

// The equations as the proof evaluates them (header, step 2), both increasing in u:
//   theorem  f(u) = x tan u - tan(mu - x u)   (the sign of H(u) - mu), for a pair
//            b tan u - a tan w = a f(u), by the integers;
//            f'(u) = x (2 + tan^2 u + tan^2 w) (b (...) for a pair);
//   paper    g(u) = u + tan u - s,  g'(u) = 2 + tan^2 u.
// The derivative from enclosures TV of tan u and TW of tan w (theorem) at DF's precision.
void derivative_from_tangents(iv& DF, const theorem_constants& K, bool theorem, const iv& TV, const iv& TW) {
  const mpfr_prec_t q = mpfi_get_prec(DF);
  iv t(q);
  mpfi_sqr(DF, TV);
  if (theorem) {
    mpfi_sqr(t, TW);
    mpfi_add(DF, DF, t);
  }
  mpfi_add_ui(DF, DF, 2);
  if (theorem && K.ratio) mpfi_mul_z(DF, DF, K.bi.backend().data());
  else if (theorem) mpfi_mul(DF, DF, K.x);
}

// The value at the centre from its enclosures (r.fc): b tan c - a tan(mu - x c) (a pair),
// x tan c - tan(mu - x c), or c + tan c - s.
void equation_at_centre(root_enclosure& r, const theorem_constants& K, bool theorem) {
  if (theorem && K.ratio) {
    iv t(K.prec);
    mpfi_mul_z(r.fc, r.tc, K.bi.backend().data());
    mpfi_mul_z(t, r.wc, K.ai.backend().data());
    mpfi_sub(r.fc, r.fc, t);
  } else if (theorem) {
    mpfi_mul(r.fc, r.tc, K.x);
    mpfi_sub(r.fc, r.fc, r.wc);
  } else {
    mpfi_add_fr(r.fc, r.tc, r.centre);
    mpfi_sub(r.fc, r.fc, r.mu);
  }
}

// The one Newton ladder: u (accurate to about `acc` bits, at r's precision) is refined on levels
// planned from the top: the last centre needs half the precision and 16 bits more (the step from
// its enclosures doubles that, and the proof of step 2 needs no more), each level below it a
// quarter of the one above and 8 bits (two Newton steps a level), down to the scout's accuracy.
// Each level takes point tangents at its centre and Newton steps about it. At full precision the
// centre's tangents are Arb enclosures (r.tc, r.wc), the equation's value there is r.fc, and
// one Newton step from them gives r.u (the quotient at the bits its size needs). Not proved if
// the enclosures could not be formed. Every level carries r.pole_bits more (header, step 1).
proof_status newton_ladder(root_enclosure& r, const theorem_constants& K, bool theorem, unsigned acc) {
  const mpfr_prec_t bits = K.prec;
  fr x(bits), mu(bits);
  mpfi_mid(x, K.x);
  mpfi_mid(mu, r.mu);
  long levels[40];
  int n = 0;
  for (long need = (long(bits) + 1) / 2 + 16; n < 40; need = need / 4 + 8) {
    levels[n++] = std::min<long>(bits, need + 8 + r.pole_bits);
    if (need / 4 <= long(acc)) break;  // the scout's accuracy starts this level
  }
  for (int i = n - 1; i >= 0; --i) {
    const mpfr_prec_t level = levels[i];
    centre_point z(level, r.pole_bits);
    mpfr_set(z.c, r.u, MPFR_RNDN);
    mpfr_set(z.x, x, MPFR_RNDN);
    mpfr_set(z.mu, mu, MPFR_RNDN);
    set_point_tangents(z, theorem);
    fr ul(level);
    mpfr_set(ul, r.u, MPFR_RNDN);
    newton_about(ul, z, theorem);
    mpfr_set(r.u, ul, MPFR_RNDN);
  }
  mpfr_set(r.centre, r.u, MPFR_RNDN);
  iv C(bits);
  mpfi_set_fr(C, r.centre);
  constexpr auto near_pole = proof_status::undecided("a tangent at the ladder's last centre is not finite (too close to pi/2)");
  if (!tan_enclosure(r.tc, C, r.pole_bits)) return near_pole;
  if (theorem) {
    iv W(bits);  // mu - x c (mu - b c/a)
    if (K.ratio) {
      mpfi_mul_z(W, C, K.bi.backend().data());
      mpfi_div_z(W, W, K.ai.backend().data());
    } else {
      mpfi_mul(W, C, K.x);
    }
    mpfi_sub(W, r.mu, W);
    if (!tan_enclosure(r.wc, W, r.pole_bits)) return near_pole;
  }
  equation_at_centre(r, K, theorem);
  // u = c - f(c)/f'(c), a point (step 2 proves the bracket about it): |f(c)/f'(c)| <= |f(c)|/(2b)
  // (a pair), |f(c)|/(2x) (a coupling) or |g(c)|/2 (paper).
  fr fmag(bits);
  mpfi_mag(fmag, r.fc);
  if (mpfr_zero_p(fmag)) return proof_status::proved();
  const long scale = !theorem ? 1 : K.ratio ? long(mpz_sizeinbase(K.bi.backend().data(), 2)) : long(mpfr_get_exp(K.x.left()));
  const long e_step = long(mpfr_get_exp(fmag)) - scale;
  const mpfr_prec_t q = offset_bits(bits, e_step, r.centre, r.pole_bits);
  iv TV(q), TW(q), DF(q);
  mpfi_set(TV, r.tc);
  if (theorem) mpfi_set(TW, r.wc);
  derivative_from_tangents(DF, K, theorem, TV, TW);
  fr step(q), df(q);
  mpfi_mid(step, r.fc);
  mpfi_mid(df, DF);
  mpfr_div(step, step, df, MPFR_RNDN);
  mpfr_sub(r.u, r.centre, step, MPFR_RNDN);
  return proof_status::proved();
}

// ---- scouts: the ladder's starting points ----

// Beyond 2^900 the pair's integers leave double's exponent range (mu, x, u* underflow).
bool beyond_double(const iv& v) { return mpfr_get_exp(v.left()) > 900 || mpfr_get_exp(v.right()) > 900; }

// Safeguarded Newton at 64 bits for a pair beyond double's range: fdf(u, f, df) evaluates f
// and f' (f increasing on [lo, hi], f(lo) < 0 < f(hi)). 64-bit MPFR numbers carry their own
// precision and exponent range; about 60 bits are accurate on return.
template <class FDF> void scout_mpfr(fr& u, mpfr_srcptr lo0, mpfr_srcptr hi0, FDF&& fdf) {
  fr lo(64), hi(64), f(64), df(64), next(64), step(64);
  mpfr_set(lo, lo0, MPFR_RNDN);
  mpfr_set(hi, hi0, MPFR_RNDN);
  for (int it = 0; it < 400; ++it) {
    fdf(u, f, df);
    if (mpfr_zero_p(f)) return;
    if (mpfr_sgn(static_cast<mpfr_srcptr>(f)) < 0) mpfr_set(lo, u, MPFR_RNDN);
    else mpfr_set(hi, u, MPFR_RNDN);
    mpfr_div(step, f, df, MPFR_RNDN);
    mpfr_sub(next, u, step, MPFR_RNDN);
    if (!(mpfr_cmp(next, lo) > 0 && mpfr_cmp(next, hi) < 0)) {  // bisect (also for df = 0, NaN)
      mpfr_add(next, lo, hi, MPFR_RNDN);
      mpfr_div_2ui(next, next, 1, MPFR_RNDN);
    }
    mpfr_sub(step, next, u, MPFR_RNDN);
    mpfr_set(u, next, MPFR_RNDN);
    mpfr_mul_2si(next, u, -60, MPFR_RNDN);
    if (mpfr_cmpabs(step, next) <= 0) return;
  }
  throw compute_error("lattice theorem: the 64-bit scout of a root did not converge");
}

// The theorem's root by the double path in r.u, accurate to about 50 bits.
void theorem_scout_double(root_enclosure& r, const theorem_constants& K) {
  fr x(53), mu(53);
  mpfi_mid(x, K.x);
  mpfi_mid(mu, r.mu);
  mpfr_set_d(r.u, theorem_root_double(mpfr_get_d(x, MPFR_RNDN), mpfr_get_d(mu, MPFR_RNDN)), MPFR_RNDN);
}

// The theorem's root in r.u to about 60 bits by safeguarded Newton at 64 bits (MPFR numbers
// carry their own exponent range: x or mu beyond double's).
unsigned theorem_scout_mpfr(root_enclosure& r, const theorem_constants& K) {
  fr x(64), mu(64), lo(64), hi(64), t(64), xt(64);
  mpfi_mid(x, K.x);
  mpfi_mid(mu, r.mu);
  mpfr_set_ui(lo, 0, MPFR_RNDN);
  mpfr_const_pi(hi, MPFR_RNDD);
  mpfr_div_2ui(hi, hi, 1, MPFR_RNDD);
  fr u(64);
  mpfr_div(u, mu, x, MPFR_RNDN);
  mpfr_div_2ui(u, u, 1, MPFR_RNDN);  // mu/(2x)
  scout_mpfr(u, lo, hi, [&](mpfr_srcptr v, fr& f, fr& df) {
    mpfr_tan(t, v, MPFR_RNDN);
    mpfr_mul(xt, x, t, MPFR_RNDN);
    mpfr_atan(f, xt, MPFR_RNDN);
    mpfr_fma(f, x, v, f, MPFR_RNDN);
    mpfr_sub(f, f, mu, MPFR_RNDN);
    mpfr_sqr(t, t, MPFR_RNDN);
    mpfr_add_ui(t, t, 1, MPFR_RNDN);
    mpfr_sqr(xt, xt, MPFR_RNDN);
    mpfr_add_ui(xt, xt, 1, MPFR_RNDN);
    mpfr_div(df, t, xt, MPFR_RNDN);
    mpfr_add_ui(df, df, 1, MPFR_RNDN);
    mpfr_mul(df, df, x, MPFR_RNDN);
  });
  mpfr_set(r.u, u, MPFR_RNDN);
  return 40;
}

// A pair's root to about 50 bits (double) or 60 (MPFR, beyond double's range) in r.u.
unsigned theorem_scout(root_enclosure& r, const theorem_constants& K) {
  if (beyond_double(K.a)) return theorem_scout_mpfr(r, K);
  theorem_scout_double(r, K);
  // Claimed accuracy: 32 bits, not double's 53: near pi/2 tan's conditioning leaves the scout
  // about 2^-39 (6/5, m = 5), and a ladder that assumes more bits than it has takes too few
  // Newton steps and fails its proof (safe, but at every other precision).
  return 32;
}

// The pole bits of a root whose tangent has MPFR exponent E (2^(E-1) <= tan u < 2^E): log2 tan u
// beyond 4, 0 while tan u < 16 (every pair: u* <= pi/4).
long pole_bits_of(long tan_exponent) { return std::max(0L, tan_exponent - 5); }

// A coupling's root near pi/2 (header, step 1), in r.u with its pole bits, when it lies within
// 2^-20 of pi/2; false otherwise. With u = pi/2 - e, x tan u = tan w reads tan e = x tan(c0 - x e),
// c0 = pi/2 - mu + x pi/2 (formed at full precision: mu may be pi/2 to many bits). The map
// e -> atan(x tan(c0 - x e)) decreases, so e <= its value e1 at 0, and where e1 is small it
// contracts by about x^2 (1 + tan^2): its iterates alternate about the root and settle in a few
// steps, at 64 bits (e carries its own exponent, which no precision of u near pi/2 could).
bool scout_near_pole(root_enclosure& r, const theorem_constants& K) {
  const mpfr_prec_t bits = K.prec;
  fr x(bits), c0(bits), half_pi(bits);
  mpfi_mid(x, K.x);
  mpfi_mid(c0, r.mu);
  mpfr_const_pi(half_pi, MPFR_RNDN);
  mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
  mpfr_sub(c0, half_pi, c0, MPFR_RNDN);
  mpfr_fma(c0, x, half_pi, c0, MPFR_RNDN);
  fr e(64), next(64), t(64), x64(64), c(64);
  mpfr_set(x64, x, MPFR_RNDN);
  mpfr_set(c, c0, MPFR_RNDN);
  if (mpfr_sgn(static_cast<mpfr_srcptr>(c)) <= 0 || mpfr_cmp(c, half_pi) >= 0) return false;  // mu <= x pi/2
  mpfr_set_ui(e, 0, MPFR_RNDN);
  for (int it = 0; it < 100; ++it) {
    mpfr_mul(t, x64, e, MPFR_RNDN);
    mpfr_sub(t, c, t, MPFR_RNDN);
    mpfr_tan(t, t, MPFR_RNDN);
    mpfr_mul(t, t, x64, MPFR_RNDN);
    mpfr_atan(next, t, MPFR_RNDN);
    if (it == 0 && mpfr_cmp_d(next, 0x1p-20) >= 0) return false;  // e <= e1: not near pi/2
    mpfr_sub(t, next, e, MPFR_RNDN);
    mpfr_set(e, next, MPFR_RNDN);
    mpfr_mul_2si(next, e, -60, MPFR_RNDN);
    if (mpfr_cmpabs(t, next) <= 0) break;
  }
  mpfr_sub(r.u, half_pi, e, MPFR_RNDN);
  r.pole_bits = pole_bits_of(1 - long(mpfr_get_exp(e)));  // tan u ~ 1/e
  return true;
}

// Any coupling's root (x and mu intervals) in r.u, with its pole bits; returns the accuracy
// claimed (bits relative to u): near pi/2 the fixed point above; else the double path, and
// safeguarded Newton at 64 bits for x or mu beyond double's range (or if the double path fails).
unsigned coupling_scout(root_enclosure& r, const theorem_constants& K) {
  if (scout_near_pole(r, K)) return 40 + unsigned(r.pole_bits);
  unsigned acc = 40;
  const bool in_range = mpfr_get_exp(K.x.left()) > -900 && mpfr_get_exp(r.mu.left()) > -900;
  try {
    if (!in_range) throw compute_error("beyond double");
    theorem_scout_double(r, K);
    acc = 32;  // as theorem_scout
  } catch (const compute_error&) {
    acc = theorem_scout_mpfr(r, K);
  }
  fr t(64);
  mpfr_tan(t, r.u, MPFR_RNDN);
  r.pole_bits = pole_bits_of(mpfr_get_exp(t));
  return acc;
}

// The paper's root of u + tan u = s in r.u, likewise.
unsigned paper_scout(root_enclosure& r) {
  if (!beyond_double(r.mu) && mpfr_get_exp(r.mu.left()) > -900) {
    fr s(53);
    mpfi_mid(s, r.mu);
    mpfr_set_d(r.u, paper_root_double(mpfr_get_d(s, MPFR_RNDN)), MPFR_RNDN);
    return 32;  // as theorem_scout
  }
  fr s(64), lo(64), hi(64), t(64), u(64);
  mpfi_mid(s, r.mu);
  mpfr_const_pi(hi, MPFR_RNDD);
  mpfr_div_2ui(hi, hi, 1, MPFR_RNDD);
  mpfr_neg(lo, hi, MPFR_RNDN);
  mpfr_div_2ui(u, s, 1, MPFR_RNDN);  // u + tan u ~ 2u for small s
  scout_mpfr(u, lo, hi, [&](mpfr_srcptr v, fr& f, fr& df) {
    mpfr_tan(t, v, MPFR_RNDN);
    mpfr_add(f, v, t, MPFR_RNDN);
    mpfr_sub(f, f, s, MPFR_RNDN);
    mpfr_sqr(df, t, MPFR_RNDN);
    mpfr_add_ui(df, df, 2, MPFR_RNDN);
  });
  mpfr_set(r.u, u, MPFR_RNDN);
  return 40;
}

// ---- brackets ----

// The bracket's two ends about the ladder's point, r.lo, r.hi = u -+ |u| 2^-(prec - 16), as
// intervals LO, HI.
void bracket_ends(iv& LO, iv& HI, root_enclosure& r) {
  const mpfr_prec_t p = mpfi_get_prec(LO);
  fr rad(p);
  mpfr_abs(rad, r.u, MPFR_RNDN);
  mpfr_mul_2si(rad, rad, -int(p) + 16, MPFR_RNDU);
  mpfr_sub(r.lo, r.u, rad, MPFR_RNDD);
  mpfr_add(r.hi, r.u, rad, MPFR_RNDU);
  mpfi_set_fr(LO, r.lo);
  mpfi_set_fr(HI, r.hi);
}

// The intervals holding the ends' outward roundings to D digits: LO = [lo - e, lo],
// HI = [hi, hi + e], e = 2^(exp(hi) - k) >= 10^(1-D) hi (a unit in the D-th digit of either end).
void decimal_ends(iv& LO, iv& HI, const root_enclosure& r, unsigned decimal_digits) {
  const mpfr_prec_t p = mpfi_get_prec(LO);
  const long k = long(digits10_to_bits(decimal_digits - 1)) - 1;  // < (D - 1) log2 10: 2^-k > 10^(1-D)
  fr unit(p), end(p);
  mpfr_set_ui_2exp(unit, 1, mpfr_get_exp(r.hi) - k, MPFR_RNDU);  // hi < 2^exp(hi)
  mpfr_sub(end, r.lo, unit, MPFR_RNDD);
  mpfi_interv_fr(LO, end, r.lo);
  mpfr_add(end, r.hi, unit, MPFR_RNDU);
  mpfi_interv_fr(HI, r.hi, end);
}

// d = U - centre, false unless |d| <= 2^-10 (the remainder bound needs |d| <= 1/4).
bool offset_from_centre(iv& d, const root_enclosure& r, const iv& U) {
  fr dmax(mpfi_get_prec(d));
  mpfi_sub_fr(d, U, r.centre);
  mpfi_mag(dmax, d);
  return mpfr_cmp_d(dmax, 0x1p-10) <= 0;
}

// Step 2's mean value form about the centre c, for ends LO <= HI within 2^-10 of it: for v in
// [LO, HI] there is xi between c and v with
//   f(v) = f(c) + f'(xi) (v - c),   tan v = tan c + (1 + tan^2 xi) (v - c),
// and xi lies in V = c + hull(0, LO - c, HI - c), where tan (and tan(mu - x xi)) is enclosed by
// the addition formula (tan_shift) from the centre's enclosures. Those factors multiply offsets
// of at most 2^-10 (2^-(prec/2) in the ladder's brackets), so they are formed at the bits the
// products need (offset_bits); f(c) and tan c keep the full precision. flo, fhi (when given)
// receive f(LO), f(HI) (g for the paper), T receives tan([LO, HI]). Refused if an end is
// farther than 2^-10 from the centre.
proof_status mean_value_ends(const theorem_constants& K, const root_enclosure& r, bool theorem, const iv& LO,
                             const iv& HI, iv& flo, iv& fhi, iv& T) {
  const mpfr_prec_t bits = K.prec;
  iv dlo(bits), dhi(bits);
  if (!offset_from_centre(dlo, r, LO) || !offset_from_centre(dhi, r, HI))
    return proof_status::out_of_domain("a bracket end lies farther than 2^-10 from the ladder's centre");
  fr m(bits), m2(bits);
  mpfi_mag(m, dlo);
  mpfi_mag(m2, dhi);
  mpfr_max(m, m, m2, MPFR_RNDU);
  const mpfr_prec_t q = mpfr_zero_p(m) ? 64 : offset_bits(bits, long(mpfr_get_exp(m)), r.centre, r.pole_bits);
  iv H(q), TV(q), S(q), p(q);
  mpfi_set(H, dlo);  // hull(0, LO - c, HI - c)
  mpfi_put(H, dhi);
  mpfi_put_si(H, 0);
  mpfi_set(p, r.tc);
  tan_shift(TV, p, H);
  constexpr auto pole = proof_status::out_of_domain("the bracket's hull reaches a pole of tan");
  if (!mpfi_bounded_p(TV)) return pole;  // V reaches a pole of tan: no mean value form
  iv TW(q), DF(q);
  if (theorem) {  // tan(mu - x xi) = tan((mu - x c) - x (xi - c))
    iv e(q), wq(q);
    mpfi_set(e, K.x);
    mpfi_mul(e, e, H);
    mpfi_neg(e, e);
    mpfi_set(wq, r.wc);
    tan_shift(TW, wq, e);
    if (!mpfi_bounded_p(TW)) return pole;
  }
  derivative_from_tangents(DF, K, theorem, TV, TW);
  mpfi_mul(p, DF, dlo);
  mpfi_add(flo, r.fc, p);
  mpfi_mul(p, DF, dhi);
  mpfi_add(fhi, r.fc, p);
  mpfi_sqr(S, TV);
  mpfi_add_ui(S, S, 1);  // 1 + tan^2 over V
  mpfi_set(p, dlo);
  mpfi_put(p, dhi);
  mpfi_mul(p, S, p);
  mpfi_add(T, r.tc, p);
  return proof_status::proved();
}

// The ends' signs: f < 0 over LO and f > 0 over HI (g for the paper), each proved ("certainly",
// never "possibly": an end within the enclosures' width of the root is refused).
proof_status signs_at_ends(const iv& flo, const iv& fhi) {
  constexpr auto close = proof_status::undecided("a bracket end lies within the enclosures' width of the root");
  if (!(mpfr_sgn(flo.right()) < 0)) return close;
  if (!(mpfr_sgn(fhi.left()) > 0)) return close;
  return proof_status::proved();
}

}  // namespace

proof_status theorem_centre(root_enclosure& r, const theorem_constants& K) {
  return newton_ladder(r, K, true, K.ratio ? theorem_scout(r, K) : coupling_scout(r, K));
}

proof_status theorem_centre_of(root_enclosure& r, const theorem_constants& K, const big_int& m) {
  // 0 < m < a keeps mu in (0, pi/2), where the bracket's argument holds (header, step 2).
  if (m <= 0 || mpfr_cmp_z(K.a.left(), m.backend().data()) <= 0)
    throw usage_error("the theorem's root needs an offset 0 < m < a, got m = " + m.str());
  pi_ratio(r.mu, K, m, K.ai);
  return theorem_centre(r, K);
}

namespace {

// 0 < LO and HI < pi/2, where the argument of step 2 holds.
proof_status in_domain(const theorem_constants& K, const iv& lo, const iv& hi) {
  iv half_pi(K.prec);
  mpfi_div_2ui(half_pi, K.pi, 1);
  if (mpfr_sgn(lo.left()) <= 0 || mpfr_cmp(hi.right(), half_pi.left()) >= 0)
    return proof_status::out_of_domain("a bracket end lies outside (0, pi/2)");
  return proof_status::proved();
}

}  // namespace

proof_status prove_theorem_bracket(const theorem_constants& K, const root_enclosure& r, const iv& lo, const iv& hi,
                                   iv& T) {
  iv flo(K.prec), fhi(K.prec);
  GYRORES_TRY_PROOF(in_domain(K, lo, hi));
  // b tan lo < a tan(mu - x lo) and b tan hi > a tan(mu - x hi), each side bounded the safe way.
  GYRORES_TRY_PROOF(mean_value_ends(K, r, true, lo, hi, flo, fhi, T));
  return signs_at_ends(flo, fhi);
}

namespace {

// Step 2 about the ladder's point (prove_theorem_root): r.U, r.T, r.lo, r.hi, and when asked
// the decimal ends (r.decimals, U and T over them), which lie beyond the binary ends. First the
// bracket of the decimals (it holds the binary ends); if the mean value form over them is too
// coarse, the binary ends, and then the decimals are brackets too wherever they stay in
// (0, pi/2), H being increasing there (proofs/lattice-theorem.md, Step A): a root within a
// decimal unit of pi/2 has none.
proof_status bracket_about_point(root_enclosure& r, const theorem_constants& K, unsigned decimal_digits) {
  iv LO(K.prec), HI(K.prec), DLO(K.prec), DHI(K.prec), T(K.prec), flo(K.prec), fhi(K.prec);
  r.decimals = 0;
  bracket_ends(LO, HI, r);
  if (decimal_digits > 0) {
    decimal_ends(DLO, DHI, r, decimal_digits);
    if (prove_theorem_bracket(K, r, DLO, DHI, r.T)) {
      mpfi_union(r.U, DLO, DHI);
      r.decimals = decimal_digits;
      return proof_status::proved();
    }
  }
  GYRORES_TRY_PROOF(prove_theorem_bracket(K, r, LO, HI, r.T));
  mpfi_union(r.U, LO, HI);
  if (decimal_digits == 0 || !in_domain(K, DLO, DHI) || !mean_value_ends(K, r, true, DLO, DHI, flo, fhi, T))
    return proof_status::proved();
  mpfi_set(r.T, T);
  mpfi_union(r.U, DLO, DHI);
  r.decimals = decimal_digits;
  return proof_status::proved();
}

}  // namespace

proof_status prove_theorem_root(root_enclosure& r, const theorem_constants& K, unsigned decimal_digits) {
  GYRORES_TRY_PROOF(theorem_centre(r, K));
  return bracket_about_point(r, K, decimal_digits);
}

proof_status prove_theorem_root(root_enclosure& r, const theorem_constants& K, const big_int& m,
                                unsigned decimal_digits) {
  GYRORES_TRY_PROOF(theorem_centre_of(r, K, m));
  return bracket_about_point(r, K, decimal_digits);
}

proof_status prove_paper_root(root_enclosure& r, const theorem_constants& K, const big_int& m) {
  pi_ratio(r.mu, K, m, K.bi);
  if (m == 0) {
    mpfr_set_ui(r.u, 0, MPFR_RNDN);
    mpfi_set_ui(r.U, 0);
    mpfi_set_ui(r.T, 0);
    return proof_status::proved();
  }
  GYRORES_TRY_PROOF(newton_ladder(r, K, false, paper_scout(r)));
  iv lo(K.prec), hi(K.prec), half_pi(K.prec), glo(K.prec), ghi(K.prec);
  bracket_ends(lo, hi, r);
  mpfi_div_2ui(half_pi, K.pi, 1);
  if (mpfr_cmpabs(lo.left(), half_pi.left()) >= 0 || mpfr_cmpabs(hi.right(), half_pi.left()) >= 0)
    return proof_status::out_of_domain("a bracket end lies outside (-pi/2, pi/2)");
  // lo + tan lo < s < hi + tan hi (g = u + tan u increases on (-pi/2, pi/2)).
  GYRORES_TRY_PROOF(mean_value_ends(K, r, false, lo, hi, glo, ghi, r.T));
  GYRORES_TRY_PROOF(signs_at_ends(glo, ghi));
  mpfi_union(r.U, lo, hi);
  return proof_status::proved();
}

void theorem_radius(iv& r, const theorem_constants& K, const iv& T) {
  iv t2(K.prec), d1(K.prec), d2(K.prec);
  mpfi_sqr(t2, T);
  mpfi_add_ui(d1, t2, 1);
  mpfi_mul(d2, t2, K.x2);
  mpfi_add_ui(d2, d2, 1);
  mpfi_mul(d1, d1, d2);
  mpfi_sqrt(d1, d1);
  mpfi_div(r, t2, d1);
  mpfi_mul(r, r, K.x);
  mpfi_mul(r, r, K.s1mx2);
}

}  // namespace gyrores
