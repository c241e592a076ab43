#include <gyrores/model/pair.hpp>
#include <gyrores/inscribed/degenerate.hpp>

int main() {
  gyrores::resonant_pair<std::int64_t> p(11, 9);
  auto r = gyrores::inscribed_degenerate<double>(p, 1.0);
  return (p.degenerate() && r.r_res == 0) ? 0 : 1;
}
