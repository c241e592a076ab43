// The producer of lattice-theorem certificates (certify/theorem_certificate.hpp). At a working
// precision of `bits` (doubled, core/refine.hpp, until every claim has the digits asked for): the
// decimal bracket of u*, proved together with its decimals by the one solver of theorem/root.hpp
// (the Newton ladder, two Arb tangents at its last centre, the bracket by the mean value form; no
// arctangent), r_res over tan of an interval holding it, theta_first = 2 (k pi + sign(m) u*)/a and
// t_first = sqrt(tau sigma) theta_first in MPFI.
#include <gyrores/certify/theorem_certificate.hpp>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/refine.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

theorem_certificate certify_by_theorem(const resonant_pair<big_int>& p, unsigned digits, unsigned max_bits,
                                       stop_token stop) {
  check_report_digits(digits);
  theorem_certificate c;
  c.theorem = lattice_theorem_id;
  c.tau = p.tau();
  c.sigma = p.sigma();
  c.digits = digits;
  c.m_min = p.strand_offset_min();
  const big_int a = p.order();
  c.lobes = minimiser_lobes_big(a, big_int(p.delta())).to_vector();
  const auto& first = c.lobes.front();
  // Relative width of each claim: at most 2^-e <= 10^-(digits + 1).
  const int e = int(digits10_to_bits(digits + 1));
  const precision_plan plan{mpfr_prec_t(std::max(64u, digits10_to_bits(digits) + 24)), mpfr_prec_t(max_bits)};
  refine(plan, stop, "certify: " + p.str() + " to " + std::to_string(digits) + " digits", [&](mpfr_prec_t bits, proof_status& status) {
    // Written digits: claims digits + 10 (outward rounding adds at most 2 10^-(digits+9) to a
    // width below 10^-(digits+1)); the bracket of u* digits + 5, what the claims need: u*'s
    // interval is the binary bracket, relative width 2^-(bits-17) <= 2^-(e+3), widened by
    // 2^-(e+8) for the decimals (theorem/root.hpp, step 2: the decimals are proved with the
    // bracket, never read back), and the claims amplify a relative width at most 4 times
    // (u* <= pi/4: d log sqrt(G)/d log u <= 2 u (1 + tan^2 u)/tan u < 4; theta_first and t_first
    // at most 1 time), so they come out within 2^-e.
    const unsigned d = digits + 10;
    theorem_constants K(bits, p);
    root_enclosure z(bits);
    fixed_mpfi r(bits), theta(bits), t(bits);
    const auto wide = proof_status::undecided("a claim is wider than the digits at this precision");
    if (c.m_min == 0) {
      c.u_star = {"0", "0"};
      mpfi_set_ui(z.U, 0);
    } else {
      status = prove_theorem_root(z, K, big_int(c.m_min), digits + 5);
      if (status && z.decimals == 0) status = proof_status::undecided("u*'s decimal ends");
      if (!status) return std::optional<bool>();
      c.u_star = {format_scientific(z.lo, digits + 5, MPFR_RNDD), format_scientific(z.hi, digits + 5, MPFR_RNDU)};
      theorem_radius(r, K, z.T);
      if (!fixed_narrow(r, e)) status = wide;
    }
    minimiser_theta(theta, K, a, first, z.U);  // 2 (k pi + sign(m) U)/a
    mpfi_mul(t, K.sqrt_ts, theta);
    if (!fixed_narrow(theta, e) || !fixed_narrow(t, e)) status = wide;
    if (!status) return std::optional<bool>();
    c.bits = unsigned(bits);
    c.r_res = c.m_min == 0 ? std::pair<std::string, std::string>{"0", "0"} : enclosure(r).outward(d);
    c.theta_first = enclosure(theta).outward(d);
    c.t_first = enclosure(t).outward(d);
    return std::optional<bool>(true);
  });
  return c;
}

}  // namespace gyrores
