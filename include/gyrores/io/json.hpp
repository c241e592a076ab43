// JSON for gyrores' files and CLI output (nlohmann-json, insertion-ordered objects).
#pragma once
#include <nlohmann/json.hpp>
#include <cstdint>
#include <string>
#include <string_view>

#include <gyrores/core/error.hpp>
#include <gyrores/core/integer.hpp>

namespace gyrores {

using json = nlohmann::ordered_json;

// A JSON number with the exact digits of v, whatever its size: nlohmann-json holds 64 bits, so
// this is a marker string that json_dump() replaces by the bare digits.
json json_integer(const big_int& v);
json json_integer(const std::string& decimal);

// json::parse, but an object with the same key twice is refused (json_value_error naming the
// key) instead of keeping the last one: every file gyrores reads goes through it.
json json_parse_strict(std::string_view text);

// j.dump(indent) with every json_integer marker replaced by its digits.
std::string json_dump(const json& j, int indent = 2);

// An integer field of a file being read. nlohmann's get<> converts a floating value (which an
// integer beyond 64 bits parses as) with undefined behaviour and wraps a large one: both are
// refused with json_value_error naming `what` and the value. Readers catch it to name the file.
struct json_value_error : usage_error {
  using usage_error::usage_error;
};
template <class J> std::int64_t json_to_int64(const J& j, const char* what) {
  if (!j.is_number_integer() || (j.is_number_unsigned() && j.template get<std::uint64_t>() > std::uint64_t(INT64_MAX)))
    throw json_value_error(std::string(what) + " must be an integer in [-2^63, 2^63), got " + j.dump());
  return j.template get<std::int64_t>();
}
template <class J> std::uint64_t json_to_uint64(const J& j, const char* what) {
  if (!j.is_number_unsigned()) throw json_value_error(std::string(what) + " must be an integer in [0, 2^64), got " + j.dump());
  return j.template get<std::uint64_t>();
}

}  // namespace gyrores
