// gyrores: the command-line front end. It only parses, calls the library and prints; the
// mathematics lives in include/gyrores/. Errors: one line on stderr, nothing on stdout; the
// exit statuses are the table of cli_output.hpp. Every write to stdout, and its final flush and
// close, is checked: a full disk or a closed stdout is exit 2, "cannot write to stdout".
// This is the one file that compiles CLI11 (header-only, ~8 s per file): main() and the
// implementation of cli::options (cli_options.hpp), through which the subcommands declare
// their options.
#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <optional>
#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/core/stop.hpp>

#include "cli_options.hpp"
#include "cli_output.hpp"
#include "commands.hpp"
#include "frontend/process.hpp"

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

#ifndef GYRORES_VERSION
#define GYRORES_VERSION "unknown"
#endif

namespace gyrores::cli {

// fd 1 was closed when the process started (it then holds /dev/null, see main()).
bool g_stdout_was_closed = false;

namespace {

// Writes all of `text` to stdout and flushes it; false (errno set) if any byte could not be written.
bool print_stdout(const std::string& text) {
  if (text.empty()) return true;
  if (g_stdout_was_closed) {
    errno = EBADF;
    return false;
  }
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) return false;
  return std::fflush(stdout) == 0;
}

}  // namespace

namespace {

// Edit distance (insertions, deletions, substitutions, adjacent transpositions) of two short words.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The candidate nearest to `word` when it is close enough to be a typo of it (a third of its
// letters, at least one), else "".
std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const auto& c : candidates)
    if (const std::size_t d = edit_distance(word, c); d < best_d) best_d = d, best = c;
  return best;
}

// " (did you mean 'X'?)" for a mistyped subcommand (the first word names none) or an option the
// subcommand does not have; "" when nothing is close.
std::string did_you_mean(CLI::App& app, int argc, char** argv, bool named) {
  if (!named) {
    std::vector<std::string> names;
    for (const auto& e : command_registry()) names.push_back(e.name);
    const std::string near = nearest(argv[1], names);
    return near.empty() ? "" : " (did you mean '" + near + "'?)";
  }
  const CLI::App* sub = app.get_subcommand(argv[1]);
  std::vector<std::string> options;
  for (const CLI::Option* o : sub->get_options())
    for (const auto& l : o->get_lnames()) options.push_back("--" + l);
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i], word = arg.substr(0, arg.find('='));
    if (word.rfind("--", 0) != 0 || std::find(options.begin(), options.end(), word) != options.end()) continue;
    if (const std::string near = nearest(word, options); !near.empty())
      return " (did you mean '" + near + "' for '" + word + "'?)";
  }
  return "";
}

}  // namespace

int cannot_write_stdout(int err) {
  std::cerr << "gyrores: error: cannot write to stdout: " << std::strerror(err) << "\n";
  return exit_usage;
}

// The whole command line: parses argv and, when `execute`, runs the subcommand; returns the exit
// status. main() is this with execute = true; the fuzz target tests/fuzz/fuzz_cli_args.cpp
// calls it in-process with execute = false (parsing only: no file written, no long run).
int run(int argc, char** argv, bool execute) {
  CLI::App app{"gyrores: certified analysis of energy exchange in gyroscopically coupled oscillators"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("gyrores ") + GYRORES_VERSION);
  app.footer(
      "Exit status: 0 ok (check: holds); 1 check: the certificate fails; 2 bad input or a file that cannot be read "
      "or written; 3 could not compute honestly; 4 sweep stopped by --max-pairs (resume state kept); 130 interrupted.");
  // Only the subcommand named on the command line is set up (its options cost more than the rest
  // of a short run); every one when the first word names none (usage, help, a typo).
  std::map<std::string, command_runner> runners;
  const std::string first = argc > 1 ? argv[1] : "";
  const auto& registry = command_registry();
  const bool named = std::any_of(registry.begin(), registry.end(), [&](const auto& e) { return e.name == first; });
  for (auto& entry : registry)
    if (!named || entry.name == first) runners[entry.name] = entry.install(app);

  // A bare `gyrores`: the usage on stderr (it answers no question), exit 2.
  if (argc <= 1) {
    if (execute) std::cerr << app.help();
    return exit_usage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    if (!execute) return 0;
    return print_stdout(app.help()) ? 0 : cannot_write_stdout(errno);
  } catch (const CLI::CallForAllHelp&) {
    if (!execute) return 0;
    return print_stdout(app.help("", CLI::AppFormatMode::All)) ? 0 : cannot_write_stdout(errno);
  } catch (const CLI::CallForVersion&) {
    if (!execute) return 0;
    return print_stdout(std::string("gyrores ") + GYRORES_VERSION + "\n") ? 0 : cannot_write_stdout(errno);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what(), hint = did_you_mean(app, argc, argv, named);
    if (!named && argv[1][0] != '-') {
      msg = std::string("unknown subcommand '") + argv[1] + "'";
      if (hint.empty()) hint = " (gyrores --help lists them)";
    }
    for (auto& ch : msg)
      if (ch == '\n') ch = ' ';
    std::cerr << "gyrores: error: " << msg << hint << "\n";
    return exit_usage;
  }
  if (!execute) return 0;

  try {
    for (auto* sub : app.get_subcommands()) {
      std::string out;
      {
        // A command still running after 2 s says so on a terminal (the sweep draws its own bar),
        // unless it was given --quiet.
        std::optional<frontend::progress_line> progress;
        const CLI::Option* quiet = sub->get_option_no_throw("--quiet");
        if (sub->get_name() != "sweep" && !(quiet && quiet->count() > 0)) progress.emplace(sub->get_name());
        out = runners.at(sub->get_name())();
      }
      if (!print_stdout(out)) return cannot_write_stdout(errno);
    }
    return 0;
  } catch (const command_exit& e) {
    std::cerr << e.message << "\n";
    return e.status;
  } catch (const partial_answer& e) {
    if (!print_stdout(e.out)) return cannot_write_stdout(errno);
    if (!e.unsettled.empty()) {
      std::cerr << "gyrores: error: not settled: " << e.unsettled << " (the proved bracket is printed)\n";
      return exit_compute;
    }
    std::cerr << "gyrores: interrupted (the proved bracket reached so far is printed)\n";
    return exit_interrupted;
  } catch (const gyrores::interrupted&) {
    std::cerr << "gyrores: interrupted\n";
    return exit_interrupted;
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
namespace {

// A standard descriptor closed at start would be taken by the first file the command opens, and
// what is printed would go into that file: /dev/null holds its place, and stdout's writes fail
// as if it were still closed (print_stdout).
void reserve_standard_fds() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int n = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (n >= 0 && n != fd) {
      ::dup2(n, fd);
      ::close(n);
    }
    if (fd == 1) gyrores::cli::g_stdout_was_closed = true;
  }
}

}  // namespace

int main(int argc, char** argv) {
  reserve_standard_fds();
  gyrores::frontend::install_interrupt_handlers();  // SIGINT, SIGTERM: exit 130 (frontend/process.hpp)
  int status = gyrores::cli::run(argc, argv, true);
  // The final flush and close: a full disk may only show here.
  if ((std::fflush(stdout) != 0 || std::ferror(stdout)) && status == 0) status = gyrores::cli::cannot_write_stdout(errno);
  if (std::fclose(stdout) != 0 && status == 0) status = gyrores::cli::cannot_write_stdout(errno);
  return status;
}
#endif
