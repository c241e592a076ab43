// The application layer (docs/architecture.md): requests in, results out, shared by the CLI and
// the Python module, which only parse their arguments into a request, call, and print the
// result. This file: `gyrores pair` and gyrores.pair, the proved report of one resonant pair.
#pragma once
#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores::app {

struct pair_request {
  resonant_pair<big_int> pair;
  unsigned digits = 17;      // [1, report_digits_max]
  big_rational qdot0 = 1;    // the impulse amplitude, > 0
  bool enclosures = false;   // also the outward enclosure of every real
  bool asymptotics = true;   // the paper's asymptotics (Python skips them until asked)
  stop_token stop;
};

// usage_error for digits outside [1, report_digits_max] or qdot0 <= 0; otherwise prove_pair.
pair_report run_pair(const pair_request& request);

}  // namespace gyrores::app
