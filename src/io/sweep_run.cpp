// include/gyrores/io/sweep_run.hpp: the run description of a sweep.
#include <gyrores/io/sweep_run.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores {

json sweep_run_json(const sweep_config& c, const std::string& type, unsigned digits) {
  json j;
  j["min_order"] = c.min_order < 3 ? 3 : c.min_order;
  j["max_order"] = c.max_order;
  j["shard"] = {c.shard_index, c.shard_count};
  j["checks"] = sweep_check_names(c.checks);
  j["max_examples"] = c.max_examples;
  j["type"] = type;
  j["digits"] = digits;
  j["method"] = sweep_rows_method;
  if (c.certified) j["certified"] = true;  // absent in uncertified runs (files of earlier versions)
  return j;
}

json sweep_run_of_version(json run, std::int64_t version, const std::string& path) {
  if (version == sweep_format_version) return run;
  if (version != 1)
    throw usage_error("'" + path + "' is a sweep output of format version " + std::to_string(version) +
                      ", which this gyrores does not read (it reads versions 1 and " +
                      std::to_string(sweep_format_version) + ")");
  for (const auto& name : run.at("checks"))
    if (name == "cross-check")
      throw usage_error("'" + path + "' (sweep format version 1) ran the check cross-check, which sweeps no longer "
                        "have: merge it with the gyrores that wrote it, or run that sweep again");
  run.erase("cross_check_max_order");
  return run;
}

sweep_check_set sweep_checks_of_run(const json& run) {
  sweep_check_set checks = 0;
  for (auto& n : run.at("checks")) checks |= sweep_parse_checks(n.get<std::string>());
  return checks;
}

json sweep_run_identity(json run) {
  run.erase("shard");
  run.erase("threads");
  run.erase("complete");
  run.erase("merged_shards");
  return run;
}

std::string sweep_run_mismatch(const json& found, const json& wanted) {
  if (!found.is_object() || !found.contains("method"))
    return "it was written by an earlier version of gyrores, whose rows came from the lattice method's solver "
           "(these come from the theorem's root, " + std::string(sweep_rows_method) + ")";
  std::string keys;
  for (const auto& [k, v] : wanted.items())
    if (!found.contains(k) || found.at(k) != v) keys += (keys.empty() ? "" : ", ") + k;
  for (const auto& [k, v] : found.items())
    if (!wanted.contains(k)) keys += (keys.empty() ? "" : ", ") + k;
  if (keys.empty()) keys = "the order of its keys";
  return "it differs in " + keys + " (" + found.dump() + " vs " + wanted.dump() + ")";
}

}  // namespace gyrores
