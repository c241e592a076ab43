// Coupling certificates as JSON text ("gyrores-coupling-certificate/1", docs/formats.md): integers
// and rationals as decimal strings, fields in a fixed order (reproducible byte for byte). Read
// only by the independent checker (src/checker/horizon_checker.hpp).
#pragma once
#include <string>

#include <gyrores/certify/horizon_certificate.hpp>
#include <gyrores/io/json.hpp>

namespace gyrores {

json horizon_certificate_to_json(const horizon_certificate& c);

// The certificate file's text: the JSON and a final newline.
std::string coupling_certificate_text(const horizon_certificate& c);

}  // namespace gyrores
