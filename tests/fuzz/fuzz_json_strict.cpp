// Fuzz target: the strict JSON reader every gyrores file goes through (io/json.hpp,
// json_parse_strict). It must agree with nlohmann's own parser except on duplicate keys: when
// it accepts a text, the plain parse gives the same value; when it refuses one as a duplicate
// key (json_value_error), the plain parse either finds a syntax error further on or accepts it
// with some object having lost a key (fewer keys kept than the text names); a syntax error is a
// syntax error (or an out-of-range number) for both.
#include <gyrores/io/json.hpp>

#include "fuzz_support.hpp"

namespace {

// The number of key events a plain parse sees, against the keys its objects keep. A text with a
// syntax error after the duplicate (which the strict reader never reached) counts as refused by
// both.
bool lost_a_key(const std::string& text) try {
  std::size_t key_events = 0;
  const gyrores::json::parser_callback_t count = [&](int, gyrores::json::parse_event_t ev, gyrores::json&) {
    if (ev == gyrores::json::parse_event_t::key) ++key_events;
    return true;
  };
  const gyrores::json j = gyrores::json::parse(text, count);
  std::size_t kept = 0;
  auto walk = [&](const auto& self, const gyrores::json& v) -> void {
    if (v.is_object()) kept += v.size();
    if (v.is_structured())
      for (const auto& x : v) self(self, x);
  };
  walk(walk, j);
  return kept < key_events;
} catch (const gyrores::json::exception&) {
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  const std::string text(gyrores::fuzz::as_text(data, size));
  gyrores::json strict;
  try {
    strict = gyrores::json_parse_strict(text);
  } catch (const gyrores::json_value_error&) {
    if (!lost_a_key(text)) std::abort();  // refused, yet no key was lost
    return 0;
  } catch (const gyrores::json::exception&) {
    bool plain_ok = true;
    try {
      (void)gyrores::json::parse(text);
    } catch (const gyrores::json::exception&) {
      plain_ok = false;
    }
    if (plain_ok) std::abort();  // a syntax error for one parser only
    return 0;
  }
  if (strict != gyrores::json::parse(text)) std::abort();
  return 0;
}
