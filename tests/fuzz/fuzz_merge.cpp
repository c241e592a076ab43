// Fuzz target: the inputs of `gyrores merge` (io/sweep_summary.hpp): up to four shard outputs,
// each a rows file or a shard summary with its values file. The input holds the files in the
// order p0, p0.values, p1, p1.values, ... separated by fuzz_support.hpp's file_separator; they
// are written as p<k>.json and p<k>.json.values in the scratch directory and merged. Anything
// that does not fit together must give usage_error.
#include <gyrores/core/error.hpp>
#include <gyrores/io/sweep_summary.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  namespace fz = gyrores::fuzz;
  const auto parts = fz::split(fz::as_text(data, size), fz::file_separator, 8);
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < parts.size(); k += 2) {
    const std::string name = "p" + std::to_string(k / 2) + ".json";
    paths.push_back(fz::scratch_file(name, parts[k]));
    fz::scratch_file(name + ".values", k + 1 < parts.size() ? parts[k + 1] : "");
  }
  try {
    (void)gyrores::sweep_merge(paths);
  } catch (const gyrores::usage_error&) {
  }
  return 0;
}
