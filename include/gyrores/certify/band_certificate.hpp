// Certificates of a band's guarantees ("gyrores-band-certificate/1"; proofs/band-theorem.md, id
// band-theorem/1; docs/formats.md): the absorption guarantee W = max over the band of M(n) and the
// containment guarantee B = min over the band of M(n), M(n) = min of R = 2 H_q over [0, T].
//
// What it states, for each guarantee (H_q units in the claims, R units in the bounds):
//   value   [lo, hi] holding the guarantee, exact decimals;
//   at      the coupling whose own minimum gives one side (W >= M(at), B <= M(at)), as a full
//           coupling certificate (certify/horizon_certificate.hpp) of that coupling and T;
//   cover   the intervals [a, b] of n^2 covering the band in order, each with the bound of
//           band-theorem item 4 it took (kind, K, k, reached, unreached) and that bound, rounded
//           outward with a relative slack of 10^-(digits + 8) (so that a checker recomputing it
//           in its own arithmetic lands on the safe side), which gives the other side.
// A certificate is written from the band proofs that were printed (theorem/band.hpp run with
// band_options::record_cover): their covers and enclosures as they are. The attaining couplings'
// certificates are horizon proofs made for a certificate at digits + 4 digits (the band proofs
// evaluate those couplings for a report only); the claims are widened to hold their h_min.
#pragma once
#include <string>
#include <vector>

#include <gyrores/certify/horizon_certificate.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/theorem/band.hpp>

namespace gyrores {

inline constexpr const char* band_certificate_format = "gyrores-band-certificate/1";

struct band_certificate_interval {
  big_rational a, b;  // n^2 at the ends
  std::string kind;   // band_bound_kind's name: lobes, line_falling, ..., end_point
  big_int K, k;
  bool reached = false, unreached = false;
  std::string bound;  // R units, exact decimal (rounded outward with the slack)
};

struct band_certificate_claim {
  decimal_bracket value;  // H_q units
  horizon_certificate at;
  std::vector<band_certificate_interval> cover;
};

struct band_certificate {
  std::string format = band_certificate_format;
  std::string theorem;
  big_rational n1, n2, horizon;
  unsigned digits = 0;
  band_certificate_claim absorption, containment;
};

// The certificate of the two band proofs W and B (made with record_cover) over [n1, n2] and T.
// compute_error when a proof was interrupted or holds no cover.
band_certificate band_certificate_of(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                     unsigned digits, const band_extreme& absorption, const band_extreme& containment);

}  // namespace gyrores
