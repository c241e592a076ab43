// include/gyrores/app/coupling_input.hpp
#include <gyrores/app/coupling_input.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores::app {

big_rational coupling_selection::energy_scale() const {
  return plant ? big_rational(plant->mass * plant->velocity * plant->velocity) : big_rational(qdot0 * qdot0);
}

coupling_selection select_coupling(const coupling_given& g, const coupling_names& names) {
  const int given = int(bool(g.n)) + int(bool(g.n2)) + int(bool(g.pair));
  const std::string& one_given = g.n ? names.n : g.n2 ? names.n2 : names.pair;
  const std::string exactly_one =
      "give exactly one of " + names.n + " (the coupling), " + names.n2 + " (its square) or " + names.pair;
  if (g.horizon_s && !g.plant) throw usage_error(names.horizon_s + " (seconds) needs a plant: give " + names.plant);
  if (g.horizon_s && g.horizon)
    throw usage_error("give at most one of " + names.horizon + " (model time) and " + names.horizon_s + " (seconds)");
  if (g.plant && g.qdot0) throw usage_error("the plant's velocity sets the impulse: drop " + names.qdot0);
  if (g.plant && given > 0)
    throw usage_error("the plant gives the coupling n = g/sqrt(m k): drop " + one_given + " or " + names.plant);
  if (given > 1) throw usage_error(exactly_one);
  if (g.band && !g.tolerance.empty()) throw usage_error("give at most one of " + names.band + " and " + names.tolerance);
  if (g.plant && g.band)
    throw usage_error(names.band + " is a band of the model's couplings n, not of a plant: give " + names.tolerance +
                      " (a tolerance on the plant's n = g/sqrt(m k))");
  if (given == 0 && !g.plant && !g.band) throw usage_error(exactly_one);
  coupling_selection s;
  s.qdot0 = g.qdot0 ? *g.qdot0 : big_rational(1);
  if (g.certificate && (s.qdot0 != 1 || g.plant))
    throw usage_error(names.certificate + " states the unit impulse in model units: drop " + (g.plant ? names.plant : names.qdot0) +
                      " or " + names.certificate);
  if (g.plant) {
    s.plant = g.plant;
    s.numbers = plant_numbers_of(*g.plant, g.digits);
    if (g.horizon_s) {
      s.horizon_s = plant_horizon_of(*g.plant, *g.horizon_s, g.digits);
      check_horizon_limits(s.horizon_s->model, names.horizon_s + " times omega0");
    }
  }
  s.horizon = s.horizon_s ? s.horizon_s->model : g.horizon ? *g.horizon : horizon_time(big_rational(100));
  if (g.n) s.spec = coupling_spec::from_n(*g.n);
  else if (g.n2) s.spec = coupling_spec::from_n2(*g.n2);
  else if (g.pair) s.spec = coupling_spec::from_n2(pair_coupling_n2(g.pair->tau(), g.pair->sigma()));
  else if (g.plant) s.spec = coupling_spec::from_n2(g.plant->n2());
  s.band = g.band;
  if (!g.tolerance.empty()) {
    if (!s.spec) throw usage_error(exactly_one);
    if (g.n) s.band = parse_tolerance_band(*g.n, g.tolerance, names.tolerance);
    else {  // n = sqrt(n^2): the exact band when n is rational, else ends enclosing it outward
      const tolerance_band_ends t = parse_tolerance_band_n2(s.spec->n2, g.tolerance, names.tolerance);
      s.band.emplace(t.n1, t.n2);
      s.band_outward = !t.exact;
      s.coupling = "sqrt(" + rational_str(s.spec->n2) + ")";
    }
  }
  return s;
}

coupling_request coupling_request_of(const coupling_selection& s) {
  coupling_request r;
  r.spec = *s.spec;
  r.qdot0 = s.qdot0;
  r.plant = s.plant;
  r.options.horizon = s.horizon;
  return r;
}

band_request band_request_of(const coupling_selection& s) {
  band_request q;
  q.n1 = s.band->first;
  q.n2 = s.band->second;
  q.horizon = s.horizon;
  q.qdot0 = s.qdot0;
  q.plant = s.plant;
  return q;
}

void add_units_json(json& j, const coupling_selection& s, const std::optional<std::string>& horizon_s_given,
                    const std::optional<std::string>& below_given) {
  if (s.qdot0 != 1) j["qdot0"] = rational_str(s.qdot0);
  if (s.plant) {
    j["plant"] = plant_json(*s.plant, *s.numbers);
    j["horizon_s"] = horizon_s_given ? json(*horizon_s_given) : json(nullptr);
    j["horizon_exact"] = !s.horizon_s || s.horizon_s->exact;
  }
  if ((s.qdot0 != 1 || s.plant) && below_given && j.contains("below")) j["below"]["level_given"] = *below_given;
}

}  // namespace gyrores::app
