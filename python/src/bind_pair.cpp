// gyrores.pair and gyrores.asymptotics: the report of inscribed/verified_pair.hpp (verify_pair)
// as the dict of `gyrores pair --json` (same keys, same order, reals as verified decimal
// strings; gyrores/__init__.py converts them), optionally with the enclosures of a certificate
// (certify/certify.hpp).
#include <gyrores/certify/theorem_certificate.hpp>

#include <optional>
#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/verified_digits.hpp>
#include <gyrores/inscribed/global_search.hpp>
#include <gyrores/io/report_json.hpp>

#include "common.hpp"

namespace gyrores::python {
namespace {

solver_choice solver_of(const std::string& method) {
  if (method == "lattice") return solver_choice::lattice;
  if (method == "global") return solver_choice::global_search;
  throw usage_error("method must be 'lattice' or 'global', got '" + method + "'");
}

verified_pair_report run_verify(const resonant_pair<big_int>& p, long long digits, const std::string& qdot0,
                                const std::string& method) {
  verified_pair_options opt;
  opt.digits = checked_digits(digits, 1, verified_digits_max);
  check_qdot0_text(qdot0, "qdot0");  // before any work
  opt.qdot0 = qdot0;
  opt.solver = solver_of(method);
  const std::int64_t limit = global_search_options{}.max_order;
  if (opt.solver == solver_choice::global_search && p.order() > big_int(limit))
    throw compute_error("the global search is limited to order tau + sigma <= " + std::to_string(limit) +
                        "; use method='lattice' for " + p.str());
  return call_library([&] { return verify_pair(p, opt); });
}

py::object pair_dict(const py::object& tau, const py::object& sigma, long long digits, const std::string& qdot0,
                     const std::string& method, bool certified) {
  const auto p = pair_of(tau, sigma);
  const verified_pair_report r = run_verify(p, digits, qdot0, method);
  json j = pair_report_json(p, r);
  std::optional<certified_enclosures> proved;
  if (certified) proved = call_library([&] { return certify_enclosures(p, r.digits, qdot0); });
  add_enclosures_json(j, proved ? &*proved : nullptr);
  return to_python(j);
}

py::object asymptotics_dict(const py::object& tau, const py::object& sigma, long long digits) {
  const auto p = pair_of(tau, sigma);
  const verified_pair_report r = run_verify(p, digits, "1", "lattice");
  json j = asymptotic_json(r);
  j["r_res_asy"] = r.r_res_asy ? json(*r.r_res_asy) : json(nullptr);
  j["r_res_asy_rel_error"] = r.r_res_asy_rel_error ? json(*r.r_res_asy_rel_error) : json(nullptr);
  j["unsettled"] = pair_report_json(p, r)["unsettled"];  // diagnostics printed with fewer digits (docs/formats.md)
  j["digits"] = r.digits;
  return to_python(j);
}

}  // namespace

void bind_pair(py::module_& m) {
  m.def("_pair", &pair_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"), py::arg("qdot0"),
        py::arg("method"), py::arg("certified"),
        "The dict of `gyrores pair --json` (reals as verified decimal strings), plus the certificate's "
        "enclosures when certified. Use gyrores.pair.");
  m.def("_asymptotics", &asymptotics_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        "The `asymptotic` object of `gyrores pair --json` with r_res_asy, r_res_asy_rel_error and digits "
        "(qdot0 = 1). Use gyrores.asymptotics.");
}

}  // namespace gyrores::python
