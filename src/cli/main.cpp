// gyrores: the command-line front end. It only parses, calls the library and prints; the
// mathematics lives in include/gyrores/. Errors: one line on stderr, nothing on stdout,
// exit 2 for bad input, 3 when a result could not be computed honestly.
// This is the one file that compiles CLI11 (header-only, ~8 s per file): main() and the
// implementation of cli::options (cli_options.hpp), through which the subcommands declare
// their options.
#include <CLI/CLI.hpp>
#include <iostream>
#include <map>

#include <gyrores/core/error.hpp>
#include <gyrores/core/stop.hpp>

#include "cli_options.hpp"
#include "cli_output.hpp"
#include "commands.hpp"

namespace gyrores::cli {
namespace {

template <class V>
const options& add_one(const options& self, CLI::App* app, const std::string& name, V& value, const std::string& help,
                       show s) {
  CLI::Option* o = app->add_option(name, value, help);
  if (s == show::with_default) o->capture_default_str();
  if (s == show::required) o->required();
  return self;
}

}  // namespace

options options::subcommand(const std::string& name, const std::string& description) const {
  return options(*app_->add_subcommand(name, description));
}
#define GYRORES_CLI_ADD(V)                                                                           \
  const options& options::add(const std::string& name, V& value, const std::string& help, show s) const { \
    return add_one(*this, app_, name, value, help, s);                                               \
  }
GYRORES_CLI_ADD(std::string)
GYRORES_CLI_ADD(int)
GYRORES_CLI_ADD(unsigned)
GYRORES_CLI_ADD(long)
GYRORES_CLI_ADD(unsigned long)
GYRORES_CLI_ADD(double)
GYRORES_CLI_ADD(std::vector<std::string>)
#undef GYRORES_CLI_ADD

const options& options::flag(const std::string& name, bool& value, const std::string& help) const {
  app_->add_flag(name, value, help);
  return *this;
}

void options::require_subcommand() const { app_->require_subcommand(1); }

bool options::parsed() const { return app_->parsed(); }

}  // namespace gyrores::cli

namespace gyrores::cli {

// The whole command line: parses argv and, when `execute`, runs the subcommand; returns the exit
// status. main() is this with execute = true; the fuzz target tests/fuzz/fuzz_cli_args.cpp
// calls it in-process with execute = false (parsing only: no file written, no long run).
int run(int argc, char** argv, bool execute) {
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
  if (!execute) return 0;

  try {
    for (auto* sub : app.get_subcommands()) {
      std::string out = runners.at(sub->get_name())();
      std::cout << out << std::flush;
    }
    return 0;
  } catch (const command_exit& e) {
    std::cerr << e.message << "\n";
    return e.status;
  } catch (const gyrores::interrupted&) {
    std::cerr << "gyrores: interrupted\n";
    return 130;
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

}  // namespace gyrores::cli

// GYRORES_CLI_NO_MAIN: the CLI's sources linked into another program (tests/fuzz/).
#ifndef GYRORES_CLI_NO_MAIN
int main(int argc, char** argv) { return gyrores::cli::run(argc, argv, true); }
#endif
