// Certificates as JSON text (docs/formats.md), read only by the independent checkers
// (src/checker/): "gyrores-certificate/2", the lattice theorem's certificate;
// "gyrores-coupling-certificate/1" (src/checker/horizon_checker.hpp) and
// "gyrores-band-certificate/1" (src/checker/band_checker.hpp). Integers and rationals are decimal
// strings. Writing is deterministic (fields in a fixed order), so a certificate's text is
// reproducible byte for byte.
//
// "gyrores-certificate/1", the interval-cover certificate of earlier versions, is retired: a file
// in that format is recognised by its "format" field and refused with one line saying how to
// re-certify; nothing of it is read or checked (docs/formats.md, "Retired: gyrores-certificate/1").
#pragma once
#include <string>

#include <gyrores/certify/band_certificate.hpp>
#include <gyrores/certify/horizon_certificate.hpp>
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/io/json.hpp>

namespace gyrores {

// The JSON object of a certificate; json_dump() gives its text.
json certificate_to_json(const theorem_certificate& c);
json certificate_to_json(const horizon_certificate& c);
json certificate_to_json(const band_certificate& c);

// The certificate file's text: the JSON and a final newline.
template <class Certificate> std::string certificate_text(const Certificate& c) {
  return json_dump(certificate_to_json(c)) + "\n";
}

// The "format" field of a certificate's text, or "" when the text is not a JSON object with a
// string "format". Never throws for bad text.
std::string certificate_format_of(const std::string& text);

// The retired format, and the one line that refuses a file in it (what the format was, that it
// is retired, how to re-certify): `gyrores check` prints it and exits 2, gyrores.check raises it.
inline constexpr const char* retired_certificate_format = "gyrores-certificate/1";
std::string retired_certificate_message();

}  // namespace gyrores
