// The merge of include/gyrores/io/sweep_summary.hpp: shard outputs read, checked to belong
// together, merged.
#include <fstream>
#include <set>

#include <gyrores/core/error.hpp>
#include <gyrores/io/files.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/io/sweep_values_file.hpp>

namespace gyrores {
namespace {

// The run description without what differs between the shards of one sweep or between a run
// and its merge.
json sweep_run_identity(json run) {
  run.erase("shard");
  run.erase("threads");
  run.erase("complete");
  run.erase("merged_shards");
  return run;
}

std::int64_t shard_index(const sweep_input& x) { return json_to_int64(x.run.at("shard").at(0), "the shard index"); }
std::int64_t shard_count(const sweep_input& x) { return json_to_int64(x.run.at("shard").at(1), "the shard count"); }
std::string shard_text(std::int64_t i, std::int64_t n) { return std::to_string(i) + "/" + std::to_string(n); }

// The run's integers are integers of their type (the merge compares and counts with them).
void check_run_integers(const json& run) {
  json_to_int64(run.at("shard").at(0), "the shard index");
  json_to_int64(run.at("shard").at(1), "the shard count");
  json_to_int64(run.at("min_order"), "min_order");
  json_to_int64(run.at("max_order"), "max_order");
  json_to_uint64(run.at("max_examples"), "max_examples");
}

// The inputs share one configuration and one shard count, and cover 0..N-1 exactly once.
void check_one_complete_set(const std::vector<sweep_input>& in, const json& ident, std::int64_t n) {
  if (n < 1) throw usage_error("'" + in[0].path + "' names a shard count " + std::to_string(n) + " (must be >= 1)");
  std::set<std::int64_t> seen;
  for (auto& x : in) {
    if (sweep_run_identity(x.run) != ident)
      throw usage_error("'" + x.path + "' comes from a different sweep than '" + in[0].path +
                        "': " + sweep_run_mismatch(sweep_run_identity(x.run), ident));
    if (shard_count(x) != n)
      throw usage_error("'" + x.path + "' is a shard of " + std::to_string(shard_count(x)) + ", the others of " +
                        std::to_string(n));
    if (shard_index(x) < 0 || shard_index(x) >= n)
      throw usage_error("'" + x.path + "' names shard " + shard_text(shard_index(x), n) + ", outside 0.." + std::to_string(n - 1));
    if (!seen.insert(shard_index(x)).second) throw usage_error("shard " + shard_text(shard_index(x), n) + " given twice");
  }
  for (std::int64_t i = 0; i < n; ++i)
    if (!seen.count(i)) throw usage_error("shard " + shard_text(i, n) + " is missing");
}

// Each input holds exactly its shard's share of the pairs (counted when max_order <= sweep_count_limit).
void check_shares(const std::vector<sweep_input>& in, const json& ident, std::int64_t n) {
  const std::int64_t max_order = json_to_int64(ident.at("max_order"), "max_order");
  const std::int64_t min_order = json_to_int64(ident.at("min_order"), "min_order");
  if (min_order < 3 || max_order < min_order)
    throw usage_error("the shard outputs name orders " + std::to_string(min_order) + ".." + std::to_string(max_order) +
                      " (need 3 <= min_order <= max_order)");
  if (max_order > sweep_count_limit) return;
  const std::uint64_t total = sweep_total_pairs(min_order, max_order);
  for (auto& x : in) {
    const std::uint64_t share = sweep_shard_pairs(total, shard_index(x), n);
    if (x.acc.pairs != share)
      throw usage_error("'" + x.path + "' holds " + std::to_string(x.acc.pairs) + " pairs, shard " +
                        shard_text(shard_index(x), n) + " has " + std::to_string(share));
  }
}

// The merge itself: the inputs as read, checked to belong together.
json merge_inputs(const std::vector<sweep_input>& in) {
  const json ident = sweep_run_identity(in[0].run);
  const std::int64_t n = shard_count(in[0]);
  check_one_complete_set(in, ident, n);
  check_shares(in, ident, n);
  sweep_accumulator acc;
  acc.max_examples = json_to_uint64(ident.at("max_examples"), "max_examples");
  double seconds = 0;
  for (auto& x : in) {
    acc.merge(x.acc);
    seconds += x.seconds;
  }
  json run = ident;
  run["shard"] = {0, 1};
  run["threads"] = nullptr;
  run["complete"] = true;
  run["merged_shards"] = n;
  return sweep_summary_json(acc, run, seconds);
}

// A complete shard summary with its values file; usage_error if it is not one (not JSON, not a
// summary, unfinished, or without values file) or of a version that is refused.
sweep_input read_summary(const std::string& path) {
  sweep_input r;
  r.path = path;
  json j;
  try {
    j = json_parse_strict(read_file(path, sweep_json_read_limit, "a sweep summary"));
  } catch (const json::exception& e) {
    throw usage_error("'" + path + "' is not JSON: " + e.what());
  }
  if (j.value("format", "") != "gyrores-sweep-summary") throw usage_error("'" + path + "' is not a gyrores sweep summary");
  r.run = sweep_run_of_version(j.at("run"), json_to_int64(j.at("version"), "version"), path);
  if (!r.run.value("complete", false)) throw usage_error("'" + path + "' is the summary of an unfinished sweep");
  r.seconds = j.at("seconds").get<double>();
  r.acc = sweep_accumulator_from_json(j, json_to_uint64(r.run.at("max_examples"), "max_examples"));
  if (j.at("values_file").is_null())
    throw usage_error("'" + path + "' has no values file (only shard runs write one); merge the row files instead");
  std::string vf = j.at("values_file").get<std::string>();
  if (vf.find('/') == std::string::npos) {
    auto slash = path.rfind('/');
    if (slash != std::string::npos) vf = path.substr(0, slash + 1) + vf;
  }
  r.acc.t_ratios = sweep_read_values_file(vf);
  // The values file must be the one this summary was written with (merge would otherwise mix
  // another shard's values into the quantiles).
  if (!j.contains("values_check"))
    throw usage_error("'" + path + "' records no values_check for its values file (written before checksums): run that shard again");
  const json digest = sweep_values_digest(r.acc.t_ratios);
  if (digest != j.at("values_check"))
    throw usage_error("the values file '" + vf + "' does not match '" + path + "' (values_check " +
                      j.at("values_check").dump() + ", the file gives " + digest.dump() + ")");
  return r;
}

// A rows file or a shard summary, told apart by its first line.
sweep_input sweep_read_output(const std::string& path) {
  check_input_path(path);
  path_lock::check_not_written(path);
  std::ifstream in(path);
  if (!in) throw usage_error("cannot read '" + path + "'");
  std::string first;
  std::getline(in, first);
  in.close();
  // A field missing or of the wrong type is bad input: usage_error naming the file, not the JSON
  // library's exception (nor compute_error, exit 3).
  try {
    sweep_input x = first.rfind("# gyrores-sweep-rows", 0) == 0 || first.find("\"gyrores_sweep_rows\"") != std::string::npos
                        ? sweep_read_rows(path)
                        : read_summary(path);
    check_run_integers(x.run);
    return x;
  } catch (const json::exception& e) {
    throw usage_error("'" + path + "' is malformed: " + e.what());
  } catch (const json_value_error& e) {
    throw usage_error("'" + path + "' is malformed: " + e.what());
  } catch (const compute_error& e) {  // a real that does not parse (sweep/real_text): bad input here
    throw usage_error("'" + path + "' is malformed: " + e.what());
  }
}

}  // namespace

json sweep_merge(const std::vector<std::string>& paths) {
  if (paths.empty()) throw usage_error("merge needs at least one file");
  std::vector<sweep_input> in;
  for (auto& p : paths) in.push_back(sweep_read_output(p));
  try {
    return merge_inputs(in);
  } catch (const json::exception& e) {
    throw usage_error("the shard outputs are malformed: " + std::string(e.what()));
  } catch (const json_value_error& e) {
    throw usage_error("the shard outputs are malformed: " + std::string(e.what()));
  }
}

}  // namespace gyrores
