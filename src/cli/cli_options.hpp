// Command-line options shared by several subcommands (the same name, help text and default
// everywhere), and the checks of flag values that must quote the flag in their message (the
// library names its parameters, not the CLI's flags).
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/design/design.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores::cli {

// TAU and SIGMA: required positional decimal integers of any size.
void add_pair_arguments(CLI::App* sub, std::string& tau, std::string& sigma);
// The pair they name; usage_error naming TAU or SIGMA (or the pair's own rule) otherwise.
resonant_pair<big_int> parse_pair_arguments(const std::string& tau, const std::string& sigma);

// --digits D, with the default shown in the help.
void add_digits_option(CLI::App* sub, int& digits, const std::string& help = "significant digits of every real printed");
// --json: "one JSON object on stdout".
void add_json_flag(CLI::App* sub, bool& json);
// --size WxH of an image.
void add_size_option(CLI::App* sub, std::string& size, const std::string& help);

// usage_error "--digits must be in [lo, hi], got D" outside [lo, hi].
void check_digits_flag(int digits, int lo, int hi);
// usage_error "<flag> must be in [lo, hi]" outside [lo, hi].
void check_flag_range(std::int64_t value, std::int64_t lo, std::int64_t hi, const std::string& flag);
// --max-order of the design catalogue (design_catalogue's limits, quoted as the flag).
void check_max_order_flag(std::int64_t max_order);
// A rational flag that must be > 0 (--tmax, --beat): usage_error naming the flag otherwise.
big_rational parse_positive_flag(const std::string& text, const std::string& flag);
// --orientation absorb|contain.
pareto_orientation parse_orientation_flag(const std::string& text);

}  // namespace gyrores::cli
