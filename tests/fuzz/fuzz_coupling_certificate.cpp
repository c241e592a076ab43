// Fuzz target: reading coupling certificates as `gyrores check` does (src/cli/cmd_certify.cpp):
// the independent checker of "gyrores-coupling-certificate/1" (src/checker/horizon_checker.hpp)
// answers every input with a verdict (0, 1, 2 and a one-line message), never a crash or an
// exception. Integers are bounded at 400 digits, so its recursion stays shallow (at most
// about 1330 calls deep, also under ASan).
#include "fuzz_support.hpp"
#include "horizon_checker.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return gyrores::fuzz::checker_verdict(data, size, 16384, gyrores_checker::check_coupling_certificate);
}
