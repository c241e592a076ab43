// 'gyrores sweep' and 'gyrores merge' as a user meets them: the summary on stdout, the JSON
// file, shards merged by the CLI equal to the single run, SIGINT or SIGKILL then --resume, usage
// errors. Skipped when the CLI is not built (cli_available()).
#include <catch2/catch.hpp>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_summary.hpp>

#include "testing/cli_run.hpp"

using gyrores::json;
using gyrores::test::cli_available;
using gyrores::test::cli_result;
using gyrores::test::path_exists;
using gyrores::test::read_text;
using gyrores::test::temp_dir;

namespace {

cli_result run(const std::string& args) { return gyrores::test::cli_run(args); }

// The file without its last line (the end line carries the run time).
std::string without_last_line(const std::string& s) {
  if (s.empty()) return s;
  auto cut = s.rfind('\n', s.size() - 2);
  return cut == std::string::npos ? std::string() : s.substr(0, cut + 1);
}

json core_of(const std::string& path) { return gyrores::sweep_summary_core(json::parse(read_text(path))); }

}  // namespace

TEST_CASE("sweep CLI: summary on stdout and as JSON; rows file", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  auto r = run("sweep --max-order 60 --quiet --summary " + d / "s.json" + " --out " + d / "rows.csv");
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("pairs visited       550") != std::string::npos);
  CHECK(r.out.find("degenerate pairs    95") != std::string::npos);
  CHECK(r.out.find("asy-bound           0 / 274") != std::string::npos);
  auto j = json::parse(read_text(d / "s.json"));
  CHECK(j["pairs"] == 550);
  CHECK(j["degenerate"] == 95);
  CHECK(j["checks"]["degeneracy"]["violations"] == 0);
  CHECK(j["asy_ratio_max"]["pair"] == json::array({30, 29}));
  CHECK(j["t_first_over_proxy"]["median"].is_string());
  CHECK(j["seconds"].is_number());
  CHECK(path_exists(d / "rows.csv"));
  CHECK_FALSE(path_exists(d / "rows.csv.part"));
  CHECK_FALSE(path_exists(d / "rows.csv.resume"));
  // --check restricts the checks (and their columns).
  auto r2 = run("sweep --max-order 40 --quiet --check degeneracy,structure --out " + d / "r2.jsonl");
  REQUIRE(r2.status == 0);
  CHECK(r2.out.find("paper-node") == std::string::npos);
  std::istringstream rows(read_text(d / "r2.jsonl"));
  std::string first, second;
  std::getline(rows, first);
  std::getline(rows, second);
  auto row = json::parse(second);
  CHECK(row["tau"] == 2);
  CHECK(row["check_degeneracy"] == "pass");
  CHECK(row["check_asy_bound"].is_null());
  CHECK(row["asy_ratio"].is_null());
}

TEST_CASE("sweep CLI: 4 shards merged by 'gyrores merge' equal the single run", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  REQUIRE(run("sweep --max-order 120 --quiet --summary " + d / "single.json").status == 0);
  std::string sums, rows;
  for (int i = 0; i < 4; ++i) {
    const std::string n = std::to_string(i), s = d / ("s" + n + ".json"), o = d / ("r" + n + ".csv");
    auto r = run("sweep --max-order 120 --quiet --threads 1 --shard " + n + "/4 --summary " + s + " --out " + o);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("shard " + std::to_string(i) + "/4") != std::string::npos);
    sums += " " + s;
    rows += " " + o;
  }
  auto m1 = run("merge" + sums + " --summary " + d / "m1.json");
  REQUIRE(m1.status == 0);
  CHECK(m1.out.find("merged from 4 shards") != std::string::npos);
  auto m2 = run("merge" + rows + " --summary " + d / "m2.json");
  REQUIRE(m2.status == 0);
  const auto want = core_of(d / "single.json");
  CHECK(core_of(d / "m1.json") == want);
  CHECK(core_of(d / "m2.json") == want);
  // Missing shard: usage error, nothing written.
  auto bad = run("merge " + d / "s0.json " + d / "s1.json --summary " + d / "m3.json");
  CHECK(bad.status == 2);
  CHECK(bad.out.empty());
  CHECK(bad.err.find("missing") != std::string::npos);
  CHECK_FALSE(path_exists(d / "m3.json"));
}

