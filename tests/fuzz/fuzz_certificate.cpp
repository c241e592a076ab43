// Fuzz target: reading certificates as `gyrores check` does (src/cli/cmd_certify.cpp):
// certificate_format_of, then the refusal of the retired format "gyrores-certificate/1", or the
// independent checker (src/checker/) for everything else. The checker answers every input with
// a verdict (0, 1, 2 and a one-line message).
#include <gyrores/io/certificate_json.hpp>

#include "certificate_checker.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return gyrores::fuzz::checker_verdict(data, size, 16384, [](const std::string& text) {
    if (gyrores::certificate_format_of(text) == gyrores::retired_certificate_format) return gyrores_checker::verdict{0, "retired"};
    return gyrores_checker::check_theorem_certificate(text);
  });
}
