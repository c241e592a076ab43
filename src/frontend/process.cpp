// src/frontend/process.hpp
#include "frontend/process.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>

#include <gyrores/core/stop.hpp>
#include <gyrores/io/files.hpp>

namespace gyrores::frontend {
namespace {

// What the handler cleans up: set before a helper starts, cleared after (async-signal-safe reads).
volatile sig_atomic_t g_helper_pid = 0;
volatile sig_atomic_t g_progress_drawn = 0;  // a progress line is on the terminal: erased first
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
  if (g_progress_drawn) {
    static const char erase[] = "\r\x1b[K";
    [[maybe_unused]] const ssize_t e = ::write(2, erase, sizeof erase - 1);
  }
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

// ---- progress line ----

namespace {
std::mutex g_stage_mutex;
std::string g_stage;
}  // namespace

void progress_stage(const std::string& stage) {
  std::lock_guard<std::mutex> lk(g_stage_mutex);
  g_stage = stage;
}

struct progress_line::impl {
  std::string command;
  std::mutex m;
  std::condition_variable cv;
  bool done = false, drawn = false;
  std::thread t;
};

progress_line::progress_line(std::string command) : p_(nullptr) {
  if (::isatty(2) != 1) return;
  p_ = new impl;
  p_->command = std::move(command);
  p_->t = std::thread([p = p_] {
    const auto t0 = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lk(p->m);
    if (p->cv.wait_for(lk, std::chrono::seconds(2), [&] { return p->done; })) return;
    for (;;) {
      std::string stage;
      {
        std::lock_guard<std::mutex> sl(g_stage_mutex);
        stage = g_stage;
      }
      const long secs = long(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      std::fprintf(stderr, "\rgyrores %s: %s%s%ld s (Ctrl-C stops it)\x1b[K", p->command.c_str(), stage.c_str(),
                   stage.empty() ? "" : ", ", secs);
      std::fflush(stderr);
      p->drawn = true;
      g_progress_drawn = 1;
      if (p->cv.wait_for(lk, std::chrono::seconds(1), [&] { return p->done; })) break;
    }
    std::fputs("\r\x1b[K", stderr);  // erased: what the command prints next starts clean
    std::fflush(stderr);
    g_progress_drawn = 0;
  });
}

progress_line::~progress_line() {
  if (!p_) return;
  {
    std::lock_guard<std::mutex> lk(p_->m);
    p_->done = true;
  }
  p_->cv.notify_all();
  p_->t.join();
  delete p_;
}

}  // namespace gyrores::frontend
