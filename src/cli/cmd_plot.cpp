// gyrores plot phase  TAU SIGMA | --n N | --n2 P/Q  [--tmax T] [--qdot0 V] [IMAGE OPTIONS]
// gyrores plot energy TAU SIGMA | --n N | --n2 P/Q  [--tmax T] [--qdot0 V] [IMAGE OPTIONS]
// gyrores plot pareto --max-order M [--orientation absorb|contain] [--proxy] [--exclude-degenerate]
//                     [IMAGE OPTIONS]
// IMAGE OPTIONS: [--out FILE.svg|png|pdf|eps] [--size WxH | 3.5in | 8.8cm | 3.5x2.5in] [--font-size PT]
// Each figure is written with its data (NAME.dat) and gnuplot script (NAME.gp) beside it; if
// gnuplot is missing the command says so and still writes both (exit 0). The data are the
// application layer's (include/gyrores/app/figures.hpp, app/pareto.hpp); frontend/plots.hpp draws.
#include <cstdio>
#include <sstream>

#include <gyrores/app/figures.hpp>
#include <gyrores/app/pareto.hpp>
#include <gyrores/model/inputs.hpp>

#include "cli_options.hpp"
#include "commands.hpp"
#include "frontend/plots.hpp"
#include "frontend/process.hpp"

