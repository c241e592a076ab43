// gyrores report [--out DIR] [--pareto-order M] [--sweep-order S] [--digits D]
// The newcomer's main job: DIR/REPORT.md, written by the report generator (src/report/report.hpp).
// Prints the report's path.
#include "cli_options.hpp"
#include "commands.hpp"
#include "report/report.hpp"

namespace gyrores::cli {
namespace {

struct report_args {
  report::report_options options;
  int digits = 10;
};

std::string run_report(report_args& a) {
  check_digits_flag(a.digits, 3, 40);
  check_flag_range(a.options.pareto_order, 3, 2000, "--pareto-order");
  check_flag_range(a.options.sweep_order, 3, 1000, "--sweep-order");
  a.options.digits = unsigned(a.digits);
  return report::write_report(a.options);
}

command_runner install_report(CLI::App& app) {
  auto a = std::make_shared<report_args>();
  auto sub = options(app).subcommand("report", "Write DIR/REPORT.md: the paper's examples recomputed, design cases, Pareto front, figures");
  sub.add("--out", a->options.out, "output directory", show::with_default);
  sub.add("--pareto-order", a->options.pareto_order, "Pareto front over pairs with tau + sigma <= M (3..2000)", show::with_default);
  sub.add("--sweep-order", a->options.sweep_order, "validation sweep over pairs with tau + sigma <= S (3..1000)", show::with_default);
  add_digits_option(sub, a->digits, "significant digits of every real printed (3..40)");
  return [a] { return run_report(*a); };
}

const command_registration registration{"report", install_report};

}  // namespace
}  // namespace gyrores::cli
