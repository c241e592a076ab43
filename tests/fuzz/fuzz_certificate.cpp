// Fuzz target: reading certificates as `gyrores check` does (src/cli/cmd_certify.cpp):
// certificate_format_of, then the refusal of the retired format "gyrores-certificate/1", or the
// independent checker (src/checker/) for everything else. The checker answers every input with
// a verdict (0, 1, 2 and a one-line message).
#include <gyrores/io/certificate_json.hpp>

#include "certificate_checker.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  const std::string text(gyrores::fuzz::as_text(data, size));
  if (gyrores::certificate_format_of(text) == gyrores::retired_certificate_format) return 0;
  const auto v = gyrores_checker::check_theorem_certificate(text);
  if (v.status < 0 || v.status > 2 || v.message.empty() || v.message.find('\n') != std::string::npos) std::abort();
  return 0;
}
