// include/gyrores/sweep/evaluate.hpp: the non-template part.
#include <gyrores/sweep/evaluate.hpp>

namespace gyrores {

const char* sweep_status_text(sweep_status s) {
  return s == sweep_status::pass ? "pass" : s == sweep_status::fail ? "fail" : "";
}

}  // namespace gyrores
