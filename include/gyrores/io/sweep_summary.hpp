// The summary of a sweep as JSON (`--summary`, `--json`, `gyrores merge`) and as text, the
// accumulator <-> JSON (summaries and resume states), and shard summaries read back with their
// values files (io/sweep_values_file.hpp). Keys and the values file's layout: docs/formats.md (sweep summary, values file).
#pragma once
#include <cstddef>
#include <string>

#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_run.hpp>
#include <gyrores/sweep/sweep.hpp>

namespace gyrores {

// Everything of the accumulator except the t_first/proxy values; `checks` selects the checks
// listed (the others are zero anyway).
json sweep_accumulator_json(const sweep_accumulator& a, sweep_check_set checks);
// The inverse (t_ratios left empty); nlohmann's exceptions on missing keys.
sweep_accumulator sweep_accumulator_from_json(const json& j, std::size_t max_examples);

// The summary JSON of a finished sweep described by `run` (computes the quantiles: a few passes
// over a.t_ratios). values_file is null; a shard run's driver sets it.
json sweep_summary_json(const sweep_accumulator& a, const json& run, double seconds);
// The parts of a summary that a merge must reproduce exactly (drops seconds, run, values_file,
// values_check).
json sweep_summary_core(json summary);
// The summary as `gyrores sweep` and `gyrores merge` print it.
std::string sweep_summary_text(const json& summary);

// A complete shard summary with its values file, read back for a merge (its run as this version
// writes it: sweep_run_of_version); usage_error if it is not one (not JSON, not a summary,
// unfinished, or without values file) or of a version sweep_run_of_version refuses.
sweep_input sweep_read_summary(const std::string& path);

}  // namespace gyrores
