// 'gyrores sweep' and 'gyrores merge' as a user meets them: the summary on stdout, the JSON
// file, shards merged by the CLI equal to the single run, SIGINT then --resume, usage errors.
// Skipped when the CLI is not built (GYRORES_CLI_PATH empty).
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include <algorithm>

#include <gyrores/io/sweep_io.hpp>

#ifndef GYRORES_CLI_PATH
#define GYRORES_CLI_PATH ""
#endif

namespace {

bool cli_built() { return !std::string(GYRORES_CLI_PATH).empty(); }

struct run_result {
  int status;
  std::string out, err;
};

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

run_result run(const std::string& args) {
  std::string errfile = "/tmp/gyrores_test_sweep_cli_stderr_" + std::to_string(::getpid());
  std::string cmd = std::string(GYRORES_CLI_PATH) + " " + args + " 2>" + errfile;
  FILE* p = ::popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  std::string out;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  int st = ::pclose(p);
  std::string err = slurp(errfile);
  std::remove(errfile.c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out, err};
}

struct temp_dir {
  std::string path;
  temp_dir() {
    char tmpl[] = "/tmp/gyrores_test_sweep_cli_XXXXXX";
    char* p = ::mkdtemp(tmpl);
    REQUIRE(p != nullptr);
    path = p;
  }
  ~temp_dir() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string operator/(const std::string& name) const { return path + "/" + name; }
};

bool exists(const std::string& p) { return ::access(p.c_str(), F_OK) == 0; }

std::string without_last_line(const std::string& s) {
  if (s.empty()) return s;
  auto cut = s.rfind('\n', s.size() - 2);
  return cut == std::string::npos ? std::string() : s.substr(0, cut + 1);
}

gyrores::sweep_json core_of(const std::string& path) {
  return gyrores::sweep_summary_core(gyrores::sweep_json::parse(slurp(path)));
}

}  // namespace

TEST_CASE("sweep CLI: summary on stdout and as JSON; rows file", "[cli][sweep]") {
  if (!cli_built()) return;
  temp_dir d;
  auto r = run("sweep --max-order 60 --quiet --summary " + d / "s.json" + " --out " + d / "rows.csv");
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("pairs visited       550") != std::string::npos);
  CHECK(r.out.find("degenerate pairs    95") != std::string::npos);
  CHECK(r.out.find("asy-bound           0 / 274") != std::string::npos);
  auto j = gyrores::sweep_json::parse(slurp(d / "s.json"));
  CHECK(j["pairs"] == 550);
  CHECK(j["degenerate"] == 95);
  CHECK(j["checks"]["degeneracy"]["violations"] == 0);
  CHECK(j["asy_ratio_max"]["pair"] == gyrores::sweep_json::array({30, 29}));
  CHECK(j["t_first_over_proxy"]["median"].is_string());
  CHECK(j["seconds"].is_number());
  CHECK(exists(d / "rows.csv"));
  CHECK_FALSE(exists(d / "rows.csv.part"));
  CHECK_FALSE(exists(d / "rows.csv.resume"));
  // --check restricts the checks (and their columns).
  auto r2 = run("sweep --max-order 40 --quiet --check degeneracy,structure --out " + d / "r2.jsonl");
  REQUIRE(r2.status == 0);
  CHECK(r2.out.find("paper-node") == std::string::npos);
  std::istringstream rows(slurp(d / "r2.jsonl"));
  std::string first, second;
  std::getline(rows, first);
  std::getline(rows, second);
  auto row = gyrores::sweep_json::parse(second);
  CHECK(row["tau"] == 2);
  CHECK(row["check_degeneracy"] == "pass");
  CHECK(row["check_asy_bound"].is_null());
  CHECK(row["asy_ratio"].is_null());
}

TEST_CASE("sweep CLI: 4 shards merged by 'gyrores merge' equal the single run", "[cli][sweep]") {
  if (!cli_built()) return;
  temp_dir d;
  REQUIRE(run("sweep --max-order 120 --quiet --summary " + d / "single.json").status == 0);
  std::string sums, rows;
  for (int i = 0; i < 4; ++i) {
    std::string s = d / ("s" + std::to_string(i) + ".json"), o = d / ("r" + std::to_string(i) + ".csv");
    auto r = run("sweep --max-order 120 --quiet --threads 1 --shard " + std::to_string(i) + "/4 --summary " + s +
                 " --out " + o);
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
  CHECK_FALSE(exists(d / "m3.json"));
}

TEST_CASE("sweep CLI: SIGINT stops cleanly and --resume completes the same rows", "[cli][sweep]") {
  if (!cli_built()) return;
  temp_dir d;
  // ~2600 pairs at orders 270..300, each cross-checked (~1 ms): a couple of seconds on one thread.
  const std::string args = "sweep --min-order 270 --max-order 300 --check cross-check,structure --threads 1 --quiet";
  const std::string out = d / "rows.csv";
  pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    int fd = ::open((d / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int fe = ::open((d / "stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fe, 2);
    std::string cmd = std::string(GYRORES_CLI_PATH) + " " + args + " --out " + out;
    ::execl("/bin/sh", "sh", "-c", ("exec " + cmd).c_str(), (char*)nullptr);
    ::_exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  ::kill(pid, SIGINT);
  int st = 0;
  ::waitpid(pid, &st, 0);
  REQUIRE(WIFEXITED(st));
  CHECK(WEXITSTATUS(st) == 3);
  CHECK(slurp(d / "stdout").empty());
  CHECK(slurp(d / "stderr").find("--resume") != std::string::npos);
  CHECK_FALSE(exists(out));
  CHECK(exists(out + ".part"));
  CHECK(exists(out + ".resume"));

  auto r = run(args + " --out " + out + " --resume");
  REQUIRE(r.status == 0);
  CHECK(exists(out));
  CHECK_FALSE(exists(out + ".resume"));
  auto full = run(args + " --out " + d / "full.csv");
  REQUIRE(full.status == 0);
  CHECK(without_last_line(slurp(out)) == without_last_line(slurp(d / "full.csv")));
}

TEST_CASE("sweep CLI: bad input exits 2 with one line on stderr", "[cli][sweep]") {
  if (!cli_built()) return;
  temp_dir d;
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
