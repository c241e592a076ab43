// src/cli/cli_process.hpp
#include "cli_process.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <gyrores/core/stop.hpp>
#include <gyrores/io/files.hpp>

namespace gyrores::cli {
namespace {

// What the handler cleans up: set before a helper starts, cleared after (async-signal-safe reads).
volatile sig_atomic_t g_helper_pid = 0;
char g_private_dir[4096] = {};
char g_private_file[4096] = {};

extern "C" void on_interrupt(int) {
  const pid_t child = pid_t(g_helper_pid);
  if (child > 0) {
    ::kill(child, SIGTERM);
    ::waitpid(child, nullptr, 0);
  }
  // unlink and rmdir are async-signal-safe; the private directory holds at most the one file.
  if (g_private_file[0]) ::unlink(g_private_file);
  if (g_private_dir[0]) ::rmdir(g_private_dir);
  static const char msg[] = "gyrores: interrupted\n";
  [[maybe_unused]] const ssize_t n = ::write(2, msg, sizeof msg - 1);
  ::_exit(130);
}

void copy_bounded(char* to, std::size_t cap, const std::string& from) {
  const std::size_t n = from.size() < cap - 1 ? from.size() : 0;  // too long: not registered
  std::memcpy(to, from.data(), n);
  to[n] = '\0';
}

}  // namespace

void install_interrupt_handlers() {
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    ::sigaction(sig, &sa, nullptr);
  }
}

bool program_in_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string p = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= p.size()) {
    const std::size_t end = std::min(p.find(':', start), p.size());
    std::string dir = p.substr(start, end - start);
    if (dir.empty()) dir = ".";
    const std::string f = dir + "/" + name;
    struct stat st {};
    if (::stat(f.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(f.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

int run_helper(const std::vector<std::string>& argv, const std::string& dir, const std::string& private_dir,
               const std::string& private_file, std::string& err) {
  err.clear();
  if (argv.empty()) return -1;
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int pipefd[2];
  if (::pipe2(pipefd, O_CLOEXEC) != 0) return -1;
  // Signals blocked across fork: the handler must not run before the pid is recorded.
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  ::pthread_sigmask(SIG_BLOCK, &block, &old);
  const pid_t pid = ::fork();
  if (pid == 0) {
    // The helper gets the dispositions gyrores started with, not our handler.
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
    const int null = ::open("/dev/null", O_RDWR);
    if (null < 0 || ::chdir(dir.c_str()) != 0) ::_exit(127);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(pipefd[1], 2);
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  ::close(pipefd[1]);
  if (pid < 0) {
    ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
    ::close(pipefd[0]);
    return -1;
  }
  copy_bounded(g_private_dir, sizeof g_private_dir, private_dir);
  copy_bounded(g_private_file, sizeof g_private_file, private_file);
  g_helper_pid = sig_atomic_t(pid);
  ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(pipefd[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (err.size() < 4096) err.append(buf, std::size_t(n) < 4096 - err.size() ? std::size_t(n) : 4096 - err.size());
  }
  ::close(pipefd[0]);
  int st = 0;
  while (::waitpid(pid, &st, 0) < 0 && errno == EINTR) {
  }
  ::pthread_sigmask(SIG_BLOCK, &block, &old);
  g_helper_pid = 0;
  g_private_dir[0] = '\0';
  g_private_file[0] = '\0';
  ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
  if (WIFSIGNALED(st) && (WTERMSIG(st) == SIGINT || WTERMSIG(st) == SIGTERM)) {
    // Ctrl-C on a terminal reaches the helper too: the user meant gyrores.
    if (!private_dir.empty()) remove_private_directory(private_dir);
    throw interrupted();
  }
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace gyrores::cli
