// Certificate data (certify/certificate.hpp).
#include <gyrores/certify/certificate.hpp>

namespace gyrores {

const certificate_obligation* find_obligation(const certificate& c, const std::string& id) {
  for (auto& o : c.obligations)
    if (o.id == id) return &o;
  return nullptr;
}

}  // namespace gyrores
