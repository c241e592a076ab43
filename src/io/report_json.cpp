// The JSON forms of the pair and coupling reports (io/report_json.hpp).
#include <gyrores/io/report_json.hpp>

#include <utility>

#include <gyrores/core/rational.hpp>

namespace gyrores {

namespace {

json lobe_json(const verified_asymptotic_lobe& l) {
  json lo;
  lo["k"] = json_integer(l.k);
  lo["m"] = json_integer(l.m);
  for (auto [name, value] : {std::pair{"s", &l.s}, {"u_asy", &l.u_asy}, {"theta_asy", &l.theta_asy},
                             {"theta_c", &l.theta_c}, {"error", &l.error}, {"bound", &l.bound}, {"ratio", &l.ratio}})
    lo[name] = *value;
  lo["holds_global_min"] = l.holds_global_min;
  return lo;
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
        c[key] = *value;
      c["degenerate"] = r.values->degenerate;
    } else {
      c["note"] = "ratio 1: no resonant pair (tau = sigma)";
    }
    arr.push_back(c);
  }
  return arr;
}

}  // namespace

json pair_json(const resonant_pair<big_int>& p) {
  json j;
  j["tau"] = json_integer(p.tau().str());
  j["sigma"] = json_integer(p.sigma().str());
  return j;
}

json pair_values_json(const resonant_pair<big_int>& p, const verified_pair_values& v) {
  json j = pair_json(p);
  for (auto [key, value] : {std::pair{"n", &v.n}, {"r_res", &v.r_res}, {"h_min", &v.h_min}, {"t_first", &v.t_first},
                            {"t_min_paper", &v.t_min_paper}})
    j[key] = *value;
  j["degenerate"] = v.degenerate;
  return j;
}

json asymptotic_json(const verified_pair_report& r) {
  json asy;
  asy["applicable"] = r.asymptotic_applicable;
  asy["reason"] = r.asymptotic_reason;
  json lobes = json::array();
  for (const auto& l : r.lobes) lobes.push_back(lobe_json(l));
  asy["lobes"] = lobes;
  return asy;
}

json pair_report_json(const resonant_pair<big_int>& p, const verified_pair_report& r) {
  json j = pair_json(p);
  j["delta"] = json_integer(big_int(p.delta()).str());
  j["delta_mod4"] = p.delta_mod4();
  j["v2_delta"] = p.v2_delta();
  j["degenerate"] = p.degenerate();
  j["order"] = json_integer(p.order().str());
  for (auto [name, value] : {std::pair{"beat_ratio", &r.beat_ratio}, {"n", &r.n}, {"omega1", &r.omega1},
                             {"omega2", &r.omega2}, {"rho0", &r.rho0}, {"qdot0", &r.qdot0}, {"r_res", &r.r_res},
                             {"h_min", &r.h_min}, {"h_z_max", &r.h_z_max}, {"theta_first", &r.theta_first},
                             {"t_first", &r.t_first}})
    j[name] = *value;
  j["minimisers"] = r.minimisers;
  j["t_min_paper"] = r.t_min_paper;
  j["asymptotic"] = asymptotic_json(r);
  j["r_res_asy"] = r.r_res_asy ? json(*r.r_res_asy) : json(nullptr);
  j["r_res_asy_rel_error"] = r.r_res_asy_rel_error ? json(*r.r_res_asy_rel_error) : json(nullptr);
  // Diagnostics that did not settle to `digits` digits: name -> digits that did (0: the value
  // is an estimated bound on its magnitude). Empty when every field settled.
  json unsettled = json::object();
  for (const auto& [name, settled] : r.unsettled) unsettled[name] = settled;
  j["unsettled"] = unsettled;
  j["method"] = r.method;
  j["cross_checked"] = r.cross_checked;
  j["digits"] = r.digits;
  j["working_precision"] = {{"type", r.working_precision.name()}, {"bits", r.working_precision.bits}};
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
  j["h_min_horizon"] = r.h_min_horizon;
  j["t_min_horizon"] = r.t_min_horizon;
  j["min_at_horizon_end"] = r.min_at_horizon_end;
  j["horizon_source"] = r.horizon_source;
  j["inf_all_time"] = r.inf_all_time;
  j["inf_attained"] = r.inf_attained;
  j["inf_reason"] = r.inf_reason;
  j["convergents"] = coupling_convergents_json(r.convergents);
  j["digits"] = digits;
  return j;
}

void add_enclosures_json(json& j, const certified_enclosures* proved) {
  j["certified"] = proved != nullptr;
  if (!proved) return;
  auto enclosure = [](const std::pair<std::string, std::string>& e) { return json::array({e.first, e.second}); };
  j["r_res_enclosure"] = enclosure(proved->r_res);
  j["theta_first_enclosure"] = enclosure(proved->theta_first);
  j["t_first_enclosure"] = enclosure(proved->t_first);
  j["theorem"] = proved->theorem;
}

}  // namespace gyrores
