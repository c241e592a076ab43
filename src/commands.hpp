// Subcommands of the gyrores CLI. Each registers its options on the app and returns the
// function that runs it; a run returns the text for stdout (printed only on success).
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace gyrores::cli {

using command_runner = std::function<std::string()>;

command_runner register_pair(CLI::App& app);

}  // namespace gyrores::cli
