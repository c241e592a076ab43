// The retired cover certificate ("gyrores-certificate/1", reference/certificate.hpp) as JSON
// text, for the tests: integers as JSON numbers of any size, fields in a fixed order. The
// product only recognises the format and refuses it (io/certificate_json.hpp); this reader and
// writer let the tests keep the cover proof as an oracle through files (test_certificate.cpp,
// test_certificate_tamper.cpp). Reading is strict: a missing or mistyped field is "malformed"
// (usage_error).
#pragma once
#include <string>

#include <gyrores/io/json.hpp>

#include "reference/certificate.hpp"

namespace gyrores {

// The JSON object of a /1 certificate; json_dump() gives its text.
json certificate_to_json(const certificate& c);

// Parses a "gyrores-certificate/1" text. Throws usage_error("malformed certificate: ...") on any
// problem (not JSON, a missing field, a wrong type, a claim that is not ["lo", "hi"] or null).
// The numbers' content is not checked here: check_certificate (reference/check.hpp) does that.
certificate certificate_from_text(const std::string& text);

}  // namespace gyrores
