// The producer of lattice-theorem certificates (certify/theorem_certificate.hpp). At a working
// precision of `bits` (doubled until every claim has the digits asked for):
//
//  1. u* by Newton on f(u) = tan(mu - x u) - x tan u, whose root in (0, pi/2) is the root of
//     H(u) = x u + arctan(x tan u) = mu (below). Near a centre c every tangent comes from tan c,
//     tan(mu - x c) and the addition formula tan(c + d) = (tan c + tan d)/(1 - tan c tan d),
//     tan d = d + d^3/3 + r: two MPFR tangents per centre, the centres on a ladder of
//     precisions (each level at most 4 times the accuracy of its centre, so |d|^5 is below it).
//  2. The decimal bracket [lo, hi] of u*, proved: H(lo) < mu < H(hi). For 0 < u < pi/2 the angle
//     w = mu - x u lies in (-pi/2, pi/2) (mu = pi m/(2a) <= pi/3, x u < pi/2) where tan
//     increases, so H(u) < mu iff arctan(x tan u) < w iff x tan u < tan w. Both sides are
//     enclosed in MPFI from enclosures of tan c and tan(mu - x c), the addition formula, and the
//     remainder |r| <= |d|^5/7 for |d| <= 1/4 (tan's Taylor coefficients are positive, so
//     0 <= r <= d^5 (tan(1/4) - 1/4 - 1/192) 4^4 < 0.137 d^5 for d >= 0; r is odd).
//  3. r_res = sqrt(G(u*)) with sqrt(G) = x sqrt(1-x^2) t^2/sqrt((1 + t^2)(1 + x^2 t^2)),
//     t = tan u, increasing in t: enclosed over tan([lo, hi]) = [tan lo, tan hi] from step 2;
//     theta_first = 2 (k pi + sign(m) u*)/a and t_first = sqrt(tau sigma) theta_first.
#include <gyrores/certify/theorem_certificate.hpp>

#include <gyrores/certify/certificate.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/interval.hpp>
#include <gyrores/inscribed/lattice_theorem.hpp>

