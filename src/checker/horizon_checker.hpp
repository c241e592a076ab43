// The independent checker of "gyrores-coupling-certificate/1" (horizon-theorem certificates:
// the minimum of H_q over [0, T] for any coupling n^2 = P/Q; docs/formats.md).
//
// Independent as certificate_checker.hpp is: it reads the JSON itself (nlohmann-json), does the
// exact arithmetic in Q(sqrt D) with FLINT's fmpz (its own floor, sign and the rotation minimum
// MinFrac, written from proofs/horizon-theorem.md, "Rotation minima"), every real inequality in
// Arb balls, and includes no header of include/gyrores/. So the Diophantine claim (which lobe
// holds the minimum) is re-derived, not trusted: the checker computes min ||k x - 1/2|| over the
// admissible lobes itself and refuses any other lobe.
#pragma once
#include <cstddef>
#include <string>

#include "certificate_checker.hpp"

namespace gyrores_checker {

inline constexpr const char* coupling_certificate_format = "gyrores-coupling-certificate/1";

// The envelope it reads (docs/formats.md, "Limits of the coupling inputs"): the producer's
// include/gyrores/model/limits.hpp has the same numbers (tests/test_limits.cpp compares them),
// so that every certificate written is read and nothing else is. Outside them: malformed.
inline constexpr std::size_t coupling_max_rational_chars = 2000;  // n2, horizon, below.level ("p/q")
inline constexpr std::size_t coupling_max_integer_digits = 1200;  // cut_lobe, lobe.k, lobe.j
inline constexpr long coupling_horizon_exponent = 1000;           // 10^-1000 <= T <= 10^1000
inline constexpr long coupling_n2_exponent = 300;                 // 10^-300 <= n^2 <= 10^300
inline constexpr long coupling_level_exponent = 100;              // E = 0 or E >= 10^-100

// Re-proves the certificate in `json_text` from its coupling, its horizon and its data alone.
verdict check_coupling_certificate(const std::string& json_text);

}  // namespace gyrores_checker
