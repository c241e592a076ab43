// python/src/common.hpp
#include "common.hpp"

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>

#include <string_view>

#include <mpfr.h>

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

namespace {

constexpr std::string_view int_marker_open = "@@gyrores-int:";  // io/json.cpp's marker of a big integer

// A decimal integer text of any length as a Python int: through hexadecimal beyond 18 digits
// (Python limits int <-> decimal text, sys.get_int_max_str_digits; not power-of-two bases).
py::object int_of_decimal(const std::string& text) {
  const bool negative = !text.empty() && text[0] == '-';
  if (text.size() <= 18 + std::size_t(negative)) return py::int_(std::stoll(text));
  big_int v;
  if (mpz_set_str(v.backend().data(), text.c_str(), 10) != 0) throw compute_error("a JSON integer is not decimal: " + text);
  const std::string hex = v.str(0, std::ios_base::hex);  // "-1f" for negatives
  PyObject* r = PyLong_FromString(hex.c_str(), nullptr, 16);
  if (r == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(r);
}

}  // namespace

py::object python_int(const big_int& v) {
  const mpz_srcptr z = v.backend().data();
  if (mpz_fits_slong_p(z)) return py::reinterpret_steal<py::object>(PyLong_FromLong(mpz_get_si(z)));
  const std::string hex = v.str(0, std::ios_base::hex);  // "-1f" for negatives
  PyObject* r = PyLong_FromString(hex.c_str(), nullptr, 16);
  if (r == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(r);
}

py::tuple mpf_parts(const std::string& text, long prec, const std::string& rounding) {
  if (prec < 2 || prec > (1L << 26)) throw usage_error("mpf_parts: prec out of range");
  const mpfr_rnd_t rnd = rounding == "f" ? MPFR_RNDD : rounding == "c" ? MPFR_RNDU : MPFR_RNDN;
  struct holder {
    mpfr_t x;
    mpz_t z;
    explicit holder(long p) { mpfr_init2(x, p), mpz_init(z); }
    ~holder() { mpfr_clear(x), mpz_clear(z); }
  } h(prec);
  if (mpfr_set_str(h.x, text.c_str(), 10, rnd) != 0 || !mpfr_number_p(h.x))
    throw usage_error("not a decimal real of the library: " + text.substr(0, 40));
  if (mpfr_zero_p(h.x)) return py::make_tuple(0, 0, 0, 0);
  // x = z 2^e exactly; mpmath's normal form has an odd mantissa and its bit count.
  long e = long(mpfr_get_z_2exp(h.z, h.x));
  const int sign = mpz_sgn(h.z) < 0 ? 1 : 0;
  mpz_abs(h.z, h.z);
  const mp_bitcnt_t zeros = mpz_scan1(h.z, 0);
  mpz_tdiv_q_2exp(h.z, h.z, zeros);
  e += long(zeros);
  const auto bits = long(mpz_sizeinbase(h.z, 2));
  big_int man;
  mpz_swap(man.backend().data(), h.z);
  return py::make_tuple(sign, python_int(man), e, bits);
}

py::object to_python(const json& j) {
  // Walks the value (no JSON text in between): objects in key order, big integers (json_integer's
  // marker strings, which json_dump would write as bare digits) as ints of any size.
  switch (j.type()) {
    case json::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = to_python(it.value());
      return d;
    }
    case json::value_t::array: {
      py::list l(j.size());
      std::size_t i = 0;
      for (const auto& value : j) l[i++] = to_python(value);
      return l;
    }
    case json::value_t::string: {
      const auto& s = j.get_ref<const std::string&>();
      if (s.size() > int_marker_open.size() + 2 && s.compare(0, int_marker_open.size(), int_marker_open) == 0 &&
          s.compare(s.size() - 2, 2, "@@") == 0)
        return int_of_decimal(s.substr(int_marker_open.size(), s.size() - int_marker_open.size() - 2));
      return py::str(s);
    }
    case json::value_t::boolean: return py::bool_(j.get<bool>());
    case json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case json::value_t::number_float: return py::float_(j.get<double>());
    case json::value_t::null: return py::none();
    default: throw compute_error("to_python: a JSON value of an unexpected type");
  }
}

}  // namespace gyrores::python
