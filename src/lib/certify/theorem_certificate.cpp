// The producer of lattice-theorem certificates (certify/theorem_certificate.hpp). At a working
// precision of `bits` (doubled until every claim has the digits asked for): u* and the proof of
// a decimal bracket of it by theorem/root.hpp (tangents from two Arb balls and the addition
// formula, no arctangent), r_res over tan of the bracket, theta_first =
// 2 (k pi + sign(m) u*)/a and t_first = sqrt(tau sigma) theta_first in MPFI.
#include <gyrores/certify/theorem_certificate.hpp>

#include <gyrores/core/error.hpp>
#include <gyrores/core/decimal.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

namespace {

using fr = fixed_mpfr;
using iv = fixed_mpfi;

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

// The decimal bracket of u* at the working precision, proved (theorem/root.hpp, step 2);
// T receives tan([lo, hi]) and U the interval [lo, hi]. Empty when not proved here.
std::pair<std::string, std::string> bracket_u_star(const resonant_pair<big_int>& p, const theorem_constants& K,
                                                   unsigned text_digits, iv& T, iv& U) {
  const mpfr_prec_t bits = K.prec;
  root_enclosure z(bits);
  if (!theorem_centre_of(z, K, big_int(p.strand_offset_min()))) return {};
  fr rad(bits), end(bits);
  mpfr_abs(rad, z.u, MPFR_RNDN);
  mpfr_mul_2si(rad, rad, -int(bits) + 16, MPFR_RNDN);
  std::pair<std::string, std::string> text;
  mpfr_sub(end, z.u, rad, MPFR_RNDD);
  text.first = format_scientific(end, text_digits, MPFR_RNDD);
  mpfr_add(end, z.u, rad, MPFR_RNDU);
  text.second = format_scientific(end, text_digits, MPFR_RNDU);
  iv lo(bits), hi(bits);
  if (!decimal_enclosure(lo, text.first) || !decimal_enclosure(hi, text.second)) return {};
  if (!prove_theorem_bracket(K, z, lo, hi, T)) return {};
  mpfi_union(U, lo, hi);
  return text;
}

// [lo, hi] of an enclosure as decimal text with `digits` digits, rounded outward.
std::pair<std::string, std::string> outward_text(const iv& x, unsigned digits) {
  return {format_scientific(x.left(), digits, MPFR_RNDD), format_scientific(x.right(), digits, MPFR_RNDU)};
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
  c.lobes = minimiser_lobes(a, b).to_vector();
  const auto& first = c.lobes.front();
  // Relative width of each claim: at most 2^-e <= 10^-(digits + 1).
  const int e = int(digits10_to_bits(digits + 1));
  for (unsigned bits = std::max(64u, digits10_to_bits(digits) + 24); bits <= max_bits; bits *= 2) {
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
    minimiser_theta(theta, K, a, first, U);  // 2 (k pi + sign(m) U)/a
    mpfi_mul(t, K.sqrt_ts, theta);
    if (!fixed_narrow(theta, e) || !fixed_narrow(t, e)) continue;
    c.bits = bits;
    c.r_res = c.m_min == 0 ? std::pair<std::string, std::string>{"0", "0"} : outward_text(r, d);
    c.theta_first = outward_text(theta, d);
    c.t_first = outward_text(t, d);
    return c;
  }
  throw compute_error("certify: " + p.str() + " did not reach " + std::to_string(digits) + " digits within " +
                      std::to_string(max_bits) + " bits");
}

}  // namespace gyrores
