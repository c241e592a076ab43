// The CLI never loses, corrupts or misreports a user's files (issue "safe files", docs/testing.md,
// "Files and exit statuses"): each case below was found by trying the CLI as a careless or
// unlucky user would, and must now end in one line on stderr and a non-zero exit (or the correct
// result), with the user's files intact. Real processes throughout (src/testing/cli_run.hpp).
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_summary.hpp>

#include "testing/cli_run.hpp"
#include "sweep_summary_core.hpp"

using gyrores::json;
using namespace gyrores::test;  // cli_run.hpp: the CLI runner and temporary files
namespace fs = std::filesystem;

namespace {

cli_result run(const std::string& args) { return gyrores::test::cli_run(args); }

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// One line on stderr naming the problem, nothing on stdout.
void check_refused(const cli_result& r, int status, const std::string& part) {
  INFO("stderr: " << r.err);
  CHECK(r.status == status);
  CHECK(r.out.empty());
  CHECK(gyrores::test::count_lines(r.err) == 1);
  CHECK(has(r.err, part));
}

json core_of(const std::string& path) { return gyrores::sweep_summary_core(json::parse(read_text(path))); }

}  // namespace

TEST_CASE("safe files: stdout that cannot be written is exit 2, never a silent 0", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  for (const std::string& args : std::vector<std::string>{"certify 6 5 >/dev/full", "pair 6 5 --json >/dev/full", "pair 6 5 --json >&-",
                                 "sweep --max-order 40 --json --quiet --state " + d / "s1" + " >/dev/full",
                                 "sweep --max-order 40 --json --quiet --state " + d / "s2" + " >&-", "certify 6 5 >&-",
                                 "--version >/dev/full"}) {
    INFO(args);
    check_refused(run(args), 2, "cannot write to stdout");
  }
  REQUIRE(run("certify 6 5 --out " + d / "c.json").status == 0);
  check_refused(run("check " + d / "c.json" + " >/dev/full"), 2, "cannot write to stdout");
  // With stdout closed, the certificate (opened on the lowest free descriptor) gets no stray text.
  REQUIRE(run("certify 6 5 --out " + d / "closed.json" + " >&-").status == 0);
  CHECK(read_text(d / "closed.json") == read_text(d / "c.json"));
}

TEST_CASE("safe files: two paths naming one file are refused before any work", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  const std::string q = " --quiet --threads 1";
  REQUIRE(run("sweep --max-order 60 --shard 0/2 --out " + d / "r0.csv" + q).status == 0);
  REQUIRE(run("sweep --max-order 60 --shard 1/2 --out " + d / "r1.csv" + q).status == 0);
  const std::string shard0 = read_text(d / "r0.csv");
  check_refused(run("merge " + d / "r0.csv " + d / "r1.csv --summary " + d / "r0.csv"), 2, "are the same file");
  CHECK(read_text(d / "r0.csv") == shard0);
  // The same file by another spelling, and by a hard link (device + inode).
  check_refused(run("merge " + d / "r0.csv " + d / "r1.csv --summary " + d.path() + "/./r1.csv"), 2, "are the same file");
  fs::create_hard_link(d / "r0.csv", d / "hard.json");
  check_refused(run("merge " + d / "r0.csv " + d / "r1.csv --summary " + d / "hard.json"), 2, "are the same file");
  CHECK(read_text(d / "r0.csv") == shard0);

  check_refused(run("sweep --max-order 60 --out " + d / "o.csv --state " + d / "o.csv" + q), 2, "are the same file");
  check_refused(run("sweep --max-order 60 --out " + d / "x.json --summary " + d / "x.json" + q), 2, "are the same file");
  check_refused(run("sweep --max-order 60 --out " + d / "y.csv --summary " + d / "y.csv.part" + q), 2, "are the same file");
  CHECK_FALSE(path_exists(d / "o.csv"));
  CHECK_FALSE(path_exists(d / "x.json"));
  // An output that is a directory: refused before the first pair, no state left behind.
  fs::create_directory(d / "DIR");
  check_refused(run("sweep --max-order 60 --summary " + d / "DIR" + q), 2, "is a directory");
  CHECK_FALSE(path_exists(d / "DIR.resume"));
  check_refused(run("sweep --max-order 60 --out " + d / "missing/rows.csv" + q), 2, "cannot write");
}

