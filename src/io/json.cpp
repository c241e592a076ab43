// include/gyrores/io/json.hpp
#include <gyrores/io/json.hpp>

#include <regex>

namespace gyrores {

namespace {
constexpr const char* marker_open = "@@gyrores-int:";
}

json json_integer(const std::string& decimal) { return json(marker_open + decimal + "@@"); }
json json_integer(const big_int& v) { return json_integer(v.str()); }

std::string json_dump(const json& j, int indent) {
  static const std::regex marker("\"@@gyrores-int:(-?[0-9]+)@@\"");
  return std::regex_replace(j.dump(indent), marker, "$1");
}

}  // namespace gyrores
