// The JSON forms of the reports that `gyrores pair`, `design`, `pareto` and `coupling` print with
// --json and that the Python module returns as dicts, one definition for both, and of a band's
// guarantees (docs/formats.md). Reals are decimal strings, each the correct rounding of a proved
// enclosure (report/pair_report.hpp).
#pragma once
#include <optional>
#include <string>

#include <gyrores/io/json.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/report/coupling_report.hpp>
#include <gyrores/report/horizon_report.hpp>
#include <gyrores/report/pair_report.hpp>
#include <gyrores/theorem/band.hpp>

namespace gyrores {

// {"tau", "sigma", "n", "r_res", "h_min", "t_first", "t_min_paper", "degenerate"}: one pair's
// values as the design, Pareto and coupling outputs list them.
json pair_values_json(const resonant_pair<big_int>& p, const pair_report& v);

// The object of `gyrores pair --json`; with `enclosures`, also "enclosures" holding [lo, hi] for
// every real under the same keys (asymptotic_lobes for the lobes' reals).
json pair_report_json(const resonant_pair<big_int>& p, const pair_report& r, bool enclosures = false);

// The object of `gyrores coupling --json`: `input` is {"n": text} or {"n2": text} as given.
json coupling_report_json(const json& input, const std::string& horizon, unsigned digits, const coupling_report& r);

inline constexpr const char* band_format = "gyrores-band/2";

// {"n2", "x", "pair"} of a coupling of the band.
json band_coupling_json(const band_coupling& c, const std::optional<resonant_pair<big_int>>& pair);

// One guarantee, and the band-wide first time below E; `at` is where it is attained.
json band_extreme_json(const band_extreme& e, unsigned digits, const json& at);
json band_first_below_json(const band_first_below& b, unsigned digits, const json& at);

// A horizon minimum's place, for "at": {"h_min", "lobe", "at_horizon_end", "t_min"}.
json horizon_place_json(const horizon_minimum_report& r);

}  // namespace gyrores
