// The data of the CLI's figures (the application layer, include/gyrores/app/figures.hpp), for
// gyrores.plot: phase portraits and H_q/H_z series of a pair or of any coupling n (a double, drawn
// as a coupling that is not resonant), as dicts of NumPy arrays (double: plotting data; the
// marked values come from the exact solvers, as design/figures.hpp says).
#include <pybind11/numpy.h>

#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/app/figures.hpp>
#include <gyrores/app/pareto.hpp>

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
  py::array_t<double> minima(py::ssize_t(e.t_minima.size()));
  for (std::size_t i = 0; i < e.t_minima.size(); ++i) minima.mutable_at(py::ssize_t(i)) = e.t_minima[i];
  d["t_minima"] = minima;
  return d;
}

// Columns time, r_res, tau, sigma of design points (the time `which`).
py::dict point_columns(const std::vector<design_point>& pts, design_time which) {
  const auto n = py::ssize_t(pts.size());
  py::array_t<double> t(n), r(n);
  py::array_t<std::int64_t> tau(n), sigma(n);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    t.mutable_at(py::ssize_t(i)) = design_time_of(pts[i], which);
    r.mutable_at(py::ssize_t(i)) = pts[i].r_res;
    tau.mutable_at(py::ssize_t(i)) = pts[i].tau;
    sigma.mutable_at(py::ssize_t(i)) = pts[i].sigma;
  }
  py::dict d;
  d["t"] = t, d["r_res"] = r, d["tau"] = tau, d["sigma"] = sigma;
  return d;
}

// The points the CLI's Pareto figure draws (app::pareto_figure_points_of: thinned above
// app::pareto_thin_above pairs to one per 2 x 2 pixels of a width x height figure).
py::dict pareto_figure_data(std::int64_t max_order, const std::string& orientation, bool proxy, bool exclude_degenerate,
                            int width, int height) {
  app::pareto_request r;
  r.orientation = app::parse_pareto_orientation(orientation, "orientation");
  r.max_order = max_order;
  r.filter.exclude_degenerate = exclude_degenerate;
  r.time = proxy ? design_time::proxy : design_time::first_hit;
  r.values = false;
  if (width < 100 || height < 100) throw usage_error("the figure's size in pixels must be at least 100 x 100");
  const auto f = run_interruptible<app::pareto_figure_points>([r, width, height](stop_token) {
    const app::pareto_outcome p = app::run_pareto(r);
    return app::pareto_figure_points_of(p.pairs, p.front, r.time, width, height);
  });
  py::dict d;
  d["pairs"] = f.pairs, d["thinned"] = f.pairs > app::pareto_thin_above, d["thin_above"] = app::pareto_thin_above;
  d["positive"] = point_columns(f.positive, r.time), d["zeros"] = point_columns(f.zeros, r.time);
  d["front"] = point_columns(f.front_positive, r.time), d["front_zeros"] = point_columns(f.front_zeros, r.time);
  d["labelled"] = point_columns(f.labelled, r.time);
  return d;
}

// A pair (tau, sigma) or a coupling n: exactly one of them.
app::figure_subject subject_of(const py::object& tau, const py::object& sigma, const py::object& n) {
  if (n.is_none() == (tau.is_none() || sigma.is_none()))
    throw usage_error("give a pair (tau, sigma) or a coupling n, not both");
  if (n.is_none()) return app::figure_subject_of(pair_of(tau, sigma));
  // The coupling exactly as the double given (every double is a binary fraction).
  return app::figure_subject_of(coupling_spec::from_n(big_rational(n.cast<double>())));
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
  m.def("_pareto_figure_data", &pareto_figure_data, py::arg("max_order"), py::arg("orientation"), py::arg("proxy"),
        py::arg("exclude_degenerate"), py::arg("width"), py::arg("height"),
        "The points of the CLI's `plot pareto` (app/figures.hpp, thinned as there). Use gyrores.plot.pareto.");
}

}  // namespace gyrores::python
