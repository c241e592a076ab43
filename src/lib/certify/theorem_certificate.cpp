// The producer of lattice-theorem certificates (certify/theorem_certificate.hpp). At a working
// precision of `bits` (doubled until every claim has the digits asked for): the decimal bracket
// of u*, written once and proved by theorem/root.hpp (the Newton ladder, two Arb tangents at its
// last centre, the bracket by the mean value form; no arctangent), r_res over tan of an interval
// holding it, theta_first = 2 (k pi + sign(m) u*)/a and t_first = sqrt(tau sigma) theta_first in
// MPFI.
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

// The decimal bracket of u* with n digits, proved in one step at the working precision: about
// the ladder's point u, the binary ends lo, hi = u -+ |u| 2^-(bits - 16) (prove_theorem_root's)
// are rounded outward to n digits once, so u_lo lies in LO = [lo - e, lo] and u_hi in
// HI = [hi, hi + e], e = 2^(exp(hi) - k) >= 10^(1-n) hi (at least a unit in the n-th digit of
// either end), and prove_theorem_bracket proves H(v) < mu for every v in LO and H(v) > mu for
// every v in HI: the decimals themselves, never read back. U receives [lo - e, hi + e], which
// holds the decimal bracket, and T = tan(U). Empty when not proved at this precision.
std::pair<std::string, std::string> bracket_u_star(const resonant_pair<big_int>& p, const theorem_constants& K,
                                                   unsigned n, iv& T, iv& U) {
  const mpfr_prec_t bits = K.prec;
  root_enclosure z(bits);
  if (!theorem_centre_of(z, K, big_int(p.strand_offset_min()))) return {};
  fr rad(bits), lo(bits), hi(bits), unit(bits), end(bits);
  mpfr_abs(rad, z.u, MPFR_RNDN);
  mpfr_mul_2si(rad, rad, -int(bits) + 16, MPFR_RNDU);
  mpfr_sub(lo, z.u, rad, MPFR_RNDD);
  mpfr_add(hi, z.u, rad, MPFR_RNDU);
  std::pair<std::string, std::string> text{format_scientific(lo, n, MPFR_RNDD), format_scientific(hi, n, MPFR_RNDU)};
  const long k = long(digits10_to_bits(n - 1)) - 1;  // < (n - 1) log2 10: 2^-k > 10^(1-n)
  mpfr_set_ui_2exp(unit, 1, mpfr_get_exp(hi) - k, MPFR_RNDU);  // hi < 2^exp(hi)
  iv LO(bits), HI(bits);
  mpfr_sub(end, lo, unit, MPFR_RNDD);
  mpfi_interv_fr(LO, end, lo);
  mpfr_add(end, hi, unit, MPFR_RNDU);
  mpfi_interv_fr(HI, hi, end);
  if (!prove_theorem_bracket(K, z, LO, HI, T)) return {};
  mpfi_union(U, LO, HI);
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
  c.lobes = minimiser_lobes_big(a, b).to_vector();
  const auto& first = c.lobes.front();
  // Relative width of each claim: at most 2^-e <= 10^-(digits + 1).
  const int e = int(digits10_to_bits(digits + 1));
  for (unsigned bits = std::max(64u, digits10_to_bits(digits) + 24); bits <= max_bits; bits *= 2) {
    // Written digits: claims digits + 10 (outward rounding adds at most 2 10^-(digits+9) to a
    // width below 10^-(digits+1)); the bracket of u* digits + 5, what the claims need: u*'s
    // interval is the binary bracket, relative width 2^-(bits-17) <= 2^-(e+3), widened by
    // 2^-(e+8) for the decimals, and the claims amplify a relative width at most 4 times
    // (u* <= pi/4: d log sqrt(G)/d log u <= 2 u (1 + tan^2 u)/tan u < 4; theta_first and t_first
    // at most 1 time), so they come out within 2^-e.
    const unsigned d = digits + 10;
    theorem_constants K(bits);
    set_theorem_constants(K, p);
    iv T(bits), U(bits), r(bits), theta(bits), t(bits);
    if (c.m_min == 0) {
      c.u_star = {"0", "0"};
      mpfi_set_ui(U, 0);
    } else {
      c.u_star = bracket_u_star(p, K, digits + 5, T, U);
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
