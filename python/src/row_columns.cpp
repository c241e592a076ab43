// python/src/row_columns.hpp
#include "row_columns.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <tuple>

namespace gyrores::python {
namespace {

template <class V> py::array column(const V& v) {
  using T = typename V::value_type;
  return py::array_t<T>(py::ssize_t(v.size()), v.data());
}

}  // namespace

void row_columns::add(const sweep_row<double>& r) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool ok = !r.failed;
  tau.push_back(r.tau);
  sigma.push_back(r.sigma);
  order.push_back(r.tau + r.sigma);
  delta_mod4.push_back(std::int8_t(r.delta_mod4));
  for (auto [col, v, have] : {std::tuple{&r_res, r.r_res, ok}, {&theta_first, r.theta_first, ok}, {&t_first, r.t_first, ok},
                              {&t_min_paper, r.t_min_paper, ok}, {&t_ratio, r.t_ratio, ok && r.has_ratio},
                              {&asy_error, r.asy_error, ok && r.has_asy}, {&asy_bound, r.asy_bound, ok && r.has_asy},
                              {&asy_ratio, r.asy_ratio, ok && r.has_asy}, {&asy_constant, r.asy_constant, ok && r.has_asy}})
    col->push_back(have ? v : nan);
  first_at_paper_node.push_back(std::int8_t(ok ? r.first_at_paper_node : -1));
  paper_lobe_min.push_back(std::int8_t(ok ? r.paper_lobe_min : -1));
  minimiser_count.push_back(ok ? r.minimiser_count : -1);
  strand_offset.push_back(r.strand_offset);
  for (int i = 0; i < sweep_check_count; ++i) {
    const sweep_status s = r.status[std::size_t(i)];
    checks[std::size_t(i)].push_back(std::int8_t(s == sweep_status::none ? -1 : s == sweep_status::pass ? 1 : 0));
  }
  failed.push_back(std::int8_t(r.failed));
  notes.push_back(r.note);
}

py::dict columns_dict(const row_columns& c) {
  py::dict d;
  for (auto [name, v] : {std::pair{"tau", &c.tau}, {"sigma", &c.sigma}, {"order", &c.order}}) d[name] = column(*v);
  d["delta_mod4"] = column(c.delta_mod4);
  for (auto [name, v] : {std::pair{"r_res", &c.r_res}, {"theta_first", &c.theta_first}, {"t_first", &c.t_first},
                         {"t_min_paper", &c.t_min_paper}, {"t_first_over_proxy", &c.t_ratio}})
    d[name] = column(*v);
  d["first_at_paper_node"] = column(c.first_at_paper_node);
  d["paper_lobe_min"] = column(c.paper_lobe_min);
  for (auto [name, v] : {std::pair{"asy_error", &c.asy_error}, {"asy_bound", &c.asy_bound},
                         {"asy_ratio", &c.asy_ratio}, {"asy_constant", &c.asy_constant}})
    d[name] = column(*v);
  d["minimiser_count"] = column(c.minimiser_count);
  d["strand_offset_min"] = column(c.strand_offset);
  for (int i = 0; i < sweep_check_count; ++i) d[sweep_check_column(i)] = column(c.checks[std::size_t(i)]);
  d["failed"] = column(c.failed);
  d["note"] = py::cast(c.notes);
  return d;
}

}  // namespace gyrores::python
