// gyrores merge FILES... [--summary OUT] [--json]
// Combines the outputs of the shards of one sweep (row files written with --out, or shard
// summaries written with --summary, which come with SUMMARY.values) into the summary a single
// run gives. What each file holds and what is checked: docs/formats.md (merge).
#include <memory>

#include <gyrores/io/files.hpp>
#include <gyrores/io/sweep_merge.hpp>
#include <gyrores/io/sweep_summary.hpp>

#include "cli_output.hpp"
#include "cli_options.hpp"
#include "commands.hpp"

namespace gyrores::cli {
namespace {

struct merge_args {
  std::vector<std::string> files;
  std::string summary;
  bool json = false;
};

std::string run_merge(const merge_args& a) {
  // Before reading anything: the output is writable, is none of the inputs (nor their values
  // files), and no other run writes it; the inputs are checked by sweep_merge.
  path_lock lock;
  if (!a.summary.empty()) {
    // The lock file too: merge writes and removes it (an input named OUT.lock would be lost).
    std::vector<named_path> paths{{"--summary", a.summary}, {"the lock file of --summary", path_lock_file(a.summary)}};
    for (const auto& f : a.files) {
      paths.push_back({"input", f});
      paths.push_back({"the values file of input", f + ".values"});
    }
    check_distinct_paths(paths);
    check_output_path(a.summary);
    lock = path_lock::acquire(a.summary);
  }
  json s = sweep_merge(a.files);
  if (!a.summary.empty()) write_file_atomically(a.summary, s.dump(2) + "\n");
  if (a.json) return s.dump(2) + "\n";
  return sweep_summary_text(s);
}

command_runner install_merge(CLI::App& app) {
  auto a = std::make_shared<merge_args>();
  auto sub = options(app).subcommand("merge", "Combine the shard outputs of a sweep into one summary");
  sub.add("FILES", a->files, "row files (--out) or shard summaries (--summary) of every shard", show::required);
  sub.add("--summary", a->summary, "write the merged summary as JSON to this file");
  sub.flag("--json", a->json, "print the merged summary as JSON instead of text");
  return [a] { return run_merge(*a); };
}

const command_registration registration{"merge", install_merge};

}  // namespace
}  // namespace gyrores::cli
