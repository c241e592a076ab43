// include/gyrores/certify/theorem_bracket.hpp: the proof of a bracket of u* (steps 1-3 there).
#include <gyrores/certify/theorem_bracket.hpp>

#include <arb.h>

#include <gyrores/core/real.hpp>
#include <gyrores/inscribed/lattice_theorem.hpp>

namespace gyrores {

namespace {

using fr = fixed_mpfr;
using iv = fixed_mpfi;

using constants = theorem_constants;

}  // namespace

void set_theorem_constants(constants& K, const resonant_pair<big_int>& p) {
  const int m = p.strand_offset_min();
  const big_int a = p.order(), b = big_int(p.delta()), ts = big_int(p.tau() * p.sigma());
  mpfi_set_z(K.a, a.backend().data());
  mpfi_set_z(K.x, b.backend().data());
  mpfi_div(K.x, K.x, K.a);
  mpfi_sqr(K.x2, K.x);
  mpfi_set_z(K.sqrt_ts, ts.backend().data());
  mpfi_sqrt(K.sqrt_ts, K.sqrt_ts);
  mpfi_mul_ui(K.s1mx2, K.sqrt_ts, 2);
  mpfi_div(K.s1mx2, K.s1mx2, K.a);
  mpfi_const_pi(K.pi);
  mpfi_mul_si(K.mu, K.pi, m);
  mpfi_div(K.mu, K.mu, K.a);
  mpfi_div_ui(K.mu, K.mu, 2);
}

namespace {

// tan(c + d) from tc = tan c and d, points (Newton: the d^5 remainder is below the precision).
// td, den: scratch.
void tan_shift_point(fr& out, mpfr_srcptr tc, mpfr_srcptr d, fr& td, fr& den) {
  mpfr_sqr(td, d, MPFR_RNDN);
  mpfr_mul(td, td, d, MPFR_RNDN);
  mpfr_div_ui(td, td, 3, MPFR_RNDN);
  mpfr_add(td, td, d, MPFR_RNDN);
  mpfr_mul(den, tc, td, MPFR_RNDN);
  mpfr_ui_sub(den, 1, den, MPFR_RNDN);
  mpfr_add(out, tc, td, MPFR_RNDN);
  mpfr_div(out, out, den, MPFR_RNDN);
}

// Temporaries of tan_shift, allocated once per precision.
struct shift_scratch {
  explicit shift_scratch(mpfr_prec_t p) : td(p), r(p), den(p), m(p), m2(p), mneg(p) {}
  iv td, r, den;
  fr m, m2, mneg;
};

// tan(c + d) for every d in D (|D| <= 1/4) and tan c in TC: (TC + TD)/(1 - TC TD) with
// TD = D + D^3/3 + [-1, 1] |D|^5/7 (the header comment).
void tan_shift(iv& out, const iv& tc, const iv& d, shift_scratch& s) {
  auto& [td, r, den, m, m2, mneg] = s;
  mpfi_mag(m, d);  // max |d| (exact: an endpoint's absolute value)
  mpfr_sqr(m2, m, MPFR_RNDU);
  mpfr_sqr(m2, m2, MPFR_RNDU);
  mpfr_mul(m, m, m2, MPFR_RNDU);
  mpfr_div_ui(m, m, 7, MPFR_RNDU);
  mpfr_neg(mneg, m, MPFR_RNDN);
  mpfi_interv_fr(r, mneg, m);
  mpfi_set(td, d);
  mpfi_mul(td, td, d);
  mpfi_mul(td, td, d);
  mpfi_div_ui(td, td, 3);
  mpfi_add(td, td, d);
  mpfi_add(td, td, r);
  mpfi_mul(den, tc, td);
  mpfi_ui_sub(den, 1, den);
  mpfi_add(out, tc, td);
  mpfi_div(out, out, den);
}

// Arb's error for a small argument |v| ~ 2^-k is not relative to v: k more bits keep the
// result as accurate, relatively, as the argument (without them the ball of tan(mu - x c) for
// (10^18+1, 10^18), w ~ 2^-61, came out 2^19 times wider than W, the bracket proof failed and
// the certificate redid everything at twice the bits: 3x the cost).
mpfr_prec_t small_argument_bits(mpfr_srcptr v) {
  return !mpfr_zero_p(v) && mpfr_get_exp(v) < 0 ? -mpfr_get_exp(v) : 0;
}

// out = an enclosure of tan over W (inside (-pi/2, pi/2)): Arb's arb_tan of the ball holding W
// (rigorous, and about 3 times cheaper than one MPFR tangent at these precisions), turned into
// an interval rounded outward. False if Arb's ball is not finite (W too close to a pole).
bool tan_enclosure(iv& out, const iv& W) {
  const mpfr_prec_t prec = mpfi_get_prec(out);
  const mpfr_prec_t extra = small_argument_bits(W.left());
  arb_t w, t;
  arb_init(w);
  arb_init(t);
  arb_set_interval_mpfr(w, W.left(), W.right(), prec + 8 + extra);
  arb_tan(t, w, prec + 8 + extra);
  const bool ok = arb_is_finite(t);
  if (ok) {
    fr lo(prec), hi(prec);
    arb_get_interval_mpfr(lo, hi, t);
    mpfi_interv_fr(out, lo, hi);
  }
  arb_clear(w);
  arb_clear(t);
  return ok;
}

// out ~ tan(v) at out's precision, for the Newton ladder's centres (no proof needed there):
// the midpoint of Arb's ball, about 3 times cheaper than mpfr_tan at these precisions.
void tan_point(fr& out, mpfr_srcptr v) {
  const mpfr_prec_t prec = mpfr_get_prec(out);
  const mpfr_prec_t extra = small_argument_bits(v);
  arb_t w, t;
  arb_init(w);
  arb_init(t);
  arf_set_mpfr(arb_midref(w), v);
  arb_tan(t, w, prec + 8 + extra);
  arf_get_mpfr(out, arb_midref(t), MPFR_RNDN);
  arb_clear(w);
  arb_clear(t);
}

// Newton on f(u) = tan(mu - x u) - x tan u about the centre c (a point at `prec`), from u
// accurate to about `acc` bits: as many steps as doublings up to prec (the proof that follows
// checks the result), fewer if a step is already below 2^-(prec - 6) |u|.
void newton_about(fr& u, mpfr_srcptr c, mpfr_srcptr tc, mpfr_srcptr wc_tan, mpfr_srcptr x, mpfr_prec_t prec,
                  unsigned acc) {
  fr d(prec), e(prec), tu(prec), tw(prec), f(prec), df(prec), t(prec), s1(prec), s2(prec);
  int steps = 1;
  for (unsigned a = acc; 2 * a < unsigned(prec); a *= 2) ++steps;
  for (int it = 0; it < steps; ++it) {
    mpfr_sub(d, u, c, MPFR_RNDN);
    tan_shift_point(tu, tc, d, s1, s2);
    mpfr_mul(e, x, d, MPFR_RNDN);
    mpfr_neg(e, e, MPFR_RNDN);
    tan_shift_point(tw, wc_tan, e, s1, s2);
    mpfr_mul(f, x, tu, MPFR_RNDN);
    mpfr_sub(f, tw, f, MPFR_RNDN);
    // f' = -x (1 + tan^2 w) - x (1 + tan^2 u)
    mpfr_sqr(df, tw, MPFR_RNDN);
    mpfr_sqr(t, tu, MPFR_RNDN);
    mpfr_add(df, df, t, MPFR_RNDN);
    mpfr_add_ui(df, df, 2, MPFR_RNDN);
    mpfr_mul(df, df, x, MPFR_RNDN);
    mpfr_div(f, f, df, MPFR_RNDN);
    mpfr_add(u, u, f, MPFR_RNDN);  // u - f/f', f' = -df
    mpfr_mul_2si(t, u, -int(prec) + 6, MPFR_RNDN);
    if (mpfr_cmpabs(f, t) <= 0) return;
  }
}

// u* to about `bits` bits, starting from the scout (accurate to about `acc` bits): a ladder of
// centres. On return tc, wc hold enclosures of tan c and tan(mu - x c) at the last centre c;
// false if they could not be formed.
bool root_ladder(fr& u, fr& c, iv& tc, iv& wc, const constants& K, unsigned acc) {
  const mpfr_prec_t bits = K.prec;
  fr x(bits), mu(bits), t(bits), w(bits);
  mpfi_mid(x, K.x);
  mpfi_mid(mu, K.mu);
  while (true) {
    const mpfr_prec_t level = std::min<mpfr_prec_t>(bits, mpfr_prec_t(4) * acc);
    mpfr_set(c, u, MPFR_RNDN);  // the centre (u is already at `bits`)
    if (level < bits) {
      fr cl(level), tl(level), wl(level), xl(level), ul(level);
      mpfr_set(cl, c, MPFR_RNDN);
      mpfr_set(ul, u, MPFR_RNDN);
      mpfr_set(xl, x, MPFR_RNDN);
      tan_point(tl, cl);
      mpfr_mul(wl, xl, cl, MPFR_RNDN);
      mpfr_sub(wl, mu, wl, MPFR_RNDN);
      tan_point(wl, wl);
      newton_about(ul, cl, tl, wl, xl, level, acc);
      mpfr_set(u, ul, MPFR_RNDN);
      acc = unsigned(level) - 8;
      continue;
    }
    // The last centre: enclosures for the proof, and the Newton steps from their midpoints.
    iv C(bits), W(bits);
    mpfi_set_fr(C, c);
    mpfi_mul(W, K.x, C);
    mpfi_sub(W, K.mu, W);
    if (!tan_enclosure(tc, C) || !tan_enclosure(wc, W)) return false;
    mpfi_mid(t, tc);
    mpfi_mid(w, wc);
    newton_about(u, c, t, w, x, bits, acc);
    return true;
  }
}

}  // namespace

bool theorem_centre_of(theorem_centre& z, const constants& K, const resonant_pair<big_int>& p) {
  unsigned acc = 50;
  const big_int a = p.order(), b = big_int(p.delta());
  const int m = p.strand_offset_min();
  if (a < (big_int(1) << 900)) {
    auto [x, mu] = detail::theorem_x_mu<double>(a, b, m);
    mpfr_set_d(z.u, detail::theorem_root_scout(x, mu), MPFR_RNDN);
  } else {
    scoped_digits d(20);
    auto [x, mu] = detail::theorem_x_mu<mpfr_real>(a, b, m);
    const mpfr_real scout = detail::theorem_root_scout(x, mu);  // named: backend() of a temporary is moved from
    mpfr_set(z.u, scout.backend().data(), MPFR_RNDN);
    acc = 56;
  }
  return root_ladder(z.u, z.c, z.tc, z.wc, K, acc);
}

namespace {

// tan u and tan(mu - x u) over the interval U (within 2^-10 of the centre; false otherwise), by
// the addition formula about the centre.
bool bracket_end(const constants& K, const theorem_centre& z, const iv& U, shift_scratch& sc, iv& tu, iv& tw) {
  iv d(K.prec), e(K.prec);
  fr dmax(K.prec);
  mpfi_sub_fr(d, U, z.c);
  mpfi_mag(dmax, d);
  if (mpfr_cmp_d(dmax, 0x1p-10) > 0) return false;
  tan_shift(tu, z.tc, d, sc);
  mpfi_mul(e, K.x, d);
  mpfi_neg(e, e);
  tan_shift(tw, z.wc, e, sc);
  return true;
}

}  // namespace

bool prove_theorem_bracket(const constants& K, const theorem_centre& z, const iv& lo, const iv& hi, iv& T) {
  const mpfr_prec_t bits = K.prec;
  iv tu(bits), tw(bits), half_pi(bits);
  mpfi_div_ui(half_pi, K.pi, 2);
  if (mpfr_sgn(lo.left()) <= 0 || mpfr_cmp(hi.right(), half_pi.left()) >= 0) return false;
  shift_scratch sc(bits);
  // x tan lo < tan(mu - x lo) and x tan hi > tan(mu - x hi), each side bounded the safe way.
  if (!bracket_end(K, z, lo, sc, tu, tw)) return false;
  mpfi_set(T, tu);
  mpfi_mul(tu, tu, K.x);
  if (!(mpfr_cmp(tu.right(), tw.left()) < 0)) return false;
  if (!bracket_end(K, z, hi, sc, tu, tw)) return false;
  mpfi_put(T, tu);
  mpfi_mul(tu, tu, K.x);
  return mpfr_cmp(tu.left(), tw.right()) > 0;
}

void theorem_radius(iv& r, const constants& K, const iv& T) {
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
