// Running a library call so that Ctrl-C stops it, on the calling thread, without the GIL.
//
// Why not a thread per call (what this file did before): a new thread for every call cost more
// than a small call's work (pair(6, 5): tens of microseconds to create it, and MPFR's and FLINT's
// per-thread caches, constants such as pi, thrown away with it), and after Ctrl-C the work was
// left running detached. Here the work runs where it was called, its caches stay, and it stops:
//
// On the interpreter's main thread (the only one where Python runs signal handlers, so the only
// one where KeyboardInterrupt is raised), a handler is chained in front of the interpreter's own
// C-level SIGINT handler (signal_scope, at the first call; again whenever the interpreter's was put
// back, as signal.signal does): the signal sets the stop flag handed to the work (core/stop.hpp)
// and then runs the interpreter's handler exactly as before (it marks the signal for Python,
// writes the wakeup fd), so that SIGINT outside a call does what it always did. It stays
// installed between calls: putting it in and out costs two system calls a call. The library's
// long loops look at the flag and throw `interrupted`; with the GIL back, PyErr_CheckSignals runs
// the Python handler, which raises KeyboardInterrupt. Calls nested in a progress callback share
// the outer call's flag. Only while SIGINT's Python handler is the default one
// (KeyboardInterrupt) does a call get the flag: with a handler of the user's (signal.signal),
// SIG_IGN or SIG_DFL the call runs to its end and the handler runs then, as after any call into
// C. On another thread the work runs without a flag, as Python never delivers KeyboardInterrupt
// there.
#pragma once
#include <pybind11/pybind11.h>

#include <atomic>
#include <exception>
#include <optional>
#include <utility>

#include <gyrores/core/stop.hpp>

namespace gyrores::python {

namespace py = pybind11;

// Kept for the callers' wording: both now wait for the work, which runs on the calling thread
// and ends soon after the flag is set (the library's loops look at it).
enum class on_stop { detach, wait };

namespace detail {
// Reads which thread is the interpreter's main thread (at import, GIL held).
void init_interruptible();
// Whether this thread is the interpreter's main thread (the GIL held).
bool on_main_thread();
// For the outermost call on the main thread: chains the SIGINT handler if needed and clears the
// flag. Main thread only, GIL held.
class signal_scope {
 public:
  signal_scope();
  ~signal_scope();
  signal_scope(const signal_scope&) = delete;
  signal_scope& operator=(const signal_scope&) = delete;
  // The flag SIGINT sets, or nullptr when SIGINT is not to stop the call (a user's handler).
  const std::atomic<bool>* flag() const;

 private:
  bool active_ = false;
};
// After the work (GIL held): raises a pending Python signal's exception; if the work was
// interrupted and no handler raised, KeyboardInterrupt.
void raise_signals(bool interrupted_work);
// Frees this thread's MPFR and FLINT caches when it ends (once registered per thread; not on
// the main thread, whose caches last as long as the process).
void release_caches_at_thread_exit();
}  // namespace detail

// Calls work(stop_token) on this thread with the GIL released and returns its result (rethrowing
// its exception); the calling thread must hold the GIL, work must not touch Python objects
// without taking it back (py::gil_scoped_acquire).
template <class R, class Work> R run_interruptible(Work work, on_stop = on_stop::wait) {
  const bool main = detail::on_main_thread();
  if (main) {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // a Ctrl-C already pending
  } else {
    detail::release_caches_at_thread_exit();
  }
  std::optional<detail::signal_scope> scope;
  if (main) scope.emplace();
  std::optional<R> result;
  bool stopped = false;
  std::exception_ptr error;
  {
    py::gil_scoped_release release;
    try {
      result.emplace(work(main ? stop_token(scope->flag()) : stop_token()));
    } catch (const interrupted&) {
      stopped = true;
      error = std::current_exception();
    } catch (...) {
      error = std::current_exception();
    }
  }
  scope.reset();
  if (main) detail::raise_signals(stopped);
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

}  // namespace gyrores::python