TEST_CASE("safe files: symbolic links, devices and permission bits of outputs", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  write_text(d / "victim", "precious\n");
  fs::create_symlink(d / "victim", d / "link.json");
  check_refused(run("certify 6 5 --out " + d / "link.json"), 2, "symbolic link");
  CHECK(fs::is_symlink(d / "link.json"));
  // A link planted where the sweep keeps its rows while running (FILE.part).
  fs::create_symlink(d / "victim", d / "r.csv.part");
  check_refused(run("sweep --max-order 40 --quiet --out " + d / "r.csv"), 2, "symbolic link");
  CHECK(read_text(d / "victim") == "precious\n");
  // A device is never replaced by a regular file (as root, rename would do it).
  check_refused(run("certify 6 5 --out /dev/full"), 2, "is a device");
  CHECK(fs::is_character_file("/dev/full"));
  // A replaced output keeps its mode; the temporary's name is not PATH.tmp.PID alone.
  REQUIRE(run("certify 6 5 --out " + d / "c.json").status == 0);
  REQUIRE(::chmod((d / "c.json").c_str(), 0600) == 0);
  REQUIRE(run("certify 6 5 --digits 40 --out " + d / "c.json").status == 0);
  struct stat st {};
  REQUIRE(::stat((d / "c.json").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0600);
  CHECK(has(read_text(d / "c.json"), "\"digits\": 40"));
  // So does a rows file, renamed from FILE.part at the end of a sweep (it became 644).
  REQUIRE(run("sweep --max-order 40 --quiet --out " + d / "rows.csv").status == 0);
  REQUIRE(::chmod((d / "rows.csv").c_str(), 0600) == 0);
  REQUIRE(run("sweep --max-order 40 --quiet --out " + d / "rows.csv").status == 0);
  REQUIRE(::stat((d / "rows.csv").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0600);
}

TEST_CASE("safe files: a resume never pads, and a saved state is never discarded silently", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  const std::string args = "sweep --max-order 120 --quiet --threads 1 --checkpoint 0 --out " + d / "r.csv";
  REQUIRE(run(args + " --max-pairs 1000").status == 4);  // stopped as asked, state kept
  const std::string state = read_text(d / "r.csv.resume");
  REQUIRE_FALSE(state.empty());
  // Without --resume: refused, the state untouched.
  check_refused(run(args), 2, "a saved run exists");
  CHECK(read_text(d / "r.csv.resume") == state);
  // The .part shortened from outside: refused, never padded with zeros.
  const auto size = fs::file_size(d / "r.csv.part");
  const std::string part = read_text(d / "r.csv.part");
  fs::resize_file(d / "r.csv.part", size / 2);
  check_refused(run(args + " --resume"), 2, "fewer than");
  CHECK(fs::file_size(d / "r.csv.part") == size / 2);
  // A state edited to claim 10^12 bytes: refused, no sparse terabyte.
  json st = json::parse(state);
  st["rows_bytes"] = std::uint64_t(1000000000000);
  write_text(d / "r.csv.resume", st.dump());
  check_refused(run(args + " --resume"), 2, "fewer than");
  CHECK(fs::file_size(d / "r.csv.part") == size / 2);
  // A key given twice in a state is refused, not "last one wins".
  std::string dup = state;
  dup.insert(1, "\"done\":0,");
  write_text(d / "r.csv.resume", dup);
  check_refused(run(args + " --resume"), 2, "appears twice");
  // A state whose counts disagree (edited by hand): refused, never a wrong count. Before, a `done`
  // below the summary's pairs repeated pairs (order 300: 15698 pairs reported of 13698, rows
  // doubled, exit 0), and a `done` beyond the sweep's pairs ended it at once with exit 0.
  write_text(d / "r.csv.part", part);
  for (const auto& [key, value, message] : std::vector<std::tuple<std::string, std::uint64_t, std::string>>{
           {"done", 300, "is inconsistent"},
           {"values_count", 5, "is inconsistent"},
           {"rows_bytes", 0, "do not end a line"}}) {
    json edited = json::parse(state);
    edited[key] = key == "rows_bytes" ? edited["rows_bytes"].get<std::uint64_t>() - 10 : value;
    write_text(d / "r.csv.resume", edited.dump());
    INFO(key);
    check_refused(run(args + " --resume"), 2, message);
  }
  json beyond = json::parse(state);
  beyond["done"] = beyond["summary"]["pairs"] = std::uint64_t(1000000);
  write_text(d / "r.csv.resume", beyond.dump());
  check_refused(run(args + " --resume"), 2, "but the sweep has");
  // --fresh discards it and gives the same rows as a lone run.
  REQUIRE(run(args + " --fresh").status == 0);
  REQUIRE(run("sweep --max-order 120 --quiet --threads 1 --out " + d / "lone.csv").status == 0);
  const std::string a = read_text(d / "r.csv"), b = read_text(d / "lone.csv");
  CHECK(a.substr(0, a.rfind("# end")) == b.substr(0, b.rfind("# end")));
  CHECK(has(a, "\n# end"));
  CHECK(a.find('\0') == std::string::npos);
  CHECK_FALSE(path_exists(d / "r.csv.resume"));
  CHECK_FALSE(path_exists(d / "r.csv.resume.lock"));
}

TEST_CASE("safe files: two concurrent sweeps on one summary, the second refused at once", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  const std::string args = "sweep --max-order 1500 --quiet --threads 1 --summary " + d / "same.json";
  const int pid = gyrores::test::cli_spawn(args, d / "a.out", d / "a.err");
  // Hold the first run still once it has taken its lock (no race on timing).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!path_exists(d / "same.json.lock") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const bool held = ::kill(pid, SIGSTOP) == 0 && path_exists(d / "same.json.lock");
  if (held) {
    check_refused(run(args), 2, "in use by another gyrores run (pid " + std::to_string(pid) + ")");
    // Another summary but the same state: refused too.
    check_refused(run("sweep --max-order 1500 --quiet --summary " + d / "other.json --state " + d / "same.json.resume"), 2,
                  "in use");
    // merge into it as well.
    check_refused(run("merge " + d / "other.json --summary " + d / "same.json"), 2, "in use");
  } else {
    WARN("the first sweep ended before it could be held; the refusal was not tested");
  }
  ::kill(pid, SIGCONT);
  REQUIRE(gyrores::test::cli_wait(pid) == 0);
  REQUIRE(run("sweep --max-order 1500 --quiet --threads 1 --summary " + d / "lone.json").status == 0);
  CHECK(core_of(d / "same.json") == core_of(d / "lone.json"));
  CHECK_FALSE(path_exists(d / "same.json.lock"));
}

TEST_CASE("safe files: two sweeps without files in one directory take turns on its default state", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  const std::string here = "cd '" + d.path() + "' &&";
  const std::string args = "sweep --max-order 1500 --quiet --threads 1 --json";
  cli_result first;
  std::thread a([&] { first = gyrores::test::cli_run(args, here); });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!path_exists(d / "gyrores-sweep.resume.lock") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const cli_result second = gyrores::test::cli_run(args, here);
  a.join();
  REQUIRE(first.status == 0);
  REQUIRE(second.status == 0);
  if (!has(second.err, "waiting for it to end")) WARN("the first sweep ended before the second started");
  CHECK(gyrores::sweep_summary_core(json::parse(first.out)) == gyrores::sweep_summary_core(json::parse(second.out)));
  CHECK_FALSE(path_exists(d / "gyrores-sweep.resume"));
  CHECK_FALSE(path_exists(d / "gyrores-sweep.resume.lock"));
}

TEST_CASE("safe files: merge checks each shard's values file by content", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  for (int k = 0; k < 2; ++k)
    REQUIRE(run("sweep --max-order 150 --quiet --threads 1 --shard " + std::to_string(k) + "/2 --summary " +
                d / ("s" + std::to_string(k) + ".json"))
                .status == 0);
  REQUIRE(run("merge " + d / "s0.json " + d / "s1.json --summary " + d / "m.json").status == 0);
  const std::string values = read_text(d / "s0.json.values");
  // One value replaced by another of the file (the count unchanged): refused.
  std::string swapped = values;
  REQUIRE(swapped.size() >= 16 + 3 * 8);
  std::copy(swapped.begin() + 16 + 2 * 8, swapped.begin() + 16 + 3 * 8, swapped.begin() + 16);
  REQUIRE(swapped != values);
  write_text(d / "s0.json.values", swapped);
  check_refused(run("merge " + d / "s0.json " + d / "s1.json"), 2, "does not match");
  // Shard 1's values under shard 0's name: refused.
  fs::copy_file(d / "s1.json.values", d / "s0.json.values", fs::copy_options::overwrite_existing);
  check_refused(run("merge " + d / "s0.json " + d / "s1.json"), 2, "does not match");
  write_text(d / "s0.json.values", values);
  REQUIRE(run("merge " + d / "s0.json " + d / "s1.json").status == 0);
  // A summary with a key twice.
  std::string s0 = read_text(d / "s0.json");
  write_text(d / "dup.json", "{\"pairs\": 1, " + s0.substr(s0.find('{') + 1));
  check_refused(run("merge " + d / "dup.json " + d / "s1.json"), 2, "appears twice");
}

TEST_CASE("safe files: directories, devices and oversized inputs", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  fs::create_directory(d / "DIR");
  check_refused(run("check " + d / "DIR"), 2, "is a directory");
  check_refused(run("merge " + d / "DIR " + d / "DIR"), 2, "is a directory");
  check_refused(run("check /dev/zero"), 2, "larger than 4194304 bytes");
  check_refused(run("merge /dev/zero"), 2, "not a regular file");
  write_text(d / "big.json", std::string((4 << 20) + 1, ' '));
  check_refused(run("check " + d / "big.json"), 2, "larger than");
  // A certificate with a key twice is malformed (exit 2), not "last one wins".
  REQUIRE(run("certify 6 5 --out " + d / "c.json").status == 0);
  std::string c = read_text(d / "c.json");
  c.insert(c.find('{') + 1, "\"tau\": \"7\", ");
  write_text(d / "dup.json", c);
  check_refused(run("check " + d / "dup.json"), 2, "appears twice");
  // Likewise a coupling certificate (horizon-theorem/1), which its checker read with "last wins".
  REQUIRE(run("coupling 2 --horizon 100 --certificate " + d / "cc.json").status == 0);
  std::string cc = read_text(d / "cc.json");
  cc.insert(cc.find('{') + 1, "\"digits\": 5, ");
  write_text(d / "ccdup.json", cc);
  check_refused(run("check " + d / "ccdup.json"), 2, "appears twice");
  // A field holding a newline (JSON "\n") is quoted in the message on one line, escaped (it was
  // printed as is: two lines).
  std::string nl = read_text(d / "c.json");
  nl.replace(nl.find("\"6\""), 3, "\"6\\n\"");
  write_text(d / "nl.json", nl);
  check_refused(run("check " + d / "nl.json"), 2, "is not an integer: '6\\n'");
  std::string ccnl = read_text(d / "cc.json");
  ccnl.replace(ccnl.find("\"4\""), 3, "\"4\\n\"");
  write_text(d / "ccnl.json", ccnl);
  check_refused(run("check " + d / "ccnl.json"), 2, "'4\\n'");
}

TEST_CASE("safe files: bounded work, limits and exit statuses", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  check_refused(run("sweep --max-order 1099511627776 --state " + d / "s"), 2, "--allow-large");
  check_refused(run("sweep --max-order 300000 --state " + d / "s"), 2, "--allow-large");
  check_refused(run("sweep --max-order 1099511627777 --allow-large --state " + d / "s"), 2, "--max-order must be <= 2^40");
  check_refused(run("sweep --max-order 50 --min-order -5 --state " + d / "s"), 2, "--min-order");
  check_refused(run("sweep --max-order 50 --checkpoint nan --state " + d / "s"), 2, "--checkpoint");
  check_refused(run("sweep --max-order 50 --resume --fresh --state " + d / "s"), 2, "exclude");
  // Out of range: refused, not an abort (too many threads) nor a wrapped-around count.
  check_refused(run("sweep --max-order 50 --threads 100000 --state " + d / "s"), 2, "--threads must be in [0, 4096]");
  check_refused(run("sweep --max-order 50 --max-pairs -5 --state " + d / "s"), 2, "--max-pairs must be >= 0");
  check_refused(run("sweep --max-order 2 --state " + d / "s"), 2, "--max-order must be >= 3");
  CHECK_FALSE(path_exists(d / "s"));
  // What certify writes, check reads: a tau beyond the checker's digits is refused by certify.
  const std::string big = "1" + std::string(20000, '0') + "1";
  check_refused(run("certify " + big + " 1"), 2, "certificates are limited to 20000");
  // qdot0: any positive decimal at every digits (the reals scale exactly with it).
  for (const std::string digits : {"17", "40"}) {
    auto tiny = run("pair 6 5 --qdot0 1e-5000 --json --digits " + digits);
    CHECK(tiny.status == 0);
    CHECK(has(tiny.out, "e-5000"));
    CHECK(run("pair 6 5 --qdot0 1e-320 --digits " + digits).status == 0);
  }
  check_refused(run("pair 6 5 --qdot0 0"), 2, "--qdot0 must be > 0");
  // --version, and a bare gyrores: the usage on stderr, exit 2.
  auto v = run("--version");
  CHECK(v.status == 0);
  CHECK(has(v.out, "gyrores "));
  auto bare = run("");
  CHECK(bare.status == 2);
  CHECK(bare.out.empty());
  CHECK(has(bare.err, "Usage"));
  CHECK(has(bare.err, "Exit status"));
}

TEST_CASE("safe files: the lock files are paths of the command too", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  const std::string q = " --quiet --threads 1";
  // A rows file named like a lock file would be truncated by the lock and removed at the end.
  check_refused(run("sweep --max-order 60 --summary " + d / "a.json --out " + d / "a.json.lock" + q), 2, "are the same file");
  check_refused(run("sweep --max-order 60 --state " + d / "s --out " + d / "s.lock" + q), 2, "are the same file");
  CHECK_FALSE(path_exists(d / "a.json.lock"));
  CHECK_FALSE(path_exists(d / "s.lock"));
  // merge's lock on --summary OUT is OUT.lock: an input of that name is refused, not destroyed.
  REQUIRE(run("sweep --max-order 60 --shard 0/2 --out " + d / "m.json.lock" + q).status == 0);
  REQUIRE(run("sweep --max-order 60 --shard 1/2 --out " + d / "r1.csv" + q).status == 0);
  const std::string shard0 = read_text(d / "m.json.lock");
  check_refused(run("merge " + d / "m.json.lock " + d / "r1.csv --summary " + d / "m.json"), 2, "are the same file");
  CHECK(read_text(d / "m.json.lock") == shard0);
  // A file of the user's at PATH.lock is neither truncated nor removed; a stale lock file (a pid
  // line left by a killed run) is taken over and removed at the end.
  write_text(d / "n.json.lock", "my notes\n");
  check_refused(run("sweep --max-order 60 --summary " + d / "n.json" + q), 2, "is not a gyrores lock file");
  CHECK(read_text(d / "n.json.lock") == "my notes\n");
  CHECK_FALSE(path_exists(d / "n.json"));
  write_text(d / "o.json.lock", "12345\n");
  REQUIRE(run("sweep --max-order 60 --summary " + d / "o.json" + q).status == 0);
  CHECK_FALSE(path_exists(d / "o.json.lock"));
}

TEST_CASE("safe files: figures follow the same rules (plot, pareto --plot, report)", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  write_text(d / "victim", "precious\n");
  // Checked before the work: a link, a directory, a link as the CSV of pareto.
  fs::create_symlink(d / "victim", d / "link.svg");
  check_refused(run("plot phase 6 5 --out " + d / "link.svg"), 2, "symbolic link");
  CHECK(fs::is_symlink(d / "link.svg"));
  fs::create_directory(d / "dir.svg");
  check_refused(run("plot pareto --max-order 200 --out " + d / "dir.svg"), 2, "is a directory");  // was exit 0, no image
  CHECK_FALSE(path_exists(d / "dir.dat"));
  fs::create_symlink(d / "victim", d / "front.csv");
  check_refused(run("pareto --max-order 200 --out " + d / "front.csv"), 2, "symbolic link");
  fs::create_symlink(d / "victim", d / "g.svg");
  check_refused(run("pareto --max-order 200 --plot " + d / "g.svg"), 2, "symbolic link");
  fs::create_directory(d / "rep");
  fs::create_directory(d / "rep/figures");
  fs::create_symlink(d / "victim", d / "rep/figures/x.png");
  check_refused(run("report --out " + d / "rep"), 2, "symbolic link");
  CHECK_FALSE(path_exists(d / "rep/REPORT.md"));
  CHECK(read_text(d / "victim") == "precious\n");
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return;  // the image needs gnuplot
  // gnuplot wrote to the predictable STEM.tmpPID.svg and its stderr to STEM.gnuplot-stderr.tmpPID,
  // following links: links planted there for the next pids made `plot --out q.svg` overwrite
  // their target, and q.svg became a link to it. gnuplot now writes in a private directory.
  std::ifstream last("/proc/sys/kernel/ns_last_pid");
  long pid = 0;
  if (last >> pid)
    for (long p = pid + 1; p < pid + 200; ++p) {
      fs::create_symlink(d / "victim", d / ("q.tmp" + std::to_string(p) + ".svg"));
      fs::create_symlink(d / "victim", d / ("q.gnuplot-stderr.tmp" + std::to_string(p)));
    }
  REQUIRE(run("plot phase 6 5 --out " + d / "q.svg").status == 0);
  CHECK(read_text(d / "victim") == "precious\n");
  CHECK_FALSE(fs::is_symlink(d / "q.svg"));
  CHECK(has(read_text(d / "q.svg"), "<svg"));
  // A replaced image keeps its mode; no private directory is left behind.
  REQUIRE(::chmod((d / "q.svg").c_str(), 0600) == 0);
  REQUIRE(run("plot phase 6 5 --out " + d / "q.svg").status == 0);
  struct stat st {};
  REQUIRE(::stat((d / "q.svg").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0600);
  int private_dirs = 0;
  for (const auto& e : fs::directory_iterator(d.path())) private_dirs += has(e.path().filename().string(), ".gyrores-tmp");
  CHECK(private_dirs == 0);
}

// A command that runs for minutes: a wide band's guarantees to 2000 digits.
const std::string long_band = "coupling --band 0.01:100 --horizon 1e50 --digits 2000";

TEST_CASE("safe files: SIGINT and SIGTERM end every command with exit 130", "[cli][files]") {
  if (!cli_available()) return;
  temp_dir d("test_safe_files");
  // report: std::system ignored SIGINT in gyrores while gnuplot ran, so the signal was lost and
  // the report went on to exit 0. Signalled as soon as it has started drawing.
  const int pid = gyrores::test::cli_spawn("report --out " + d / "rep", d / "r.out", d / "r.err");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!path_exists(d / "rep/figures") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ::kill(pid, SIGINT);
  const int status = gyrores::test::cli_wait(pid);
  if (status == 0) {
    WARN("the report ended before SIGINT reached it");
  } else {
    CHECK(status == 130);
    CHECK(has(read_text(d / "r.err"), "interrupted"));
    CHECK_FALSE(path_exists(d / "rep/REPORT.md"));
    int private_dirs = 0;
    for (const auto& e : fs::directory_iterator(d / "rep/figures")) private_dirs += has(e.path().filename().string(), ".gyrores-tmp");
    CHECK(private_dirs == 0);
  }
  // SIGTERM killed the other commands (128 + 15 in a shell); now 130 as documented, like a sweep.
  // A band proved to 2000 digits runs for minutes; stopped, it prints the bracket it reached.
  // Signalled once its first progress line (after a second of work) shows the proof has started.
  const int band = gyrores::test::cli_spawn(long_band, d / "b.out", d / "b.err");
  const auto band_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (read_text(d / "b.err").empty() && std::chrono::steady_clock::now() < band_deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(band, SIGTERM);
  CHECK(gyrores::test::cli_wait(band) == 130);
  const std::string out = read_text(d / "b.out");
  INFO("stdout: " << out.substr(0, 300) << "\nstderr: " << read_text(d / "b.err"));
  CHECK(has(out, "absorption guarantee   in ["));
  CHECK(has(out, "interrupted"));
  CHECK_FALSE(has(out, "each the correct rounding"));
}

TEST_CASE("safe files: a long command shows progress on a terminal", "[cli][files]") {
  if (!cli_available()) return;
  if (std::system("command -v script >/dev/null 2>&1 && command -v timeout >/dev/null 2>&1") != 0) return;
  // script(1) gives gyrores a terminal; timeout stops it with SIGINT after 3 s (the band: minutes).
  const std::string cmd = "script -qfec \"timeout -s INT 3 " + gyrores::test::cli_path() + " " + long_band +
                          " >/dev/null\" /dev/null 2>&1";
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    ::pclose(p);
  }
  INFO(out);
  CHECK(has(out, "gyrores coupling: absorption in ["));
  CHECK(has(out, "(Ctrl-C stops it)"));
  CHECK(has(out, "gyrores: interrupted"));
}
