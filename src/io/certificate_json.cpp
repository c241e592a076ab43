// Certificates as JSON text (io/certificate_json.hpp).
#include <gyrores/io/certificate_json.hpp>

namespace gyrores {

namespace {

json claim_json(const std::pair<std::string, std::string>& claim) {
  return claim.first.empty() ? json(nullptr) : json::array({claim.first, claim.second});
}

json bracket_json(const decimal_bracket& b) { return json::array({b.first, b.second}); }

json optional_bracket(const std::optional<decimal_bracket>& v) { return v ? bracket_json(*v) : json(nullptr); }

json lobe_json(const certificate_lobe& l) { return json{{"k", l.k.str()}, {"j", l.j.str()}, {"side", l.side}}; }

json claim_json(const band_certificate_claim& c) {
  json cover = json::array();
  for (const band_certificate_interval& I : c.cover)
    cover.push_back(json{{"a", rational_str(I.a)},
                         {"b", rational_str(I.b)},
                         {"kind", I.kind},
                         {"K", I.K.str()},
                         {"k", I.k.str()},
                         {"reached", I.reached},
                         {"unreached", I.unreached},
                         {"bound", I.bound}});
  return json{{"value", bracket_json(c.value)}, {"at", certificate_to_json(c.at)}, {"cover", cover}};
}

}  // namespace

json certificate_to_json(const theorem_certificate& c) {
  json lobes = json::array();
  for (const auto& f : c.lobes) lobes.push_back(json{{"k", f.k.str()}, {"j", f.j.str()}, {"m", f.m.str()}});
  json claims{{"r_res", claim_json(c.r_res)}, {"theta_first", claim_json(c.theta_first)},
              {"t_first", claim_json(c.t_first)}};
  return json{{"format", c.format},
              {"theorem", c.theorem},
              {"tau", c.tau.str()},
              {"sigma", c.sigma.str()},
              {"digits", c.digits},
              {"degenerate", c.m_min == 0},
              {"m_min", c.m_min},
              {"minimiser_count", c.lobes.size()},
              {"minimiser_lobes", lobes},
              {"u_star", claim_json(c.u_star)},
              {"claims", claims}};
}

json certificate_to_json(const horizon_certificate& c) {
  json minimum{{"cut_lobe", c.cut_lobe.str()},
               {"cut_lobe_reached", c.cut_lobe_reached},
               {"cut_root", bracket_json(c.cut_root)},
               {"lobe", c.lobe ? lobe_json(*c.lobe) : json(nullptr)},
               {"root", c.lobe ? bracket_json(c.lobe->root) : json(nullptr)},
               {"at_horizon_end", c.at_horizon_end},
               {"h_min", bracket_json(c.h_min)},
               {"t_min", bracket_json(c.t_min)}};
  json below = nullptr;
  if (c.below) {
    const below_certificate& b = *c.below;
    below = json{{"level", rational_str(b.level)},
                 {"case", b.kase},
                 {"lobe", b.lobe ? lobe_json(*b.lobe) : json(nullptr)},
                 {"level_root", optional_bracket(b.level_root)},
                 {"delta", optional_bracket(b.delta)},
                 {"root", b.lobe && b.kase == "lobe" ? bracket_json(b.lobe->root) : json(nullptr)},
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

json certificate_to_json(const band_certificate& c) {
  return json{{"format", c.format},
              {"theorem", c.theorem},
              {"n1", rational_str(c.n1)},
              {"n2", rational_str(c.n2)},
              {"horizon", rational_str(c.horizon)},
              {"digits", c.digits},
              {"absorption", claim_json(c.absorption)},
              {"containment", claim_json(c.containment)}};
}

std::string certificate_format_of(const std::string& text) {
  auto j = nlohmann::json::parse(text, nullptr, false);
  return j.is_object() && j.contains("format") && j["format"].is_string() ? j["format"].get<std::string>() : "";
}

std::string retired_certificate_message() {
  return std::string(retired_certificate_format) +
         " (the interval-cover certificate) is retired and no longer checked: re-certify with "
         "`gyrores certify TAU SIGMA --digits D --out FILE` (" +
         theorem_certificate_format + ", from the lattice theorem) and check that file with `gyrores check FILE`";
}

}  // namespace gyrores
