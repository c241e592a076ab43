// src/cli/pair_output.hpp
#include "pair_output.hpp"

#include <sstream>

namespace gyrores::cli {

std::string pareto_csv_row(const design_point& p, const verified_pair_values& v) {
  std::ostringstream c;
  c << p.tau << "," << p.sigma << "," << p.order() << "," << p.delta() << "," << (p.degenerate ? "true" : "false") << ","
    << v.n << "," << v.r_res << "," << v.t_first << "," << v.t_min_paper << "\n";
  return c.str();
}

std::string radius_text(const verified_pair_values& v) { return v.degenerate ? "0 (exact, delta = 2 mod 4)" : v.r_res; }

}  // namespace gyrores::cli
