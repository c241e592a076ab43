// gyrores.design, gyrores.pareto: the application layer's requests (include/gyrores/app/design.hpp,
// app/pareto.hpp), returned as the dicts of the matching `gyrores ... --json` commands
// (io/design_output.hpp; the files the CLI can write beside them, CSV and plots, are left to the
// caller). The Python arguments become a request; the application layer checks it.
#include <gyrores/app/design.hpp>
#include <gyrores/app/pareto.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/io/design_output.hpp>

#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

// A rational parameter (None: not given) as its text and its value.
std::optional<big_rational> rational_of(const py::object& v, const std::string& what, std::string& text) {
  if (v.is_none()) return std::nullopt;
  text = rational_text(v);
  return parse_rational(text, what);
}

py::object design_dict(const std::string& problem, const py::object& tmax, const py::object& beat,
                       std::int64_t max_order, std::int64_t exclude_low, const py::object& delta, bool proxy,
                       std::int64_t candidates, long long digits) {
  app::design_request r;
  design_options& o = r.options;
  o.problem = app::parse_design_problem(problem);
  r.digits = checked_digits(digits, 1, app::listed_digits_max);
  r.tmax_text = rational_text(tmax);
  o.tmax = parse_rational(r.tmax_text, "tmax");
  o.filter.beat_min = rational_of(beat, "beat", r.beat_text);
  o.filter.exclude_low = exclude_low;
  if (!delta.is_none()) o.filter.delta = delta.cast<std::int64_t>();
  if (candidates < 0) throw usage_error("candidates must be in [0, 1000]");
  o.candidates = std::size_t(candidates);
  o.time = proxy ? design_time::proxy : design_time::first_hit;
  o.max_order = max_order;
  // By value: on Ctrl-C the work may outlive this call (interruptible.hpp).
  return to_python(run_interruptible<json>([r](stop_token stop) mutable {
    r.stop = stop;
    const app::design_outcome out = app::run_design(r);
    return design_json(r.options, r.tmax_text, r.beat_text, out.result, out.values, out.chosen_exceeds_tmax, r.digits);
  }));
}

py::object pareto_dict(std::int64_t max_order, const std::string& orientation, bool proxy, bool exclude_degenerate,
                       const py::object& beat, std::int64_t exclude_low, long long digits) {
  app::pareto_request r;
  r.orientation = app::parse_pareto_orientation(orientation, "orientation");
  r.digits = checked_digits(digits, 1, app::listed_digits_max);
  std::string beat_text;
  r.filter.beat_min = rational_of(beat, "beat", beat_text);
  r.filter.exclude_low = exclude_low;
  r.filter.exclude_degenerate = exclude_degenerate;
  r.time = proxy ? design_time::proxy : design_time::first_hit;
  r.max_order = max_order;
  return to_python(run_interruptible<json>([r](stop_token) {
    const app::pareto_outcome p = app::run_pareto(r);
    return pareto_json(r.orientation, r.time, r.max_order, p.pairs.size(), p.front, p.values, r.digits);
  }));
}

}  // namespace

void bind_design(py::module_& m) {
  m.def("_design", &design_dict, py::arg("problem"), py::arg("tmax"), py::arg("beat"), py::arg("max_order"),
        py::arg("exclude_low"), py::arg("delta"), py::arg("proxy"), py::arg("candidates"), py::arg("digits"),
        "The dict of `gyrores design --json`. Use gyrores.design.");
  m.def("_pareto", &pareto_dict, py::arg("max_order"), py::arg("orientation"), py::arg("proxy"),
        py::arg("exclude_degenerate"), py::arg("beat"), py::arg("exclude_low"), py::arg("digits"),
        "The dict of `gyrores pareto --json` (without its file keys). Use gyrores.pareto.");
}

}  // namespace gyrores::python
