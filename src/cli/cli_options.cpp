// src/cli/cli_options.hpp
#include "cli_options.hpp"

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/design/design.hpp>

namespace gyrores::cli {

void add_pair_arguments(const options& sub, std::string& tau, std::string& sigma) {
  sub.add("TAU", tau, "tau (integer > sigma; any size)", show::required);
  sub.add("SIGMA", sigma, "sigma (integer >= 1, coprime to tau)", show::required);
}

resonant_pair<big_int> parse_pair_arguments(const std::string& tau, const std::string& sigma) {
  big_int t = parse_big_int(tau, "TAU"), s = parse_big_int(sigma, "SIGMA");
  return resonant_pair<big_int>(t, s);
}

void add_digits_option(const options& sub, int& digits, const std::string& help) {
  sub.add("--digits", digits, help, show::with_default);
}

void add_json_flag(const options& sub, bool& json) { sub.flag("--json", json, "one JSON object on stdout"); }

void add_output_options(const options& sub, int& digits, bool& json) {
  add_digits_option(sub, digits);
  add_json_flag(sub, json);
}

void add_size_option(const options& sub, std::string& size, std::string& font_size) {
  sub.add("--size", size, "image size: WxH pixels (100 per inch), or a width or WxH in inches or cm (3.5in, 8.8cm, 3.5x2.5in)");
  sub.add("--font-size", font_size, "font size in points (default: from the width, 8 to 12)");
}

void add_pair_filter_options(const options& sub, pair_filter_flags& f) {
  sub.add("--beat", f.beat, "only pairs with (tau+sigma)/(tau-sigma) >= B (decimal or fraction)");
  sub.add("--exclude-low", f.exclude_low, "drop the low-order set tau + sigma <= L");
}

void apply_pair_filter_flags(const pair_filter_flags& f, pair_filter& filter) {
  if (!f.beat.empty()) filter.beat_min = parse_positive_flag(f.beat, "--beat");
  if (f.exclude_low < 0) throw usage_error("--exclude-low must be >= 0");
  filter.exclude_low = f.exclude_low;
}

void check_digits_flag(int digits, int lo, int hi) {
  if (digits < lo || digits > hi)
    throw usage_error("--digits must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                      std::to_string(digits));
}

void check_flag_range(std::int64_t value, std::int64_t lo, std::int64_t hi, const std::string& flag) {
  if (value < lo || value > hi)
    throw usage_error(flag + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

void check_max_order_flag(std::int64_t max_order) {
  if (max_order < 3) throw usage_error("--max-order must be >= 3 (the smallest pair (2, 1) has order 3)");
  if (max_order > design_max_order_limit)
    throw usage_error("--max-order must be <= " + std::to_string(design_max_order_limit) + ", got " + std::to_string(max_order));
}

big_rational parse_positive_flag(const std::string& text, const std::string& flag) {
  big_rational v = parse_rational(text, flag);
  if (!(v > 0)) throw usage_error(flag + " must be > 0, got " + text);
  return v;
}

}  // namespace gyrores::cli
