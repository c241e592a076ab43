// Output conventions of the CLI: a report is built completely before anything is printed, so a
// failing command writes nothing to stdout; JSON goes through gyrores::json_dump (io/json.hpp),
// which prints integers of any size as JSON numbers.
#pragma once
#include <gyrores/io/json.hpp>

namespace gyrores::cli {

// Exit statuses: 0 success, 2 usage (bad input), 3 could not compute honestly.
inline constexpr int exit_usage = 2;
inline constexpr int exit_compute = 3;

}  // namespace gyrores::cli
