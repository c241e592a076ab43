// How the CLI prints pairs and their proved values in its tables (design, pareto, coupling).
// The JSON objects and the Pareto CSV are io/'s (io/report_json.hpp), shared with Python.
#pragma once
#include <cstddef>
#include <string>

#include <gyrores/report/pair_report.hpp>

namespace gyrores::cli {

// r_res for text output: "0 (exact, delta = 2 mod 4)" for degenerate pairs.
std::string radius_text(const pair_report& v);

// `text` then spaces up to `width` columns (at least one).
std::string padded(const std::string& text, std::size_t width);
// The rank column of row i (rank i + 1), 6 columns wide below rank 10.
std::string rank_cell(std::size_t i);
// "n  r_res  t_first  pi/|n|": the values columns of the tables.
std::string values_columns(const pair_report& v);

}  // namespace gyrores::cli
