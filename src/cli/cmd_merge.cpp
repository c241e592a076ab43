// gyrores merge FILES... [--summary OUT] [--json]
// Combines the outputs of the shards of one sweep (row files written with --out, or shard
// summaries written with --summary, which come with SUMMARY.values) into the summary a single
// run gives (app/sweep.hpp). What each file holds and what is checked: docs/formats.md (merge).
#include <memory>

#include <gyrores/app/sweep.hpp>
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
  const json s = app::run_merge(a.files, a.summary);
  return a.json ? s.dump(2) + "\n" : sweep_summary_text(s);
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
