// gyrores.design, gyrores.pareto: the application layer's requests (include/gyrores/app/design.hpp,
// app/pareto.hpp), returned as the dicts of the matching `gyrores ... --json` commands
// (io/report_json.hpp; the files the CLI can write beside them, CSV and plots, are left to the
// caller). The Python arguments become a request; the application layer checks it. design's
// tolerance, level and horizon are `gyrores design --tolerance P% --level E [--horizon H]`: read
// by the CLI's parsers, checked as src/cli/cmd_design.cpp checks them (named as in Python).
#include <gyrores/app/design.hpp>
#include <gyrores/app/pareto.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/model/inputs.hpp>

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

// The band guarantee asked for: the tolerance "P%" with the level E (an energy or "1%" of
// H_q(0)) and, for contain, the horizon H (default tmax); none without a tolerance.
std::optional<app::design_tolerance> tolerance_of(const py::object& tolerance, const py::object& level,
                                                  const py::object& horizon, design_problem problem) {
  if (tolerance.is_none()) {
    if (!level.is_none() || !horizon.is_none()) throw usage_error("level and horizon need tolerance");
    return std::nullopt;
  }
  app::design_tolerance t;
  // The band 1 (1 -+ P/100): its upper end less 1 is the fraction P/100, as the CLI takes it.
  t.fraction = parse_tolerance_band(1, tolerance.cast<std::string>(), "tolerance").second - 1;
  if (level.is_none()) throw usage_error("tolerance needs level E: the energy to absorb down to (absorb) or to keep (contain)");
  t.level = parse_energy_level(level.cast<std::string>(), "level");
  if (!horizon.is_none()) {
    if (problem == design_problem::absorb) throw usage_error("horizon is for contain (absorb uses tmax)");
    const std::string text = rational_text(horizon);
    const big_rational h = parse_rational(text, "horizon");
    if (!(h > 0)) throw usage_error("horizon must be > 0, got " + text);
    t.horizon = horizon_time(h);
  }
  return t;
}

py::object design_dict(const std::string& problem, const py::object& tmax, const py::object& beat,
                       std::int64_t max_order, std::int64_t exclude_low, const py::object& delta, bool proxy,
                       std::int64_t candidates, long long digits, const py::object& tolerance,
                       const py::object& level, const py::object& horizon) {
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
  r.tolerance = tolerance_of(tolerance, level, horizon, o.problem);
  // The JSON echoes the tolerance and level as given, as the CLI's does.
  const std::string percent = tolerance.is_none() ? "" : tolerance.cast<std::string>();
  const std::string level_text = level.is_none() ? "" : level.cast<std::string>();
  // By value: on Ctrl-C the work may outlive this call (interruptible.hpp); the band proofs of a
  // tolerance look at the stop flag.
  return to_python(run_interruptible<json>([r, percent, level_text](stop_token stop) mutable {
    r.stop = stop;
    const app::design_outcome out = app::run_design(r);
    if (out.tolerance && out.tolerance->interrupted) throw interrupted();  // KeyboardInterrupt
    json j = design_json(r.options, r.tmax_text, r.beat_text, out.result, out.values, out.chosen_exceeds_tmax, r.digits);
    if (out.tolerance) j["tolerance"] = tolerance_json(r.options.problem, *out.tolerance, percent, level_text);
    return j;
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
        py::arg("tolerance") = py::none(), py::arg("level") = py::none(), py::arg("horizon") = py::none(),
        "The dict of `gyrores design --json` (with --tolerance P% --level E [--horizon H]). Use gyrores.design.");
  m.def("_pareto", &pareto_dict, py::arg("max_order"), py::arg("orientation"), py::arg("proxy"),
        py::arg("exclude_degenerate"), py::arg("beat"), py::arg("exclude_low"), py::arg("digits"),
        "The dict of `gyrores pareto --json` (without its file keys). Use gyrores.pareto.");
}

}  // namespace gyrores::python
