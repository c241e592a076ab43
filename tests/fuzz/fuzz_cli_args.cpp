// Fuzz target: the command line of `gyrores` (src/cli/main.cpp), in-process. The input is the
// argument vector after the program name, arguments separated by NUL bytes (at most 24).
// gyrores::cli::run parses it with every subcommand's options and stops before running the
// command (execute = false: no file is written and no long computation starts). Every input
// must give a status (0 or 2 for a usage error), never an exception or a crash.
#include <cstring>

#include "fuzz_support.hpp"

namespace gyrores::cli {
int run(int argc, char** argv, bool execute);  // src/cli/main.cpp
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;
  auto args = gyrores::fuzz::split(gyrores::fuzz::as_text(data, size), std::string_view("\0", 1), 24);
  args.insert(args.begin(), "gyrores");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int status = gyrores::cli::run(int(args.size()), argv.data(), false);
  if (status != 0 && status != 2) std::abort();
  return 0;
}
