// The application layer (include/gyrores/app/pair.hpp): `gyrores pareto`, gyrores.pareto and the
// report's Pareto section. The Pareto front of (r_res, time) over the resonant pairs up to an
// order (design/design.hpp) and the proved values of its pairs.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <gyrores/app/design.hpp>

namespace gyrores::app {

// "absorb" or "contain"; usage_error naming `what` otherwise.
pareto_orientation parse_pareto_orientation(const std::string& text, const std::string& what);

struct pareto_request {
  std::int64_t max_order = 0;  // [3, design_max_order_limit]
  pareto_orientation orientation = pareto_orientation::absorb;
  design_time time = design_time::first_hit;
  pair_filter filter;          // the pairs kept
  unsigned digits = 10;        // of the front's values
  bool values = true;          // prove them (a figure draws the front without them)
  std::function<void(const std::string&)> progress;  // told the name of each stage (optional)
};

struct pareto_outcome {
  std::vector<design_point> pairs;  // every pair up to max_order that passes the filter
  std::vector<design_point> front;  // pareto_front(pairs): by increasing time
  std::vector<pair_report> values;  // of the front, proved (when asked)
};

// usage_error as check_listed and design_catalogue; compute_error when no pair passes the filter.
pareto_outcome run_pareto(const pareto_request& r);

}  // namespace gyrores::app
