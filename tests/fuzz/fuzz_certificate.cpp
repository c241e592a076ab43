// Fuzz target: reading certificates as `gyrores check` does (src/cli/cmd_certify.cpp):
// certificate_format_of, then the independent checker (src/checker/) for
// "gyrores-certificate/2" or certificate_from_text (io/certificate_json.hpp) for /1. The checker
// answers every input with a verdict (0, 1, 2 and a one-line message); the /1 reader accepts or
// throws usage_error.
#include <gyrores/core/error.hpp>
#include <gyrores/io/certificate_json.hpp>

#include "certificate_checker.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  const std::string text(gyrores::fuzz::as_text(data, size));
  if (gyrores::certificate_format_of(text) == "gyrores-certificate/2") {
    const auto v = gyrores_checker::check_theorem_certificate(text);
    if (v.status < 0 || v.status > 2 || v.message.empty() || v.message.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  try {
    (void)gyrores::certificate_from_text(text);
  } catch (const gyrores::usage_error&) {
  }
  return 0;
}
