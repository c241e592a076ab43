// Band certificates as JSON text ("gyrores-band-certificate/1", docs/formats.md): integers and
// rationals as decimal strings, fields in a fixed order. Read only by the independent checker
// (src/checker/band_checker.hpp).
#pragma once
#include <string>

#include <gyrores/certify/band_certificate.hpp>
#include <gyrores/io/json.hpp>

namespace gyrores {

json band_certificate_to_json(const band_certificate& c);

// The certificate file's text: the JSON and a final newline.
std::string band_certificate_text(const band_certificate& c);

}  // namespace gyrores
