// The band certificates of certify/band_certificate.hpp, from the band proofs' covers
// (theorem/band.hpp, record_cover) and the attaining couplings' horizon proofs.
#include <gyrores/certify/band_certificate.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

// The exact decimal text of a rational that is a terminating decimal (as decimal_rounded gives).
std::string exact_decimal(const big_rational& q) {
  if (q == 0) return "0";
  for (unsigned d = 1; d <= 400; ++d) {
    bool exact = false;
    std::string s = format_rational_scientific(q, d, &exact);
    if (exact) return s;
  }
  throw compute_error("band certificate: a bound is not a short decimal");
}

big_rational ten_to_minus(unsigned e) { return big_rational(big_int(1), boost::multiprecision::pow(big_int(10), e)); }

// A bound in R units rounded outward with the relative slack 10^-(digits + 8).
big_rational bound_out(const big_rational& bound, unsigned digits, bool upper) {
  if (bound == 0 && !upper) return 0;
  const unsigned D = digits + 8;
  if (upper) return decimal_rounded(bound * (1 + ten_to_minus(D)), D, +1);
  const big_rational v = decimal_rounded(bound * (1 - ten_to_minus(D)), D, -1);
  return v > 0 ? v : big_rational(0);
}

// The name of a bound kind in the format.
const char* band_bound_kind_name(band_bound_kind kind) {
  switch (kind) {
    case band_bound_kind::lobes: return "lobes";
    case band_bound_kind::line_falling: return "line_falling";
    case band_bound_kind::line_rising: return "line_rising";
    case band_bound_kind::line_turning: return "line_turning";
    case band_bound_kind::line_unproved: return "line_unproved";
    case band_bound_kind::end_point: return "end_point";
  }
  return "?";
}

band_certificate_claim claim_of(const band_extreme& e, const horizon_time& T, unsigned digits, bool absorption) {
  if (e.interrupted) throw compute_error("band certificate: the band proof was interrupted");
  if (e.cover.empty()) throw compute_error("band certificate: the band proof holds no cover (record_cover)");
  band_certificate_claim c;
  c.at = certify_horizon_minimum(e.at.spec, T.value, digits + 4);
  big_rational lo = decimal_rounded(e.value.lo_rational(), digits + 3, -1);
  big_rational hi = decimal_rounded(e.value.hi_rational(), digits + 3, +1);
  if (lo < 0) lo = 0;
  // The attaining coupling's certified minimum is on the claim's side.
  const big_rational h_lo = parse_rational(c.at.h_min.first, "h_min"), h_hi = parse_rational(c.at.h_min.second, "h_min");
  if (absorption && h_lo < lo) lo = h_lo;
  if (!absorption && h_hi > hi) hi = h_hi;
  for (const band_cover_interval& J : e.cover) {
    band_certificate_interval I;
    I.a = J.a.spec.n2;
    I.b = J.b.spec.n2;
    I.kind = band_bound_kind_name(J.kind);
    I.K = J.K;
    // The line's lobe; 0 for the kinds that have none (the checker refuses any other value there:
    // docs/formats.md, a field a kind leaves unused is at its fixed value).
    const bool line = J.kind != band_bound_kind::lobes && J.kind != band_bound_kind::end_point;
    I.k = line ? J.k : big_int(0);
    I.reached = J.reached;
    I.unreached = J.unreached;
    const big_rational b = bound_out(J.bound, digits, absorption);
    I.bound = exact_decimal(b);
    if (absorption && b / 2 > hi) hi = b / 2;
    if (!absorption && b / 2 < lo) lo = b / 2;
    c.cover.push_back(std::move(I));
  }
  c.value = {exact_decimal(lo), exact_decimal(hi)};
  return c;
}

}  // namespace

band_certificate band_certificate_of(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                     unsigned digits, const band_extreme& absorption, const band_extreme& containment) {
  check_certificate_horizon(T, "a band certificate");
  band_certificate out;
  out.theorem = band_theorem_id;
  out.n1 = n1;
  out.n2 = n2;
  out.horizon = T.value;
  out.digits = digits;
  out.absorption = claim_of(absorption, T, digits, true);
  out.containment = claim_of(containment, T, digits, false);
  return out;
}

}  // namespace gyrores
