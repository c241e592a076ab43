// The parts of a sweep summary that a merge, a resume or another thread count must reproduce
// exactly: without seconds, run, values_file and values_check (docs/formats.md, merge).
#pragma once
#include <gyrores/io/json.hpp>
#include <gyrores/sweep/checks.hpp>

namespace gyrores {

inline json sweep_summary_core(json j) {
  j.erase("seconds");
  j.erase("run");
  j.erase("values_file");
  j.erase("values_check");
  return j;
}

// Shard `index` of `count` of the sweep c.
inline sweep_config shard_of(sweep_config c, int index, int count) {
  c.shard_index = index;
  c.shard_count = count;
  return c;
}

}  // namespace gyrores
