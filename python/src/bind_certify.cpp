// gyrores.certify and gyrores.check: the producer (certify/theorem_certificate.hpp) and the
// independent Arb checker (src/checker/), through the JSON form (io/certificate_json.hpp), so
// that a certificate made in Python is byte for byte the one `gyrores certify` writes, and
// check answers as `gyrores check` does. A certificate of the retired format /1 is refused at
// once (UsageError), as `gyrores check` refuses it with exit 2.
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/certificate_json.hpp>

#include "certificate_checker.hpp"
#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

py::object certify_dict(const py::object& tau, const py::object& sigma, long long digits) {
  const auto p = pair_of(tau, sigma);
  const unsigned d = checked_digits(digits, 1, 10000);
  return to_python(certificate_to_json(run_interruptible<theorem_certificate>([p, d](stop_token) { return certify_by_theorem(p, d); })));
}

// As `gyrores check`: a retired or malformed text is a usage_error (ValueError); otherwise the
// checker's verdict, (holds, failure).
py::tuple check_text(const std::string& text) {
  if (certificate_format_of(text) == retired_certificate_format) throw usage_error(retired_certificate_message());
  auto v = gyrores_checker::check_theorem_certificate(text);
  if (v.status == 2) throw usage_error("malformed certificate: " + v.message.substr(v.message.find(':') + 2));
  return py::make_tuple(v.status == 0, v.status == 0 ? std::string() : v.message);
}

}  // namespace

void bind_certify(py::module_& m) {
  m.def("_certify", &certify_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        "The certificate of `gyrores certify` as a dict. Use gyrores.certify.");
  m.def("_check_text", &check_text, py::arg("text"),
        "(holds, failure) for a certificate's JSON text. Use gyrores.check.");
}

}  // namespace gyrores::python