namespace gyrores {

namespace {

using fr = fixed_mpfr;
using iv = fixed_mpfi;

// The pair's constants as intervals at one precision.
struct constants {
  explicit constants(mpfr_prec_t p) : prec(p), a(p), x(p), x2(p), s1mx2(p), sqrt_ts(p), pi(p), mu(p) {}
  mpfr_prec_t prec;
  iv a, x, x2, s1mx2, sqrt_ts, pi, mu;  // a, b/a, x^2, sqrt(1-x^2) = 2 sqrt(tau sigma)/a, sqrt(tau sigma), pi, pi m/(2a)
};

void set_constants(constants& K, const resonant_pair<big_int>& p, int m) {
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

// out = an enclosure of tan over W (inside (-pi/2, pi/2), width Delta tiny) from one MPFR
// tangent: t = tan(w_lo) rounded down; with M = 1 + (|t+| + 1)^2, t+ the float above t, and
// Delta M <= 1/2, tan stays below t+ + 1 on W (it cannot reach t+ + 1 while its slope
// sec^2 = 1 + tan^2 is below M), so tan(w_hi) <= t+ + Delta M by the mean value theorem.
// False (nothing proved) when Delta M > 1/2.
bool tan_enclosure(iv& out, const iv& W) {
  const mpfr_prec_t prec = mpfi_get_prec(out);
  fr lo(prec), up(prec), delta(prec), m(prec);
  mpfr_tan(lo, W.left(), MPFR_RNDD);
  mpfr_set(up, lo, MPFR_RNDN);
  mpfr_nextabove(up);
  mpfr_sub(delta, W.right(), W.left(), MPFR_RNDU);
  mpfr_abs(m, up, MPFR_RNDN);
  mpfr_add_ui(m, m, 1, MPFR_RNDU);
  mpfr_sqr(m, m, MPFR_RNDU);
  mpfr_add_ui(m, m, 1, MPFR_RNDU);
  mpfr_mul(m, m, delta, MPFR_RNDU);
  if (mpfr_cmp_d(m, 0.5) > 0) return false;
  mpfr_add(up, up, m, MPFR_RNDU);
  mpfi_interv_fr(out, lo, up);
  return true;
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
      mpfr_tan(tl, cl, MPFR_RNDN);
      mpfr_mul(wl, xl, cl, MPFR_RNDN);
      mpfr_sub(wl, mu, wl, MPFR_RNDN);
      mpfr_tan(wl, wl, MPFR_RNDN);
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

// A number as Boost's mpfr_real (the current default precision, at least its own), for decimal text.
mpfr_real boost_real(const fr& x) {
  mpfr_real r;
  mpfr_set(r.backend().data(), x, MPFR_RNDN);
  return r;
}

// out = an enclosure of the decimal number `text`: the nearest float and its two neighbours
// (one conversion instead of two directed ones).
bool decimal_enclosure(iv& out, const std::string& text) {
  const mpfr_prec_t prec = mpfi_get_prec(out);
  fr lo(prec), hi(prec);
  if (mpfr_set_str(lo, text.c_str(), 10, MPFR_RNDN) != 0) return false;
  mpfr_set(hi, lo, MPFR_RNDN);
  mpfr_nextbelow(lo);
  mpfr_nextabove(hi);
  mpfi_interv_fr(out, lo, hi);
  return true;
}

// The decimal bracket of u* at the working precision, proved (step 2 of the header comment);
// T receives tan([lo, hi]) and U the interval [lo, hi]. Empty when not proved here.
std::pair<std::string, std::string> bracket_u_star(const resonant_pair<big_int>& p, const constants& K,
                                                   unsigned text_digits, iv& T, iv& U) {
  const mpfr_prec_t bits = K.prec;
  fr u(bits), c(bits);
  unsigned acc = 50;
  const big_int a = p.order(), b = big_int(p.delta());
  const int m = p.strand_offset_min();
  if (a < (big_int(1) << 900)) {
    auto [x, mu] = detail::theorem_x_mu<double>(a, b, m);
    mpfr_set_d(u, detail::theorem_root_scout(x, mu), MPFR_RNDN);
  } else {
    scoped_digits d(20);
    auto [x, mu] = detail::theorem_x_mu<mpfr_real>(a, b, m);
    const mpfr_real scout = detail::theorem_root_scout(x, mu);  // named: backend() of a temporary is moved from
    mpfr_set(u, scout.backend().data(), MPFR_RNDN);
    acc = 56;
  }
  iv tc(bits), wc(bits);
  if (!root_ladder(u, c, tc, wc, K, acc)) return {};
  fr rad(bits), end(bits);
  mpfr_abs(rad, u, MPFR_RNDN);
  mpfr_mul_2si(rad, rad, -int(bits) + 16, MPFR_RNDN);
  std::pair<std::string, std::string> text;
  mpfr_sub(end, u, rad, MPFR_RNDD);
  text.first = format_scientific(boost_real(end), text_digits, MPFR_RNDD);
  mpfr_add(end, u, rad, MPFR_RNDU);
  text.second = format_scientific(boost_real(end), text_digits, MPFR_RNDU);
  iv lo(bits), hi(bits), d(bits), e(bits), tu(bits), tw(bits), half_pi(bits);
  if (!decimal_enclosure(lo, text.first) || !decimal_enclosure(hi, text.second)) return {};
  mpfi_div_ui(half_pi, K.pi, 2);
  if (mpfr_sgn(lo.left()) <= 0 || mpfr_cmp(hi.right(), half_pi.left()) >= 0) return {};
  fr dmax(bits);
  shift_scratch sc(bits);
  // x tan lo < tan(mu - x lo): the upper bound of the left below the lower bound of the right.
  mpfi_sub_fr(d, lo, c);
  mpfi_mag(dmax, d);
  if (mpfr_cmp_d(dmax, 0x1p-10) > 0) return {};
  tan_shift(tu, tc, d, sc);
  mpfi_mul(e, K.x, d);
  mpfi_neg(e, e);
  tan_shift(tw, wc, e, sc);
  mpfi_set(T, tu);
  mpfi_mul(tu, tu, K.x);
  if (!(mpfr_cmp(tu.right(), tw.left()) < 0)) return {};
  // x tan hi > tan(mu - x hi).
  mpfi_sub_fr(d, hi, c);
  mpfi_mag(dmax, d);
  if (mpfr_cmp_d(dmax, 0x1p-10) > 0) return {};
  tan_shift(tu, tc, d, sc);
  mpfi_mul(e, K.x, d);
  mpfi_neg(e, e);
  tan_shift(tw, wc, e, sc);
  mpfi_put(T, tu);
  mpfi_mul(tu, tu, K.x);
  if (!(mpfr_cmp(tu.left(), tw.right()) > 0)) return {};
  mpfi_union(U, lo, hi);
  return text;
}

// sqrt(G) over T = tan(U) (step 3 of the header comment).
void radius_of(iv& r, const constants& K, const iv& T) {
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

// An interval as Boost's mpfi_real (at the current default precision), for the decimal output.
mpfi_real boost_interval(const iv& x) {
  mpfi_real r;
  mpfi_set(r.backend().data(), x);
  return r;
}

}  // namespace

theorem_certificate certify_by_theorem(const resonant_pair<big_int>& p, unsigned digits, unsigned max_bits) {
  if (digits < 1 || digits > 10000) throw usage_error("digits must be in [1, 10000], got " + std::to_string(digits));
  theorem_certificate c;
  c.theorem = lattice_theorem_id;
  c.tau = p.tau();
  c.sigma = p.sigma();
  c.digits = digits;
  c.m_min = p.strand_offset_min();
  const big_int a = p.order(), b = big_int(p.delta());
  c.lobes = minimiser_lobes(a, b);
  const auto& first = c.lobes.front();
  // Relative width of each claim: at most 2^-e <= 10^-(digits + 1).
  const int e = int(digits10_to_bits(digits + 1));
  for (unsigned bits = std::max(64u, digits10_to_bits(digits) + 24); bits <= max_bits; bits *= 2) {
    scoped_digits sd(digits10_for_bits(bits));
    // Written digits: claims digits + 10 (outward rounding adds at most 2 10^-(digits+9) to a
    // width below 10^-(digits+1)); the bracket the digits the precision carries less 2 (its
    // radius, 2^-(bits-16) relative, is 10^3 times larger), far inside what the claims need.
    const unsigned d = digits + 10;
    constants K(bits);
    set_constants(K, p, c.m_min);
    iv T(bits), U(bits), r(bits), theta(bits), t(bits);
    if (c.m_min == 0) {
      c.u_star = {"0", "0"};
      mpfi_set_ui(U, 0);
    } else {
      c.u_star = bracket_u_star(p, K, bits_to_digits10(bits) - 2, T, U);
      if (c.u_star.first.empty()) continue;
      radius_of(r, K, T);
      if (!fixed_narrow(r, e)) continue;
    }
    // theta = 2 (k pi + sign(m) U)/a, 0 <= k < a.
    iv k(bits);
    mpfi_set_z(k, big_int(first.k).backend().data());
    mpfi_mul(theta, K.pi, k);
    if (first.m < 0) mpfi_sub(theta, theta, U);
    else mpfi_add(theta, theta, U);
    mpfi_mul_ui(theta, theta, 2);
    mpfi_div(theta, theta, K.a);
    mpfi_mul(t, K.sqrt_ts, theta);
    if (!fixed_narrow(theta, e) || !fixed_narrow(t, e)) continue;
    c.bits = bits;
    c.r_res = c.m_min == 0 ? std::pair<std::string, std::string>{"0", "0"} : interval_to_decimal(boost_interval(r), d);
    c.theta_first = interval_to_decimal(boost_interval(theta), d);
    c.t_first = interval_to_decimal(boost_interval(t), d);
    return c;
  }
  throw compute_error("certify: " + p.str() + " did not reach " + std::to_string(digits) + " digits within " +
                      std::to_string(max_bits) + " bits");
}

certified_enclosures certify_enclosures(const resonant_pair<big_int>& p, unsigned digits, const std::string& qdot0) {
  theorem_certificate c = certify_by_theorem(p, digits);
  certified_enclosures out{c.theorem, c.r_res, c.theta_first, c.t_first};
  scoped_digits sd(digits + 30);
  mpfi_real v = interval_from_decimal(qdot0, qdot0);
  if (!certainly_positive(v)) throw usage_error("qdot0 must be a decimal number > 0, got '" + qdot0 + "'");
  if (interval_lower(v) == 1 && interval_upper(v) == 1) return out;
  out.r_res = interval_to_decimal(interval_from_decimal(c.r_res.first, c.r_res.second) * v, digits + 10);
  return out;
}

}  // namespace gyrores
