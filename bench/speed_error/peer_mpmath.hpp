// The mpmath peer: mpmath's findroot (bench/mpmath_peer.py), run as a child process during the same
// benchmark run, timed inside Python (CPU time, median of repetitions). Optional: when python3
// or mpmath is missing the rows are skipped with a note.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core.hpp"
#include "reference.hpp"

namespace gyrores::bench {

struct mpmath_run {
  bool available = false;
  std::string status;       // "# mpmath 1.3.0 backend python python 3.11.7", or why it was skipped
  std::vector<measurement> rows;
  std::vector<skip_note> skips;
};

// Start of the solve: theta_first rounded to ceil(log10(a)) + 8 significant digits (the lobe
// known to ~1e-8 of its width, as a user who located it by other means would have), and a
// second point 1e-4 half-periods away.
mpmath_run run_mpmath_peer(const std::string& python, const std::string& script, const std::vector<bench_pair>& pairs,
                           const std::vector<precision>& precisions, const std::map<std::string, reference>& refs);

}  // namespace gyrores::bench
