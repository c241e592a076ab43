// The JSON forms of the reports that `gyrores pair`, `design`, `pareto` and `coupling` print with
// --json and that the Python module returns as dicts, one definition for both, and the Pareto
// front's CSV (docs/formats.md); a band's guarantees are app/band.hpp's. Reals are decimal strings, each the
// correct rounding of a proved enclosure (report/pair_report.hpp); exact rationals are text.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/design/design.hpp>
#include <gyrores/design/tolerance.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/report/coupling_report.hpp>
#include <gyrores/report/horizon_report.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores {

// {"tau": ..., "sigma": ...}.
json pair_json(const resonant_pair<big_int>& p);

// The format name of `gyrores pair --json` (the Python module builds the same dict directly); "/2":
// every real proved (the output before the lattice theorem, without this field, printed verified
// estimates).
inline constexpr const char* pair_report_format = "gyrores-pair/2";

// The object of `gyrores pair --json`; with `enclosures`, also "enclosures" holding [lo, hi] for
// every real under the same keys (asymptotic_lobes for the lobes' reals).
json pair_report_json(const resonant_pair<big_int>& p, const pair_report& r, bool enclosures = false);

// The object of `gyrores coupling --json`: `input` is {"n": text} or {"n2": text} as given.
json coupling_report_json(const json& input, const std::string& horizon, unsigned digits, const coupling_report& r);

// `gyrores design --json`: `tmax` and `beat` as given ("" for none); "chosen" and "candidates"
// are ranked[i] with values[i].
json design_json(const design_options& o, const std::string& tmax, const std::string& beat, const design_result& r,
                 const std::vector<pair_report>& values, bool chosen_exceeds_tmax, unsigned digits);

// Its "tolerance" object; the tolerance and level as given.
json tolerance_json(design_problem problem, const tolerance_result& r, const std::string& percent, const std::string& level);

// "absorb orientation: lower r_res and lower time are better", or the contain one.
std::string pareto_orientation_text(pareto_orientation o);

// `gyrores pareto --json`; `files` (the CLI's "csv" and "plot") come before "digits".
json pareto_json(pareto_orientation o, design_time time, std::int64_t max_order, std::size_t pairs,
                 const std::vector<design_point>& front, const std::vector<pair_report>& values, unsigned digits,
                 const json& files = json::object());

// The front as CSV (pareto --out, the report's pareto-front.csv): a header, one line per pair.
std::string pareto_csv(const std::vector<design_point>& front, const std::vector<pair_report>& values);

}  // namespace gyrores
