// How the CLI prints pairs and their proved values in its tables (design, pareto, coupling).
// The JSON objects and the Pareto CSV are io/'s (io/report_json.hpp), shared with Python.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <gyrores/report/pair_report.hpp>

namespace gyrores::cli {

// r_res for text output: "0 (exact, delta = 2 mod 4)" for degenerate pairs, else plain text.
std::string radius_text(const pair_report& v);
// H_q min for text output: "0 (exact)" for degenerate pairs, else plain text with its share of
// H_q(0) ("0.001287568403  (0.2575% of H_q(0))").
std::string energy_text(const pair_report& v);

// `text` then spaces up to `width` columns (at least one).
std::string padded(const std::string& text, std::size_t width);
// The rank column of row i (rank i + 1), 6 columns wide below rank 10.
std::string rank_cell(std::size_t i);
// The width of a value column of reals with `digits` digits: the widest spelling (plain with
// exponent -4, a sign) and two spaces.
std::size_t value_column_width(unsigned digits);
// The header cells `names`, each padded to value_column_width(digits) (the last not padded).
std::string value_columns_header(const std::vector<std::string>& names, unsigned digits);
// The cells `values` in plain notation, each padded as value_columns_header pads its names.
std::string value_columns(const std::vector<std::string>& values, unsigned digits);
// "n  r_res  t_first  pi/|n|": the values columns of the tables.
std::string values_columns(const pair_report& v);

}  // namespace gyrores::cli
