// python/src/interruptible.hpp
#include "interruptible.hpp"

#include <pythread.h>
#include <signal.h>

#include <gyrores/core/thread_caches.hpp>

namespace gyrores::python::detail {
namespace {

// The main thread's stop flag and the handler chained to (the interpreter's, saved when the
// outermost call installed ours). Written only by the main thread with the GIL, while our handler
// is not installed; read by the handler.
std::atomic<bool> g_stop{false};
struct sigaction g_chained {};
int g_depth = 0;  // calls in progress on the main thread (nested ones from progress callbacks)
bool g_outer_active = false;  // whether the outermost call's flag is set by SIGINT

extern "C" void on_sigint(int sig, siginfo_t* info, void* context) {
  g_stop.store(true, std::memory_order_relaxed);
  if ((g_chained.sa_flags & SA_SIGINFO) != 0) {
    if (g_chained.sa_sigaction != nullptr) g_chained.sa_sigaction(sig, info, context);
  } else if (g_chained.sa_handler != SIG_DFL && g_chained.sa_handler != SIG_IGN && g_chained.sa_handler != nullptr) {
    g_chained.sa_handler(sig);
  }
}

bool is_ours(const struct sigaction& sa) {
  return (sa.sa_flags & SA_SIGINFO) != 0 && sa.sa_sigaction == on_sigint;
}

// threading.main_thread().ident, read when the module is imported (init_interruptible), and
// signal.getsignal and signal.default_int_handler (references kept for the process's life: a
// py::object would be released after the interpreter at exit).
unsigned long g_main_ident = 0;
PyObject* g_getsignal = nullptr;
PyObject* g_default_int_handler = nullptr;

// Whether SIGINT's Python handler is the default one, which raises KeyboardInterrupt (GIL held).
bool python_handler_is_default() {
  PyObject* h = PyObject_CallFunction(g_getsignal, "i", SIGINT);
  if (h == nullptr) {
    PyErr_Clear();
    return false;
  }
  const bool is_default = h == g_default_int_handler;
  Py_DECREF(h);
  return is_default;
}

// Whether SIGINT will set the flag: our handler chained in front of the interpreter's (installed
// now if the interpreter's was put back since, e.g. by signal.signal), and the Python handler the
// default one. Main thread, GIL held. One sigaction call when nothing changed.
bool chain_sigint() {
  // A Python handler of the user's (signal.signal) decides what SIGINT does: the call is not
  // stopped for it, and the handler runs when the call ends, as after any call into C.
  if (!python_handler_is_default()) return false;
  struct sigaction current {};
  if (sigaction(SIGINT, nullptr, &current) != 0) return false;
  if (is_ours(current)) return true;
  const bool chainable = (current.sa_flags & SA_SIGINFO) != 0
                             ? current.sa_sigaction != nullptr
                             : current.sa_handler != SIG_DFL && current.sa_handler != SIG_IGN;
  if (!chainable) return false;  // SIG_IGN: Ctrl-C is ignored; SIG_DFL: it ends the process anyway
  // Our handler is not installed: g_chained can be written without a race with it.
  g_chained = current;
  struct sigaction ours = current;  // the same mask, and SA_RESTART as the interpreter set it
  ours.sa_flags = (current.sa_flags | SA_SIGINFO) & ~SA_RESETHAND;
  ours.sa_sigaction = on_sigint;
  return sigaction(SIGINT, &ours, nullptr) == 0;
}

struct cache_releaser {
  ~cache_releaser() { release_thread_caches(); }
};

}  // namespace

void init_interruptible() {
  g_main_ident = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  // _signal's own getsignal: signal.getsignal wraps it in an enum conversion (microseconds a call).
  const py::module_ signal_module = py::module_::import("_signal");
  g_getsignal = py::object(signal_module.attr("getsignal")).release().ptr();
  g_default_int_handler = py::object(signal_module.attr("default_int_handler")).release().ptr();
}

bool on_main_thread() { return PyThread_get_thread_ident() == g_main_ident; }

signal_scope::signal_scope() {
  if (g_depth++ > 0) {
    active_ = g_outer_active;  // nested in a callback: the outer call's flag
    return;
  }
  g_stop.store(false, std::memory_order_relaxed);
  g_outer_active = active_ = chain_sigint();
}

signal_scope::~signal_scope() { --g_depth; }

const std::atomic<bool>* signal_scope::flag() const { return active_ ? &g_stop : nullptr; }

void raise_signals(bool interrupted_work) {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (interrupted_work) {
    // Stopped by SIGINT, but the Python handler raised nothing (a handler of the user's that
    // returns): the call still has no result to give.
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
}

void release_caches_at_thread_exit() {
  static thread_local cache_releaser releaser;
  (void)releaser;
}

}  // namespace gyrores::python::detail
