// Fuzz target: exact rationals (core/rational.hpp). parse_rational either throws usage_error or
// gives a rational whose exact text (rational_str) parses back to the same value.
#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;
  const std::string text(gyrores::fuzz::as_text(data, size));
  gyrores::big_rational q;
  try {
    q = gyrores::parse_rational(text, "N");
  } catch (const gyrores::usage_error&) {
    return 0;
  }
  if (gyrores::parse_rational(gyrores::rational_str(q), "N") != q) std::abort();
  return 0;
}
