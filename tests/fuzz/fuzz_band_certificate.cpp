// Fuzz target: reading band certificates as `gyrores check` does (src/app/certify.cpp): the
// independent checker of "gyrores-band-certificate/1" (src/checker/band_checker.hpp) answers
// every input with a verdict (0, 1, 2 and a one-line message), never a crash or an exception;
// its work bounds (band_checker.hpp) keep every input finite.
#include "band_checker.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return gyrores::fuzz::checker_verdict(data, size, 65536, gyrores_checker::check_band_certificate);
}
