// Fuzz target: decimal input (core/decimal.hpp). parse_big_int either throws usage_error or gives
// an integer whose decimal text is the input without sign clutter and leading zeros;
// real_from_decimal (below: a reading of decimal reals that the product no longer has; the product
// reads decimals exactly, core/rational.hpp) in double and in MPFR accepts exactly the same texts.
#include <cctype>
#include <cstdlib>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>

#include "fuzz_support.hpp"

namespace {

// Parse a decimal real (e.g. "1", "0.25", "1e-3") into T, correctly rounded by T's parser.
// Throws usage_error naming `what` for anything else.
using gyrores::usage_error;

template <class T> T real_from_decimal(const std::string& text, const std::string& what) {
  char* end = nullptr;
  if (text.empty()) throw usage_error(what + " must be a number, got ''");
  std::strtold(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
    throw usage_error(what + " must be a number, got '" + text + "'");
  for (char ch : text)
    if (!(std::isdigit((unsigned char)ch) || ch == '.' || ch == 'e' || ch == 'E' || ch == '+' || ch == '-'))
      throw usage_error(what + " must be a decimal number, got '" + text + "'");
  if constexpr (std::is_floating_point_v<T>) {
    if constexpr (std::is_same_v<T, double>) return std::strtod(text.c_str(), nullptr);
    else return std::strtold(text.c_str(), nullptr);
  } else {
    return T(text);
  }
}

// The canonical decimal text of an accepted integer literal: sign kept only when negative and
// the value non-zero, leading zeros dropped.
std::string canonical_integer(std::string s) {
  bool neg = false;
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
    neg = s[0] == '-';
    s.erase(0, 1);
  }
  const auto nz = s.find_first_not_of('0');
  s = nz == std::string::npos ? "0" : s.substr(nz);
  return (neg && s != "0" ? "-" : "") + s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;  // long numbers add nothing but time
  const std::string text(gyrores::fuzz::as_text(data, size));
  try {
    const gyrores::big_int v = gyrores::parse_big_int(text, "N");
    if (gyrores::to_decimal(v) != canonical_integer(text)) std::abort();
  } catch (const gyrores::usage_error&) {
  }
  bool double_ok = true, mpfr_ok = true;
  try {
    (void)real_from_decimal<double>(text, "X");
  } catch (const gyrores::usage_error&) {
    double_ok = false;
  }
  try {
    gyrores::mpfr_real::default_precision(30);  // a single-threaded process
    (void)real_from_decimal<gyrores::mpfr_real>(text, "X");
  } catch (const gyrores::usage_error&) {
    mpfr_ok = false;
  }
  if (double_ok != mpfr_ok) std::abort();
  return 0;
}
