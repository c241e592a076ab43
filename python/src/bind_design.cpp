// gyrores.design, gyrores.pareto: design/design.hpp (the design problems and the Pareto front
// over resonant pairs), as the dicts of the matching `gyrores ... --json` commands (the files the
// CLI can write beside them, CSV and plots, are left to the caller). Parameters are checked here
// with their Python names.
#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/design/design.hpp>
#include <gyrores/io/report_json.hpp>

#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

json text_or_null(const py::object& v) { return v.is_none() ? json(nullptr) : json(rational_text(v)); }

// A rational parameter that must be > 0; usage_error naming it otherwise.
big_rational positive_rational(const py::object& v, const std::string& what) {
  const std::string text = rational_text(v);
  big_rational r = parse_rational(text, what);
  if (!(r > 0)) throw usage_error(what + " must be > 0, got " + text);
  return r;
}

void check_max_order(std::int64_t max_order) {
  if (max_order < 3 || max_order > design_max_order_limit)
    throw usage_error("max_order must be in [3, " + std::to_string(design_max_order_limit) + "], got " +
                      std::to_string(max_order));
}

pair_filter filter_of(const py::object& beat, std::int64_t exclude_low) {
  if (exclude_low < 0) throw usage_error("exclude_low must be >= 0");
  pair_filter f;
  f.exclude_low = exclude_low;
  if (!beat.is_none()) f.beat_min = positive_rational(beat, "beat");
  return f;
}

json values_json(const design_point& p, unsigned digits) {
  const resonant_pair<big_int> bp(big_int(p.tau), big_int(p.sigma));
  return pair_values_json(bp, prove_pair_values(bp, digits));
}

design_problem problem_of(const std::string& text) {
  if (text == "absorb") return design_problem::absorb;
  if (text == "contain") return design_problem::contain;
  throw usage_error("the design problem must be 'absorb' or 'contain', got '" + text + "'");
}

py::object design_dict(const std::string& problem, const py::object& tmax, const py::object& beat,
                       std::int64_t max_order, std::int64_t exclude_low, const py::object& delta, bool proxy,
                       std::int64_t candidates, long long digits) {
  design_options o;
  o.problem = problem_of(problem);
  const unsigned d = checked_digits(digits, 1, 1000);
  o.tmax = positive_rational(tmax, "tmax");
  o.filter = filter_of(beat, exclude_low);
  if (!delta.is_none()) {
    if (delta.cast<std::int64_t>() < 1) throw usage_error("delta must be >= 1");
    o.filter.delta = delta.cast<std::int64_t>();
  }
  if (candidates < 0 || candidates > 1000) throw usage_error("candidates must be in [0, 1000]");
  o.candidates = std::size_t(candidates);
  o.time = proxy ? design_time::proxy : design_time::first_hit;
  check_max_order(max_order);
  o.max_order = max_order;
  const std::string tmax_text = rational_text(tmax);  // Python objects are read before the GIL is released
  const json beat_json = text_or_null(beat);
  // By value: on Ctrl-C the work may outlive this call (interruptible.hpp).
  const json result = run_interruptible<json>([=](stop_token) {
    json j;
    const auto res = design_solve(design_catalogue(max_order), o);
    if (!res.feasible_any())
      throw compute_error("no resonant pair meets the constraints (" + std::to_string(res.examined) +
                          " pairs examined); nothing chosen");
    j["problem"] = problem;
    j["tmax"] = tmax_text;
    j["time"] = proxy ? "proxy" : "t_first";
    j["beat"] = beat_json;
    j["max_order"] = max_order;
    j["exclude_low"] = exclude_low;
    j["delta"] = o.filter.delta ? json(*o.filter.delta) : json(nullptr);
    j["examined"] = res.examined;
    j["feasible"] = res.feasible;
    j["chosen"] = values_json(res.ranked.front(), d);
    j["chosen_t_first_exceeds_tmax"] = proxy && !design_time_within(res.ranked.front(), design_time::first_hit, o.tmax);
    json c = json::array();
    for (std::size_t i = 1; i < res.ranked.size(); ++i) c.push_back(values_json(res.ranked[i], d));
    j["candidates"] = c;
    j["digits"] = d;
    return j;
  });
  return to_python(result);
}

pareto_orientation orientation_of(const std::string& text) {
  if (text == "absorb") return pareto_orientation::absorb;
  if (text == "contain") return pareto_orientation::contain;
  throw usage_error("orientation must be 'absorb' or 'contain', got '" + text + "'");
}

py::object pareto_dict(std::int64_t max_order, const std::string& orientation, bool proxy, bool exclude_degenerate,
                       const py::object& beat, std::int64_t exclude_low, long long digits) {
  const pareto_orientation o = orientation_of(orientation);
  const unsigned d = checked_digits(digits, 1, 1000);
  pair_filter f = filter_of(beat, exclude_low);
  f.exclude_degenerate = exclude_degenerate;
  check_max_order(max_order);
  const design_time which = proxy ? design_time::proxy : design_time::first_hit;
  const json result = run_interruptible<json>([=](stop_token) {
    json j;
    std::vector<design_point> pairs;
    for (const auto& p : design_catalogue(max_order))
      if (pair_filter_accepts(f, p)) pairs.push_back(p);
    if (pairs.empty()) throw compute_error("no resonant pair up to order " + std::to_string(max_order) + " passes the filters");
    j["orientation"] = orientation;
    j["orientation_meaning"] = o == pareto_orientation::absorb ? "absorb orientation: lower r_res and lower time are better"
                                                               : "contain orientation: higher r_res and lower time are better";
    j["time"] = proxy ? "proxy" : "t_first";
    j["max_order"] = max_order;
    j["pairs"] = pairs.size();
    json front = json::array();
    for (const auto& p : pareto_front(pairs, o, which)) front.push_back(values_json(p, d));
    j["front"] = front;
    j["digits"] = d;
    return j;
  });
  return to_python(result);
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
