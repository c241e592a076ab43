// Sweeps: every resonant pair with min_order <= tau + sigma <= max_order, evaluated and checked
// against the paper's claims (docs/mathematics.md §2), with a deterministic, mergeable summary.
// (Not here: testing.hpp, the steps the tests call; the files, io/sweep_files.hpp; the request of
// the CLI and Python, app/sweep.hpp.)
#pragma once
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/engine.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/sweep/filtered.hpp>
#include <gyrores/sweep/summary.hpp>
