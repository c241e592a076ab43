// Certificates as JSON text ("gyrores-certificate/1", docs/formats.md). Writing is
// deterministic (fields in a fixed order, integers of any size as JSON numbers), so a
// certificate's text is reproducible byte for byte. Reading is strict: a missing or mistyped
// field is "malformed" (usage_error), which `gyrores check` reports with exit 2.
#pragma once
#include <string>

#include <gyrores/certify/certificate.hpp>
#include <gyrores/io/json.hpp>

namespace gyrores {

// The JSON object of a certificate; json_dump() gives its text.
json certificate_to_json(const certificate& c);

// Parses a certificate's text. Throws usage_error("malformed certificate: ...") on any problem
// (not JSON, a missing field, a wrong type, a claim that is not ["lo", "hi"] or null). The
// numbers' content is not checked here: check_certificate (certify/check.hpp) does that.
certificate certificate_from_text(const std::string& text);

}  // namespace gyrores
