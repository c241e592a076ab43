// Errors raised by gyrores. Two kinds, matching the CLI's exit codes:
//   usage_error   - the input is invalid (exit 2): a non-coprime pair, tau <= sigma, ...
//   compute_error - the input is valid but a computation could not finish honestly (exit 3):
//                   a bracket without a sign change, an exhausted iteration budget, a pair
//                   beyond a method's documented limit, two methods that disagree.
// Every message is one line and names the function or the input at fault.
#pragma once
#include <stdexcept>
#include <string>

namespace gyrores {

struct usage_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct compute_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A user's text quoted inside a message: an argument may hold a newline or another control
// character, shown escaped so that the message stays one line.
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
