// `gyrores merge`: the outputs of the shards of one sweep (rows files, or shard summaries with
// their values files) combined into the summary a single run gives. What is checked:
// docs/formats.md (merge).
#pragma once
#include <string>
#include <vector>

#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_run.hpp>

namespace gyrores {

// A rows file or a shard summary, told apart by its first line (sweep_read_rows,
// sweep_read_summary).
sweep_input sweep_read_output(const std::string& path);

// The summary JSON of the whole sweep (run: shard [0, 1], threads null, merged_shards N).
// usage_error unless the outputs come from one configuration, cover every shard 0..N-1 exactly
// once and (for max_order <= sweep_count_limit) each hold exactly their shard's pairs.
json sweep_merge(const std::vector<std::string>& paths);

}  // namespace gyrores
