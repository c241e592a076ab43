// gyrores.pair and gyrores.asymptotics: the proved report of report/pair_report.hpp (prove_pair)
// as the dict of `gyrores pair --json` (same keys, same order, reals as decimal strings, each the
// correct rounding of a proved enclosure; gyrores/__init__.py converts them), with the
// enclosures when asked, without the asymptotics when told (gyrores.pair computes them on
// first access).
#include <time.h>

#include <chrono>

#include <gyrores/app/pair.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/report/pair_report.hpp>

#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

pair_report run_pair(const resonant_pair<big_int>& p, long long digits, const std::string& qdot0, bool enclosures,
                     bool asymptotics = true) {
  app::pair_request request{p, {}};
  request.options.enclosures = enclosures;
  request.options.asymptotics = asymptotics;
  request.options.digits = checked_digits(digits, 1, report_digits_max);
  request.options.qdot0 = parse_rational(qdot0, "qdot0");
  return run_interruptible<pair_report>([request](stop_token stop) mutable {
    request.options.stop = stop;
    return app::run_pair(request);
  });
}

py::object pair_dict(const py::object& tau, const py::object& sigma, long long digits, const std::string& qdot0,
                     bool enclosures, bool asymptotics) {
  const auto p = pair_of(tau, sigma);
  return to_python(pair_report_json(p, run_pair(p, digits, qdot0, enclosures, asymptotics), enclosures));
}

py::object asymptotics_dict(const py::object& tau, const py::object& sigma, long long digits) {
  const auto p = pair_of(tau, sigma);
  const json full = pair_report_json(p, run_pair(p, digits, "1", false));
  json j = full["asymptotic"];
  for (const char* key : {"r_res_asy", "r_res_asy_rel_error", "digits"}) j[key] = full[key];
  return to_python(j);
}

// The library work pair() wraps, for bench/python_overhead.py: `calls` runs of app::run_pair with
// the request pair() makes (no asymptotics, no enclosures, qdot0 = 1), on this thread without the
// GIL; (thread CPU seconds, wall seconds) of all of them.
py::tuple library_pair_seconds(const py::object& tau, const py::object& sigma, long long digits, long long calls) {
  app::pair_request request{pair_of(tau, sigma), {}};
  request.options.enclosures = false;
  request.options.asymptotics = false;
  request.options.digits = checked_digits(digits, 1, report_digits_max);
  const auto seconds = call_library([&] {
    timespec c0{}, c1{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c0);
    const auto w0 = std::chrono::steady_clock::now();
    for (long long i = 0; i < calls; ++i) {
      const pair_report r = app::run_pair(request);
      if (r.r_res.value.empty()) throw compute_error("no r_res");
    }
    const auto w1 = std::chrono::steady_clock::now();
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c1);
    const double cpu = double(c1.tv_sec - c0.tv_sec) + 1e-9 * double(c1.tv_nsec - c0.tv_nsec);
    return std::make_pair(cpu, std::chrono::duration<double>(w1 - w0).count());
  });
  return py::make_tuple(seconds.first, seconds.second);
}

}  // namespace

void bind_pair(py::module_& m) {
  m.def("_pair", &pair_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"), py::arg("qdot0"),
        py::arg("enclosures"), py::arg("asymptotics") = true,
        "The dict of `gyrores pair --json` (reals as decimal strings, each the correct rounding of a proved "
        "enclosure), with the enclosures when asked. asymptotics=False skips the paper's asymptotics (and their "
        "guard bits): `asymptotic`, `r_res_asy`, `r_res_asy_rel_error` and `bits` are then not those of the "
        "CLI; gyrores.pair fills them on first access. Use gyrores.pair.");
  m.def("_asymptotics", &asymptotics_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        "The `asymptotic` object of `gyrores pair --json` with r_res_asy, r_res_asy_rel_error and digits "
        "(qdot0 = 1). Use gyrores.asymptotics.");
  m.def("_library_pair_seconds", &library_pair_seconds, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        py::arg("calls"), "(thread CPU s, wall s) of `calls` runs of the library work of pair() (bench/python_overhead.py).");
}

}  // namespace gyrores::python
