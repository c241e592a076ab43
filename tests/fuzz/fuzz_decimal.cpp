// Fuzz target: decimal input (core/decimal.hpp). parse_big_int either throws usage_error or gives
// an integer whose decimal text is the input without sign clutter and leading zeros;
// real_from_decimal in double and in MPFR accepts exactly the same texts.
#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>

#include "fuzz_support.hpp"

namespace {

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
    (void)gyrores::real_from_decimal<double>(text, "X");
  } catch (const gyrores::usage_error&) {
    double_ok = false;
  }
  try {
    gyrores::scoped_digits digits(30);
    (void)gyrores::real_from_decimal<gyrores::mpfr_real>(text, "X");
  } catch (const gyrores::usage_error&) {
    mpfr_ok = false;
  }
  if (double_ok != mpfr_ok) std::abort();
  return 0;
}
