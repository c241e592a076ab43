// Certificates as JSON text (io/certificate_json.hpp).
#include <gyrores/io/certificate_json.hpp>

namespace gyrores {

namespace {

json claim_json(const std::pair<std::string, std::string>& claim) {
  return claim.first.empty() ? json(nullptr) : json::array({claim.first, claim.second});
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
