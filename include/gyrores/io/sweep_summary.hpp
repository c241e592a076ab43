// The summary of a sweep as JSON (`--summary`, `--json`, `gyrores merge`) and as text, the
// accumulator <-> JSON (summaries and resume states), and the merge of shard outputs (rows files,
// or shard summaries read back with their values files). Keys and what a merge checks:
// docs/formats.md.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_rows.hpp>
#include <gyrores/sweep/sweep.hpp>

namespace gyrores {

// Everything but the t_first/proxy values, the checks in `checks` listed (the others are zero).
json sweep_accumulator_json(const sweep_accumulator& a, sweep_check_set checks);
// The inverse (t_ratios left empty); nlohmann's exceptions on missing keys.
sweep_accumulator sweep_accumulator_from_json(const json& j, std::size_t max_examples);

// The summary of a finished sweep (a few passes over a.t_ratios for the quantiles); values_file
// is null (a shard run's driver sets it).
json sweep_summary_json(const sweep_accumulator& a, const json& run, double seconds);
// As `gyrores sweep` and `gyrores merge` print it.
std::string sweep_summary_text(const json& summary);

// The summary of the whole sweep from its shards' rows files or summaries (run: shard [0, 1],
// threads null, merged_shards N). usage_error unless they come from one configuration, cover
// every shard 0..N-1 once and (max_order <= sweep_count_limit) each hold exactly their pairs.
json sweep_merge(const std::vector<std::string>& paths);

}  // namespace gyrores
