// gyrores.pair and gyrores.asymptotics: the proved report of report/pair_report.hpp (prove_pair)
// as the dict of `gyrores pair --json` (same keys, same order, reals as decimal strings, each the
// correct rounding of a proved enclosure; gyrores/__init__.py converts them), with the
// enclosures when asked, without the asymptotics when told (gyrores.pair computes them on
// first access).
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include <gyrores/app/pair.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/report/pair_report.hpp>
#include <gyrores/theorem/lobes.hpp>

#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

pair_report run_pair(const resonant_pair<big_int>& p, long long digits, const std::string& qdot0, bool enclosures,
                     bool asymptotics = true, bool doubles = false) {
  app::pair_request request{p, {}};
  request.options.enclosures = enclosures;
  request.options.doubles = doubles;
  request.options.asymptotics = asymptotics;
  request.options.digits = checked_digits(digits, 1, report_digits_max);
  request.options.qdot0 = qdot0 == "1" ? big_rational(1) : parse_rational(qdot0, "qdot0");
  return run_interruptible<pair_report>([request](stop_token stop) mutable {
    request.options.stop = stop;
    return app::run_pair(request);
  });
}

// The dict of pair_report_json(p, r, false) built directly, the same keys in the same order (no
// JSON value in between: this is most of what a small pair's call costs beyond the library's
// work; python/tests/test_pair.py compares keys, order and values with the CLI's JSON).
template <class Real> py::dict pair_report_dict(const resonant_pair<big_int>& p, const pair_report& r, Real real) {
  py::dict d;
  d["format"] = pair_report_format;
  d["tau"] = python_int(p.tau());
  d["sigma"] = python_int(p.sigma());
  d["delta"] = python_int(big_int(p.delta()));
  d["delta_mod4"] = p.delta_mod4();
  d["v2_delta"] = p.v2_delta();
  d["degenerate"] = p.degenerate();
  d["order"] = python_int(p.order());
  d["m_min"] = r.m_min;
  for (auto [name, value] : {std::pair{"beat_ratio", &r.beat_ratio}, {"n", &r.n}, {"omega1", &r.omega1},
                             {"omega2", &r.omega2}, {"rho0", &r.rho0}, {"qdot0", &r.qdot0}, {"r_res", &r.r_res},
                             {"h_min", &r.h_min}, {"h_z_max", &r.h_z_max}, {"theta_first", &r.theta_first},
                             {"t_first", &r.t_first}, {"t_min_paper", &r.t_min_paper}})
    d[name] = real(*value);
  py::list mins(r.minimisers.size());
  for (std::size_t i = 0; i < r.minimisers.size(); ++i) mins[i] = real(r.minimisers[i]);
  d["minimisers"] = mins;
  d["r_res_asy"] = r.r_res_asy ? py::object(real(*r.r_res_asy)) : py::none();
  d["r_res_asy_rel_error"] = r.r_res_asy_rel_error ? py::object(real(*r.r_res_asy_rel_error)) : py::none();
  py::dict asy;
  asy["applicable"] = r.asymptotic_applicable;
  asy["reason"] = r.asymptotic_reason;
  py::list lobes;
  for (const auto& l : r.lobes) {
    py::dict lo;
    lo["k"] = python_int(l.k);
    lo["m"] = python_int(l.m);
    for (auto [name, value] : {std::pair{"s", &l.s}, {"u_asy", &l.u_asy}, {"theta_asy", &l.theta_asy},
                               {"theta_c", &l.theta_c}, {"error", &l.error}, {"bound", &l.bound}, {"ratio", &l.ratio}})
      lo[name] = real(*value);
    lo["holds_global_min"] = l.holds_global_min;
    lobes.append(lo);
  }
  asy["lobes"] = lobes;
  d["asymptotic"] = asy;
  d["digits"] = r.digits;
  d["theorem"] = lattice_theorem_id;
  d["bits"] = r.bits;
  return d;
}

py::object pair_dict(const py::object& tau, const py::object& sigma, long long digits, const std::string& qdot0,
                     bool enclosures, bool asymptotics) {
  const auto p = pair_of(tau, sigma);
  const pair_report r = run_pair(p, digits, qdot0, enclosures, asymptotics);
  if (!enclosures) return pair_report_dict(p, r, [](const proved_real& v) { return py::str(v.value); });
  return to_python(pair_report_json(p, r, enclosures));
}

// pair()'s dict for digits <= 15: every real the double nearest its exact value, decided by the
// report's own enclosures (pair_report_options::doubles: the report's precision rises until each
// is), with the report's 17-digit enclosures when asked; `digits` is the caller's.
py::object pair_doubles(const py::object& tau, const py::object& sigma, long long digits, const std::string& qdot0,
                        bool asymptotics, bool enclosures) {
  const auto p = pair_of(tau, sigma);
  checked_digits(digits, 1, 15);
  const pair_report r = run_pair(p, 17, qdot0, enclosures, asymptotics, true);
  py::dict d = pair_report_dict(p, r, [](const proved_real& v) { return py::float_(v.nearest); });
  d["digits"] = digits;
  if (enclosures) d["enclosures"] = to_python(pair_report_json(p, r, true)["enclosures"]);
  return d;
}

py::object asymptotics_dict(const py::object& tau, const py::object& sigma, long long digits) {
  const auto p = pair_of(tau, sigma);
  const json full = pair_report_json(p, run_pair(p, digits, "1", false));
  json j = full["asymptotic"];
  for (const char* key : {"r_res_asy", "r_res_asy_rel_error", "digits"}) j[key] = full[key];
  return to_python(j);
}

// The library work pair() wraps, for bench/python_overhead.py: `calls` runs of app::run_pair with
// the request pair() makes (no asymptotics, qdot0 = 1; digits <= 15: 17 digits with the doubles
// decided), on this thread without the GIL; (thread CPU seconds, wall seconds) of all of them.
py::tuple library_pair_seconds(const py::object& tau, const py::object& sigma, long long digits, bool doubles,
                               long long calls) {
  app::pair_request request{pair_of(tau, sigma), {}};
  request.options.doubles = doubles;
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
  m.def("_pair_doubles", &pair_doubles, py::arg("tau"), py::arg("sigma"), py::arg("digits"), py::arg("qdot0"),
        py::arg("asymptotics"), py::arg("enclosures") = false,
        "pair()'s dict for digits <= 15: every real the correctly rounded double of its exact value (decided by "
        "the report's enclosures), with the 17-digit enclosures when asked. Use gyrores.pair.");
  m.def("_asymptotics", &asymptotics_dict, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        "The `asymptotic` object of `gyrores pair --json` with r_res_asy, r_res_asy_rel_error and digits "
        "(qdot0 = 1). Use gyrores.asymptotics.");
  m.def("_library_pair_seconds", &library_pair_seconds, py::arg("tau"), py::arg("sigma"), py::arg("digits"),
        py::arg("doubles"), py::arg("calls"), "(thread CPU s, wall s) of `calls` runs of the library work of pair() (bench/python_overhead.py).");
}

}  // namespace gyrores::python
