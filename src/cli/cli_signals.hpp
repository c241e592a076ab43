// Ctrl-C for long computations: while a signal_scope lives, SIGINT and SIGTERM set the stop flag
// (the library looks at it at safe points and throws `interrupted`, or a sweep stops after its
// current blocks; main.cpp then exits 130); a second signal leaves at once (exit 130). Outside a
// scope the default actions apply.
#pragma once
#include <signal.h>

#include <atomic>

#include <gyrores/core/stop.hpp>

namespace gyrores::cli {

// The one stop flag of the process (set by the handler, cleared when a scope begins).
std::atomic<bool>& stop_flag();

class signal_scope {
 public:
  signal_scope();
  ~signal_scope();
  signal_scope(const signal_scope&) = delete;
  signal_scope& operator=(const signal_scope&) = delete;
  stop_token token() const { return stop_token(&stop_flag()); }

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

}  // namespace gyrores::cli
