// include/gyrores/io/band_json.hpp
#include <gyrores/io/band_json.hpp>

namespace gyrores {

namespace {

json rounded_or_null(const enclosure& e, unsigned digits, bool settled) {
  if (!settled) return nullptr;
  const auto v = e.rounded(digits);
  return v ? json(*v) : json(nullptr);
}

json outward_json(const enclosure& e, unsigned digits) {
  const auto [lo, hi] = e.outward(digits + 3);
  return json::array({lo, hi});
}

}  // namespace

json band_coupling_json(const band_coupling& c, const std::optional<resonant_pair<big_int>>& pair) {
  return json{{"n2", rational_str(c.spec.n2)},
              {"x", c.x.str()},
              {"pair", pair ? json{{"tau", json_integer(pair->tau())}, {"sigma", json_integer(pair->sigma())}} : json(nullptr)}};
}

json horizon_place_json(const horizon_minimum_report& r) {
  return json{{"h_min", r.h_min.value},
              {"lobe", r.lobe ? json(json_integer(r.lobe->k)) : json(nullptr)},
              {"at_horizon_end", r.proof.at_horizon_end},
              {"t_min", r.t_min.value}};
}

json band_extreme_json(const band_extreme& e, unsigned digits, const json& at) {
  return json{{"h_min", rounded_or_null(e.value, digits, e.settled)},
              {"enclosure", outward_json(e.value, digits)},
              {"settled", e.settled},
              {"interrupted", e.interrupted},
              {"reason", e.unsettled_reason.empty() ? json(nullptr) : json(e.unsettled_reason)},
              {"at", at},
              {"intervals", e.intervals},
              {"couplings", e.couplings}};
}

json band_first_below_json(const band_first_below& b, unsigned digits, const json& at) {
  return json{{"level", rational_str(b.level)},
              {"never", b.never},
              {"reason", b.reason},
              {"t_below", b.never ? json(nullptr) : rounded_or_null(b.time, digits, b.settled)},
              {"enclosure", b.never ? json(nullptr) : outward_json(b.time, digits)},
              {"settled", b.settled},
              {"interrupted", b.interrupted},
              {"at", at},
              {"intervals", b.intervals},
              {"couplings", b.couplings}};
}

}  // namespace gyrores
