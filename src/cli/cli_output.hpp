// Output conventions of the CLI: a report is built completely before anything is printed, so a
// failing command writes nothing to stdout; JSON goes through gyrores::json_dump (io/json.hpp),
// which prints integers of any size as JSON numbers.
#pragma once
#include <gyrores/io/json.hpp>

namespace gyrores::cli {

// Exit statuses, the one table (also in README.md and docs/formats.md, "Exit statuses"):
//   0   success (gyrores check: the certificate holds)
//   1   gyrores check: a claim or fact of the certificate fails
//   2   bad input or a file that cannot be read or written (stdout included: "cannot write")
//   3   a result could not be computed honestly within the resource limits
//   4   gyrores sweep stopped as asked by --max-pairs; the resume state is kept
//   130 interrupted (SIGINT/SIGTERM); a sweep keeps its resume state
inline constexpr int exit_check_fails = 1;
inline constexpr int exit_usage = 2;
inline constexpr int exit_compute = 3;
inline constexpr int exit_stopped = 4;
inline constexpr int exit_interrupted = 130;

// main.cpp: stdout was closed when the process started; prints "cannot write to stdout: ..."
// and returns exit_usage.
extern bool g_stdout_was_closed;
int cannot_write_stdout(int err);

}  // namespace gyrores::cli
