// The application layer (docs/architecture.md): requests in, results out, shared by the CLI and
// the Python module, which only parse their arguments into a request, call, and print the
// result. This file: `gyrores pair` and gyrores.pair, the proved report of one resonant pair.
#pragma once
#include <gyrores/model/pair.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores::app {

struct pair_request {
  resonant_pair<big_int> pair;
  pair_report_options options;  // digits, qdot0, enclosures, asymptotics (Python skips them until asked), stop
};

// As prove_pair (usage_error for digits outside [1, report_digits_max] or qdot0 <= 0).
pair_report run_pair(const pair_request& request);

}  // namespace gyrores::app
