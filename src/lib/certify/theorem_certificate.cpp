// The producer of lattice-theorem certificates (certify/theorem_certificate.hpp): the integer
// facts, then, at increasing precision, a proof by directed rounding that the decimal bracket of
// u* holds and MPFI enclosures of the claims it implies, until every claim has the digits asked
// for.
#include <gyrores/certify/theorem_certificate.hpp>

#include <gyrores/certify/certificate.hpp>
#include <gyrores/certify/proof_steps.hpp>  // meets_digits
#include <gyrores/core/error.hpp>
#include <gyrores/inscribed/lattice_theorem.hpp>

namespace gyrores {

namespace {

using proof::I;
using proof::P;

// What the enclosures need, as intervals at the current precision.
struct constants {
  I x, s1mx2, sqrt_ts, pi, a;
};

constants constants_of(const resonant_pair<big_int>& p) {
  constants K;
  K.a = real_from_int<I>(p.order());
  K.x = real_from_int<I>(big_int(p.delta())) / K.a;
  K.sqrt_ts = sqrt(real_from_int<I>(p.tau())) * sqrt(real_from_int<I>(p.sigma()));
  K.s1mx2 = 2 * K.sqrt_ts / K.a;
  K.pi = real_pi<I>();
  return K;
}

// sqrt(G(U)) = x sqrt(1-x^2) sin^2 U/sqrt(cos^2 U + x^2 sin^2 U), U in [0, pi/2).
I radius_of(const constants& K, const I& U) {
  I s2 = interval_sqr(sin(U));
  return K.x * K.s1mx2 * s2 / sqrt(interval_sqr(cos(U)) + interval_sqr(K.x) * s2);
}

// Bounds by directed rounding (cheaper than MPFI, which rounds every operation both ways): on
// u in (0, pi/2) with x in (0, 1) every step of H(u) = x u + atan(x tan u) and of
// mu = pi m/(2a) is increasing in its inputs, so rounding every step down (up) gives a lower
// (upper) bound. big_int inputs are rounded in the direction that keeps the bound.
mpfr_rnd_t opposite(mpfr_rnd_t r) { return r == MPFR_RNDD ? MPFR_RNDU : MPFR_RNDD; }

P int_bound(const big_int& n, mpfr_rnd_t rnd) {
  P r;
  mpfr_set_z(r.backend().data(), n.backend().data(), rnd);
  return r;
}

P h_bound(const big_int& a, const big_int& b, const P& u, mpfr_rnd_t rnd) {
  P x, t, h;
  mpfr_div(x.backend().data(), int_bound(b, rnd).backend().data(), int_bound(a, opposite(rnd)).backend().data(), rnd);
  mpfr_tan(t.backend().data(), u.backend().data(), rnd);
  mpfr_mul(t.backend().data(), t.backend().data(), x.backend().data(), rnd);
  mpfr_atan(t.backend().data(), t.backend().data(), rnd);
  mpfr_mul(h.backend().data(), x.backend().data(), u.backend().data(), rnd);
  mpfr_add(h.backend().data(), h.backend().data(), t.backend().data(), rnd);
  return h;
}

P mu_bound(const big_int& a, int m, mpfr_rnd_t rnd) {
  P mu;
  mpfr_const_pi(mu.backend().data(), rnd);
  mpfr_mul_si(mu.backend().data(), mu.backend().data(), m, rnd);
  mpfr_div(mu.backend().data(), mu.backend().data(), int_bound(2 * a, opposite(rnd)).backend().data(), rnd);
  return mu;
}

// A decimal read rounded in the direction rnd.
P decimal_bound(const std::string& text, mpfr_rnd_t rnd) {
  P r;
  mpfr_set_str(r.backend().data(), text.c_str(), 10, rnd);
  return r;
}

// The decimal bracket of u* at the current precision, proved: H(lo) < mu < H(hi), with the
// bound of H(lo) from above (lo read upwards) and of H(hi) from below (hi read downwards).
// Empty when not proved here.
std::pair<std::string, std::string> bracket_u_star(const resonant_pair<big_int>& p, const constants& K,
                                                   unsigned bits, unsigned text_digits) {
  P u = theorem_root<P>(p, false);
  P rad = abs(u) * pow(P(2), -int(bits) + 16);
  std::pair<std::string, std::string> text{format_scientific(P(u - rad), text_digits, MPFR_RNDD),
                                           format_scientific(P(u + rad), text_digits, MPFR_RNDU)};
  const big_int a = p.order(), b = big_int(p.delta());
  const int m = p.strand_offset_min();
  P lo = decimal_bound(text.first, MPFR_RNDD), hi = decimal_bound(text.second, MPFR_RNDU);
  if (!(lo > 0) || !certainly_less(interval_point(hi), K.pi / 2)) return {};
  if (h_bound(a, b, decimal_bound(text.first, MPFR_RNDU), MPFR_RNDU) < mu_bound(a, m, MPFR_RNDD) &&
      mu_bound(a, m, MPFR_RNDU) < h_bound(a, b, decimal_bound(text.second, MPFR_RNDD), MPFR_RNDD))
    return text;
  return {};
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
  for (unsigned bits = std::max(64u, digits10_to_bits(digits) + 24); bits <= max_bits; bits *= 2) {
    scoped_digits sd(digits10_for_bits(bits));
    // Written digits: claims digits + 10 (outward rounding adds at most 2 10^-(digits+9) to a
    // width below 10^-(digits+1)); the bracket digits + 20, far inside what the claims need.
    const unsigned d = digits + 10;
    const constants K = constants_of(p);
    I U = 0;
    if (c.m_min == 0) {
      c.u_star = {"0", "0"};
    } else {
      c.u_star = bracket_u_star(p, K, bits, digits + 20);
      if (c.u_star.first.empty()) continue;
      U = interval_from_decimal(c.u_star.first, c.u_star.second);
    }
    // One interval evaluation over U: the bracket is far narrower than the claims, so the
    // dependency overestimate does not matter (the checker evaluates at the ends instead).
    I r = c.m_min == 0 ? I(0) : radius_of(K, U);
    I theta = 2 * (K.pi * real_from_int<I>(first.k) + (first.m < 0 ? I(-U) : U)) / K.a;  // 0 <= k < a
    I t = K.sqrt_ts * theta;
    if (c.m_min != 0 && !proof::meets_digits(r, digits + 1)) continue;
    if (!proof::meets_digits(theta, digits + 1) || !proof::meets_digits(t, digits + 1)) continue;
    c.bits = bits;
    c.r_res = c.m_min == 0 ? std::pair<std::string, std::string>{"0", "0"} : interval_to_decimal(r, d);
    c.theta_first = interval_to_decimal(theta, d);
    c.t_first = interval_to_decimal(t, d);
    return c;
  }
  throw compute_error("certify: " + p.str() + " did not reach " + std::to_string(digits) + " digits within " +
                      std::to_string(max_bits) + " bits");
}

certified_enclosures certify_enclosures(const resonant_pair<big_int>& p, unsigned digits, const std::string& qdot0) {
  theorem_certificate c = certify_by_theorem(p, digits);
  certified_enclosures out{c.theorem, c.r_res, c.theta_first, c.t_first};
  scoped_digits sd(digits + 30);
  I v = interval_from_decimal(qdot0, qdot0);
  if (!certainly_positive(v)) throw usage_error("qdot0 must be a decimal number > 0, got '" + qdot0 + "'");
  if (interval_lower(v) == 1 && interval_upper(v) == 1) return out;
  out.r_res = interval_to_decimal(interval_from_decimal(c.r_res.first, c.r_res.second) * v, digits + 10);
  return out;
}

}  // namespace gyrores
