// src/cli/pair_output.hpp
#include "pair_output.hpp"

#include "frontend/number_text.hpp"

namespace gyrores::cli {

using frontend::decimal_text;
using frontend::energy_text;
using frontend::plain;

std::string radius_text(const pair_report& v) { return v.degenerate ? "0 (exact, delta = 2 mod 4)" : plain(v.r_res); }

std::string energy_text(const pair_report& v) { return energy_text(v.h_min.value, v.h_min_share.value); }

std::string padded(const std::string& text, std::size_t width) {
  return text + std::string(text.size() < width ? width - text.size() : 1, ' ');
}

std::string rank_cell(std::size_t i) { return std::to_string(i + 1) + std::string(i + 1 < 10 ? 5 : 4, ' '); }

std::size_t value_column_width(unsigned digits) { return std::size_t(digits) + std::size_t(-frontend::plain_exponent_min) + 5; }

std::string value_columns_header(const std::vector<std::string>& names, unsigned digits) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += i + 1 < names.size() ? padded(names[i], value_column_width(digits)) : names[i];
  return out;
}

std::string value_columns(const std::vector<std::string>& values, unsigned digits) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i)
    out += i + 1 < values.size() ? padded(plain(values[i]), value_column_width(digits)) : plain(values[i]);
  return out;
}

std::string values_columns(const pair_report& v) {
  return value_columns({v.n.value, v.r_res.value, v.t_first.value, v.t_min_paper.value}, v.digits);
}

}  // namespace gyrores::cli
