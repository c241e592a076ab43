// 'gyrores sweep' and 'gyrores merge' as a user meets them: the summary on stdout, the JSON
// file, shards merged by the CLI equal to the single run, SIGINT or SIGKILL then --resume (once,
// and 20 times at random moments), a full disk, usage errors. Skipped when the CLI is not built
// (cli_available()).
#include <catch2/catch.hpp>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_summary.hpp>

#include "testing/cli_run.hpp"
#include "sweep_summary_core.hpp"

using gyrores::json;
using namespace gyrores::test;  // cli_run.hpp: the CLI runner and temporary files

namespace {

cli_result run(const std::string& args) { return gyrores::test::cli_run(args); }

// The file without its last line (the end line carries the run time).
std::string without_last_line(const std::string& s) {
  if (s.empty()) return s;
  auto cut = s.rfind('\n', s.size() - 2);
  return cut == std::string::npos ? std::string() : s.substr(0, cut + 1);
}

json core_of(const std::string& path) { return gyrores::sweep_summary_core(json::parse(read_text(path))); }

// A summary file's text with the value of its "seconds" line (the run time) blanked: everything
// else must match byte for byte.
std::string without_seconds(std::string s) {
  const auto at = s.find("\n  \"seconds\": ");
  if (at == std::string::npos) return s;
  const auto end = s.find('\n', at + 1);
  return s.erase(at, end - at);
}

// The names in a directory, sorted.
std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> v;
  for (auto& e : std::filesystem::directory_iterator(dir)) v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

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
  CHECK(j["checks"].size() == 4);  // the default checks
  CHECK(j["version"] == 2);
  CHECK(j["run"]["method"] == "lattice-theorem/1");
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
  // The cross-check of format version 1 is gone from sweeps: asked for, it is refused naming why.
  auto r3 = run("sweep --max-order 40 --quiet --check all,cross-check --json");
  CHECK(r3.status == 2);
  CHECK(r3.err.find("no longer part of sweeps") != std::string::npos);
  // MPFR rows on every thread asked for, the same summary as on one.
  auto m1 = run("sweep --max-order 60 --digits 40 --threads 1 --quiet --json");
  auto m2 = run("sweep --max-order 60 --digits 40 --threads 2 --quiet --json");
  REQUIRE(m1.status == 0);
  REQUIRE(m2.status == 0);
  const auto s1 = json::parse(m1.out), s2 = json::parse(m2.out);
  CHECK(s2["run"]["threads"] == 2);
  CHECK(s2["run"]["type"] == "mpfr(161 bits)");
  CHECK(gyrores::sweep_summary_core(s1) == gyrores::sweep_summary_core(s2));
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
  // ~2600 pairs at orders 270..300, each in MPFR at 1000 digits (~0.5 ms): about a second on one
  // thread.
  const std::string args = "sweep --min-order 270 --max-order 300 --digits 1000 --threads 1 --quiet";
  const std::string out = d / "rows.csv";
  const int pid = gyrores::test::cli_spawn(args + " --out " + out, d / "stdout", d / "stderr");
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  ::kill(pid, SIGINT);
  REQUIRE(gyrores::test::cli_wait(pid) == 130);  // exited by itself (not killed), status 130 (interrupted)
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
  // As above (~2600 pairs in blocks of 1024, ~0.5 s per block): the first checkpoint comes after
  // the first block, so the kill lands with most of the sweep still to do.
  const std::string args =
      "sweep --min-order 270 --max-order 300 --digits 1000 --threads 1 --quiet --checkpoint 0.05";
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

TEST_CASE("sweep CLI: 20 SIGKILLs at random moments, each resumed, give the uninterrupted files", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  // ~55000 pairs of orders 3..600 in double: a block of 1024 pairs takes ~10 ms, a
  // checkpoint follows every block, the whole sweep about half a second, so 20 kills 0-80 ms
  // after the start land anywhere: before the first checkpoint (no state yet: the next run
  // starts afresh), inside a block or a checkpoint, during the end (summary, rows renamed,
  // state removed), or after it (the run finished: the next one starts afresh).
  const std::string args = "sweep --max-order 600 --check structure,degeneracy,paper-node --threads 1 --quiet";
  const std::string files = " --out " + d / "rows.csv" + " --summary " + d / "s.json";
  const std::string state = d / "rows.csv.resume";
  auto full = run(args + " --out " + d / "full.csv --summary " + d / "full.json");
  REQUIRE(full.status == 0);

  const char* seed_env = std::getenv("GYRORES_TEST_SEED");
  const unsigned seed = seed_env ? unsigned(std::strtoul(seed_env, nullptr, 10)) : std::random_device{}();
  WARN("SIGKILL test seed " << seed << " (GYRORES_TEST_SEED=" << seed << " repeats it)");
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> delay_us(0, 80000);
  int kills = 0, fresh_starts = 0, runs = 0;
  bool finished = false;
  while (!finished && runs < 200) {
    ++runs;
    const bool resume = path_exists(state);
    if (!resume) ++fresh_starts;
    const int pid = gyrores::test::cli_spawn(args + " --checkpoint 0.001" + files + (resume ? " --resume" : ""),
                                             d / "stdout", d / "stderr");
    // 20 kills first; later runs are left to finish.
    if (kills < 20) {
      std::this_thread::sleep_for(std::chrono::microseconds(delay_us(rng)));
      ::kill(pid, SIGKILL);
    }
    const int status = gyrores::test::cli_wait(pid);
    INFO("run " << runs << (resume ? " (resumed)" : " (fresh)") << ": status " << status << ", stderr "
                << read_text(d / "stderr"));
    if (status == 128 + SIGKILL) {
      ++kills;
      continue;
    }
    REQUIRE(status == 0);
    finished = kills >= 20;  // a run that ended before its kill: the next one starts afresh
    if (!finished) {
      std::filesystem::remove(d / "rows.csv");
      std::filesystem::remove(d / "s.json");
    }
  }
  WARN(kills << " kills, " << fresh_starts << " fresh starts, " << runs << " runs");
  REQUIRE(finished);
  CHECK(kills >= 20);
  CHECK(without_seconds(read_text(d / "s.json")) == without_seconds(read_text(d / "full.json")));
  CHECK(without_last_line(read_text(d / "rows.csv")) == without_last_line(read_text(d / "full.csv")));
  CHECK_FALSE(path_exists(state));
  CHECK_FALSE(path_exists(state + ".values"));
  CHECK_FALSE(path_exists(d / "rows.csv.part"));
  // Temporaries of atomic writes that a kill interrupted are gone too (io/files.hpp).
  for (const auto& e : std::filesystem::directory_iterator(d.path()))
    CHECK(e.path().filename().string().find(".tmp.") == std::string::npos);
}

TEST_CASE("sweep CLI: a run killed after renaming its rows, before removing the state, resumes", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  // The last steps of a sweep: summary written, rows file renamed, state removed. A kill between
  // the last two leaves a state with the rows already under their final name.
  const std::string args = "sweep --max-order 80 --quiet --threads 1 --out " + d / "rows.csv" + " --summary " + d / "s.json";
  REQUIRE(run(args + " --max-pairs 500").status == 4);  // stopped early as asked: a state at 500 pairs
  std::filesystem::copy_file(d / "rows.csv.resume", d / "saved.state");
  std::filesystem::copy_file(d / "rows.csv.resume.values", d / "saved.values");
  REQUIRE(run(args + " --resume").status == 0);
  const std::string rows = read_text(d / "rows.csv"), summary = read_text(d / "s.json");
  std::filesystem::copy_file(d / "saved.state", d / "rows.csv.resume");
  std::filesystem::copy_file(d / "saved.values", d / "rows.csv.resume.values");
  auto r = run(args + " --resume");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(without_last_line(read_text(d / "rows.csv")) == without_last_line(rows));
  CHECK(without_seconds(read_text(d / "s.json")) == without_seconds(summary));
  CHECK_FALSE(path_exists(d / "rows.csv.part"));
  CHECK_FALSE(path_exists(d / "rows.csv.resume"));
}

TEST_CASE("sweep CLI: a full disk gives one clear line and no truncated output file", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  // Every file the command writes is limited to 8000 bytes (RLIMIT_FSIZE: writes beyond fail
  // with EFBIG, as they fail with ENOSPC on a full disk). The rows of order <= 60 take ~40 kB.
  auto check_failed = [&](const std::string& args, const std::string& path) {
    const int pid = gyrores::test::cli_spawn(args, d / "stdout", d / "stderr", 8000);
    const int status = gyrores::test::cli_wait(pid);
    const std::string err = read_text(d / "stderr");
    INFO(args << "\nstderr: " << err);
    CHECK(status == 2);
    CHECK(read_text(d / "stdout").empty());
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
    CHECK(err.find("cannot write '" + path) != std::string::npos);
    CHECK(err.find("File too large") != std::string::npos);
    CHECK_FALSE(path_exists(path));
  };
  // The rows file: written as rows.csv.part, renamed only when complete.
  check_failed("sweep --max-order 60 --quiet --out " + d / "rows.csv" + " --summary " + d / "s.json", d / "rows.csv");
  CHECK_FALSE(path_exists(d / "s.json"));
  // Whole files replaced atomically (temp file, fsync, rename): the JSON summary of a sweep
  // (~5 kB) fits, a certificate at 5000 digits (~60 kB) does not.
  check_failed("certify 6 5 --digits 5000 --out " + d / "c.json", d / "c.json");
  // Nothing else is left behind: no temp file, no summary, and no resume state (a stream that
  // failed a write is never checkpointed, io/files.hpp); the rows' part stays, as after a kill.
  CHECK(names_in(d) == std::vector<std::string>{"rows.csv.part", "stderr", "stdout"});
}

TEST_CASE("sweep CLI: bad input exits 2 with one line on stderr", "[cli][sweep]") {
  if (!cli_available()) return;
  temp_dir d("test_sweep_cli");
  const std::vector<std::string> cases = {"sweep --max-order 2", "sweep --max-order 50 --min-order 60", "sweep --max-order 50 --shard 4/4",
        "sweep --max-order 50 --shard x", "sweep --max-order 50 --check bogus", "sweep --max-order 50 --format xml --out x",
        "sweep --max-order 50 --digits 0", "sweep --max-order 50 --resume --summary " + d / "none.json",
        "sweep --max-order 50 --check cross-check", "sweep --max-order 50 --cross-check-max-order 300",
        "merge " + d / "nothing.csv"};
  for (const auto& args : cases) {
    auto r = run(args);
    INFO(args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
}
