// include/gyrores/io/report_json.hpp: the pair, coupling, design and Pareto outputs.
#include <gyrores/io/report_json.hpp>

#include <utility>

#include <gyrores/core/rational.hpp>
#include <gyrores/theorem/horizon.hpp>
#include <gyrores/theorem/lobes.hpp>

namespace gyrores {
namespace {

json real_json(const proved_real& r) { return r.value; }
json enclosure_json(const proved_real& r) { return json::array({r.enclosure.first, r.enclosure.second}); }

// The asymptotic lobe's reals, by key: value (enclosures = false) or [lo, hi].
json lobe_json(const paper_lobe_report& l, bool enclosures) {
  json lo;
  if (!enclosures) {
    lo["k"] = json_integer(l.k.str());
    lo["m"] = json_integer(l.m.str());
  }
  for (auto [name, value] : {std::pair{"s", &l.s}, {"u_asy", &l.u_asy}, {"theta_asy", &l.theta_asy},
                             {"theta_c", &l.theta_c}, {"error", &l.error}, {"bound", &l.bound}, {"ratio", &l.ratio}})
    lo[name] = enclosures ? enclosure_json(*value) : real_json(*value);
  if (!enclosures) lo["holds_global_min"] = l.holds_global_min;
  return lo;
}

// The "asymptotic" object of `gyrores pair --json`: applicable, reason, lobes.
json asymptotic_json(const pair_report& r) {
  json asy;
  asy["applicable"] = r.asymptotic_applicable;
  asy["reason"] = r.asymptotic_reason;
  json lobes = json::array();
  for (const auto& l : r.lobes) lobes.push_back(lobe_json(l, false));
  asy["lobes"] = lobes;
  return asy;
}

// Every real of the report by its key, as value strings or as enclosures.
void put_reals(json& j, const pair_report& r, bool enclosures) {
  auto put = [&](const char* key, const proved_real& v) { j[key] = enclosures ? enclosure_json(v) : real_json(v); };
  for (auto [name, value] : {std::pair{"beat_ratio", &r.beat_ratio}, {"n", &r.n}, {"omega1", &r.omega1},
                             {"omega2", &r.omega2}, {"rho0", &r.rho0}, {"qdot0", &r.qdot0}, {"r_res", &r.r_res},
                             {"h_min", &r.h_min}, {"h_z_max", &r.h_z_max}, {"theta_first", &r.theta_first},
                             {"t_first", &r.t_first}, {"t_min_paper", &r.t_min_paper}})
    put(name, *value);
  json mins = json::array();
  for (const auto& m : r.minimisers) mins.push_back(enclosures ? enclosure_json(m) : real_json(m));
  j["minimisers"] = mins;
  if (r.r_res_asy) put("r_res_asy", *r.r_res_asy);
  else j["r_res_asy"] = nullptr;
  if (r.r_res_asy_rel_error) put("r_res_asy_rel_error", *r.r_res_asy_rel_error);
  else j["r_res_asy_rel_error"] = nullptr;
}

// {"tau", "sigma", "n", "r_res", "h_min", "t_first", "t_min_paper", "degenerate"}: one pair's
// values as the design, Pareto and coupling outputs list them.
json pair_values_json(const resonant_pair<big_int>& p, const pair_report& v) {
  json j = pair_json(p);
  for (auto [key, value] : {std::pair{"n", &v.n}, {"r_res", &v.r_res}, {"h_min", &v.h_min}, {"t_first", &v.t_first},
                            {"t_min_paper", &v.t_min_paper}})
    j[key] = value->value;
  j["degenerate"] = v.degenerate;
  return j;
}

// Each convergent of W1/W2 with its pair's values, or a note when it is 1 (tau = sigma).
json coupling_convergents_json(const std::vector<coupling_convergent>& rows) {
  json arr = json::array();
  for (const auto& r : rows) {
    json c;
    c["partial_quotient"] = json_integer(r.convergent.partial_quotient.str());
    c["tau"] = json_integer(r.convergent.p.str());
    c["sigma"] = json_integer(r.convergent.q.str());
    if (r.values) {
      for (auto [key, value] : {std::pair{"n", &r.values->n}, {"r_res", &r.values->r_res},
                                {"t_first", &r.values->t_first}, {"t_min_paper", &r.values->t_min_paper}})
        c[key] = value->value;
      c["degenerate"] = r.values->degenerate;
    } else {
      c["note"] = "ratio 1: no resonant pair (tau = sigma)";
    }
    arr.push_back(c);
  }
  return arr;
}

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

json pair_json(const resonant_pair<big_int>& p) {
  json j;
  j["tau"] = json_integer(p.tau().str());
  j["sigma"] = json_integer(p.sigma().str());
  return j;
}

json pair_report_json(const resonant_pair<big_int>& p, const pair_report& r, bool enclosures) {
  json j;
  j["format"] = pair_report_format;
  j.update(pair_json(p));
  j["delta"] = json_integer(big_int(p.delta()).str());
  j["delta_mod4"] = p.delta_mod4();
  j["v2_delta"] = p.v2_delta();
  j["degenerate"] = p.degenerate();
  j["order"] = json_integer(p.order().str());
  j["m_min"] = r.m_min;
  put_reals(j, r, false);
  j["asymptotic"] = asymptotic_json(r);
  j["digits"] = r.digits;
  j["theorem"] = lattice_theorem_id;
  j["bits"] = r.bits;
  if (enclosures) {
    json e;
    put_reals(e, r, true);
    json lobes = json::array();
    for (const auto& l : r.lobes) lobes.push_back(lobe_json(l, true));
    e["asymptotic_lobes"] = lobes;
    j["enclosures"] = e;
  }
  return j;
}

json coupling_report_json(const json& input, const std::string& horizon, unsigned digits, const coupling_report& r) {
  json j;
  j["input"] = input;
  j["n2"] = rational_str(r.spec.n2);
  j["n"] = r.abs_n;
  j["n_negative"] = r.n_negative;
  j["discriminant"] = json_integer(r.spec.discriminant().str());
  j["resonant"] = bool(r.pair);
  j["pair"] = r.pair ? pair_json(*r.pair) : json(nullptr);
  if (r.pair) j["pair_analysis"] = pair_values_json(*r.pair, *r.pair_values);
  j["t_min_paper"] = r.t_min_paper;
  j["horizon"] = horizon;
  const horizon_minimum_report& h = r.horizon;
  j["theorem"] = horizon_theorem_id;
  j["x"] = h.proof.x.str();
  j["h_min_horizon"] = h.h_min.value;
  j["t_min_horizon"] = h.t_min.value;
  j["r_min_horizon"] = h.r_min.value;
  j["min_at_horizon_end"] = h.proof.at_horizon_end;
  j["horizon_lobe"] = h.lobe ? json_integer(h.lobe->k) : json(nullptr);
  j["horizon_lobe_distance"] = h.lobe ? json(h.lobe->nu.str()) : json(nullptr);
  j["cut_lobe"] = json_integer(h.proof.cut_lobe);
  j["cut_lobe_reached"] = h.proof.cut_lobe_reached;
  json enc;
  enc["h_min_horizon"] = enclosure_json(h.h_min);
  enc["t_min_horizon"] = enclosure_json(h.t_min);
  enc["r_min_horizon"] = enclosure_json(h.r_min);
  if (r.below) {
    const first_below_report& b = *r.below;
    json jb;
    jb["level"] = rational_str(b.proof.level);
    jb["never"] = b.never;
    jb["reason"] = b.reason;
    jb["lobe"] = b.lobe ? json_integer(b.lobe->k) : json(nullptr);
    jb["t_below"] = b.never ? json(nullptr) : json(b.t_below.value);
    j["below"] = jb;
    j["t_below"] = jb["t_below"];
    if (!b.never) enc["t_below"] = enclosure_json(b.t_below);
  }
  j["enclosures"] = enc;
  j["inf_all_time"] = r.inf_all_time;
  j["inf_attained"] = r.inf_attained;
  j["inf_reason"] = r.inf_reason;
  j["convergents"] = coupling_convergents_json(r.convergents);
  j["digits"] = digits;
  return j;
}

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
