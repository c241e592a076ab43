// Subcommands of the gyrores CLI. Each src/cli/cmd_<name>.cpp registers itself through a static
// command_registration object: it adds its options to the app and returns the function that
// runs it. A run returns the text for stdout, printed only on success (so a failing command
// writes nothing to stdout).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace gyrores::cli {

using command_runner = std::function<std::string()>;

// Thrown by a runner that ends with its own exit status and stderr line (gyrores check: 1 when
// a certificate fails); main.cpp prints the line and returns the status.
struct command_exit {
  int status;
  std::string message;
};
// Thrown by a command that has a proved partial answer but not the answer (a band's bracket): main
// prints `out` on stdout, then exits 130 when it was stopped by Ctrl-C (`unsettled` empty), or 3
// with `unsettled`, the documented cap that stopped it before the answer settled.
struct partial_answer {
  std::string out;
  std::string unsettled;
};
using command_installer = std::function<command_runner(CLI::App&)>;

struct command_entry {
  std::string name;  // must equal the subcommand name the installer creates
  command_installer install;
};

inline std::vector<command_entry>& command_registry() {
  static std::vector<command_entry> r;
  return r;
}

struct command_registration {
  command_registration(std::string name, command_installer install) {
    command_registry().push_back({std::move(name), std::move(install)});
  }
};

}  // namespace gyrores::cli
