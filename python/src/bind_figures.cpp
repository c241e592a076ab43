// The data of the CLI's figures (the application layer, include/gyrores/app/figures.hpp), for
// gyrores.plot: phase portraits and H_q/H_z series of a pair or of any coupling n (a double, drawn
// as a coupling that is not resonant), as dicts of NumPy arrays (double: plotting data; the
// marked values come from the exact solvers, as design/figures.hpp says).
#include <pybind11/numpy.h>

#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/app/figures.hpp>

#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

py::array_t<double> xy(const std::vector<plane_point<double>>& points) {
  py::array_t<double> a({py::ssize_t(points.size()), py::ssize_t(2)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    m(py::ssize_t(i), 0) = points[i].x;
    m(py::ssize_t(i), 1) = points[i].y;
  }
  return a;
}

py::dict phase_dict(const phase_portrait& p) {
  py::dict d;
  d["n"] = p.n, d["qdot0"] = p.qdot0, d["resonant"] = p.resonant, d["t_span"] = p.t_span;
  if (p.resonant) d["tau"] = p.tau, d["sigma"] = p.sigma;
  d["trajectory"] = xy(p.trajectory);
  d["envelope"] = xy(p.envelope);
  d["r_inscribed"] = p.r_inscribed, d["inscribed_is_infimum"] = p.inscribed_is_infimum, d["r_max"] = p.r_max;
  d["first_min"] = py::make_tuple(p.first_min.x, p.first_min.y);
  d["t_first"] = p.t_first, d["t_proxy"] = p.t_proxy;
  py::list near;
  for (const auto& curve : p.near_minimisers) near.append(xy(curve));
  d["near_minimisers"] = near;
  return d;
}

py::dict energy_dict(const energy_series& e) {
  py::array_t<double> t(py::ssize_t(e.samples.size())), hq(py::ssize_t(e.samples.size())), hz(py::ssize_t(e.samples.size()));
  for (std::size_t i = 0; i < e.samples.size(); ++i) {
    t.mutable_at(py::ssize_t(i)) = e.samples[i].t;
    hq.mutable_at(py::ssize_t(i)) = e.samples[i].h_q;
    hz.mutable_at(py::ssize_t(i)) = e.samples[i].h_z;
  }
  py::dict d;
  d["n"] = e.n, d["qdot0"] = e.qdot0, d["t"] = t, d["h_q"] = hq, d["h_z"] = hz;
  d["t_first"] = e.t_first, d["h_min"] = e.h_min, d["t_proxy"] = e.t_proxy, d["t_end"] = e.t_end;
  return d;
}

// A pair (tau, sigma) or a coupling n: exactly one of them.
app::figure_subject subject_of(const py::object& tau, const py::object& sigma, const py::object& n) {
  if (n.is_none() == (tau.is_none() || sigma.is_none()))
    throw usage_error("give a pair (tau, sigma) or a coupling n, not both");
  if (n.is_none()) return app::figure_subject_of(pair_of(tau, sigma));
  return {std::nullopt, n.cast<double>()};
}

py::dict phase_data(const py::object& tau, const py::object& sigma, const py::object& n, double qdot0, double t_span) {
  const app::figure_subject s = subject_of(tau, sigma, n);
  return phase_dict(run_interruptible<phase_portrait>([=](stop_token) { return app::phase_figure(s, qdot0, t_span); }));
}

py::dict energy_data(const py::object& tau, const py::object& sigma, const py::object& n, double qdot0, double t_end) {
  const app::figure_subject s = subject_of(tau, sigma, n);
  return energy_dict(run_interruptible<energy_series>([=](stop_token) { return app::energy_figure(s, qdot0, t_end); }));
}

}  // namespace

void bind_figures(py::module_& m) {
  m.def("_phase_data", &phase_data, py::arg("tau"), py::arg("sigma"), py::arg("n"), py::arg("qdot0"), py::arg("t_span"),
        "The phase portrait of the CLI's `plot phase` (app/figures.hpp). Use gyrores.plot.phase.");
  m.def("_energy_data", &energy_data, py::arg("tau"), py::arg("sigma"), py::arg("n"), py::arg("qdot0"), py::arg("t_end"),
        "H_q(t), H_z(t) of the CLI's `plot energy` (app/figures.hpp). Use gyrores.plot.energy.");
}

}  // namespace gyrores::python
