// gyrores plot phase  TAU SIGMA | --n N | --n2 P/Q  [--tmax T] [--out FILE.svg|png] [--size WxH]
// gyrores plot energy TAU SIGMA | --n N | --n2 P/Q  [--tmax T] [--out FILE.svg|png] [--size WxH]
// gyrores plot pareto --max-order M [--orientation absorb|contain] [--proxy] [--exclude-degenerate]
//                     [--out FILE.svg|png] [--size WxH]
// Each figure is written with its data (NAME.dat) and gnuplot script (NAME.gp) beside it; if
// gnuplot is missing the command says so and still writes both (exit 0).
#include <sstream>

#include <gyrores/design/coupling.hpp>
#include <gyrores/design/design.hpp>
#include <gyrores/design/figures.hpp>
#include <gyrores/model/resonant.hpp>

#include "cli_options.hpp"
#include "cli_process.hpp"
#include "commands.hpp"
#include "plots.hpp"

namespace gyrores::cli {
namespace {

struct plot_args {
  std::string tau, sigma, n, n2, tmax, out, size, orientation = "absorb";
  std::int64_t max_order = 0;
  bool proxy = false, exclude_degenerate = false;
};

// The subject of a phase or energy plot: a resonant pair, or a non-resonant coupling n.
struct plot_subject {
  std::optional<resonant_pair<std::int64_t>> pair;
  double n = 0;
  std::string label;
};

plot_subject subject_of(const plot_args& a) {
  const bool have_pair = !a.tau.empty() || !a.sigma.empty();
  const int given = int(have_pair) + int(!a.n.empty()) + int(!a.n2.empty());
  if (given != 1) throw usage_error("give exactly one of TAU SIGMA, --n N or --n2 P/Q");
  plot_subject s;
  std::optional<resonant_pair<big_int>> bp;
  if (have_pair) {
    if (a.tau.empty() || a.sigma.empty()) throw usage_error("a pair needs both TAU and SIGMA");
    bp = parse_pair_arguments(a.tau, a.sigma);
  } else {
    auto spec = !a.n.empty() ? coupling_spec::from_n(parse_rational(a.n, "--n")) : coupling_spec::from_n2(parse_rational(a.n2, "--n2"));
    bp = coupling_resonant_pair(spec);
    if (!bp) {
      s.n = spec.abs_n<double>();
      s.label = (!a.n.empty() ? "n = " + a.n : "n^2 = " + a.n2) + " (not resonant)";
      return s;
    }
  }
  s.pair = figure_pair_of(*bp);
  s.n = resonant_constants_of<double>(*s.pair, 1.0).n;
  s.label = "pair " + s.pair->str();
  return s;
}

double tmax_of(const plot_args& a) {
  if (a.tmax.empty()) return 0;
  return parse_positive_flag(a.tmax, "--tmax").convert_to<double>();
}

std::string files_text(const figure_output& f) {
  std::ostringstream os;
  for (auto& im : f.images) os << "figure: " << im.string() << "\n";
  os << "data:   " << f.data.string() << "\nscript: " << f.script.string() << "\n";
  if (!f.message.empty()) os << "note: " << f.message << "\n";
  return os.str();
}

std::string run_phase(const plot_args& a) {
  auto s = subject_of(a);
  auto spec = figure_spec_from_out(a.out.empty() ? "phase.svg" : a.out, a.size, 1200, 640);
  const double pi = real_pi<double>();
  phase_portrait f;
  std::string title;
  if (s.pair) {
    if (!a.tmax.empty()) throw usage_error("--tmax does not apply to a resonant pair (one full period is drawn)");
    f = phase_portrait_of_pair(*s.pair);
    char buf[200];
    std::snprintf(buf, sizeof buf, "(%lld, %lld): n = %.6g, r_res = %.6g%s", (long long)s.pair->tau(),
                  (long long)s.pair->sigma(), f.n, f.r_inscribed, s.pair->degenerate() ? " (degenerate)" : "");
    title = buf;
  } else {
    double span = tmax_of(a);
    if (span == 0) span = 200 * pi / s.n;
    f = phase_portrait_of_coupling(s.n, 1.0, span);
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s, t in [0, %.6g]; min radius on span %.4g", s.label.c_str(), span, f.r_inscribed);
    title = buf;
  }
  return files_text(write_phase_figure(spec, f, title));
}

std::string run_energy(const plot_args& a) {
  auto s = subject_of(a);
  auto spec = figure_spec_from_out(a.out.empty() ? "energy.svg" : a.out, a.size, 900, 500);
  const double pi = real_pi<double>();
  energy_series e;
  std::string title, label;
  if (s.pair) {
    e = energy_of_pair(*s.pair, 1.0, tmax_of(a));
    char buf[200];
    std::snprintf(buf, sizeof buf, "(%lld, %lld): n = %.6g, H_q min = %.6g", (long long)s.pair->tau(),
                  (long long)s.pair->sigma(), e.n, e.h_min);
    title = buf;
    label = "exact t_{first}";
  } else {
    double span = tmax_of(a);
    if (span == 0) span = 8 * pi / s.n;
    e = energy_of_coupling(s.n, 1.0, span);
    title = s.label;
    label = "first min on span, t";
  }
  return files_text(write_energy_figure(spec, e, title, label));
}

std::string run_pareto_plot(const plot_args& a) {
  const pareto_orientation o = parse_orientation_flag(a.orientation);
  auto spec = figure_spec_from_out(a.out.empty() ? "pareto.svg" : a.out, a.size, 900, 640);
  check_max_order_flag(a.max_order);
  progress_stage("evaluating every pair up to order " + std::to_string(a.max_order));
  auto cat = design_catalogue(a.max_order);
  std::vector<design_point> pts;
  for (auto& p : cat)
    if (!a.exclude_degenerate || !p.degenerate) pts.push_back(p);
  const design_time which = a.proxy ? design_time::proxy : design_time::first_hit;
  auto front = pareto_front(pts, o, which);
  std::string title = "Pareto front, tau+sigma <= " + std::to_string(a.max_order) + " (" + pareto_orientation_caption(o) +
                      (a.exclude_degenerate ? ", degenerate pairs excluded" : "") + ")";
  auto f = write_pareto_figure(spec, pts, front, which, title);
  return std::to_string(front.size()) + " front points of " + std::to_string(pts.size()) + " pairs\n" + files_text(f);
}

command_runner install_plot(CLI::App& app) {
  auto a = std::make_shared<plot_args>();
  auto sub = options(app).subcommand("plot", "Figures with gnuplot (SVG or PNG), data and script kept beside each");
  sub.require_subcommand();
  auto image = [&](const options& s) {
    s.add("--out", a->out, "output FILE.svg or FILE.png");
    add_size_option(s, a->size, "image size WxH in pixels");
  };
  auto common = [&](const options& s, const char* what) {
    s.add("TAU", a->tau, "tau of a resonant pair");
    s.add("SIGMA", a->sigma, "sigma of a resonant pair");
    s.add("--n", a->n, "any coupling n (decimal or fraction)");
    s.add("--n2", a->n2, "n^2 as a fraction (e.g. 1/12)");
    s.add("--tmax", a->tmax, what);
    image(s);
  };
  auto phase = sub.subcommand("phase", "Phase portrait (q, q') with envelope, inscribed and maximal circles");
  common(phase, "time span for a non-resonant n (default 200 pi/n, as the paper's Fig. 1)");
  auto energy = sub.subcommand("energy", "H_q(t) and H_z(t) with the exact first-hit time and the paper's proxy");
  common(energy, "time span (default: one period for a pair, 8 pi/n otherwise)");
  auto pareto = sub.subcommand("pareto", "Pareto front of (r_res, first-hit time)");
  pareto.add("--max-order", a->max_order, "pairs with tau + sigma <= M", show::required);
  pareto.add("--orientation", a->orientation, "absorb or contain", show::with_default);
  pareto.flag("--proxy", a->proxy, "use the paper's proxy pi/|n| as the time");
  pareto.flag("--exclude-degenerate", a->exclude_degenerate, "drop delta = 2 mod 4 pairs");
  image(pareto);
  return [a, phase, energy, pareto] {
    if (phase.parsed()) return run_phase(*a);
    if (energy.parsed()) return run_energy(*a);
    if (pareto.parsed()) return run_pareto_plot(*a);
    throw usage_error("plot needs one of: phase, energy, pareto");
  };
}

const command_registration registration{"plot", install_plot};

}  // namespace
}  // namespace gyrores::cli
