// gyrores pareto --max-order M [--orientation absorb|contain] [--proxy] [--exclude-degenerate]
//                [--beat B] [--exclude-low L] [--out FILE.csv] [--plot FILE.svg|png]
//                [--size WxH] [--digits D] [--json]
// The non-dominated set of (r_res, time) over resonant pairs (include/gyrores/design.hpp).
#include <sstream>

#include <gyrores/design/design.hpp>

#include "cli_output.hpp"
#include "commands.hpp"
#include "plots.hpp"
#include "verified_pair.hpp"

namespace gyrores::cli {
namespace {

struct pareto_args {
  std::int64_t max_order = 0, exclude_low = 0;
  std::string orientation = "absorb", beat, out, plot, size;
  bool proxy = false, exclude_degenerate = false, json = false;
  int digits = 10;
};

std::string run_pareto(const pareto_args& a) {
  pareto_orientation o;
  if (a.orientation == "absorb") o = pareto_orientation::absorb;
  else if (a.orientation == "contain") o = pareto_orientation::contain;
  else throw usage_error("--orientation must be 'absorb' or 'contain', got '" + a.orientation + "'");
  if (a.digits < 1 || a.digits > 1000) throw usage_error("--digits must be in [1, 1000], got " + std::to_string(a.digits));
  if (a.exclude_low < 0) throw usage_error("--exclude-low must be >= 0");
  pair_filter f;
  f.exclude_low = a.exclude_low;
  f.exclude_degenerate = a.exclude_degenerate;
  if (!a.beat.empty()) {
    f.beat_min = parse_rational(a.beat, "--beat");
    if (!(*f.beat_min > 0)) throw usage_error("--beat must be > 0, got " + a.beat);
  }
  std::optional<figure_spec> spec;
  if (!a.plot.empty()) spec = figure_spec_from_out(a.plot, a.size, 900, 640);
  if (!a.out.empty() && fs::path(a.out).extension() != ".csv") throw usage_error("--out must end in .csv, got '" + a.out + "'");
  const design_time which = a.proxy ? design_time::proxy : design_time::first_hit;

  auto catalogue = design_catalogue(a.max_order);
  std::vector<design_point> pts;
  for (const auto& p : catalogue)
    if (pair_filter_accepts(f, p)) pts.push_back(p);
  if (pts.empty()) throw compute_error("no resonant pair up to order " + std::to_string(a.max_order) + " passes the filters");
  auto front = pareto_front(pts, o, which);

  std::vector<pair_values> vals;
  for (const auto& p : front) vals.push_back(pair_values_verified(p.tau, p.sigma, unsigned(a.digits)));

  const std::string orient_text = o == pareto_orientation::absorb
                                      ? "absorb orientation: lower r_res and lower time are better"
                                      : "contain orientation: higher r_res and lower time are better";
  const std::string time_text = a.proxy ? "the paper's proxy pi/|n|" : "the exact first-hit time t_first";

  std::string csv_note, plot_note;
  if (!a.out.empty()) {
    fs::path out(a.out);
    if (!out.parent_path().empty()) ensure_directory(out.parent_path());
    std::ostringstream c;
    c << "tau,sigma,order,delta,degenerate,n,r_res,t_first,t_min_paper\n";
    for (std::size_t i = 0; i < front.size(); ++i)
      c << front[i].tau << "," << front[i].sigma << "," << front[i].order() << "," << front[i].delta() << ","
        << (front[i].degenerate ? "true" : "false") << "," << vals[i].n << "," << vals[i].r_res << "," << vals[i].t_first
        << "," << vals[i].t_min_paper << "\n";
    write_file_atomically(out, c.str());
    csv_note = out.string();
  }
  std::optional<figure_output> fig;
  if (spec) {
    std::string title = "Pareto front, pairs with tau+sigma <= " + std::to_string(a.max_order) + " (" +
                        (o == pareto_orientation::absorb ? "absorb: min r_res, min time" : "contain: max r_res, min time") + ")";
    fig = write_pareto_figure(*spec, pts, front, which, title);
  }

  if (a.json) {
    json j;
    j["orientation"] = a.orientation;
    j["orientation_meaning"] = orient_text;
    j["time"] = a.proxy ? "proxy" : "t_first";
    j["max_order"] = a.max_order;
    j["pairs"] = pts.size();
    json arr = json::array();
    for (std::size_t i = 0; i < front.size(); ++i) {
      resonant_pair<big_int> bp(big_int(front[i].tau), big_int(front[i].sigma));
      arr.push_back(pair_values_json(bp, vals[i]));
    }
    j["front"] = arr;
    j["csv"] = csv_note.empty() ? json(nullptr) : json(csv_note);
    if (fig) {
      j["plot"] = {{"data", fig->data.string()}, {"script", fig->script.string()},
                   {"image", fig->images.empty() ? json(nullptr) : json(fig->images.front().string())},
                   {"note", fig->message}};
    }
    j["digits"] = a.digits;
    return json_dump(j) + "\n";
  }
  std::ostringstream os;
  os << "Pareto front of (r_res, time) over " << pts.size() << " resonant pairs with tau+sigma <= " << a.max_order << "\n"
     << "  " << orient_text << "; time = " << time_text << "; qdot0 = 1\n"
     << "  " << front.size() << " non-dominated pairs, by increasing time:\n"
     << "  pair          n                 r_res             t_first           pi/|n|\n";
  for (std::size_t i = 0; i < front.size(); ++i) {
    std::string pr = "(" + std::to_string(front[i].tau) + ", " + std::to_string(front[i].sigma) + ")";
    os << "  " << pr << std::string(pr.size() < 14 ? 14 - pr.size() : 1, ' ') << vals[i].n << "  " << vals[i].r_res << "  "
       << vals[i].t_first << "  " << vals[i].t_min_paper << (front[i].degenerate ? "  (degenerate: r_res = 0 exactly)" : "")
       << "\n";
  }
  if (!csv_note.empty()) os << "csv: " << csv_note << "\n";
  if (fig) {
    os << "plot data: " << fig->data.string() << "\nplot script: " << fig->script.string() << "\n";
    for (auto& im : fig->images) os << "plot: " << im.string() << "\n";
    if (!fig->message.empty()) os << "note: " << fig->message << "\n";
  }
  return os.str();
}

command_runner install_pareto(CLI::App& app) {
  auto a = std::make_shared<pareto_args>();
  auto* sub = app.add_subcommand("pareto", "Pareto front of (r_res, first-hit time) over resonant pairs");
  sub->add_option("--max-order", a->max_order, "pairs with tau + sigma <= M (3..5000)")->required();
  sub->add_option("--orientation", a->orientation, "absorb (min r_res, min time) or contain (max r_res, min time)")
      ->capture_default_str();
  sub->add_flag("--proxy", a->proxy, "use the paper's proxy pi/|n| as the time");
  sub->add_flag("--exclude-degenerate", a->exclude_degenerate, "drop delta = 2 mod 4 pairs (r_res = 0)");
  sub->add_option("--beat", a->beat, "only pairs with (tau+sigma)/(tau-sigma) >= B");
  sub->add_option("--exclude-low", a->exclude_low, "drop the low-order set tau + sigma <= L");
  sub->add_option("--out", a->out, "write the front as CSV to FILE.csv");
  sub->add_option("--plot", a->plot, "draw the front to FILE.svg or FILE.png (data and gnuplot script beside it)");
  sub->add_option("--size", a->size, "plot size WxH in pixels (default 900x600)");
  sub->add_option("--digits", a->digits, "significant digits of every real printed")->capture_default_str();
  sub->add_flag("--json", a->json, "one JSON object on stdout");
  return [a] { return run_pareto(*a); };
}

const command_registration registration{"pareto", install_pareto};

}  // namespace
}  // namespace gyrores::cli
