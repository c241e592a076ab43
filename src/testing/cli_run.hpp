// Running the built gyrores executable from a test (GYRORES_CLI_PATH, set by tests/CMakeLists.txt
// for the tests that drive the CLI; empty when the CLI is not built, and those checks are skipped).
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#ifndef GYRORES_CLI_PATH
#define GYRORES_CLI_PATH ""
#endif

namespace gyrores::test {

struct cli_result {
  int status;
  std::string out, err;
};

inline bool cli_available() { return std::string(GYRORES_CLI_PATH).size() > 0; }

// Runs `[env] GYRORES_CLI_PATH args`, capturing stdout and stderr.
inline cli_result cli_run(const std::string& args, const std::string& env = "") {
  static int counter = 0;
  std::string errfile = "/tmp/gyrores_test_stderr_" + std::to_string(::getpid()) + "_" + std::to_string(++counter);
  std::string cmd = (env.empty() ? "" : env + " ") + std::string(GYRORES_CLI_PATH) + " " + args + " 2>" + errfile;
  cli_result r{-1, "", ""};
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  int st = ::pclose(p);
  std::ifstream in(errfile);
  std::ostringstream ss;
  ss << in.rdbuf();
  r.err = ss.str();
  std::remove(errfile.c_str());
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

inline int count_lines(const std::string& s) {
  int c = 0;
  for (char ch : s) c += ch == '\n';
  return c;
}

// A fresh empty directory under /tmp.
inline std::string temp_dir(const std::string& tag) {
  std::string tmpl = "/tmp/gyrores_" + tag + "_XXXXXX";
  std::string buf = tmpl;
  char* d = ::mkdtemp(buf.data());
  return d ? std::string(d) : std::string();
}

}  // namespace gyrores::test
