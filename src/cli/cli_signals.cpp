// src/cli/cli_signals.hpp
#include "cli_signals.hpp"

#include <unistd.h>

namespace gyrores::cli {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_stop_signal(int) {
  if (g_stop.load()) ::_exit(130);  // a second signal: leave at once
  g_stop.store(true);
}

}  // namespace

std::atomic<bool>& stop_flag() { return g_stop; }

signal_scope::signal_scope() {
  g_stop.store(false);
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
