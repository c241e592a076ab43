// The independent checker of "gyrores-band-certificate/1" (band-theorem certificates: the
// absorption and containment guarantees over a band of couplings [n1, n2] and a horizon T;
// proofs/band-theorem.md, docs/formats.md).
//
// Independent as horizon_checker.hpp is: it reads the JSON itself, re-proves the attaining
// couplings' minima with check_coupling_certificate, finds every fraction it needs with its own
// Stern-Brocot search (exact comparisons of p/q with x through x^2 = n^2/(n^2 + 4)), every
// rotation minimum F_K with exact_field.hpp's MinFrac, every lobe value V_x(nu) by its own
// bisection of H(u) = pi nu in Arb, and includes no header of include/gyrores/.
//
// It bounds its own work: a certificate with more than band_max_intervals intervals, a number
// field longer than band_max_field_chars characters, digits above band_max_digits, one whose
// inequalities need more than band_max_prec_bits bits, or whose end-point bounds need more than
// band_max_pieces pieces in all, is refused (status 1, "work bound").
#pragma once
#include <cstddef>
#include <string>

#include "certificate_checker.hpp"

namespace gyrores_checker {

inline constexpr const char* band_certificate_format = "gyrores-band-certificate/1";
inline constexpr std::size_t band_max_intervals = 4000;
inline constexpr std::size_t band_max_field_chars = 2000;
inline constexpr long band_max_digits = 40;
inline constexpr long band_max_prec_bits = 8192;
inline constexpr long band_max_pieces = 100000;  // the end point's pieces, over the whole certificate

// Re-proves the certificate in `json_text` from its band, its horizon and its data alone.
verdict check_band_certificate(const std::string& json_text);

}  // namespace gyrores_checker
