// The JSON forms of the reports that `gyrores pair`, `design`, `pareto` and `coupling` print
// with --json and that the Python module returns as dicts (docs/formats.md): one definition for
// both, so the two stay key for key the same. Integers of any size are JSON numbers; reals are
// the verified decimal strings of the reports.
#pragma once
#include <string>
#include <vector>

#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/design/coupling_report.hpp>
#include <gyrores/inscribed/verified_pair.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// {"tau": ..., "sigma": ...}.
json pair_json(const resonant_pair<big_int>& p);

// {"tau", "sigma", "n", "r_res", "h_min", "t_first", "t_min_paper", "degenerate"}: one pair's
// verified values as the design, Pareto and coupling outputs list them.
json pair_values_json(const resonant_pair<big_int>& p, const verified_pair_values& v);

// The "asymptotic" object of `gyrores pair --json`: applicable, reason, lobes.
json asymptotic_json(const verified_pair_report& r);

// The whole object of `gyrores pair --json`, key for key.
json pair_report_json(const resonant_pair<big_int>& p, const verified_pair_report& r);

// Adds "certified" (whether `proved` is given) and, when it is, the enclosures
// "r_res_enclosure", "theta_first_enclosure", "t_first_enclosure" ([lo, hi]) and "theorem".
void add_enclosures_json(json& j, const certified_enclosures* proved);

// The object of `gyrores coupling --json`. `input` is {"n": text} or {"n2": text} as the user gave
// it, `horizon` the horizon's text, `digits` the digits asked for.
json coupling_report_json(const json& input, const std::string& horizon, unsigned digits, const coupling_report& r);

}  // namespace gyrores