TEST_CASE("sweep CLI: SIGINT stops cleanly and --resume completes the same rows", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  // ~2600 pairs at orders 270..300, each cross-checked (~1 ms): a couple of seconds on one thread.
  const std::string args = "sweep --min-order 270 --max-order 300 --check cross-check,structure --threads 1 --quiet";
  const std::string out = d / "rows.csv";
  const int pid = gyrores::test::cli_spawn(args + " --out " + out, d / "stdout", d / "stderr");
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  ::kill(pid, SIGINT);
  REQUIRE(gyrores::test::cli_wait(pid) == 3);  // exited by itself (not killed), status 3
  CHECK(read_text(d / "stdout").empty());
  CHECK(read_text(d / "stderr").find("--resume") != std::string::npos);
  CHECK_FALSE(path_exists(out));
  CHECK(path_exists(out + ".part"));
  CHECK(path_exists(out + ".resume"));

  auto r = run(args + " --out " + out + " --resume");
  REQUIRE(r.status == 0);
  CHECK(path_exists(out));
  CHECK_FALSE(path_exists(out + ".resume"));
  auto full = run(args + " --out " + d / "full.csv");
  REQUIRE(full.status == 0);
  CHECK(without_last_line(read_text(out)) == without_last_line(read_text(d / "full.csv")));
}

TEST_CASE("sweep CLI: SIGKILL after a checkpoint, then --resume gives the uninterrupted result", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  // As above (~2600 pairs in blocks of 1024, ~1 s per block): the first checkpoint comes after
  // the first block, so the kill lands with most of the sweep still to do.
  const std::string args =
      "sweep --min-order 270 --max-order 300 --check cross-check,structure --threads 1 --quiet --checkpoint 0.05";
  const std::string out = d / "rows.csv", state = out + ".resume";
  const int pid = gyrores::test::cli_spawn(args + " --out " + out + " --summary " + d / "s.json", d / "stdout",
                                           d / "stderr");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!path_exists(state) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);
  REQUIRE(gyrores::test::cli_wait(pid) == 128 + SIGKILL);  // killed, not finished
  REQUIRE(path_exists(state));
  CHECK(json::parse(read_text(state))["done"].get<std::uint64_t>() > 0);  // a checkpoint with pairs in it
  CHECK_FALSE(path_exists(out));
  CHECK_FALSE(path_exists(d / "s.json"));

  auto r = run(args + " --out " + out + " --summary " + d / "s.json --resume");
  REQUIRE(r.status == 0);
  CHECK(path_exists(out));
  CHECK_FALSE(path_exists(state));
  CHECK_FALSE(path_exists(state + ".values"));
  auto full = run(args + " --out " + d / "full.csv --summary " + d / "full.json");
  REQUIRE(full.status == 0);
  CHECK(core_of(d / "s.json") == core_of(d / "full.json"));
  CHECK(without_last_line(read_text(out)) == without_last_line(read_text(d / "full.csv")));
  // The text summary differs only in the run time.
  auto mask_time = [](const std::string& s) { return s.substr(s.find("\n  degenerate")); };
  CHECK(mask_time(r.out) == mask_time(full.out));
}

TEST_CASE("sweep CLI: bad input exits 2 with one line on stderr", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  const std::vector<std::string> cases = {"sweep --max-order 2", "sweep --max-order 50 --min-order 60", "sweep --max-order 50 --shard 4/4",
        "sweep --max-order 50 --shard x", "sweep --max-order 50 --check bogus", "sweep --max-order 50 --format xml --out x",
        "sweep --max-order 50 --digits 0", "sweep --max-order 50 --resume --summary " + d / "none.json",
        "merge " + d / "nothing.csv"};
  for (const auto& args : cases) {
    auto r = run(args);
    INFO(args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
}
