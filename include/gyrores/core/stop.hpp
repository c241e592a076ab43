// Stopping a long computation from outside: a signal handler (the CLI's Ctrl-C) or a waiting
// thread (the Python module, which polls for KeyboardInterrupt while the work runs without the
// GIL) sets an atomic flag; the computation looks at it at safe points and throws `interrupted`.
// The flag is passed in, never global, so concurrent computations stop independently.
#pragma once
#include <atomic>
#include <stdexcept>

namespace gyrores {

// Thrown when a stop was requested: the input was valid and nothing was computed wrongly (the
// CLI exits 130, the Python module raises KeyboardInterrupt).
struct interrupted : std::runtime_error {
  interrupted() : std::runtime_error("interrupted") {}
};

// A view of a stop flag owned by the caller; a default stop_token never stops.
class stop_token {
 public:
  stop_token() = default;
  explicit stop_token(const std::atomic<bool>* flag) : flag_(flag) {}

  bool requested() const { return flag_ != nullptr && flag_->load(std::memory_order_relaxed); }
  void throw_if_requested() const {
    if (requested()) throw interrupted();
  }

 private:
  const std::atomic<bool>* flag_ = nullptr;
};

}  // namespace gyrores
