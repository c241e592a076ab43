// include/gyrores/io/design_output.hpp: the design and Pareto outputs.
#include <gyrores/io/design_output.hpp>

#include <gyrores/io/report_json.hpp>
#include <gyrores/theorem/horizon.hpp>

namespace gyrores {
namespace {

// pair_values_json of pairs[i] and values[i] for i in [from, to).
json listed_json(const std::vector<design_point>& pairs, const std::vector<pair_report>& values, std::size_t from,
                 std::size_t to) {
  json a = json::array();
  for (std::size_t i = from; i < to; ++i)
    a.push_back(pair_values_json(resonant_pair<big_int>(big_int(pairs[i].tau), big_int(pairs[i].sigma)), values[i]));
  return a;
}

json optional_text(const std::string& text) { return text.empty() ? json(nullptr) : json(text); }

constexpr const char* pareto_csv_header = "tau,sigma,order,delta,degenerate,n,r_res,t_first,t_min_paper\n";

}  // namespace

json design_json(const design_options& o, const std::string& tmax, const std::string& beat, const design_result& r,
                 const std::vector<pair_report>& values, bool chosen_exceeds_tmax, unsigned digits) {
  json j;
  j["problem"] = design_problem_name(o.problem);
  j["tmax"] = tmax;
  j["time"] = design_time_name(o.time);
  j["beat"] = optional_text(beat);
  j["max_order"] = o.max_order;
  j["exclude_low"] = o.filter.exclude_low;
  j["delta"] = o.filter.delta ? json(*o.filter.delta) : json(nullptr);
  j["examined"] = r.examined;
  j["feasible"] = r.feasible;
  j["chosen"] = listed_json(r.ranked, values, 0, 1).at(0);
  j["chosen_t_first_exceeds_tmax"] = chosen_exceeds_tmax;
  j["candidates"] = listed_json(r.ranked, values, 1, values.size());
  j["digits"] = digits;
  return j;
}

json tolerance_json(design_problem problem, const tolerance_result& r, const std::string& percent, const std::string& level) {
  json checked = json::array();
  for (const auto& c : r.checked) {
    const auto [lo, hi] = c.guarantee.value.outward(8);
    checked.push_back({{"tau", c.point.tau}, {"sigma", c.point.sigma},
                       {"band", {rational_str(c.n1), rational_str(c.n2)}},
                       {problem == design_problem::absorb ? "absorption" : "containment", {lo, hi}},
                       {"at_n2", rational_str(c.guarantee.at.spec.n2)},
                       {"verdict", c.guarantee.interrupted ? "interrupted" : tolerance_verdict_name(c.verdict)}});
  }
  json j{{"checked", checked}, {"theorem", band_theorem_id}};
  j["chosen"] = r.chosen ? json{{"tau", r.checked[*r.chosen].point.tau}, {"sigma", r.checked[*r.chosen].point.sigma}}
                         : json(nullptr);
  j["interrupted"] = r.interrupted;
  j["percent"] = percent;
  j["level"] = level;
  return j;
}

std::string pareto_orientation_text(pareto_orientation o) {
  return o == pareto_orientation::absorb ? "absorb orientation: lower r_res and lower time are better"
                                         : "contain orientation: higher r_res and lower time are better";
}

json pareto_json(pareto_orientation o, design_time time, std::int64_t max_order, std::size_t pairs,
                 const std::vector<design_point>& front, const std::vector<pair_report>& values, unsigned digits,
                 const json& files) {
  json j;
  j["orientation"] = o == pareto_orientation::absorb ? "absorb" : "contain";
  j["orientation_meaning"] = pareto_orientation_text(o);
  j["time"] = design_time_name(time);
  j["max_order"] = max_order;
  j["pairs"] = pairs;
  j["front"] = listed_json(front, values, 0, values.size());
  for (const auto& [key, value] : files.items()) j[key] = value;
  j["digits"] = digits;
  return j;
}

std::string pareto_csv(const std::vector<design_point>& front, const std::vector<pair_report>& values) {
  std::string c = pareto_csv_header;
  for (std::size_t i = 0; i < front.size() && i < values.size(); ++i) {
    const design_point& p = front[i];
    const pair_report& v = values[i];
    c += std::to_string(p.tau) + "," + std::to_string(p.sigma) + "," + std::to_string(p.order()) + "," +
         std::to_string(p.delta()) + "," + (p.degenerate ? "true" : "false") + "," + v.n.value + "," + v.r_res.value +
         "," + v.t_first.value + "," + v.t_min_paper.value + "\n";
  }
  return c;
}

}  // namespace gyrores
