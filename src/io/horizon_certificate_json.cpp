// Coupling certificates as JSON text (io/horizon_certificate_json.hpp).
#include <gyrores/io/horizon_certificate_json.hpp>

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
  json below = nullptr;
  if (c.below) {
    const below_certificate& b = *c.below;
    auto optional_bracket = [](const std::optional<decimal_bracket>& v) { return v ? bracket_json(*v) : json(nullptr); };
    json blobe = nullptr, broot = nullptr;
    if (b.lobe) {
      blobe = json{{"k", b.lobe->k.str()}, {"j", b.lobe->j.str()}, {"side", b.lobe->side}};
      if (b.kase == "lobe") broot = bracket_json(b.lobe->root);
    }
    below = json{{"level", rational_str(b.level)},
                 {"case", b.kase},
                 {"lobe", blobe},
                 {"level_root", optional_bracket(b.level_root)},
                 {"delta", optional_bracket(b.delta)},
                 {"root", broot},
                 {"crossing", optional_bracket(b.crossing)},
                 {"t_below", optional_bracket(b.t_below)}};
  }
  return json{{"format", c.format},
              {"theorem", c.theorem},
              {"n2", rational_str(c.n2)},
              {"horizon", rational_str(c.horizon)},
              {"digits", c.digits},
              {"minimum", minimum},
              {"below", below}};
}

std::string coupling_certificate_text(const horizon_certificate& c) { return json_dump(horizon_certificate_to_json(c)) + "\n"; }

}  // namespace gyrores
