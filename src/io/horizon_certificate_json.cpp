// Coupling certificates as JSON text (io/horizon_certificate_json.hpp).
#include <gyrores/io/horizon_certificate_json.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores {

namespace {

json bracket_json(const decimal_bracket& b) { return json::array({b.first, b.second}); }

}  // namespace

json horizon_certificate_to_json(const horizon_certificate& c) {
  json lobe = nullptr, root = nullptr;
  if (c.lobe) {
    lobe = json{{"k", c.lobe->k.str()}, {"j", c.lobe->j.str()}, {"side", c.lobe->side}};
    root = bracket_json(c.lobe->root);
  }
  json minimum{{"cut_lobe", c.cut_lobe.str()},
               {"cut_lobe_reached", c.cut_lobe_reached},
               {"cut_root", bracket_json(c.cut_root)},
               {"lobe", lobe},
               {"root", root},
               {"at_horizon_end", c.at_horizon_end},
               {"h_min", bracket_json(c.h_min)},
               {"t_min", bracket_json(c.t_min)}};
  return json{{"format", c.format},     {"theorem", c.theorem},   {"n2", rational_str(c.n2)},
              {"horizon", rational_str(c.horizon)}, {"digits", c.digits}, {"minimum", minimum}};
}

std::string coupling_certificate_text(const coupling_spec& c, const big_rational& horizon,
                                      const std::optional<big_rational>& level, unsigned digits) {
  if (level)
    throw usage_error("--certificate covers the minimum over [0, T] only: a certificate of --below is not "
                      "part of gyrores-coupling-certificate/1 yet");
  return json_dump(horizon_certificate_to_json(certify_horizon_minimum(c, horizon, digits))) + "\n";
}

}  // namespace gyrores
