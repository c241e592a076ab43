// How the text outputs (the CLI's and REPORT.md's) spell proved reals for people (the JSON keeps
// the scientific text).
// Every function here only moves the decimal point of a correctly rounded scientific text
// (core/decimal.hpp): the digits printed are exactly the digits of the proved rounding.
#pragma once
#include <cstddef>
#include <string>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/rational.hpp>

namespace gyrores::frontend {

// Decimal exponents written without an exponent ("16.35107798", "0.001287568403").
inline constexpr long plain_exponent_min = -4, plain_exponent_max = 6;

// "d.ddd...e+XX" in plain notation when its exponent lies in [plain_exponent_min,
// plain_exponent_max] and the digits reach the units (1.57e+04 with 3 digits stays as it is: its
// plain form would show zeros that are not digits of the rounding); zero (only an exact zero
// rounds to zero) as "0"; anything else unchanged.
std::string plain(const std::string& scientific);
inline std::string plain(const proved_real& r) { return plain(r.value); }

// An energy for people: "0 (exact)" when zero, else its plain text and "  (S% of H_q(0))" with
// the share (report/scales.hpp) in plain text.
std::string energy_text(const std::string& energy, const std::string& share);

// A rational in decimals: exact when its decimal terminates within 60 places ("0.198"), else
// "~" and its correct rounding to `digits` significant digits ("~0.3333333333").
std::string decimal_text(const big_rational& v, unsigned digits);

}  // namespace gyrores::frontend
