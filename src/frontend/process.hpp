// The process of a program around the library (the gyrores tool, src/cli/, with the report
// generator, src/report/): how SIGINT and SIGTERM end a command, helper processes (gnuplot) run
// without a shell, and the progress line of long commands on a terminal.
//
// Interrupts (docs/formats.md, "Exit statuses"): main() installs a handler that ends any
// command with exit 130 ("gyrores: interrupted" on stderr), after stopping a helper process
// started by run_helper and removing its private directory; a sweep replaces it for its run
// (src/cli/cmd_sweep.cpp: a checkpoint first). A signal ignored when gyrores starts (nohup, `&`
// in a script) stays ignored.
#pragma once
#include <string>
#include <vector>

namespace gyrores::frontend {

// Called once by main(): the handlers above.
void install_interrupt_handlers();

// Runs `argv[0]` (searched in PATH, no shell) in directory `dir` with stdin and stdout on
// /dev/null; returns its stderr (at most 4 KiB kept) in `err` and its exit status (-1 if it
// could not be started or was killed). While it runs, an interrupt stops it, removes
// `private_file` and `private_dir` (the one file the helper writes there; either may be empty)
// and exits 130; a helper ended by SIGINT or SIGTERM (Ctrl-C on a terminal reaches it too)
// throws `interrupted` (exit 130).
int run_helper(const std::vector<std::string>& argv, const std::string& dir, const std::string& private_dir,
               const std::string& private_file, std::string& err);

// True when an executable `name` is in PATH.
bool program_in_path(const std::string& name);

// The progress line: on a terminal (stderr), a command still running after 2 s shows
// "gyrores CMD: STAGE, N s (Ctrl-C stops it)", redrawn every second and erased when it ends.
// Nothing when stderr is not a terminal (logs stay clean). The sweep has its own (src/cli/cmd_sweep.cpp).
class progress_line {
 public:
  explicit progress_line(std::string command);
  ~progress_line();
  progress_line(const progress_line&) = delete;
  progress_line& operator=(const progress_line&) = delete;

 private:
  struct impl;
  impl* p_;
};

// What the running command is doing, for the progress line ("proving the band's extremes").
void progress_stage(const std::string& stage);

}  // namespace gyrores::frontend
