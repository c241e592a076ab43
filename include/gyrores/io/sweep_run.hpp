// The run description of a sweep: the JSON object naming its configuration, which rows files,
// summaries and resume states carry (docs/formats.md, `{run}`), and a finished output read back.
// Inputs to a merge or a resume must agree on it (a merge: except the shard index).
#pragma once
#include <cstdint>
#include <string>
#include <type_traits>

#include <gyrores/core/real.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/sweep/sweep.hpp>

namespace gyrores {

// {min_order (at least 3), max_order, shard, checks, max_examples, type, digits, method[,
// certified: true]}; `type` is the working real type's name (sweep_type_name),
// `digits` the significant digits of its reals in rows (17 for double), `method` how the rows'
// values are computed: sweep_rows_method.
json sweep_run_json(const sweep_config& c, const std::string& type, unsigned digits);
template <class T> json sweep_run_json(const sweep_config& c) {
  return sweep_run_json(c, sweep_type_name<T>(c), std::is_same_v<T, double> ? 17u : c.digits);
}

// The format version of the three files that carry a run description: the rows' first line, the
// summary and the resume state (docs/formats.md). Version 1 (the rows' first line had no version)
// had the check cross-check, its rows column and the run's cross_check_max_order.
inline constexpr int sweep_format_version = 2;

// A run description read from a finished output of format `version` (1 or 2), as this version
// writes it: version 1's cross_check_max_order dropped (the rows' values are the same, so such
// outputs merge with version-2 ones). usage_error naming `path` for a version-1 run that checked
// cross-check, whose verdicts a summary of this version cannot carry.
json sweep_run_of_version(json run, std::int64_t version, const std::string& path);

// The run descriptions' `method`: the rows come from the lattice theorem's root (sweep/evaluate.hpp).
// Files of earlier versions (rows from the lattice method's solver) have no `method`: a resume or
// a merge refuses to mix them with these.
inline constexpr const char* sweep_rows_method = "lattice-theorem/1";

// Why a resume state or shard output described by `found` cannot continue or join the sweep
// described by `wanted` (run descriptions): one clause ("it was written by an earlier version
// ...", or the keys that differ), without a full stop.
std::string sweep_run_mismatch(const json& found, const json& wanted);

// The checks of a run description.
sweep_check_set sweep_checks_of_run(const json& run);

// The run description without what differs between the shards of one sweep or between a run
// and its merge (shard, threads, complete, merged_shards).
json sweep_run_identity(json run);

// A finished sweep output read back (rows file or shard summary), for a merge.
struct sweep_input {
  std::string path;
  json run;               // the run description (shard included)
  sweep_accumulator acc;  // with every t_first/proxy value
  double seconds = 0;
};

}  // namespace gyrores
