// src/cli/pair_output.hpp
#include "pair_output.hpp"

#include <sstream>

namespace gyrores::cli {

json pair_json(const resonant_pair<big_int>& p) {
  json j;
  j["tau"] = json_integer(p.tau().str());
  j["sigma"] = json_integer(p.sigma().str());
  return j;
}

json pair_values_json(const resonant_pair<big_int>& p, const verified_pair_values& v) {
  json j = pair_json(p);
  for (auto [key, value] : {std::pair{"n", &v.n}, {"r_res", &v.r_res}, {"h_min", &v.h_min}, {"t_first", &v.t_first},
                            {"t_min_paper", &v.t_min_paper}})
    j[key] = *value;
  j["degenerate"] = v.degenerate;
  return j;
}

std::string pareto_csv_row(const design_point& p, const verified_pair_values& v) {
  std::ostringstream c;
  c << p.tau << "," << p.sigma << "," << p.order() << "," << p.delta() << "," << (p.degenerate ? "true" : "false") << ","
    << v.n << "," << v.r_res << "," << v.t_first << "," << v.t_min_paper << "\n";
  return c.str();
}

std::string radius_text(const verified_pair_values& v) { return v.degenerate ? "0 (exact, delta = 2 mod 4)" : v.r_res; }

}  // namespace gyrores::cli
