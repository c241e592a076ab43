// gyrores.certify and gyrores.check: the requests of app/certify.hpp (the producer and the
// independent Arb checkers of both formats), the certificate as its JSON form
// (io/certificate_json.hpp), so that a certificate made in Python is byte for byte the one
// `gyrores certify` writes, and check answers as `gyrores check` does. A certificate of the
// retired format /1 is refused at once (UsageError), as `gyrores check` refuses it with exit 2.
#include <gyrores/app/certify.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/certificate_json.hpp>

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
// checker's verdict, (holds, failure).
py::tuple check_text(const std::string& text) {
  const app::check_verdict v = app::run_check(text);
  if (v.retired) throw usage_error(v.message);
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
