// The files holding a sweep's t_first/(pi/|n|) values (docs/formats.md, values file), read back
// in pieces, never whole (10 GB at order 10^5):
//  - raw: doubles in host byte order and nothing else: the resume state's STATE.values, to which
//    a running sweep appends as its values pile up (sweep_files.hpp);
//  - a shard summary's values file: "GYRVAL01", the count (uint64, host byte order), the doubles.
#pragma once
#include <cstdint>
#include <string>

#include <gyrores/io/json.hpp>
#include <gyrores/sweep/values.hpp>

namespace gyrores {

// What a shard summary records of its values file ("values_check", docs/formats.md) and merge
// compares: the count, the smallest and largest value, and the FNV-1a 64-bit hash of the
// doubles' bytes (host order). A file swapped for another shard's, or edited, differs in one of
// them (FNV-1a guards against accidents, not against a forger: the summary is not signed).
json sweep_values_digest(const sweep_values& v);

// Replays `count` doubles of `path` from byte `offset` (a usage_error at replay if the file is
// shorter or unreadable by then).
sweep_value_source sweep_values_file_source(const std::string& path, std::uint64_t offset, std::uint64_t count);

// Writes every value of v as a values file (header, count, doubles), atomically; returns the
// digest of what it wrote (sweep_values_digest).
json sweep_write_values_file(const std::string& path, const sweep_values& v);

// The values of a values file, as a source; usage_error if it is not one or its length
// disagrees with its count.
sweep_values sweep_read_values_file(const std::string& path);

}  // namespace gyrores
