// Coupling certificates as JSON text ("gyrores-coupling-certificate/1", docs/formats.md): integers
// and rationals as decimal strings, fields in a fixed order (reproducible byte for byte). Read
// only by the independent checker (src/checker/horizon_checker.hpp).
#pragma once
#include <optional>
#include <string>

#include <gyrores/certify/horizon_certificate.hpp>
#include <gyrores/io/json.hpp>

namespace gyrores {

json horizon_certificate_to_json(const horizon_certificate& c);

// The certificate text (JSON and a final newline) for `gyrores coupling N --horizon T
// [--below E] --certificate FILE`: min H_q over [0, T] of coupling c to `digits` digits, and the
// first time H_q <= E when a level is given ("below": null otherwise).
std::string coupling_certificate_text(const coupling_spec& c, const big_rational& horizon,
                                      const std::optional<big_rational>& level, unsigned digits);

}  // namespace gyrores
