// Running a library call so that Ctrl-C stops it: the work runs on its own thread, without the
// GIL, while the calling thread waits in short slices and, between them, takes the GIL to let
// Python run its signal handlers (PyErr_CheckSignals). On KeyboardInterrupt (or any exception a
// handler raises) the stop flag handed to the work is set and the exception is raised at once,
// within one slice (20 ms): the caller never waits for the work to notice the flag. A work that
// has not ended after a short grace period is left to finish on its own (detached: it owns its
// state through a shared pointer, and its result is dropped); the library's long loops look at
// the flag (core/stop.hpp), so it ends soon after. No lock is held while waiting, so a call made
// from a progress callback, or from another Python thread, never waits for this one.
#pragma once
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <gyrores/core/stop.hpp>
#include <gyrores/core/thread_caches.hpp>

namespace gyrores::python {

namespace py = pybind11;

namespace detail {
template <class R> struct interruptible_state {
  std::atomic<bool> stop{false};
  std::mutex mtx;
  std::condition_variable cv;
  bool done = false;
  std::optional<R> result;
  std::exception_ptr error;
};
}  // namespace detail

// What to do when a signal handler raised: leave a work that has not stopped after a short grace
// period running on its own, or wait for it (for a work that writes into a caller's buffer and
// looks at the stop flag often).
enum class on_stop { detach, wait };

// Calls work(stop_token) on a new thread and returns its result (rethrowing its exception);
// the calling thread must hold the GIL, work must not touch Python objects.
template <class R, class Work> R run_interruptible(Work work, on_stop after_stop = on_stop::detach) {
  auto state = std::make_shared<detail::interruptible_state<R>>();
  std::thread worker([state, work = std::move(work)]() mutable {
    try {
      R r = work(stop_token(&state->stop));
      std::lock_guard<std::mutex> lk(state->mtx);
      state->result.emplace(std::move(r));
    } catch (...) {
      std::lock_guard<std::mutex> lk(state->mtx);
      state->error = std::current_exception();
    }
    release_thread_caches();  // MPFR's and FLINT's per-thread caches die with the thread
    {
      std::lock_guard<std::mutex> lk(state->mtx);
      state->done = true;
    }
    state->cv.notify_all();
  });
  bool signalled = false;
  {
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> lk(state->mtx);
    while (!state->done) {
      if (state->cv.wait_for(lk, std::chrono::milliseconds(20), [&] { return state->done; })) break;
      lk.unlock();
      {
        py::gil_scoped_acquire gil;
        signalled = PyErr_CheckSignals() != 0;
      }
      lk.lock();
      if (signalled) {
        state->stop = true;
        // A short grace period so that a work which stops quickly is joined, not detached.
        if (after_stop == on_stop::wait) state->cv.wait(lk, [&] { return state->done; });
        else state->cv.wait_for(lk, std::chrono::milliseconds(50), [&] { return state->done; });
        break;
      }
    }
  }
  // Here the GIL is held again.
  bool done;
  {
    std::lock_guard<std::mutex> lk(state->mtx);
    done = state->done;
  }
  // After a signal the thread is left to free the work's state on its own (a million inputs take
  // most of a second to free): joining it would hold KeyboardInterrupt back until then.
  if (done && !signalled) worker.join(); else worker.detach();
  if (signalled) throw py::error_already_set();
  if (state->error) std::rethrow_exception(state->error);
  return std::move(*state->result);
}

}  // namespace gyrores::python
