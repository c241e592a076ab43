// src/cli/pair_output.hpp
#include "pair_output.hpp"

namespace gyrores::cli {

std::string radius_text(const pair_report& v) { return v.degenerate ? "0 (exact, delta = 2 mod 4)" : v.r_res.value; }

std::string padded(const std::string& text, std::size_t width) {
  return text + std::string(text.size() < width ? width - text.size() : 1, ' ');
}

std::string rank_cell(std::size_t i) { return std::to_string(i + 1) + std::string(i + 1 < 10 ? 5 : 4, ' '); }

std::string values_columns(const pair_report& v) {
  return v.n.value + "  " + v.r_res.value + "  " + v.t_first.value + "  " + v.t_min_paper.value;
}

}  // namespace gyrores::cli
