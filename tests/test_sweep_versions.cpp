// Sweep files of format version 1 (docs/formats.md: the check cross-check, its rows column and
// the run's cross_check_max_order), as the CLI of commit 9cd03bc wrote them (tests/fixtures/):
// a merge reads them, alone or beside version-2 files, into the summary a version-2 run gives;
// one that ran the cross-check, or of an unknown version, is refused in one line naming the
// version. (Resume states of version 1 are refused: tests/test_sweep.cpp.)
#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <vector>

#include <gyrores/app/sweep.hpp>
#include <gyrores/io/sweep_files.hpp>
#include <gyrores/io/sweep_summary.hpp>

#include "testing/cli_run.hpp"
#include "sweep_summary_core.hpp"

using namespace gyrores;
using gyrores::test::read_text;
using gyrores::test::temp_dir;

namespace {

const std::string v1 = std::string(GYRORES_TEST_FIXTURES) + "/sweep_v1/";

// The summary of a version-2 run to order 20 in double: shard `index` of `count`, its rows (and,
// for a shard, its summary) written to dir.
json run_v2(const temp_dir& d, const std::string& name, std::int64_t index = 0, std::int64_t count = 1) {
  sweep_config c;
  c.max_order = 20;
  c.shard_index = index;
  c.shard_count = count;
  sweep_files f;
  f.rows_path = d / (name + ".csv");
  f.summary_path = d / (name + ".json");
  sweep_engine_options e;
  e.threads = 1;
  const auto rep = app::sweep_to_files<double>(c, f, e);
  REQUIRE(rep.complete);
  return rep.summary;
}

std::string merge_error(const std::vector<std::string>& paths) {
  try {
    sweep_merge(paths);
  } catch (const usage_error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("sweep versions: version-1 rows files and shard summaries merge into a version-2 run's summary", "[sweep]") {
  temp_dir d("test_sweep_versions");
  const json want = sweep_summary_core(run_v2(d, "single"));
  REQUIRE(want["version"] == 2);
  for (const auto& inputs : {std::vector<std::string>{v1 + "rows0.csv", v1 + "rows1.csv"},
                             std::vector<std::string>{v1 + "summary0.json", v1 + "summary1.json"},
                             std::vector<std::string>{v1 + "summary1.json", v1 + "rows0.csv"}}) {
    INFO(inputs[0] << " " << inputs[1]);
    const json merged = sweep_merge(inputs);
    CHECK(sweep_summary_core(merged) == want);
    CHECK_FALSE(merged["run"].contains("cross_check_max_order"));  // the old field, ignored
  }
  // A shard of each version: the rows' values are the same, so they merge too.
  run_v2(d, "shard1", 1, 2);
  CHECK(sweep_summary_core(sweep_merge({v1 + "rows0.csv", d / "shard1.csv"})) == want);
  CHECK(sweep_summary_core(sweep_merge({d / "shard1.json", v1 + "summary0.json"})) == want);
  // The version-2 rows file says its version in its first line.
  CHECK(read_text(d / "shard1.csv").rfind("# gyrores-sweep-rows/2 {", 0) == 0);
}

TEST_CASE("sweep versions: a version-1 output that ran the cross-check, or an unknown version, is refused", "[sweep]") {
  const std::string crossed = merge_error({v1 + "cross_check.jsonl"});
  INFO(crossed);
  CHECK(crossed.find("cross_check.jsonl' (sweep format version 1) ran the check cross-check") != std::string::npos);
  CHECK(crossed.find('\n') == std::string::npos);
  temp_dir d("test_sweep_versions");
  run_v2(d, "single");
  std::string rows = read_text(d / "single.csv");
  rows.replace(0, std::string("# gyrores-sweep-rows/2").size(), "# gyrores-sweep-rows/3");
  std::ofstream(d / "v3.csv") << rows;
  const std::string later = merge_error({d / "v3.csv"});
  INFO(later);
  CHECK(later.find("is a sweep output of format version 3, which this gyrores does not read") != std::string::npos);
  std::ofstream(d / "bad.csv") << "# gyrores-sweep-rows/x {}\n";
  CHECK(merge_error({d / "bad.csv"}).find("is not a gyrores sweep rows file") != std::string::npos);
}
