// gyrores.certify and gyrores.check: the producers (certify/theorem_certificate.hpp, the default;
// certify/certify.hpp with cover=True) and the checkers (the independent Arb checker of
// src/checker/ for "gyrores-certificate/2", certify/check.hpp for /1), through the JSON form
// (io/certificate_json.hpp), so that a certificate made in Python is byte for byte the one
// `gyrores certify` writes.
#include <gyrores/certify/check.hpp>
#include <gyrores/certify/certify.hpp>
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/certificate_json.hpp>

#include "certificate_checker.hpp"
#include "common.hpp"

namespace gyrores::python {
namespace {

py::object certify_dict(const py::object& tau, const py::object& sigma, long long digits, bool cover) {
  const auto p = pair_of(tau, sigma);
  const unsigned d = checked_digits(digits, 1, 10000);
  if (cover) return to_python(certificate_to_json(call_library([&] { return certify_pair(p, d); })));
  return to_python(certificate_to_json(call_library([&] { return certify_by_theorem(p, d); })));
}

// As `gyrores check`: malformed text is a usage_error (ValueError); a checker that cannot compute
// its own enclosures has not re-proved the certificate, which is a failing verdict, not an error.
py::tuple check_text(const std::string& text) {
  if (certificate_format_of(text) == theorem_certificate_format) {
    auto v = gyrores_checker::check_theorem_certificate(text);
    if (v.status == 2) throw usage_error("malformed certificate: " + v.message.substr(v.message.find(':') + 2));
    return py::make_tuple(v.status == 0, v.status == 0 ? std::string() : v.message);
  }
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
  m.def("_certify", &certify_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"), py::arg("cover"),
        "The certificate of `gyrores certify` as a dict. Use gyrores.certify.");
  m.def("_check_text", &check_text, py::arg("text"),
        "(holds, failure) for a certificate's JSON text. Use gyrores.check.");
}

}  // namespace gyrores::python
