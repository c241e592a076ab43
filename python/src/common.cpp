// python/src/common.hpp
#include "common.hpp"

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>

namespace gyrores::python {

big_int big_int_of(const py::handle& value, const std::string& what) {
  // bool is a subclass of int in Python; True as a pair member is almost certainly a mistake.
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
    throw usage_error(what + " must be an integer, got " + std::string(py::repr(value)));
  return parse_big_int(std::string(py::str(value)), what);
}

resonant_pair<big_int> pair_of(const py::handle& tau, const py::handle& sigma) {
  return resonant_pair<big_int>(big_int_of(tau, "tau"), big_int_of(sigma, "sigma"));
}

unsigned checked_digits(long long digits, long long lo, long long hi) {
  if (digits < lo || digits > hi)
    throw usage_error("digits must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                      std::to_string(digits));
  return unsigned(digits);
}

std::string rational_text(const py::handle& value) {
  // A float goes through repr (its shortest round-trip text: 0.1 stays "0.1").
  if (py::isinstance<py::float_>(value)) return std::string(py::repr(value));
  return std::string(py::str(value));
}

py::object to_python(const json& j) {
  // Imported per call (a dictionary lookup once loaded): a static py::object would outlive the
  // interpreter at exit.
  return py::module_::import("json").attr("loads")(json_dump(j, -1));
}

}  // namespace gyrores::python
