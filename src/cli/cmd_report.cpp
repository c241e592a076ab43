// gyrores report [--out DIR] [--pareto-order M] [--sweep-order S] [--digits D]
// The newcomer's main job: DIR/REPORT.md, written by the report generator (src/report/report.hpp).
// Prints the report's path.
#include "cli_options.hpp"
#include "commands.hpp"
#include "report/report.hpp"

namespace gyrores::cli {
namespace {

command_runner install_report(CLI::App& app) {
  auto a = std::make_shared<report::report_options>();
  auto digits = std::make_shared<int>(int(a->digits));
  auto sub = options(app).subcommand("report", "Write DIR/REPORT.md: the paper's examples recomputed, design cases, Pareto front, figures");
  sub.add("--out", a->out, "output directory", show::with_default);
  sub.add("--pareto-order", a->pareto_order, "Pareto front over pairs with tau + sigma <= M (3..2000)", show::with_default);
  sub.add("--sweep-order", a->sweep_order, "validation sweep over pairs with tau + sigma <= S (3..1000)", show::with_default);
  add_digits_option(sub, *digits, "significant digits of every real printed (3..40)");
  return [a, digits] {
    check_digits_flag(*digits, 3, 40);
    check_flag_range(a->pareto_order, 3, 2000, "--pareto-order");
    check_flag_range(a->sweep_order, 3, 1000, "--sweep-order");
    a->digits = unsigned(*digits);
    return report::write_report(*a);
  };
}

const command_registration registration{"report", install_report};

}  // namespace
}  // namespace gyrores::cli
