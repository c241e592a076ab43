// Certificates as JSON text (docs/formats.md): "gyrores-certificate/2" (the lattice theorem's,
// the default; integers as decimal strings; read only by the independent checker, src/checker/)
// and "gyrores-certificate/1" (the cover's, `gyrores certify --cover`; integers as JSON numbers
// of any size). Writing is deterministic (fields in a fixed order), so a certificate's text is
// reproducible byte for byte. Reading is strict: a missing or mistyped
// field is "malformed" (usage_error), which `gyrores check` reports with exit 2.
#pragma once
#include <string>

#include <gyrores/certify/certificate.hpp>
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/io/json.hpp>

namespace gyrores {

// The JSON object of a certificate; json_dump() gives its text.
json certificate_to_json(const certificate& c);
json certificate_to_json(const theorem_certificate& c);

// The "format" field of a certificate's text, or "" when the text is not a JSON object with a
// string "format" (such a text is then read as /1, whose reader says what is wrong).
std::string certificate_format_of(const std::string& text);

// Parses a "gyrores-certificate/1" text. Throws usage_error("malformed certificate: ...") on any problem
// (not JSON, a missing field, a wrong type, a claim that is not ["lo", "hi"] or null). The
// numbers' content is not checked here: check_certificate (certify/check.hpp) does that.
certificate certificate_from_text(const std::string& text);

}  // namespace gyrores
