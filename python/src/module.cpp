// The compiled part of the Python package `gyrores`: _gyrores. Each area registers its
// functions (common.hpp); this file maps the library's errors (core/error.hpp) to Python:
// usage_error -> gyrores.UsageError (a ValueError), compute_error -> gyrores.ComputeError (an
// ArithmeticError), with the library's one-line messages.
#include <gyrores/core/error.hpp>

#include "common.hpp"
#include "interruptible.hpp"

PYBIND11_MODULE(_gyrores, m) {
  namespace gp = gyrores::python;
  m.doc() = "Compiled bindings of the gyrores C++ library; use the package gyrores.";
  pybind11::register_exception<gyrores::usage_error>(m, "UsageError", PyExc_ValueError);
  pybind11::register_exception<gyrores::compute_error>(m, "ComputeError", PyExc_ArithmeticError);
  gp::detail::init_interruptible();
  gp::bind_pair(m);
  gp::bind_certify(m);
  gp::bind_design(m);
  gp::bind_coupling(m);
  gp::bind_sweep(m);
  gp::bind_pairs(m);
  gp::bind_figures(m);
  m.def("_mpf_parts", &gp::mpf_parts, pybind11::arg("text"), pybind11::arg("prec"), pybind11::arg("rounding"),
        "mpmath's (sign, man, exp, bc) of a decimal rounded to prec bits ('n', 'f' down, 'c' up).");
  m.attr("__version__") = GYRORES_VERSION;  // the project version (python/CMakeLists.txt)
}
