// src/frontend/plots.hpp
#include "frontend/plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <sstream>

#include <gyrores/app/figures.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/io/files.hpp>

#include "frontend/gnuplot.hpp"
#include "frontend/process.hpp"
#include "frontend/ticks.hpp"

namespace gyrores::frontend {
namespace {

// Writes the data and script, then draws every image (a failure is reported, not thrown).
figure_output figure_finish(const figure_spec& s, const std::string& data, const std::string& script) {
  figure_output o;
  o.data = s.dir / (s.stem + ".dat");
  o.script = s.dir / (s.stem + ".gp");
  write_file_atomically(o.data, data);
  write_file_atomically(o.script, script);
  for (const auto& img : s.images) {
    progress_stage("drawing " + img + " with gnuplot");
    auto r = gnuplot_render(s.dir, s.stem + ".gp", img);
    if (r.rendered) o.images.push_back(s.dir / img);
    else if (o.message.empty()) o.message = r.message;
  }
  return o;
}

// The opening of every script: what it draws, how to redraw it, terminal and data file.
std::string script_head(const std::string& kind, const std::string& title, const figure_spec& s) {
  std::ostringstream g;
  g << "# gyrores " << kind << ": " << title << "\n"
    << "# Redraw: cd to this directory, then gnuplot -e \"outfile='" << s.stem << ".svg'\" " << s.stem << ".gp\n"
    << gnuplot_preamble(s.default_image(), s.width, s.height, s.inches_wide(), s.inches_high(), s.font()) << "datafile = " << gnuplot_string(s.stem + ".dat") << "\n";
  return g.str();
}

// A gnuplot font option: the figure's font size (gnuplot.hpp) plus `delta` points.
std::string font_of(const figure_spec& s, int delta) {
  return "font \"," + std::to_string(std::max(5, s.font() + delta)) + "\"";
}

void put_points(std::ostringstream& d, const std::vector<plane_point<double>>& pts) {
  for (const auto& p : pts) d << num(p.x) << " " << num(p.y) << "\n";
}

void circle_block(std::ostringstream& d, double r) {
  const double two_pi = 2 * real_pi<double>();
  for (int i = 0; i <= 720; ++i) {
    double a = two_pi * i / 720;
    d << num(r * std::cos(a)) << " " << num(r * std::sin(a)) << "\n";
  }
}

std::string phase_data(const phase_portrait& f, const std::string& title) {
  std::ostringstream d;
  d << "# gyrores phase portrait: " << title << "\n"
    << "# n = " << num(f.n) << ", qdot0 = " << num(f.qdot0) << ", t in [0, " << num(f.t_span) << "]\n"
    << "# index 0: trajectory (q, q')\n";
  put_points(d, f.trajectory);
  d << "\n\n# index 1: envelope x_d(phi), paper eq. (boundary)\n";
  put_points(d, f.envelope);
  d << "\n\n# index 2: inscribed circle, radius " << num(f.r_inscribed)
    << (f.inscribed_is_infimum ? " (r_res over all time)" : " (minimum radius over the plotted span)") << "\n";
  circle_block(d, f.r_inscribed);
  d << "\n\n# index 3: maximal circle, radius qdot0 = " << num(f.r_max) << " (H_q(0) = H)\n";
  circle_block(d, f.r_max);
  d << "\n\n# index 4: first minimiser (q, q') at t = " << num(f.t_first) << "\n"
    << num(f.first_min.x) << " " << num(f.first_min.y) << "\n";
  d << "\n\n# index 5: dense samples within one fast period of each minimiser (segments separated by a blank line)\n";
  for (const auto& seg : f.near_minimisers) {
    put_points(d, seg);
    d << "\n";
  }
  if (f.near_minimisers.empty()) d << num(f.first_min.x) << " " << num(f.first_min.y) << "\n";
  return d.str();
}

// The half-width of a square view holding the points: their largest |x| or |y|, 4% more.
double half_width_of(const std::vector<plane_point<double>>& pts, double at_least) {
  double r = at_least;
  for (const auto& p : pts) r = std::max(r, std::max(std::fabs(p.x), std::fabs(p.y)));
  return 1.04 * r;
}

std::string phase_script(const figure_spec& s, const phase_portrait& f, const std::string& title) {
  const double zoom = 3 * (f.r_inscribed > 0 ? f.r_inscribed : 0.02 * f.qdot0);
  const double whole = half_width_of(f.envelope, f.r_max);
  const auto main_ticks = linear_ticks(-whole, whole, 4), zoom_ticks = linear_ticks(-zoom, zoom, 3);
  std::ostringstream g;
  g << script_head("phase portrait", title, s) << "r_in = " << num(f.r_inscribed) << "\n"
    << "t_first = " << num(f.t_first) << "\n"
    << "zoom = " << num(zoom) << "\n"
    << "set multiplot layout 1,2 title " << gnuplot_string(title) << " noenhanced\n"
    << "set size ratio -1\n"
    << "set xlabel \"q\"\nset ylabel \"dq/dt\"\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "# Keys below the panels (outside the data), one entry per line (a wide key is dropped when it does not fit)\n"
    << "set key below box opaque maxcols 1 samplen 2 spacing 1 width -2\n"
    << "set bmargin (small ? 7 : 8)\n"
    << "# Ticks chosen by gyrores (frontend/ticks.hpp): at least three labelled on every axis\n"
    << "set xrange [" << num(-whole) << ":" << num(whole) << "]\nset yrange [" << num(-whole) << ":" << num(whole) << "]\n"
    << tics_command("x", main_ticks) << tics_command("y", main_ticks)
    << "set title (small ? \"whole motion\" : \"trajectory, envelope, maximal circle\")\n"
    << "set object 1 rect from -zoom,-zoom to zoom,zoom fs empty border lc rgb \"#444444\" dt 2\n"
    << "# The maximal circle is drawn last, dashed black over the envelope (they touch where the\n"
    << "# envelope reaches radius dq/dt(0)), so that it shows where both run together.\n"
    << "plot datafile index 0 with lines lc rgb \"#1f77b4\" lw 0.6 title \"trajectory\", \\\n"
    << "     '' index 1 with lines lc rgb \"#d62728\" lw 2.5 title \"envelope x_d({/Symbol f})\", \\\n"
    << "     '' index 3 with lines dt (5,4) lc rgb \"black\" lw 1.2 title (small ? \"maximal circle\" : \"maximal circle (r = dq/dt(0))\")\n"
    << "unset object 1\n"
    << "set title sprintf(\"zoom: |q|, |dq/dt| <= %.3g\", zoom)\n"
    << "set xrange [-zoom:zoom]\nset yrange [-zoom:zoom]\n"
    << tics_command("x", zoom_ticks) << tics_command("y", zoom_ticks)
    << "plot datafile index 0 with lines lc rgb \"#1f77b4\" lw 0.6 notitle, \\\n"
    << "     '' index 5 with lines lc rgb \"#1f77b4\" lw 1.2 title \"trajectory near the minimisers\", \\\n";
  if (f.r_inscribed > 0)
    g << "     '' index 2 with lines dt 2 lc rgb \"black\" lw 1.6 title sprintf(\""
      << (f.inscribed_is_infimum ? "inscribed r_{res}" : "min radius on the span") << " = %.4g\", r_in), \\\n";
  else
    g << "     '' index 4 using (0):(0) with points pt 6 ps 2.5 lc rgb \"black\" title \"r_{res} = 0 (degenerate)\", \\\n";
  g << "     '' index 4 with points pt 7 ps 1.6 lc rgb \"#2ca02c\" title sprintf(\"first minimum, t = %.5g\", t_first)\n"
    << "unset multiplot\n";
  return g.str();
}

// Pareto data: every pair with r_res > 0, the degenerate pairs, the front, labelled front points.
std::string pareto_data(const app::pareto_figure_points& f, design_time which, const std::string& title) {
  const std::string tname = which == design_time::first_hit ? "t_first" : "pi/n";
  std::ostringstream d;
  auto rows = [&](const std::vector<design_point>& pts, const char* none) {
    for (const auto& p : pts) d << num(design_time_of(p, which)) << " " << num(p.r_res) << " " << p.tau << " " << p.sigma << "\n";
    if (pts.empty()) d << none;
  };
  d << "# gyrores Pareto front: " << title << "\n";
  if (f.pairs > app::pareto_thin_above)
    d << "# thinned: " << f.positive.size() + f.zeros.size() << " of " << f.pairs
      << " pairs drawn, one per cell of 2x2 pixels in log coordinates (the front is complete)\n";
  d << "# index 0: pairs with r_res > 0: " << tname << " r_res tau sigma\n";
  rows(f.positive, "NaN NaN 0 0\n");
  d << "\n\n# index 1: degenerate pairs (r_res = 0 exactly): " << tname << " r_res tau sigma\n";
  for (const auto& p : f.zeros) d << num(design_time_of(p, which)) << " 0 " << p.tau << " " << p.sigma << "\n";
  if (f.zeros.empty()) d << "NaN NaN 0 0\n";
  d << "\n\n# index 2: the front (r_res > 0): " << tname << " r_res tau sigma\n";
  rows(f.front_positive, "NaN NaN 0 0\n");
  d << "\n\n# index 3: labelled front points (ends, and steps of half a decade in r_res): " << tname << " r_res label\n";
  for (const auto& p : f.labelled)
    d << num(design_time_of(p, which)) << " " << num(p.r_res) << " \"(" << p.tau << "," << p.sigma << ")\"\n";
  if (f.labelled.empty()) d << "NaN NaN \"\"\n";
  d << "\n\n# index 4: front pairs with r_res = 0: " << tname << " r_res tau sigma\n";
  rows(f.front_zeros, "NaN NaN 0 0\n");
  return d.str();
}

// The front's own ranges [t0, t1] x [r0, r1] (r_res > 0); false when it has fewer than two
// distinct points there.
bool front_ranges(const std::vector<design_point>& front, design_time which, double& t0, double& t1, double& r0, double& r1) {
  t0 = 1e300, t1 = 0, r0 = 1e300, r1 = 0;
  for (const auto& p : front) {
    const double t = design_time_of(p, which);
    t0 = std::min(t0, t), t1 = std::max(t1, t), r0 = std::min(r0, p.r_res), r1 = std::max(r1, p.r_res);
  }
  return front.size() >= 2 && t1 > t0 && r1 > r0;
}

// A panel of its own on the front alone, right of the main panels: on the whole time axis the
// front is a sliver at its left end (the fastest pairs), so it gets its own axes over its own
// time and r_res ranges. (An inset inside the main panel hid the pairs under it.)
std::string pareto_front_panel(const figure_spec& s, const std::vector<design_point>& front, design_time which, double split) {
  double t0, t1, r0, r1;
  if (!front_ranges(front, which, t0, t1, r0, r1)) return "";
  const double pad_t = 0.05 * (t1 - t0), x_lo = t0 - pad_t, x_hi = t1 + pad_t;
  const double y_lo = r0 / std::pow(r1 / r0, 0.05), y_hi = r1 * std::pow(r1 / r0, 0.05);
  std::ostringstream g;
  g << "# right panel: the front alone, over its own ranges (linear time)\n"
    << "set origin " << num(split) << ", 0\nset size " << num(1 - split) << ", 0.93\n"
    << "set lmargin (small ? 8 : 10)\nset rmargin (small ? 1 : 2)\nset tmargin 2\nset bmargin 3\n"
    << "unset logscale x\nset logscale y\n"
    << "set xrange [" << num(x_lo) << ":" << num(x_hi) << "]\nset yrange [" << num(y_lo) << ":" << num(y_hi) << "]\n"
    << "set format x \"%g\"\n"
    << tics_command("x", linear_ticks(x_lo, x_hi, 3)) << tics_command("y", log_ticks(y_lo, y_hi))
    << "set title \"the front, zoomed\" " << font_of(s, 0) << "\n"
    << "set xlabel " << gnuplot_string(which == design_time::first_hit ? "t_{first}" : "{/Symbol p}/n") << "\n"
    << "unset ylabel\nunset key\n"
    << "plot datafile index 2 using 1:2 with linespoints pt 7 ps 0.5 lw 1.2 lc rgb \"#d62728\" notitle\n";
  return g.str();
}

// Two panels sharing the time axis: r_res > 0 on a log axis above, and the pairs with r_res = 0
// on a strip of their own below it (a log axis has no 0: no stand-in floor value is drawn); the
// front zoomed on a panel of its own at the right; the key above the upper panel, off the data.
std::string pareto_script(const figure_spec& s, const app::pareto_figure_points& f, design_time which,
                          const std::string& title) {
  double t0 = f.t_lo, t1 = f.t_hi;
  if (!(t1 > t0)) t0 = t0 / 2, t1 = t1 * 2 + 1;
  const double tlo = t0 / 1.15, thi = t1 * 1.15;
  double r_lo = 1e300, r_hi = 0;
  for (const auto* pts : {&f.positive, &f.front_positive})
    for (const auto& p : *pts) r_lo = std::min(r_lo, p.r_res), r_hi = std::max(r_hi, p.r_res);
  if (!(r_hi > 0)) r_lo = 1e-3, r_hi = 1;
  if (!(r_hi > r_lo)) r_lo /= 10, r_hi *= 10;
  r_lo /= 2, r_hi *= 2;
  double ft0, ft1, fr0, fr1;
  const bool side = front_ranges(f.front_positive, which, ft0, ft1, fr0, fr1);
  const double split = side ? 0.64 : 1.0;
  const std::string thinned = f.pairs > app::pareto_thin_above
                                  ? " (" + std::to_string(f.pairs) + " pairs, thinned to one per 2x2 pixels)"
                                  : "";
  const auto time_ticks = log_ticks(tlo, thi);
  std::ostringstream g;
  g << script_head("Pareto front", title, s)
    << "set multiplot title " << gnuplot_string(title + thinned) << " noenhanced\n"
    << "tlo = " << num(tlo) << "\nthi = " << num(thi) << "   # the time axis both left panels share\n"
    << "set logscale x\nset xrange [tlo:thi]\n"
    << "set lmargin (small ? 9 : 11)\nset rmargin (small ? 1 : 2)\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "# Ticks chosen by gyrores (frontend/ticks.hpp): at least three labelled on every axis\n"
    << "# upper panel: r_res > 0 (its time ticks unlabelled: the strip below carries them)\n"
    << "set origin 0, 0.27\nset size " << num(split) << ", 0.66\n"
    << "set bmargin 0\n"
    << tics_command("x", time_ticks, false)
    << "set logscale y\nset yrange [" << num(r_lo) << ":" << num(r_hi) << "]\n"
    << tics_command("y", log_ticks(r_lo, r_hi))
    << "set ylabel \"r_{res} (dq/dt(0) = 1)\"\n"
    << "# The key above the panel, off the data\n"
    << "set key above horizontal samplen 1 " << font_of(s, -1) << "\n"
    << "plot datafile index 0 using 1:2 with points pt 7 ps 0.35 lc rgb \"#999999\" title \"resonant pairs\", \\\n"
    << "     '' index 2 using 1:2 with linespoints pt 7 ps 0.8 lw 1.5 lc rgb \"#d62728\" title \"Pareto front\", \\\n"
    << "     '' index 3 using 1:2:3 with labels left offset 0.6,0.6 " << font_of(s, -2) << " notitle\n"
    << "# lower panel: the pairs with r_res = 0 exactly (delta = 2 mod 4)\n"
    << "set origin 0, 0\nset size " << num(split) << ", 0.27\n"
    << "set tmargin 0.3\nset bmargin 3\nunset logscale y\nset yrange [-1:1]\nunset ytics\n"
    << tics_command("x", time_ticks)
    << "set ylabel \"r_{res} = 0\"\n"
    << "set xlabel " << gnuplot_string(which == design_time::first_hit ? "exact first-hit time t_{first}" : "paper proxy {/Symbol p}/n") << "\n"
    << "unset key\n"
    << "plot datafile index 1 using 1:(0) with points pt 2 ps 0.5 lc rgb \"#8c564b\" title \"r_{res} = 0\", \\\n"
    << "     '' index 4 using 1:(0) with points pt 7 ps 1.0 lc rgb \"#d62728\" notitle\n"
    << "set ytics\n"
    << pareto_front_panel(s, f.front_positive, which, split)
    << "unset multiplot\n";
  return g.str();
}

}  // namespace

int figure_spec::font() const { return font_pt > 0 ? font_pt : figure_font_size(width); }

void apply_figure_size(figure_spec& s, const std::string& size, int default_w, int default_h) {
  s.width = default_w, s.height = default_h, s.width_in = 0, s.height_in = 0;
  if (size.empty()) return;
  const auto bad = [&]() {
    return usage_error("--size must be WxH in pixels (100..10000, 100 per inch) or a size in inches or centimetres "
                       "(3.5in, 8.8cm, 3.5x2.5in, 8.8cmx6cm; 1 to 100 inches), got '" + size + "'");
  };
  static const std::regex pixels(R"(([0-9]+)[xX]([0-9]+))");
  static const std::regex physical(R"(([0-9]*\.?[0-9]+)(in|cm)?(?:[xX]([0-9]*\.?[0-9]+)(in|cm)?)?)");
  std::smatch m;
  if (std::regex_match(size, m, pixels)) {
    if (m[1].length() > 5 || m[2].length() > 5) throw bad();
    const int w = std::stoi(m[1]), h = std::stoi(m[2]);
    if (w < 100 || h < 100 || w > 10000 || h > 10000) throw bad();
    s.width = w, s.height = h;
    return;
  }
  if (!std::regex_match(size, m, physical) || (!m[2].matched && !m[4].matched)) throw bad();
  if (m[2].matched && m[4].matched && m[2] != m[4]) throw bad();  // 3in x 8cm: one unit, please
  if (!m[3].matched && !m[2].matched) throw bad();
  const double per_inch = (m[2].matched ? m[2].str() : m[4].str()) == "cm" ? 2.54 : 1.0;
  const double w = std::stod(m[1]) / per_inch;
  const double h = m[3].matched ? std::stod(m[3]) / per_inch : w * default_h / default_w;
  if (!(w >= 1 && h >= 1 && w <= 100 && h <= 100)) throw bad();
  s.width_in = w, s.height_in = h;
  s.width = int(std::lround(w * 100)), s.height = int(std::lround(h * 100));
}

int parse_font_size(const std::string& text) {
  if (text.empty()) return 0;
  static const std::regex integer("[0-9]{1,2}");
  if (!std::regex_match(text, integer) || std::stoi(text) < 5 || std::stoi(text) > 30)
    throw usage_error("--font-size must be a whole number of points from 5 to 30, got '" + text + "'");
  return std::stoi(text);
}

figure_spec figure_spec_from_out(const fs::path& out, const std::string& size, int default_w, int default_h,
                                 const std::string& font_size) {
  image_format_of(out);
  figure_spec s;
  s.dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  s.stem = out.stem().string();
  if (s.stem.empty()) throw usage_error("--out needs a file name, got '" + out.string() + "'");
  s.images = {out.filename().string()};
  apply_figure_size(s, size, default_w, default_h);
  s.font_pt = parse_font_size(font_size);
  ensure_directory(s.dir);
  check_figure_outputs(s);
  return s;
}

void check_figure_outputs(const figure_spec& s, const std::vector<named_path>& more) {
  std::vector<named_path> paths{{"the figure's data", (s.dir / (s.stem + ".dat")).string()},
                                {"the figure's script", (s.dir / (s.stem + ".gp")).string()}};
  for (const auto& img : s.images) paths.push_back({"the figure", (s.dir / img).string()});
  paths.insert(paths.end(), more.begin(), more.end());
  check_distinct_paths(paths);
  for (const auto& p : paths) check_output_path(p.path);
}

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

figure_output write_phase_figure(const figure_spec& s, const phase_portrait& f, const std::string& title) {
  return figure_finish(s, phase_data(f, title), phase_script(s, f, title));
}

figure_output write_energy_figure(const figure_spec& s, const energy_series& e, const std::string& title,
                                  const std::string& first_label) {
  std::ostringstream d;
  d << "# gyrores energy exchange: " << title << "\n"
    << "# index 0: t H_q H_z (uniform samples, refined around every marked minimum: design/figures.hpp)\n";
  for (const auto& p : e.samples) d << num(p.t) << " " << num(p.h_q) << " " << num(p.h_z) << "\n";
  d << "\n\n# index 1: first minimum of H_q: t H_q\n" << num(e.t_first) << " " << num(e.h_min) << "\n";
  d << "\n\n# index 2: the same minimum of H_q at its other times in the span: t H_q\n";
  bool others = false;
  for (double t : e.t_minima)
    if (t != e.t_first) d << num(t) << " " << num(e.h_min) << "\n", others = true;
  if (!others) d << "NaN NaN\n";
  // The lower panel: H_q on a log axis in a window around its minimum, where a linear axis shows
  // nothing (min H_q of (6, 5) is 0.26% of H). Zero (a degenerate pair) has no log: the panel
  // then shows H_q from 1e-6 H.
  const double window = std::max(e.t_end / 12, 2 * std::fabs(e.t_proxy - e.t_first));
  const double lo_t = std::max(0.0, e.t_first - window), hi_t = std::min(e.t_end, e.t_first + window);
  double hq_max = 0;
  for (const auto& p : e.samples)
    if (p.t >= lo_t && p.t <= hi_t) hq_max = std::max(hq_max, p.h_q);
  const double H = e.qdot0 * e.qdot0 / 2;
  const double y_lo = e.h_min > 0 ? e.h_min / 4 : 1e-6 * H;
  const double y_hi = hq_max > y_lo ? 2 * hq_max : 10 * y_lo;
  std::ostringstream g;
  g << script_head("energy exchange", title, s)
    << "t_first = " << num(e.t_first) << "\nt_proxy = " << num(e.t_proxy) << "\nh_min = " << num(e.h_min) << "\n"
    << "set multiplot layout 2,1 title " << gnuplot_string(title) << " noenhanced\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "set lmargin (small ? 9 : 11)\nset rmargin (small ? 2 : 3)\n"
    << "# Keys above the panels, outside the data (every curve and mark stays visible)\n"
    << "set key above horizontal samplen 2 " << font_of(s, -1) << "\n"
    << "set ylabel \"energy\"\n"
    << "set xrange [0:" << num(e.t_end) << "]\nset yrange [0:" << num(H) << "]\n"
    << "# Ticks chosen by gyrores (frontend/ticks.hpp): at least three labelled on every axis\n"
    << tics_command("x", linear_ticks(0, e.t_end)) << tics_command("y", linear_ticks(0, H))
    << "set arrow 1 from t_first, graph 0 to t_first, graph 1 nohead dt 2 lw 1.5 lc rgb \"black\"\n"
    << "set arrow 2 from t_proxy, graph 0 to t_proxy, graph 1 nohead dt 4 lw 1.5 lc rgb \"#9467bd\"\n"
    << "plot datafile index 0 using 1:2 with lines lc rgb \"#1f77b4\" lw 1.2 title \"H_q\", \\\n"
    << "     '' index 0 using 1:3 with lines lc rgb \"#ff7f0e\" lw 1.2 title \"H_z\", \\\n"
    << "     NaN with lines dt 2 lw 1.5 lc rgb \"black\" title sprintf(\"" << first_label << " = %.5g\", t_first), \\\n"
    << "     NaN with lines dt 4 lw 1.5 lc rgb \"#9467bd\" title sprintf(\"proxy {/Symbol p}/n = %.5g\", t_proxy)\n"
    << "set title (small ? \"H_q near its minimum (log)\" : \"H_q near its minimum (log axis)\") " << font_of(s, 0) << "\n"
    << "set xlabel \"t\"\n"
    << "set logscale y\n"
    << "set xrange [" << num(lo_t) << ":" << num(hi_t) << "]\n"
    << "set yrange [" << num(y_lo) << ":" << num(y_hi) << "]\n"
    << tics_command("x", linear_ticks(lo_t, hi_t)) << tics_command("y", log_ticks(y_lo, y_hi))
    << "plot datafile index 0 using 1:($2 > 0 ? $2 : NaN) with lines lc rgb \"#1f77b4\" lw 1.2 notitle, \\\n"
    << "     '' index 1 using 1:($2 > 0 ? $2 : " << num(y_lo) << ") with points pt 7 ps 1.2 lc rgb \"#2ca02c\" "
    << "title sprintf(\"min H_q = %.4g\", h_min)";
  if (others)
    g << ", \\\n     '' index 2 using 1:($2 > 0 ? $2 : " << num(y_lo) << ") with points pt 6 ps 1.2 lw 1.5 lc rgb \"#2ca02c\" "
      << "title \"the same minimum, again\"";
  g << "\nunset multiplot\n";
  return figure_finish(s, d.str(), g.str());
}

figure_output write_pareto_figure(const figure_spec& s, const std::vector<design_point>& all,
                                  const std::vector<design_point>& front, design_time which,
                                  const std::string& title) {
  const auto points = app::pareto_figure_points_of(all, front, which, s.width, s.height);
  return figure_finish(s, pareto_data(points, which, title), pareto_script(s, points, which, title));
}

std::string figure_script_head(const std::string& kind, const std::string& title, const figure_spec& s) {
  return script_head(kind, title, s);
}

figure_output write_figure_files(const figure_spec& s, const std::string& data, const std::string& script) {
  return figure_finish(s, data, script);
}

std::string pareto_orientation_caption(pareto_orientation o) {
  return o == pareto_orientation::absorb ? "absorb: min r_res, min time" : "contain: max r_res, min time";
}

}  // namespace gyrores::frontend
