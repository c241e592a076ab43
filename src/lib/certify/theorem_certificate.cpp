// The producer of lattice-theorem certificates (certify/theorem_certificate.hpp): the integer
// facts, then, at increasing precision, an MPFI proof that the decimal bracket of u* holds and
// the claims it implies, until every claim has the digits asked for.
#include <gyrores/certify/theorem_certificate.hpp>

#include <gyrores/certify/certificate.hpp>
#include <gyrores/certify/proof_steps.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/inscribed/lattice_theorem.hpp>

namespace gyrores {

namespace {

using proof::I;
using proof::P;

// H(U) = x U + arctan(x tan U).
I h_of(const proof::constants& K, const I& U) { return K.c.x * U + atan(K.c.x * tan(U)); }

// sqrt(G(U)) = x sqrt(1-x^2) sin^2 U/sqrt(cos^2 U + x^2 sin^2 U), U in [0, pi/2).
I radius_of(const proof::constants& K, const I& U) {
  I s2 = interval_sqr(sin(U));
  return K.c.x * K.c.s1mx2 * s2 / sqrt(interval_sqr(cos(U)) + interval_sqr(K.c.x) * s2);
}

// The decimal bracket of u* at the current precision, proved: H(lo) < mu < H(hi) with lo, hi
// read exactly (each a point interval holding the decimal). Empty when not proved here.
std::pair<std::string, std::string> bracket_u_star(const resonant_pair<big_int>& p, const proof::constants& K,
                                                   unsigned bits, unsigned text_digits) {
  P u = theorem_root<P>(p);
  P rad = abs(u) * pow(P(2), -int(bits) + 16);
  std::pair<std::string, std::string> text{format_scientific(P(u - rad), text_digits, MPFR_RNDD),
                                           format_scientific(P(u + rad), text_digits, MPFR_RNDU)};
  I mu = proof::mu_of(K, big_int(p.strand_offset_min()));
  I lo = interval_from_decimal(text.first, text.first), hi = interval_from_decimal(text.second, text.second);
  if (certainly_positive(lo) && certainly_less(h_of(K, lo), mu) && certainly_less(mu, h_of(K, hi)) &&
      certainly_less(hi, K.c.pi / 2))
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
    auto K = proof::constants_of(p);
    I lo = 0, hi = 0;
    if (c.m_min == 0) {
      c.u_star = {"0", "0"};
    } else {
      c.u_star = bracket_u_star(p, K, bits, digits + 20);
      if (c.u_star.first.empty()) continue;
      lo = interval_from_decimal(c.u_star.first, c.u_star.first);
      hi = interval_from_decimal(c.u_star.second, c.u_star.second);
    }
    // r and theta are monotone in u (theorem, Step C): the hulls of the ends' values.
    I r = c.m_min == 0 ? I(0) : interval_hull(radius_of(K, lo), radius_of(K, hi));
    auto theta_at = [&](const I& u) { return proof::theta_of(K, first.k, first.m < 0 ? I(-u) : u); };
    I theta = interval_hull(theta_at(lo), theta_at(hi));
    I t = K.c.sqrt_ts * theta;
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
