// The producer of lattice-theorem certificates (certify/theorem_certificate.hpp). At a working
// precision of `bits` (doubled until every claim has the digits asked for): u* and the proof of
// a decimal bracket of it by certify/theorem_bracket.hpp (tangents from two Arb balls and the
// addition formula, no arctangent), r_res over tan of the bracket, theta_first =
// 2 (k pi + sign(m) u*)/a and t_first = sqrt(tau sigma) theta_first in MPFI.
#include <gyrores/certify/theorem_certificate.hpp>

#include <gyrores/certify/certificate.hpp>
#include <gyrores/certify/theorem_bracket.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/interval.hpp>
#include <gyrores/inscribed/lattice_theorem.hpp>

namespace gyrores {

namespace {

using fr = fixed_mpfr;
using iv = fixed_mpfi;

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

// The decimal bracket of u* at the working precision, proved (theorem_bracket.hpp, step 2);
// T receives tan([lo, hi]) and U the interval [lo, hi]. Empty when not proved here.
std::pair<std::string, std::string> bracket_u_star(const resonant_pair<big_int>& p, const theorem_constants& K,
                                                   unsigned text_digits, iv& T, iv& U) {
  const mpfr_prec_t bits = K.prec;
  theorem_centre z(bits);
  if (!theorem_centre_of(z, K, p)) return {};
  fr rad(bits), end(bits);
  mpfr_abs(rad, z.u, MPFR_RNDN);
  mpfr_mul_2si(rad, rad, -int(bits) + 16, MPFR_RNDN);
  std::pair<std::string, std::string> text;
  mpfr_sub(end, z.u, rad, MPFR_RNDD);
  text.first = format_scientific(boost_real(end), text_digits, MPFR_RNDD);
  mpfr_add(end, z.u, rad, MPFR_RNDU);
  text.second = format_scientific(boost_real(end), text_digits, MPFR_RNDU);
  iv lo(bits), hi(bits);
  if (!decimal_enclosure(lo, text.first) || !decimal_enclosure(hi, text.second)) return {};
  if (!prove_theorem_bracket(K, z, lo, hi, T)) return {};
  mpfi_union(U, lo, hi);
  return text;
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
    theorem_constants K(bits);
    set_theorem_constants(K, p);
    iv T(bits), U(bits), r(bits), theta(bits), t(bits);
    if (c.m_min == 0) {
      c.u_star = {"0", "0"};
      mpfi_set_ui(U, 0);
    } else {
      c.u_star = bracket_u_star(p, K, bits_to_digits10(bits) - 2, T, U);
      if (c.u_star.first.empty()) continue;
      theorem_radius(r, K, T);
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
