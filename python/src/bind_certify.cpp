// gyrores.certify and gyrores.check: the requests of app/certify.hpp (the producer and the
// independent Arb checkers of both formats), the certificate as its JSON form
// (io/certificate_json.hpp), so that a certificate made in Python is byte for byte the one
// `gyrores certify` writes, and check answers as `gyrores check` does. A certificate of the
// retired format /1 is refused at once (UsageError), as `gyrores check` refuses it with exit 2.
#include <gyrores/app/certify.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/io/files.hpp>
#include <gyrores/io/json.hpp>

#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

py::object certify_dict(const py::object& tau, const py::object& sigma, long long digits) {
  app::certify_request request{pair_of(tau, sigma), checked_digits(digits, 1, report_digits_max), {}};
  return to_python(certificate_to_json(run_interruptible<theorem_certificate>([request](stop_token stop) mutable {
    request.stop = stop;
    return app::run_certify(request);
  })));
}

// As `gyrores check`: a retired or malformed text is a usage_error (ValueError); otherwise the
// checker's verdict, (holds, failure). The text is bytes as read from the file (or str): every
// format `gyrores check` reads (app/certify.hpp chooses the checker by the text's "format").
py::tuple check_text(const std::string& text) {
  const app::check_verdict v = call_library([&] { return app::run_check(text); });
  if (v.retired) throw usage_error(v.message);
  if (v.status == 2) throw usage_error("malformed certificate: " + v.message.substr(v.message.find(':') + 2));
  return py::make_tuple(v.status == 0, v.status == 0 ? std::string() : v.message);
}

// A certificate given as Python objects (json.load of a file, or certify()'s dict) as the JSON
// value the library writes: dicts with str keys, lists and tuples, str, int of any size (exactly,
// never through Python's int-to-decimal conversion and its digit limit), float, bool, None.
// `budget` counts down the text's size (the 4 MiB cap of `gyrores check`), depth is bounded
// (a dict holding itself).
usage_error too_large() {
  return usage_error("the certificate is larger than " + std::to_string(certificate_read_limit) +
                     " bytes (the limit for a certificate)");
}

struct json_builder {
  std::size_t budget;
  json of(const py::handle& v, int depth) {
    if (depth > 64) throw usage_error("malformed certificate: nested deeper than 64 levels");
    if (budget < 8) throw too_large();
    budget -= 4;
    if (v.is_none()) return nullptr;
    if (PyBool_Check(v.ptr())) return v.ptr() == Py_True;
    if (PyLong_Check(v.ptr())) {
      int overflow = 0;
      const long long small = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
      if (overflow == 0) return json(std::int64_t(small));
      const big_int b = big_int_of(v, "an integer of the certificate");
      const std::string digits = b.str();
      take(digits.size());
      return json_integer(digits);
    }
    if (PyFloat_Check(v.ptr())) return json(PyFloat_AsDouble(v.ptr()));
    if (PyUnicode_Check(v.ptr())) {
      std::string s = v.cast<std::string>();
      take(s.size());
      return json(std::move(s));
    }
    if (PyDict_Check(v.ptr())) {
      json j = json::object();
      for (const auto item : py::reinterpret_borrow<py::dict>(v)) {
        if (!PyUnicode_Check(item.first.ptr()))
          throw usage_error("malformed certificate: a key is not text: " + std::string(py::repr(item.first)));
        std::string key = item.first.cast<std::string>();
        take(key.size());
        j[key] = of(item.second, depth + 1);
      }
      return j;
    }
    if (PyList_Check(v.ptr()) || PyTuple_Check(v.ptr())) {
      json j = json::array();
      for (const auto item : v) j.push_back(of(item, depth + 1));
      return j;
    }
    throw usage_error("malformed certificate: a value is not JSON: " + std::string(py::repr(v.get_type())));
  }
  void take(std::size_t n) {
    if (n >= budget) throw too_large();
    budget -= n;
  }
};

py::tuple check_object(const py::dict& cert) {
  const std::string text = json_dump(json_builder{certificate_read_limit}.of(cert, 0), -1);
  if (text.size() > certificate_read_limit) throw too_large();
  return check_text(text);
}

}  // namespace

void bind_certify(py::module_& m) {
  m.def("_certify", &certify_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        "The certificate of `gyrores certify` as a dict. Use gyrores.certify.");
  m.def("_check_text", &check_text, py::arg("text"),
        "(holds, failure) for a certificate's JSON text (bytes or str). Use gyrores.check.");
  m.def("_check_object", &check_object, py::arg("cert"),
        "(holds, failure) for a certificate as a dict. Use gyrores.check.");
}

}  // namespace gyrores::python