namespace gyrores::cli {
namespace {

struct plot_args {
  std::string tau, sigma, n, n2, tmax, qdot0, out, size, font_size, orientation = "absorb";
  std::int64_t max_order = 0;
  bool proxy = false, exclude_degenerate = false;
};

// The subject: TAU SIGMA, --n N or --n2 P/Q (a resonant coupling is its pair).
app::figure_subject subject_of(const plot_args& a) {
  const bool have_pair = !a.tau.empty() || !a.sigma.empty();
  const int given = int(have_pair) + int(!a.n.empty()) + int(!a.n2.empty());
  if (given != 1) throw usage_error("give exactly one of TAU SIGMA, --n N or --n2 P/Q");
  if (!have_pair)
    return app::figure_subject_of(!a.n.empty() ? coupling_spec::from_n(parse_rational(a.n, "--n"))
                                               : coupling_spec::from_n2(parse_rational(a.n2, "--n2")));
  if (a.tau.empty() || a.sigma.empty()) throw usage_error("a pair needs both TAU and SIGMA");
  return app::figure_subject_of(parse_pair_arguments(a.tau, a.sigma));
}

// "n = N (not resonant)" or "n^2 = P/Q (not resonant)".
std::string coupling_label(const plot_args& a) { return (!a.n.empty() ? "n = " + a.n : "n^2 = " + a.n2) + " (not resonant)"; }

double tmax_of(const plot_args& a) {
  if (a.tmax.empty()) return 0;
  return parse_positive_flag(a.tmax, "--tmax").convert_to<double>();
}

// The impulse of --qdot0 (default 1): the figures' radii times qdot0, energies times qdot0^2, times
// unchanged (design/figures.hpp); the figures are drawn in doubles.
double qdot0_of(const plot_args& a) { return a.qdot0.empty() ? 1.0 : parse_qdot0(a.qdot0, "--qdot0").convert_to<double>(); }

// ", qdot0 = V" for a title when --qdot0 is given and not 1 (the titles at qdot0 = 1 as before).
std::string qdot0_title(const plot_args& a) { return qdot0_of(a) == 1.0 ? "" : ", qdot0 = " + a.qdot0; }

std::string files_text(const frontend::figure_output& f) {
  std::ostringstream os;
  for (auto& im : f.images) os << "figure: " << im.string() << "\n";
  os << "data:   " << f.data.string() << "\nscript: " << f.script.string() << "\n";
  if (!f.message.empty()) os << "note: " << f.message << "\n";
  return os.str();
}

// "(tau, sigma): " of a figure's title.
std::string pair_title(const resonant_pair<std::int64_t>& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%lld, %lld): ", (long long)p.tau(), (long long)p.sigma());
  return buf;
}

std::string run_phase(const plot_args& a) {
  const auto s = subject_of(a);
  const auto spec = frontend::figure_spec_from_out(a.out.empty() ? "phase.svg" : a.out, a.size, 1200, 640, a.font_size);
  if (s.pair && !a.tmax.empty()) throw usage_error("--tmax does not apply to a resonant pair (one full period is drawn)");
  const phase_portrait f = app::phase_figure(s, qdot0_of(a), tmax_of(a));
  char buf[200];
  if (s.pair)
    std::snprintf(buf, sizeof buf, "%sn = %.6g, r_res = %.6g%s", pair_title(*s.pair).c_str(), f.n, f.r_inscribed,
                  s.pair->degenerate() ? " (degenerate)" : "");
  else
    std::snprintf(buf, sizeof buf, "%s, t in [0, %.6g]; min radius on span %.4g", coupling_label(a).c_str(), f.t_span,
                  f.r_inscribed);
  return files_text(frontend::write_phase_figure(spec, f, buf + qdot0_title(a)));
}

std::string run_energy(const plot_args& a) {
  const auto s = subject_of(a);
  const auto spec = frontend::figure_spec_from_out(a.out.empty() ? "energy.svg" : a.out, a.size, 900, 500, a.font_size);
  const energy_series e = app::energy_figure(s, qdot0_of(a), tmax_of(a));
  if (!s.pair) return files_text(frontend::write_energy_figure(spec, e, coupling_label(a) + qdot0_title(a), "first min on span, t"));
  char buf[200];
  std::snprintf(buf, sizeof buf, "%sn = %.6g, H_q min = %.6g", pair_title(*s.pair).c_str(), e.n, e.h_min);
  return files_text(frontend::write_energy_figure(spec, e, buf + qdot0_title(a), "exact t_{first}"));
}

std::string run_pareto_plot(const plot_args& a) {
  app::pareto_request r;
  r.orientation = app::parse_pareto_orientation(a.orientation, "--orientation");
  const auto spec = frontend::figure_spec_from_out(a.out.empty() ? "pareto.svg" : a.out, a.size, 900, 640, a.font_size);
  check_max_order_flag(a.max_order);
  r.max_order = a.max_order;
  r.filter.exclude_degenerate = a.exclude_degenerate;
  r.time = a.proxy ? design_time::proxy : design_time::first_hit;
  r.values = false;
  r.progress = frontend::progress_stage;
  const app::pareto_outcome p = app::run_pareto(r);
  const std::string title = "Pareto front, tau+sigma <= " + std::to_string(a.max_order) + " (" +
                            frontend::pareto_orientation_caption(r.orientation) +
                            (a.exclude_degenerate ? ", degenerate pairs excluded" : "") + ")";
  const auto f = frontend::write_pareto_figure(spec, p.pairs, p.front, r.time, title);
  return std::to_string(p.front.size()) + " front points of " + std::to_string(p.pairs.size()) + " pairs\n" + files_text(f);
}

command_runner install_plot(CLI::App& app) {
  auto a = std::make_shared<plot_args>();
  auto sub = options(app).subcommand("plot", "Figures with gnuplot (SVG, PNG, PDF or EPS), data and script kept beside each");
  sub.require_subcommand();
  auto image = [&](const options& s) {
    s.add("--out", a->out, "output FILE.svg, .png, .pdf or .eps");
    add_size_option(s, a->size, a->font_size);
  };
  auto common = [&](const options& s, const char* what) {
    s.add("TAU", a->tau, "tau of a resonant pair");
    s.add("SIGMA", a->sigma, "sigma of a resonant pair");
    s.add("--n", a->n, "any coupling n (decimal or fraction)");
    s.add("--n2", a->n2, "n^2 as a fraction (e.g. 1/12)");
    s.add("--tmax", a->tmax, what);
    s.add("--qdot0", a->qdot0, "impulse amplitude qdot0 = q'(0) > 0 (exact decimal or fraction; default 1): radii times qdot0, energies times qdot0^2, times unchanged");
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
