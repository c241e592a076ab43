// gyrores pareto --max-order M [--orientation absorb|contain] [--proxy] [--exclude-degenerate]
//                [--beat B] [--exclude-low L] [--out FILE.csv] [--plot FILE.svg|png|pdf|eps]
//                [--size WxH|3.5in|8.8cm] [--font-size PT] [--digits D] [--json]
// The non-dominated set of (r_res, time) over resonant pairs (include/gyrores/app/pareto.hpp),
// with its CSV (io/report_json.hpp) and figure (frontend/plots.hpp).
#include <optional>
#include <sstream>

#include <gyrores/app/pareto.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/io/files.hpp>
#include <gyrores/io/json.hpp>

#include "cli_options.hpp"
#include "commands.hpp"
#include "frontend/plots.hpp"
#include "frontend/process.hpp"
#include "pair_output.hpp"

namespace gyrores::cli {
namespace {

namespace fs = std::filesystem;
using frontend::figure_output;
using frontend::figure_spec;

struct pareto_args {
  std::int64_t max_order = 0;
  pair_filter_flags filter;
  std::string orientation = "absorb", out, plot, size, font_size;
  bool proxy = false, exclude_degenerate = false, json = false;
  int digits = 10;
};

// The files written: the CSV (or ""), the figure.
struct pareto_files {
  std::string csv;
  std::optional<figure_output> fig;
};

std::string pareto_json_text(const app::pareto_request& r, const app::pareto_outcome& p, const pareto_files& f) {
  json files;
  files["csv"] = f.csv.empty() ? json(nullptr) : json(f.csv);
  if (f.fig)
    files["plot"] = {{"data", f.fig->data.string()}, {"script", f.fig->script.string()},
                     {"image", f.fig->images.empty() ? json(nullptr) : json(f.fig->images.front().string())},
                     {"note", f.fig->message}};
  return json_dump(pareto_json(r.orientation, r.time, r.max_order, p.pairs.size(), p.front, p.values, r.digits, files)) + "\n";
}

std::string pareto_text(const app::pareto_request& r, const app::pareto_outcome& p, const pareto_files& f) {
  std::ostringstream os;
  os << "Pareto front of (r_res, time) over " << p.pairs.size() << " resonant pairs with tau+sigma <= " << r.max_order << "\n"
     << "  " << pareto_orientation_text(r.orientation) << "; time = "
     << (r.time == design_time::proxy ? "the paper's proxy pi/|n|" : "the exact first-hit time t_first") << "; qdot0 = 1\n"
     << "  " << p.front.size() << " non-dominated pairs, by increasing time:\n"
     << "  pair          " << value_columns_header({"n", "r_res", "t_first", "pi/|n|"}, r.digits) << "\n";
  for (std::size_t i = 0; i < p.front.size(); ++i)
    os << "  " << padded(p.front[i].pair().str(), 14) << values_columns(p.values[i])
       << (p.front[i].degenerate ? "  (degenerate: r_res = 0 exactly)" : "") << "\n";
  if (!f.csv.empty()) os << "csv: " << f.csv << "\n";
  if (f.fig) {
    os << "plot data: " << f.fig->data.string() << "\nplot script: " << f.fig->script.string() << "\n";
    for (auto& im : f.fig->images) os << "plot: " << im.string() << "\n";
    if (!f.fig->message.empty()) os << "note: " << f.fig->message << "\n";
  }
  return os.str();
}

std::string run_pareto(const pareto_args& a) {
  app::pareto_request r;
  r.orientation = app::parse_pareto_orientation(a.orientation, "--orientation");
  check_digits_flag(a.digits, 1, int(app::listed_digits_max));
  apply_pair_filter_flags(a.filter, r.filter);
  r.filter.exclude_degenerate = a.exclude_degenerate;
  std::optional<figure_spec> spec;
  if (!a.plot.empty()) spec = frontend::figure_spec_from_out(a.plot, a.size, 900, 640, a.font_size);
  const fs::path out(a.out);
  if (!a.out.empty() && out.extension() != ".csv") throw usage_error("--out must end in .csv, got '" + a.out + "'");
  r.time = a.proxy ? design_time::proxy : design_time::first_hit;
  check_max_order_flag(a.max_order);
  r.max_order = a.max_order;
  r.digits = unsigned(a.digits);
  // Every output checked before the work (io/files.hpp), the CSV against the figure's files too.
  if (!a.out.empty()) {
    if (!out.parent_path().empty()) ensure_directory(out.parent_path());
    if (spec) frontend::check_figure_outputs(*spec, {{"--out", a.out}});
    else check_output_path(a.out);
  }
  r.progress = frontend::progress_stage;
  const app::pareto_outcome p = app::run_pareto(r);
  pareto_files f;
  if (!a.out.empty()) write_file_atomically(out, pareto_csv(p.front, p.values)), f.csv = a.out;
  if (spec)
    f.fig = frontend::write_pareto_figure(*spec, p.pairs, p.front, r.time,
                                          "Pareto front, pairs with tau+sigma <= " + std::to_string(a.max_order) + " (" +
                                              frontend::pareto_orientation_caption(r.orientation) + ")");
  return a.json ? pareto_json_text(r, p, f) : pareto_text(r, p, f);
}

command_runner install_pareto(CLI::App& app) {
  auto a = std::make_shared<pareto_args>();
  auto sub = options(app).subcommand("pareto", "Pareto front of (r_res, first-hit time) over resonant pairs (qdot0 = 1: r_res scales by qdot0, the front does not; docs/units.md)");
  sub.add("--max-order", a->max_order, "pairs with tau + sigma <= M (3..5000)", show::required);
  sub.add("--orientation", a->orientation, "absorb (min r_res, min time) or contain (max r_res, min time)", show::with_default);
  sub.flag("--proxy", a->proxy, "use the paper's proxy pi/|n| as the time");
  sub.flag("--exclude-degenerate", a->exclude_degenerate, "drop delta = 2 mod 4 pairs (r_res = 0)");
  add_pair_filter_options(sub, a->filter);
  sub.add("--out", a->out, "write the front as CSV to FILE.csv");
  sub.add("--plot", a->plot, "draw the front to FILE.svg, .png, .pdf or .eps (data and gnuplot script beside it)");
  add_size_option(sub, a->size, a->font_size);
  add_output_options(sub, a->digits, a->json);
  return [a] { return run_pareto(*a); };
}

const command_registration registration{"pareto", install_pareto};

}  // namespace
}  // namespace gyrores::cli
