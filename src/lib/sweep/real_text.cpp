// include/gyrores/sweep/real_text.hpp: doubles to shortest text and back.
#include <gyrores/sweep/real_text.hpp>

#include <charconv>
#include <cstdlib>

#include <gyrores/core/error.hpp>

namespace gyrores {

GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_REAL_TEXT_INSTANCES, )

std::string sweep_double_text(double v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

double sweep_text_double(const std::string& s) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) throw compute_error("not a real number: '" + s + "'");
  return v;
}

}  // namespace gyrores
