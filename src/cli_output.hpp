// Output assembly for the CLI: a report is built completely before anything is printed, so a
// failing command writes nothing to stdout. JSON integers of any size are emitted as JSON
// numbers (nlohmann-json holds 64 bits, so larger ones pass through a marker string that is
// replaced in the dumped text).
#pragma once
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

namespace gyrores::cli {

using json = nlohmann::ordered_json;

// Exit statuses: 0 success, 2 usage (bad input), 3 could not compute honestly.
inline constexpr int exit_usage = 2;
inline constexpr int exit_compute = 3;

inline json json_integer(const std::string& decimal) { return json("@@gyrores-int:" + decimal + "@@"); }

inline std::string json_dump(const json& j, int indent = 2) {
  static const std::regex marker("\"@@gyrores-int:(-?[0-9]+)@@\"");
  return std::regex_replace(j.dump(indent), marker, "$1");
}

}  // namespace gyrores::cli
