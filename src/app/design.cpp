// include/gyrores/app/design.hpp
#include <gyrores/app/design.hpp>
#include <gyrores/app/pareto.hpp>

#include <algorithm>
#include <sstream>

#include <gyrores/core/error.hpp>

namespace gyrores::app {
namespace {

void check_request(const design_request& r) {
  check_listed(r.digits, r.options.filter);
  if (r.options.candidates > 1000) throw usage_error("candidates must be in [0, 1000]");
  if (!r.tolerance) return;
  if (r.options.time == design_time::proxy) throw usage_error("a tolerance needs the exact first-hit time (not the proxy)");
  if (r.tolerance->horizon && r.options.problem == design_problem::absorb)
    throw usage_error("a horizon is for contain (absorb uses tmax)");
}

// What design_with_tolerance walks: at least 20 ranked pairs, over [0, tmax] unless a contain
// horizon is given.
tolerance_options tolerance_options_of(const design_request& r) {
  tolerance_options t;
  t.fraction = r.tolerance->fraction;
  t.level = r.tolerance->level;
  t.horizon = r.tolerance->horizon ? *r.tolerance->horizon : horizon_time(r.options.tmax);
  t.max_pairs = std::max<std::size_t>(r.options.candidates + 1, 20);
  t.band.stop = r.stop;
  return t;
}

}  // namespace

design_problem parse_design_problem(const std::string& text) {
  const bool absorb = parse_pareto_orientation(text, "the design problem") == pareto_orientation::absorb;
  return absorb ? design_problem::absorb : design_problem::contain;
}

void check_listed(unsigned digits, const pair_filter& f) {
  if (digits < 1 || digits > listed_digits_max)
    throw usage_error("digits must be in [1, " + std::to_string(listed_digits_max) + "], got " + std::to_string(digits));
  if (f.exclude_low < 0) throw usage_error("exclude_low must be >= 0");
  if (f.delta && *f.delta < 1) throw usage_error("delta must be >= 1");
  if (f.beat_min && !(*f.beat_min > 0)) throw usage_error("beat must be > 0, got " + rational_str(*f.beat_min));
}

std::vector<pair_report> prove_listed(const std::vector<design_point>& pairs, std::size_t count, unsigned digits) {
  std::vector<pair_report> out;
  for (std::size_t i = 0; i < pairs.size() && i < count; ++i)
    out.push_back(prove_pair_values(resonant_pair<big_int>(big_int(pairs[i].tau), big_int(pairs[i].sigma)), digits));
  return out;
}

std::string design_constraints_text(const design_request& r) {
  const design_options& o = r.options;
  std::ostringstream os;
  os << (o.time == design_time::first_hit ? "t_first" : "pi/|n|") << " <= " << r.tmax_text;
  if (!r.beat_text.empty()) os << ", beat (tau+sigma)/(tau-sigma) >= " << r.beat_text;
  if (o.filter.exclude_low > 0) os << ", tau+sigma > " << o.filter.exclude_low << " (R_low excluded)";
  if (o.filter.delta) os << ", delta = " << *o.filter.delta;
  os << ", tau+sigma <= " << o.max_order;
  return os.str();
}

design_outcome run_design(const design_request& r) {
  check_request(r);
  design_options o = r.options;
  std::optional<tolerance_options> tolerance;
  if (r.tolerance) o.candidates = (tolerance = tolerance_options_of(r))->max_pairs;  // ranks more than it lists
  design_outcome out;
  out.result = design_solve(design_catalogue(o.max_order), o);
  if (!out.result.feasible_any())
    throw compute_error("no resonant pair meets the constraints (" + design_constraints_text(r) + "; " +
                        std::to_string(out.result.examined) + " pairs examined); nothing chosen");
  out.values = prove_listed(out.result.ranked, r.options.candidates + 1, r.digits);
  out.chosen_exceeds_tmax = o.time == design_time::proxy &&
                            !design_time_within(out.result.ranked.front(), design_time::first_hit, o.tmax);
  r.stop.throw_if_requested();
  if (tolerance) out.tolerance = design_with_tolerance(out.result.ranked, o.problem, *tolerance);
  return out;
}

}  // namespace gyrores::app
