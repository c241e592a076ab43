// gyrores: the command-line front end. It only parses, calls the library and prints; the
// mathematics lives in include/gyrores/. Errors: one line on stderr, nothing on stdout,
// exit 2 for bad input, 3 when a result could not be computed honestly.
#include <CLI/CLI.hpp>
#include <iostream>
#include <map>

#include <gyrores/core/error.hpp>

#include "cli_output.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace gyrores::cli;
  CLI::App app{"gyrores: certified analysis of energy exchange in gyroscopically coupled oscillators"};
  app.require_subcommand(1);
  std::map<std::string, command_runner> runners;
  for (auto& entry : command_registry()) runners[entry.name] = entry.install(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (auto& ch : msg)
      if (ch == '\n') ch = ' ';
    std::cerr << "gyrores: error: " << msg << "\n";
    return exit_usage;
  }

  try {
    for (auto* sub : app.get_subcommands()) {
      std::string out = runners.at(sub->get_name())();
      std::cout << out << std::flush;
    }
    return 0;
  } catch (const command_exit& e) {
    std::cerr << e.message << "\n";
    return e.status;
  } catch (const gyrores::usage_error& e) {
    std::cerr << "gyrores: error: " << e.what() << "\n";
    return exit_usage;
  } catch (const gyrores::compute_error& e) {
    std::cerr << "gyrores: could not compute: " << e.what() << "\n";
    return exit_compute;
  } catch (const std::exception& e) {
    std::cerr << "gyrores: internal error: " << e.what() << "\n";
    return exit_compute;
  }
}
