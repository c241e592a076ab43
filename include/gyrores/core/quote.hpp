// A user's text quoted inside an error message: every message is one line (core/error.hpp), and
// an argument may hold a newline or another control character, shown escaped instead.
#pragma once
#include <string>

namespace gyrores {

inline std::string shown_input(const std::string& text) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') out += "\\n";
    else if (c < 0x20 || c == 0x7f) out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    else out += ch;
  }
  return out;
}

}  // namespace gyrores
