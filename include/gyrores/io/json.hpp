// JSON for gyrores' files and CLI output (nlohmann-json, insertion-ordered objects).
//
// Integers of any size: nlohmann-json holds 64 bits, so a big_int is emitted through a marker
// string that json_dump() replaces by the bare digits (a JSON number of any length). Reading
// them back needs the number's text, not nlohmann's double: see io/certificate_json.hpp.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include <gyrores/core/integer.hpp>

namespace gyrores {

using json = nlohmann::ordered_json;

// A JSON number with the exact decimal digits of v, whatever its size (see json_dump).
json json_integer(const big_int& v);
json json_integer(const std::string& decimal);

// j.dump(indent) with every json_integer marker replaced by its digits.
std::string json_dump(const json& j, int indent = 2);

}  // namespace gyrores
