// Band certificates as JSON text (io/band_certificate_json.hpp).
#include <gyrores/io/band_certificate_json.hpp>

#include <gyrores/io/horizon_certificate_json.hpp>

namespace gyrores {

namespace {

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
  return json{{"value", json::array({c.value.first, c.value.second})}, {"at", horizon_certificate_to_json(c.at)}, {"cover", cover}};
}

}  // namespace

json band_certificate_to_json(const band_certificate& c) {
  return json{{"format", c.format},
              {"theorem", c.theorem},
              {"n1", rational_str(c.n1)},
              {"n2", rational_str(c.n2)},
              {"horizon", rational_str(c.horizon)},
              {"digits", c.digits},
              {"absorption", claim_json(c.absorption)},
              {"containment", claim_json(c.containment)}};
}

std::string band_certificate_text(const band_certificate& c) { return json_dump(band_certificate_to_json(c)) + "\n"; }

}  // namespace gyrores
