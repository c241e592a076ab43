// python/src/common.hpp
#include "common.hpp"

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>

namespace gyrores::python {

big_int big_int_of(const py::handle& value, const std::string& what) {
  // The Python wrappers pass ints made by operator.index (gyrores/_args.py); bool, a subclass of
  // int, is refused there and here (True as a pair member is almost certainly a mistake).
  if (!PyLong_CheckExact(value.ptr()) && (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)))
    throw usage_error(what + " must be an integer, got " + std::string(py::repr(value)));
  // Through hexadecimal: Python limits int <-> decimal text (sys.get_int_max_str_digits), not
  // power-of-two bases, and int.__str__ of a subclass could say anything. The value itself is read.
  const py::object hex = py::reinterpret_steal<py::object>(PyNumber_ToBase(value.ptr(), 16));
  if (!hex) throw py::error_already_set();
  std::string text = hex.cast<std::string>();  // "0x1f" or "-0x1f"
  const bool negative = !text.empty() && text[0] == '-';
  big_int r;
  if (mpz_set_str(r.backend().data(), text.c_str() + (negative ? 3 : 2), 16) != 0)
    throw usage_error(what + " must be an integer");
  return negative ? big_int(-r) : r;
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
  // interpreter at exit. gyrores._numbers.loads reads integers of any size.
  return py::module_::import("gyrores._numbers").attr("loads")(json_dump(j, -1));
}

}  // namespace gyrores::python
