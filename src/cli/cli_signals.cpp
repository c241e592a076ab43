// src/cli/cli_signals.hpp
#include "cli_signals.hpp"

#include <unistd.h>

namespace gyrores::cli {
namespace {

std::atomic<bool> g_stop{false};
volatile sig_atomic_t g_tty = 0;  // stderr is a terminal (a progress line may need erasing)

extern "C" void on_stop_signal(int) {
  if (g_stop.load()) {  // a second signal (or one sent to the process and to its group): leave at once
    static const char msg[] = "\r\x1b[K" "gyrores: interrupted\n";
    const bool tty = g_tty != 0;
    [[maybe_unused]] const ssize_t n = ::write(2, tty ? msg : msg + 4, sizeof msg - 1 - (tty ? 0 : 4));
    ::_exit(130);
  }
  g_stop.store(true);
}

}  // namespace

std::atomic<bool>& stop_flag() { return g_stop; }

signal_scope::signal_scope() {
  g_stop.store(false);
  g_tty = ::isatty(2) == 1;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
}

signal_scope::~signal_scope() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
}

}  // namespace gyrores::cli
