// include/gyrores/io/json.hpp
#include <gyrores/io/json.hpp>

#include <regex>
#include <unordered_set>
#include <vector>

namespace gyrores {

namespace {
constexpr const char* marker_open = "@@gyrores-int:";
}

json json_integer(const std::string& decimal) { return json(marker_open + decimal + "@@"); }
json json_integer(const big_int& v) { return json_integer(v.str()); }

json json_parse_strict(std::string_view text) {
  // The keys of every object being parsed, innermost last.
  std::vector<std::unordered_set<std::string>> open;
  const json::parser_callback_t on_event = [&](int, json::parse_event_t ev, json& parsed) {
    if (ev == json::parse_event_t::object_start) {
      open.emplace_back();
    } else if (ev == json::parse_event_t::object_end) {
      if (!open.empty()) open.pop_back();
    } else if (ev == json::parse_event_t::key && !open.empty()) {
      std::string k = parsed.get<std::string>();
      if (!open.back().insert(k).second)
        throw json_value_error("the key '" + k.substr(0, 60) + "' appears twice in one object");
    }
    return true;
  };
  return json::parse(text, on_event);
}

std::string json_dump(const json& j, int indent) {
  static const std::regex marker("\"@@gyrores-int:(-?[0-9]+)@@\"");
  return std::regex_replace(j.dump(indent), marker, "$1");
}

}  // namespace gyrores
