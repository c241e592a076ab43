// Declaring command-line options, the options shared by several subcommands (the same name,
// help text and default everywhere), and the checks of flag values that must quote the flag in
// their message (the library names its parameters, not the CLI's flags).
//
// The subcommands declare their options through `options`, a thin wrapper whose only
// implementation file includes CLI11: CLI11 is header-only and costs several seconds of
// compilation in every file that includes it, so it is compiled here and in main.cpp only.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/model/pair.hpp>

namespace CLI {
class App;
}

namespace gyrores {
struct pair_filter;
}

namespace gyrores::cli {

// How an option appears: plain, with its default shown in the help, or required.
enum class show { plain, with_default, required };

// A (sub)command's options. A name starting with '-' is an option ("--digits"), any other a
// positional argument ("TAU"). The referenced variables must outlive the parse.
class options {
 public:
  explicit options(CLI::App& app) : app_(&app) {}
  options subcommand(const std::string& name, const std::string& description) const;
  const options& add(const std::string& name, std::string& value, const std::string& help, show s = show::plain) const;
  const options& add(const std::string& name, int& value, const std::string& help, show s = show::plain) const;
  const options& add(const std::string& name, unsigned& value, const std::string& help, show s = show::plain) const;
  const options& add(const std::string& name, long& value, const std::string& help, show s = show::plain) const;
  const options& add(const std::string& name, unsigned long& value, const std::string& help,
                     show s = show::plain) const;
  const options& add(const std::string& name, double& value, const std::string& help, show s = show::plain) const;
  const options& add(const std::string& name, std::vector<std::string>& values, const std::string& help,
                     show s = show::plain) const;
  const options& flag(const std::string& name, bool& value, const std::string& help) const;
  // Exactly one of this command's subcommands must be given.
  void require_subcommand() const;
  // This (sub)command was given on the command line.
  bool parsed() const;

 private:
  CLI::App* app_;
};

// TAU and SIGMA: required positional decimal integers of any size.
void add_pair_arguments(const options& sub, std::string& tau, std::string& sigma);
// The pair they name; usage_error naming TAU or SIGMA (or the pair's own rule) otherwise.
resonant_pair<big_int> parse_pair_arguments(const std::string& tau, const std::string& sigma);

// --digits D, with the default shown in the help.
void add_digits_option(const options& sub, int& digits, const std::string& help = "significant digits of every real printed");
// --json: "one JSON object on stdout".
void add_json_flag(const options& sub, bool& json);
// Both, as the commands that list pairs with their proved values (design, pareto) take them.
void add_output_options(const options& sub, int& digits, bool& json);
// --size of an image (WxH pixels, or inches or centimetres: frontend/plots.hpp apply_figure_size)
// and --font-size in points.
void add_size_option(const options& sub, std::string& size, std::string& font_size);

// --beat B and --exclude-low L: the pair filters that design and pareto share.
struct pair_filter_flags {
  std::string beat;
  std::int64_t exclude_low = 0;
};
void add_pair_filter_options(const options& sub, pair_filter_flags& f);
// Their values into `filter` (usage_error naming the flag).
void apply_pair_filter_flags(const pair_filter_flags& f, pair_filter& filter);

// usage_error "--digits must be in [lo, hi], got D" outside [lo, hi].
void check_digits_flag(int digits, int lo, int hi);
// usage_error "<flag> must be in [lo, hi]" outside [lo, hi].
void check_flag_range(std::int64_t value, std::int64_t lo, std::int64_t hi, const std::string& flag);
// --max-order of the design catalogue (design_catalogue's limits, quoted as the flag).
void check_max_order_flag(std::int64_t max_order);
// A rational flag that must be > 0 (--tmax, --beat): usage_error naming the flag otherwise.
big_rational parse_positive_flag(const std::string& text, const std::string& flag);

}  // namespace gyrores::cli
