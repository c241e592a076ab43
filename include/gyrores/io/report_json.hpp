// The JSON forms of the reports that `gyrores pair`, `design`, `pareto` and `coupling` print
// with --json and that the Python module returns as dicts (docs/formats.md): one definition for
// both, so the two stay key for key the same. Integers of any size are JSON numbers; reals are
// decimal strings, each the correct rounding of a proved enclosure (report/pair_report.hpp).
#pragma once
#include <string>
#include <vector>

#include <gyrores/report/coupling_report.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores {

// {"tau": ..., "sigma": ...}.
json pair_json(const resonant_pair<big_int>& p);

// The version of the pair object (docs/formats.md); "/2": every real proved (the output before
// the lattice theorem, without this field, printed verified estimates).
inline constexpr const char* pair_report_format = "gyrores-pair/2";

// {"tau", "sigma", "n", "r_res", "h_min", "t_first", "t_min_paper", "degenerate"}: one pair's
// values as the design, Pareto and coupling outputs list them.
json pair_values_json(const resonant_pair<big_int>& p, const pair_report& v);

// The "asymptotic" object of `gyrores pair --json`: applicable, reason, lobes.
json asymptotic_json(const pair_report& r);

// The whole object of `gyrores pair --json`, key for key; with `enclosures`, also the object
// "enclosures" holding [lo, hi] for every real under the same keys (asymptotic_lobes for the
// lobes' reals).
json pair_report_json(const resonant_pair<big_int>& p, const pair_report& r, bool enclosures = false);

// The object of `gyrores coupling --json`. `input` is {"n": text} or {"n2": text} as the user gave
// it, `horizon` the horizon's text, `digits` the digits asked for.
json coupling_report_json(const json& input, const std::string& horizon, unsigned digits, const coupling_report& r);

}  // namespace gyrores
