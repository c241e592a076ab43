// gyrores.certify and gyrores.check: the producer (certify/certify.hpp) and the independent
// checker (certify/check.hpp) of certificates, through their JSON form (io/certificate_json.hpp),
// so that a certificate made in Python is byte for byte the one `gyrores certify` writes.
#include <gyrores/certify/check.hpp>
#include <gyrores/certify/certify.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/certificate_json.hpp>

#include "common.hpp"

namespace gyrores::python {
namespace {

py::object certify_dict(const py::object& tau, const py::object& sigma, long long digits) {
  const auto p = pair_of(tau, sigma);
  const unsigned d = checked_digits(digits, 1, 10000);
  const certificate c = call_library([&] { return certify_pair(p, d); });
  return to_python(certificate_to_json(c));
}

// As `gyrores check`: malformed text is a usage_error (ValueError); a checker that cannot compute
// its own enclosures has not re-proved the certificate, which is a failing verdict, not an error.
py::tuple check_text(const std::string& text) {
  const certificate c = certificate_from_text(text);
  const check_verdict v = call_library([&] {
    try {
      return check_certificate(c);
    } catch (const compute_error& e) {
      return check_verdict{false, e.what()};
    }
  });
  return py::make_tuple(v.holds, v.failure);
}

}  // namespace

void bind_certify(py::module_& m) {
  m.def("_certify", &certify_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        "The certificate of `gyrores certify` as a dict. Use gyrores.certify.");
  m.def("_check_text", &check_text, py::arg("text"),
        "(holds, failure) for a certificate's JSON text. Use gyrores.check.");
}

}  // namespace gyrores::python
