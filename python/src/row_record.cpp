// python/src/row_record.hpp
#include "row_record.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include <gyrores/core/error.hpp>

namespace gyrores::python {
namespace {

template <class T> void put(char* record, std::ptrdiff_t offset, T value) { std::memcpy(record + offset, &value, sizeof value); }

}  // namespace

py::list row_fields() {
  py::list f;
  auto add = [&](const std::string& name, const char* format) { f.append(py::make_tuple(name, format)); };
  for (const char* n : {"tau", "sigma", "order"}) add(n, "<i8");
  add("delta_mod4", "i1");
  for (const char* n : {"r_res", "theta_first", "t_first", "t_min_paper", "t_first_over_proxy"}) add(n, "<f8");
  add("first_at_paper_node", "i1");
  add("paper_lobe_min", "i1");
  for (const char* n : {"asy_error", "asy_bound", "asy_ratio", "asy_constant"}) add(n, "<f8");
  add("minimiser_count", "<i4");
  add("strand_offset_min", "<i4");
  for (int i = 0; i < sweep_check_count; ++i) add(sweep_check_column(i), "i1");
  add("failed", "?");
  add("note", "<U1");  // widened by gyrores.pairs to the longest note, when there is one
  return f;
}

row_layout row_layout::of(const py::array& table) {
  const py::dict fields = table.dtype().attr("fields");
  auto at = [&](const std::string& name) {
    if (!fields.contains(name)) throw usage_error("the table has no field " + name);
    return fields[py::str(name)].cast<py::tuple>()[1].cast<std::ptrdiff_t>();
  };
  row_layout l;
  l.tau = at("tau"), l.sigma = at("sigma"), l.order = at("order"), l.delta_mod4 = at("delta_mod4");
  l.r_res = at("r_res"), l.theta_first = at("theta_first"), l.t_first = at("t_first"), l.t_min_paper = at("t_min_paper");
  l.t_ratio = at("t_first_over_proxy"), l.first_at_paper_node = at("first_at_paper_node");
  l.paper_lobe_min = at("paper_lobe_min"), l.asy_error = at("asy_error"), l.asy_bound = at("asy_bound");
  l.asy_ratio = at("asy_ratio"), l.asy_constant = at("asy_constant"), l.minimiser_count = at("minimiser_count");
  l.strand_offset = at("strand_offset_min"), l.failed = at("failed");
  for (int i = 0; i < sweep_check_count; ++i) l.checks[std::size_t(i)] = at(sweep_check_column(i));
  l.itemsize = table.itemsize();
  return l;
}

// Not applicable is NaN for reals, -1 for flags (as the CSV rows leave them empty).
void row_layout::write(char* rec, const sweep_row<double>& r) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool ok = !r.failed;
  put<std::int64_t>(rec, tau, r.tau);
  put<std::int64_t>(rec, sigma, r.sigma);
  put<std::int64_t>(rec, order, r.tau + r.sigma);
  put(rec, delta_mod4, std::int8_t(r.delta_mod4));
  put(rec, r_res, ok ? r.r_res : nan);
  put(rec, theta_first, ok ? r.theta_first : nan);
  put(rec, t_first, ok ? r.t_first : nan);
  put(rec, t_min_paper, ok ? r.t_min_paper : nan);
  put(rec, t_ratio, ok && r.has_ratio ? r.t_ratio : nan);
  const bool asy = ok && r.has_asy;
  put(rec, asy_error, asy ? r.asy_error : nan);
  put(rec, asy_bound, asy ? r.asy_bound : nan);
  put(rec, asy_ratio, asy ? r.asy_ratio : nan);
  put(rec, asy_constant, asy ? r.asy_constant : nan);
  put(rec, first_at_paper_node, std::int8_t(ok ? r.first_at_paper_node : -1));
  put(rec, paper_lobe_min, std::int8_t(ok ? r.paper_lobe_min : -1));
  put<std::int32_t>(rec, minimiser_count, ok ? r.minimiser_count : -1);
  put<std::int32_t>(rec, strand_offset, r.strand_offset);
  for (int i = 0; i < sweep_check_count; ++i) {
    const sweep_status s = r.status[std::size_t(i)];
    put(rec, checks[std::size_t(i)], std::int8_t(s == sweep_status::none ? -1 : s == sweep_status::pass ? 1 : 0));
  }
  put(rec, failed, bool(r.failed));
}

}  // namespace gyrores::python
