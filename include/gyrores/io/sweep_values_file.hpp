// The files holding a sweep's t_first/(pi/|n|) values (docs/formats.md, values file), read back
// in pieces, never whole (10 GB at order 10^5): the resume state's raw STATE.values (doubles in
// host byte order, appended to as they pile up) and a shard summary's values file ("GYRVAL01",
// the count, the doubles).
#pragma once
#include <cstdint>
#include <string>

#include <gyrores/io/json.hpp>
#include <gyrores/sweep/values.hpp>

namespace gyrores {

// The "values_check" a shard summary records of its values file and a merge compares: the count,
// the smallest and largest value, and the FNV-1a 64-bit hash of the doubles' bytes (against
// accidents, not a forger: the summary is not signed).
json sweep_values_digest(const sweep_values& v);

// Replays `count` doubles of `path` from byte `offset` (usage_error at replay if it is shorter).
sweep_value_source sweep_values_file_source(const std::string& path, std::uint64_t offset, std::uint64_t count);

// Writes v as a values file, atomically; returns its digest.
json sweep_write_values_file(const std::string& path, const sweep_values& v);

// usage_error if `path` is not a values file or its length disagrees with its count.
sweep_values sweep_read_values_file(const std::string& path);

}  // namespace gyrores
