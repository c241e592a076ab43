// The outputs of `gyrores design` and `gyrores pareto` (docs/formats.md), one definition for the
// CLI and the Python module: the objects of --json and the Pareto front's CSV. Reals are the
// proved decimal strings of report/pair_report.hpp; exact rationals are text.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <gyrores/design/design.hpp>
#include <gyrores/design/tolerance.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores {

// `tmax` and `beat` as given ("" for none); "chosen" and "candidates" are ranked[i] with values[i].
json design_json(const design_options& o, const std::string& tmax, const std::string& beat, const design_result& r,
                 const std::vector<pair_report>& values, bool chosen_exceeds_tmax, unsigned digits);

// Its "tolerance" object; the tolerance and level as given.
json tolerance_json(design_problem problem, const tolerance_result& r, const std::string& percent, const std::string& level);

// "absorb orientation: lower r_res and lower time are better", or the contain one.
std::string pareto_orientation_text(pareto_orientation o);

// `files` (the CLI's "csv" and "plot") come before "digits".
json pareto_json(pareto_orientation o, design_time time, std::int64_t max_order, std::size_t pairs,
                 const std::vector<design_point>& front, const std::vector<pair_report>& values, unsigned digits,
                 const json& files = json::object());

// The front as CSV (pareto --out, the report's pareto-front.csv): a header, one line per pair.
std::string pareto_csv(const std::vector<design_point>& front, const std::vector<pair_report>& values);

}  // namespace gyrores
