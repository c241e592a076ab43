// The outputs of `gyrores design` and `gyrores pareto` (docs/formats.md), one definition for the
// CLI and the Python module: the objects of --json (the Python dicts, key for key) and the Pareto
// front's CSV (pareto --out, the report's pareto-front.csv). Reals are the proved decimal
// strings of theorem/pair_report.hpp; exact rationals are text.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <gyrores/design/design.hpp>
#include <gyrores/design/tolerance.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores {

// The object of `gyrores design --json`: the problem and its constraints (tmax and beat, "" for
// none, as given), the counts, "chosen" and "candidates" (pair_values_json of ranked[i] and
// values[i]), whether the proxy's choice exceeds tmax, and the digits.
json design_json(const design_options& o, const std::string& tmax, const std::string& beat, const design_result& r,
                 const std::vector<pair_report>& values, bool chosen_exceeds_tmax, unsigned digits);

// Its "tolerance" object: every ranked pair walked with its band, the enclosure of its worst
// (absorb) or best (contain) minimum, its verdict; the chosen pair; the tolerance and level as given.
json tolerance_json(design_problem problem, const tolerance_result& r, const std::string& percent, const std::string& level);

// "absorb orientation: lower r_res and lower time are better", or the contain one.
std::string pareto_orientation_text(pareto_orientation o);

// The object of `gyrores pareto --json`: the orientation, the time, the counts and the front
// (pair_values_json of front[i] and values[i]); `files` (the CLI's "csv" and "plot") come before
// "digits".
json pareto_json(pareto_orientation o, design_time time, std::int64_t max_order, std::size_t pairs,
                 const std::vector<design_point>& front, const std::vector<pair_report>& values, unsigned digits,
                 const json& files = json::object());

// The Pareto front as CSV: pareto_csv_header, then one line per pair with its proved values.
inline constexpr const char* pareto_csv_header = "tau,sigma,order,delta,degenerate,n,r_res,t_first,t_min_paper\n";
std::string pareto_csv(const std::vector<design_point>& front, const std::vector<pair_report>& values);

}  // namespace gyrores
