// What every binding file of the Python module shares: the call into the library (GIL released),
// Python integers and digits to the library's types, and JSON (gyrores::json, io/json.hpp) to
// Python objects.
#pragma once
#include <pybind11/pybind11.h>

#include <cstdint>
#include <mutex>  // bind_sweep.cpp relies on it (its std::mutex); it should include <mutex> itself
#include <string>
#include <utility>

#include <gyrores/core/integer.hpp>
#include <gyrores/report/pair_report.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores::python {

namespace py = pybind11;

// Runs f() with the GIL released, so that other Python threads keep running, library calls
// included: every library function the bindings call may run on any number of threads at once
// (none writes process-wide state such as Boost's default MPFR precision: docs/architecture.md,
// Conventions; python/tests/test_threads.py). f must not touch Python objects (read them
// before, convert after) unless it takes the GIL back (py::gil_scoped_acquire, as the sweep's
// progress callback does).
template <class F> auto call_library(F&& f) {
  py::gil_scoped_release release;
  return std::forward<F>(f)();
}

// A Python int of any size as the library's integer; usage_error naming `what` for anything
// else (a float, a bool, a string).
big_int big_int_of(const py::handle& value, const std::string& what);
// The resonant pair (tau, sigma); usage_error from the pair's own checks (model/pair.hpp).
resonant_pair<big_int> pair_of(const py::handle& tau, const py::handle& sigma);
// digits in [lo, hi] or usage_error "digits must be in [lo, hi], got D" (the library's wording).
unsigned checked_digits(long long digits, long long lo, long long hi);
// A Python int of the library's integer (any size, exactly).
py::object python_int(const big_int& v);
// mpmath's normal form (sign, mantissa, exponent, bit count) of the decimal `text` rounded to
// `prec` bits: to nearest ("n"), down ("f") or up ("c"); one correct rounding (MPFR).
py::tuple mpf_parts(const std::string& text, long prec, const std::string& rounding);
// A decimal or fraction given as a Python int, float or str, as text for parse_rational.
std::string rational_text(const py::handle& value);

// A JSON value as Python objects (dict in key order, list, int of any size, str, bool, float,
// None), built directly from the value (no text), big integers (json_integer) with every digit.
py::object to_python(const json& j);

// The module's areas, one file each.
void bind_pair(py::module_& m);      // pair, asymptotics
void bind_certify(py::module_& m);   // certify, check
void bind_design(py::module_& m);    // design, pareto
void bind_coupling(py::module_& m);  // coupling, couplings
void bind_sweep(py::module_& m);     // enumerate_pairs, sweep
void bind_pairs(py::module_& m);     // pairs
void bind_figures(py::module_& m);   // the figures' data (gyrores.plot)

}  // namespace gyrores::python
