// gyrores pareto --max-order M [--orientation absorb|contain] [--proxy] [--exclude-degenerate]
//                [--beat B] [--exclude-low L] [--out FILE.csv] [--plot FILE.svg|png]
//                [--size WxH] [--digits D] [--json]
// The non-dominated set of (r_res, time) over resonant pairs (include/gyrores/design/design.hpp).
#include <sstream>

#include <gyrores/design/design.hpp>
#include <gyrores/report/pair_report.hpp>
#include <gyrores/io/files.hpp>
#include <gyrores/io/json.hpp>

#include "cli_options.hpp"
#include "cli_process.hpp"
#include "commands.hpp"
#include "pair_output.hpp"
#include "plots.hpp"

namespace gyrores::cli {
namespace {

struct pareto_args {
  std::int64_t max_order = 0, exclude_low = 0;
  std::string orientation = "absorb", beat, out, plot, size;
  bool proxy = false, exclude_degenerate = false, json = false;
  int digits = 10;
};

// The front with its proved values, and the files written.
struct pareto_run {
  pareto_orientation orientation;
  std::vector<design_point> pairs, front;
  std::vector<pair_report> values;
  std::string csv;                  // the CSV file written, or ""
  std::optional<figure_output> fig;
};

pair_filter filter_of(const pareto_args& a) {
  pair_filter f;
  f.exclude_low = a.exclude_low;
  f.exclude_degenerate = a.exclude_degenerate;
  if (!a.beat.empty()) f.beat_min = parse_positive_flag(a.beat, "--beat");
  return f;
}

std::string orientation_text(pareto_orientation o) {
  return o == pareto_orientation::absorb ? "absorb orientation: lower r_res and lower time are better"
                                         : "contain orientation: higher r_res and lower time are better";
}

std::string write_front_csv(const fs::path& out, const pareto_run& r) {
  if (!out.parent_path().empty()) ensure_directory(out.parent_path());
  std::ostringstream c;
  c << pareto_csv_header;
  for (std::size_t i = 0; i < r.front.size(); ++i) c << pareto_csv_row(r.front[i], r.values[i]);
  write_file_atomically(out, c.str());
  return out.string();
}

std::string pareto_json(const pareto_args& a, const pareto_run& r) {
  json j;
  j["orientation"] = a.orientation;
  j["orientation_meaning"] = orientation_text(r.orientation);
  j["time"] = a.proxy ? "proxy" : "t_first";
  j["max_order"] = a.max_order;
  j["pairs"] = r.pairs.size();
  json arr = json::array();
  for (std::size_t i = 0; i < r.front.size(); ++i)
    arr.push_back(pair_values_json(resonant_pair<big_int>(big_int(r.front[i].tau), big_int(r.front[i].sigma)), r.values[i]));
  j["front"] = arr;
  j["csv"] = r.csv.empty() ? json(nullptr) : json(r.csv);
  if (r.fig) {
    j["plot"] = {{"data", r.fig->data.string()}, {"script", r.fig->script.string()},
                 {"image", r.fig->images.empty() ? json(nullptr) : json(r.fig->images.front().string())},
                 {"note", r.fig->message}};
  }
  j["digits"] = a.digits;
  return json_dump(j) + "\n";
}

std::string pareto_text(const pareto_args& a, const pareto_run& r) {
  std::ostringstream os;
  os << "Pareto front of (r_res, time) over " << r.pairs.size() << " resonant pairs with tau+sigma <= " << a.max_order << "\n"
     << "  " << orientation_text(r.orientation) << "; time = "
     << (a.proxy ? "the paper's proxy pi/|n|" : "the exact first-hit time t_first") << "; qdot0 = 1\n"
     << "  " << r.front.size() << " non-dominated pairs, by increasing time:\n"
     << "  pair          n                 r_res             t_first           pi/|n|\n";
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    const auto& p = r.front[i];
    const auto& v = r.values[i];
    std::string pr = "(" + std::to_string(p.tau) + ", " + std::to_string(p.sigma) + ")";
    os << "  " << pr << std::string(pr.size() < 14 ? 14 - pr.size() : 1, ' ') << v.n << "  " << v.r_res << "  "
       << v.t_first << "  " << v.t_min_paper << (p.degenerate ? "  (degenerate: r_res = 0 exactly)" : "") << "\n";
  }
  if (!r.csv.empty()) os << "csv: " << r.csv << "\n";
  if (r.fig) {
    os << "plot data: " << r.fig->data.string() << "\nplot script: " << r.fig->script.string() << "\n";
    for (auto& im : r.fig->images) os << "plot: " << im.string() << "\n";
    if (!r.fig->message.empty()) os << "note: " << r.fig->message << "\n";
  }
  return os.str();
}

std::string run_pareto(const pareto_args& a) {
  pareto_run r;
  r.orientation = parse_orientation_flag(a.orientation);
  check_digits_flag(a.digits, 1, 1000);
  if (a.exclude_low < 0) throw usage_error("--exclude-low must be >= 0");
  const pair_filter f = filter_of(a);
  std::optional<figure_spec> spec;
  if (!a.plot.empty()) spec = figure_spec_from_out(a.plot, a.size, 900, 640);
  if (!a.out.empty() && fs::path(a.out).extension() != ".csv") throw usage_error("--out must end in .csv, got '" + a.out + "'");
  const design_time which = a.proxy ? design_time::proxy : design_time::first_hit;
  check_max_order_flag(a.max_order);
  // Every output checked before the work (io/files.hpp), the CSV against the figure's files too.
  if (!a.out.empty()) {
    if (!fs::path(a.out).parent_path().empty()) ensure_directory(fs::path(a.out).parent_path());
    if (spec) check_figure_outputs(*spec, {{"--out", a.out}});
    else check_output_path(a.out);
  }
  progress_stage("evaluating every pair up to order " + std::to_string(a.max_order));
  for (const auto& p : design_catalogue(a.max_order))
    if (pair_filter_accepts(f, p)) r.pairs.push_back(p);
  if (r.pairs.empty()) throw compute_error("no resonant pair up to order " + std::to_string(a.max_order) + " passes the filters");
  r.front = pareto_front(r.pairs, r.orientation, which);
  progress_stage("proving the values of the " + std::to_string(r.front.size()) + " front pairs");
  for (const auto& p : r.front) r.values.push_back(prove_pair_values(resonant_pair<big_int>(big_int(p.tau), big_int(p.sigma)), unsigned(a.digits)));
  if (!a.out.empty()) r.csv = write_front_csv(a.out, r);
  if (spec)
    r.fig = write_pareto_figure(*spec, r.pairs, r.front, which,
                                "Pareto front, pairs with tau+sigma <= " + std::to_string(a.max_order) + " (" +
                                    pareto_orientation_caption(r.orientation) + ")");
  return a.json ? pareto_json(a, r) : pareto_text(a, r);
}

command_runner install_pareto(CLI::App& app) {
  auto a = std::make_shared<pareto_args>();
  auto sub = options(app).subcommand("pareto", "Pareto front of (r_res, first-hit time) over resonant pairs");
  sub.add("--max-order", a->max_order, "pairs with tau + sigma <= M (3..5000)", show::required);
  sub.add("--orientation", a->orientation, "absorb (min r_res, min time) or contain (max r_res, min time)", show::with_default);
  sub.flag("--proxy", a->proxy, "use the paper's proxy pi/|n| as the time");
  sub.flag("--exclude-degenerate", a->exclude_degenerate, "drop delta = 2 mod 4 pairs (r_res = 0)");
  sub.add("--beat", a->beat, "only pairs with (tau+sigma)/(tau-sigma) >= B");
  sub.add("--exclude-low", a->exclude_low, "drop the low-order set tau + sigma <= L");
  sub.add("--out", a->out, "write the front as CSV to FILE.csv");
  sub.add("--plot", a->plot, "draw the front to FILE.svg or FILE.png (data and gnuplot script beside it)");
  add_size_option(sub, a->size, "plot size WxH in pixels (default 900x600)");
  add_digits_option(sub, a->digits);
  add_json_flag(sub, a->json);
  return [a] { return run_pareto(*a); };
}

const command_registration registration{"pareto", install_pareto};

}  // namespace
}  // namespace gyrores::cli
