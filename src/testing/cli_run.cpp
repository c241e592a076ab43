// src/testing/cli_run.hpp
#include "testing/cli_run.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gyrores::test {

cli_result cli_run(const std::string& args, const std::string& env) {
  static int counter = 0;
  const std::string errfile =
      "/tmp/gyrores_test_stderr_" + std::to_string(::getpid()) + "_" + std::to_string(++counter);
  const std::string cmd = (env.empty() ? "" : env + " ") + cli_path() + " " + args + " 2>" + errfile;
  cli_result r;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int st = ::pclose(p);
  r.err = read_text(errfile);
  std::remove(errfile.c_str());
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

int cli_spawn(const std::string& args, const std::string& out_file, const std::string& err_file,
              std::uint64_t max_file_bytes) {
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("cli_spawn: fork failed");
  if (pid == 0) {
    if (max_file_bytes > 0) {
      // An ignored signal stays ignored across exec: the write fails with EFBIG instead.
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit lim{rlim_t(max_file_bytes), rlim_t(max_file_bytes)};
      if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) ::_exit(127);
    }
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0) ::_exit(127);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    const std::string cmd = "exec " + cli_path() + " " + args;
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return int(pid);
}

int cli_wait(int pid) {
  int st = 0;
  if (::waitpid(pid_t(pid), &st, 0) < 0) return -1;
  if (WIFEXITED(st)) return WEXITSTATUS(st);
  if (WIFSIGNALED(st)) return 128 + WTERMSIG(st);
  return -1;
}

int count_lines(const std::string& s) {
  int c = 0;
  for (char ch : s) c += ch == '\n';
  return c;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool path_exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

temp_dir::temp_dir(const std::string& tag) {
  std::string buf = "/tmp/gyrores_" + tag + "_XXXXXX";
  char* d = ::mkdtemp(buf.data());
  if (!d) throw std::runtime_error("temp_dir: mkdtemp failed for " + buf);
  path_ = d;
}

temp_dir::~temp_dir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace gyrores::test
