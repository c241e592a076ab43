// include/gyrores/app/pareto.hpp
#include <gyrores/app/pareto.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores::app {

pareto_orientation parse_pareto_orientation(const std::string& text, const std::string& what) {
  if (text == "absorb") return pareto_orientation::absorb;
  if (text == "contain") return pareto_orientation::contain;
  throw usage_error(what + " must be 'absorb' or 'contain', got '" + text + "'");
}

pareto_outcome run_pareto(const pareto_request& r) {
  check_listed(r.digits, r.filter);
  const auto stage = [&r](const std::string& name) {
    if (r.progress) r.progress(name);
  };
  stage("evaluating every pair up to order " + std::to_string(r.max_order));
  pareto_outcome out;
  for (const auto& p : design_catalogue(r.max_order))
    if (pair_filter_accepts(r.filter, p)) out.pairs.push_back(p);
  if (out.pairs.empty()) throw compute_error("no resonant pair up to order " + std::to_string(r.max_order) + " passes the filters");
  out.front = pareto_front(out.pairs, r.orientation, r.time);
  if (!r.values) return out;
  stage("proving the values of the " + std::to_string(out.front.size()) + " front pairs");
  out.values = prove_listed(out.front, out.front.size(), r.digits);
  return out;
}

}  // namespace gyrores::app
