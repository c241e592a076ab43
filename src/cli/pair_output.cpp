// src/cli/pair_output.hpp
#include "pair_output.hpp"

#include <sstream>

namespace gyrores::cli {

std::string pareto_csv_row(const design_point& p, const pair_report& v) {
  std::ostringstream c;
  c << p.tau << "," << p.sigma << "," << p.order() << "," << p.delta() << "," << (p.degenerate ? "true" : "false") << ","
    << v.n.value << "," << v.r_res.value << "," << v.t_first.value << "," << v.t_min_paper.value << "\n";
  return c.str();
}

std::string radius_text(const pair_report& v) { return v.degenerate ? "0 (exact, delta = 2 mod 4)" : v.r_res.value; }

}  // namespace gyrores::cli
