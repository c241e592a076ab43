// How the CLI prints a pair and its verified values (design, pareto, coupling, report): the
// Pareto CSV row and text.
#pragma once
#include <string>

#include <gyrores/design/design.hpp>
#include <gyrores/report/pair_report.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores::cli {

// The JSON objects (pair_json, pair_values_json) are io/report_json.hpp's, shared with Python.

// The Pareto front CSV (pareto --out, report's pareto-front.csv): header line and one row.
inline constexpr const char* pareto_csv_header = "tau,sigma,order,delta,degenerate,n,r_res,t_first,t_min_paper\n";
std::string pareto_csv_row(const design_point& p, const pair_report& v);

// r_res for text output: "0 (exact, delta = 2 mod 4)" for degenerate pairs.
std::string radius_text(const pair_report& v);

}  // namespace gyrores::cli
