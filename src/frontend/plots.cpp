// src/frontend/plots.hpp
#include "frontend/plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <gyrores/app/figures.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/io/files.hpp>

#include "frontend/gnuplot.hpp"
#include "frontend/process.hpp"

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
    << gnuplot_preamble(s.default_image(), s.width, s.height) << "datafile = " << gnuplot_string(s.stem + ".dat") << "\n";
  return g.str();
}

// A gnuplot font option: the figure's font size (gnuplot.hpp) plus `delta` points.
std::string font_of(const figure_spec& s, int delta) {
  return "font \"," + std::to_string(figure_font_size(s.width) + delta) + "\"";
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

std::string phase_script(const figure_spec& s, const phase_portrait& f, const std::string& title) {
  const double zoom = 3 * (f.r_inscribed > 0 ? f.r_inscribed : 0.02 * f.qdot0);
  std::ostringstream g;
  g << script_head("phase portrait", title, s) << "r_in = " << num(f.r_inscribed) << "\n"
    << "t_first = " << num(f.t_first) << "\n"
    << "zoom = " << num(zoom) << "\n"
    << "set multiplot layout 1,2 title " << gnuplot_string(title) << " noenhanced\n"
    << "set size ratio -1\n"
    << "set xlabel \"q\"\nset ylabel \"dq/dt\"\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "# Keys below the panels, one entry per line (a wide key is dropped when it does not fit)\n"
    << "set key below box opaque maxcols 1 samplen 2 spacing 1 width -2\n"
    << "set bmargin (small ? 7 : 8)\n"
    << "set xtics (small ? 1 : 0.5)\nset ytics (small ? 1 : 0.5)\n"
    << "set title (small ? \"whole motion\" : \"trajectory, envelope, maximal circle\")\n"
    << "set object 1 rect from -zoom,-zoom to zoom,zoom fs empty border lc rgb \"#444444\" dt 2\n"
    << "plot datafile index 0 with lines lc rgb \"#1f77b4\" lw 0.6 title \"trajectory\", \\\n"
    << "     '' index 1 with lines lc rgb \"#d62728\" lw 2 title \"envelope x_d({/Symbol f})\", \\\n"
    << "     '' index 3 with lines dt 3 lc rgb \"#555555\" lw 1.6 title (small ? \"maximal circle\" : \"maximal circle (r = dq/dt(0))\")\n"
    << "unset object 1\n"
    << "set title sprintf(\"zoom: |q|, |dq/dt| <= %.3g\", zoom)\n"
    << "set xrange [-zoom:zoom]\nset yrange [-zoom:zoom]\n"
    << "set xtics zoom/(small ? 1 : 2)\nset ytics zoom/(small ? 1 : 2)\nset format xy \"%.2g\"\n"
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

// An inset on the front alone: on the whole time axis the front is a sliver at its left end
// (the fastest pairs), so it gets its own axes, over its own time and r_res ranges, at the lower
// right of the upper panel. Empty when the front has fewer than two pairs with r_res > 0.
std::string pareto_inset(const figure_spec& s, const std::vector<design_point>& front, design_time which) {
  double t0 = 1e300, t1 = 0, r0 = 1e300, r1 = 0;
  for (const auto& p : front) {
    const double t = design_time_of(p, which);
    t0 = std::min(t0, t), t1 = std::max(t1, t), r0 = std::min(r0, p.r_res), r1 = std::max(r1, p.r_res);
  }
  if (front.size() < 2 || !(t1 > t0) || !(r1 > r0)) return "";
  std::ostringstream g;
  g << "# inset: the front alone, over its own ranges\n"
    << "set origin 0.55, 0.31\nset size 0.43, (small ? 0.3 : 0.32)\n"
    << "set lmargin (small ? 6 : 8)\nset rmargin 0.5\nset tmargin 0.5\nset bmargin 1.5\n"
    << "set object 9 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb \"white\" fillstyle solid 1.0 border lc rgb \"#444444\"\n"
    << "set xrange [" << num(t0 / std::pow(t1 / t0, 0.05)) << ":" << num(t1 * std::pow(t1 / t0, 0.05)) << "]\n"
    << "set yrange [" << num(r0 / std::pow(r1 / r0, 0.05)) << ":" << num(r1 * std::pow(r1 / r0, 0.05)) << "]\n"
    << "set format x \"%.3g\"\nset xtics " << font_of(s, -3) << "\nset ytics " << font_of(s, -3) << "\n"
    << "set xtics (" << num(t0) << ", " << num(t1) << ")\n"
    << "set ytics 100\nset mytics 1\nunset ylabel\nunset key\n"
    << "set label 9 \"front, zoomed\" at graph 0.97, graph 0.9 right " << font_of(s, -2) << "\n"
    << "plot datafile index 2 using 1:2 with linespoints pt 7 ps 0.5 lw 1.2 lc rgb \"#d62728\" notitle\n"
    << "unset label 9\nunset object 9\nset xtics autofreq " << font_of(s, 0) << "\nset ytics autofreq " << font_of(s, 0) << "\nset lmargin (small ? 9 : 11)\nset rmargin (small ? 2 : 3)\n"
    << "set xrange [tlo:thi]\nset yrange [*:*]\n";
  return g.str();
}

// Two panels sharing the time axis: r_res > 0 on a log axis above, and the pairs with r_res = 0
// on a strip of their own below it (a log axis has no 0: no stand-in floor value is drawn).
std::string pareto_script(const figure_spec& s, const app::pareto_figure_points& f, design_time which,
                          const std::string& title) {
  double t0 = f.t_lo, t1 = f.t_hi;
  if (!(t1 > t0)) t0 = t0 / 2, t1 = t1 * 2 + 1;
  const std::string thinned = f.pairs > app::pareto_thin_above
                                  ? " (" + std::to_string(f.pairs) + " pairs, thinned to one per 2x2 pixels)"
                                  : "";
  std::ostringstream g;
  g << script_head("Pareto front", title, s)
    << "set multiplot title " << gnuplot_string(title + thinned) << " noenhanced\n"
    << "tlo = " << num(t0 / 1.15) << "\nthi = " << num(t1 * 1.15) << "   # the time axis both panels share\n"
    << "set logscale x\nset xrange [tlo:thi]\n"
    << "set lmargin (small ? 9 : 11)\nset rmargin (small ? 2 : 3)\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "# upper panel: r_res > 0\n"
    << "set origin 0, 0.27\nset size 1, (small ? 0.63 : 0.66)\n"
    << "set bmargin 0\nset tmargin 0.5\nset format x \"\"\n"
    << "set logscale y\nset format y \"10^{%L}\"\n"
    << "set ylabel \"r_{res} (dq/dt(0) = 1)\"\n"
    << "set key top right maxrows 2 samplen 1 box opaque " << font_of(s, -1) << "\n"
    << "plot datafile index 0 using 1:2 with points pt 7 ps 0.35 lc rgb \"#999999\" title \"resonant pairs\", \\\n"
    << "     '' index 2 using 1:2 with linespoints pt 7 ps 0.8 lw 1.5 lc rgb \"#d62728\" title \"Pareto front\", \\\n"
    << "     '' index 3 using 1:2:3 with labels left offset 0.6,0.6 " << font_of(s, -2) << " notitle\n"
    << pareto_inset(s, f.front_positive, which)
    << "# lower panel: the pairs with r_res = 0 exactly (delta = 2 mod 4)\n"
    << "set origin 0, 0\nset size 1, 0.27\n"
    << "set tmargin 0.3\nset bmargin 3\nunset logscale y\nset yrange [-1:1]\nunset ytics\n"
    << "set format x \"10^{%L}\"\n"
    << "set ylabel \"r_{res} = 0\"\n"
    << "set xlabel " << gnuplot_string(which == design_time::first_hit ? "exact first-hit time t_{first}" : "paper proxy {/Symbol p}/n") << "\n"
    << "unset key\n"
    << "plot datafile index 1 using 1:(0) with points pt 2 ps 0.5 lc rgb \"#8c564b\" title \"r_{res} = 0\", \\\n"
    << "     '' index 4 using 1:(0) with points pt 7 ps 1.0 lc rgb \"#d62728\" notitle\n"
    << "unset multiplot\n";
  return g.str();
}

}  // namespace

figure_spec figure_spec_from_out(const fs::path& out, const std::string& size, int default_w, int default_h) {
  image_format_of(out);
  figure_spec s;
  s.dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  s.stem = out.stem().string();
  if (s.stem.empty()) throw usage_error("--out needs a file name, got '" + out.string() + "'");
  s.images = {out.filename().string()};
  s.width = default_w;
  s.height = default_h;
  if (!size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 100 || h < 100 ||
        w > 10000 || h > 10000)
      throw usage_error("--size must be WxH with 100 <= W, H <= 10000, got '" + size + "'");
    s.width = w;
    s.height = h;
  }
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
  d << "# gyrores energy exchange: " << title << "\n# index 0: t H_q H_z\n";
  for (const auto& p : e.samples) d << num(p.t) << " " << num(p.h_q) << " " << num(p.h_z) << "\n";
  d << "\n\n# index 1: first minimum of H_q: t H_q\n" << num(e.t_first) << " " << num(e.h_min) << "\n";
  // The lower panel: H_q on a log axis in a window around its minimum, where a linear axis shows
  // nothing (min H_q of (6, 5) is 0.26% of H). Zero (a degenerate pair) has no log: the panel
  // then shows H_q from 1e-6 H.
  const double window = std::max(e.t_end / 12, 2 * std::fabs(e.t_proxy - e.t_first));
  const double lo_t = std::max(0.0, e.t_first - window), hi_t = std::min(e.t_end, e.t_first + window);
  double hq_max = 0;
  for (const auto& p : e.samples)
    if (p.t >= lo_t && p.t <= hi_t) hq_max = std::max(hq_max, p.h_q);
  const double y_lo = e.h_min > 0 ? e.h_min / 4 : 1e-6 * (e.qdot0 * e.qdot0 / 2);
  std::ostringstream g;
  g << script_head("energy exchange", title, s)
    << "t_first = " << num(e.t_first) << "\nt_proxy = " << num(e.t_proxy) << "\nh_min = " << num(e.h_min) << "\n"
    << "set multiplot layout 2,1 title " << gnuplot_string(title) << " noenhanced\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "set lmargin (small ? 9 : 11)\nset rmargin (small ? 2 : 3)\n"
    << "set key top right horizontal maxrows 1 samplen 2 box opaque " << font_of(s, -1) << "\n"
    << "set ylabel \"energy\"\n"
    << "set xrange [0:" << num(e.t_end) << "]\nset yrange [0:*]\n"
    << "set arrow 1 from t_first, graph 0 to t_first, graph 1 nohead dt 2 lw 1.5 lc rgb \"black\"\n"
    << "set arrow 2 from t_proxy, graph 0 to t_proxy, graph 1 nohead dt 4 lw 1.5 lc rgb \"#9467bd\"\n"
    << "plot datafile index 0 using 1:2 with lines lc rgb \"#1f77b4\" lw 1.2 title \"H_q\", \\\n"
    << "     '' index 0 using 1:3 with lines lc rgb \"#ff7f0e\" lw 1.2 title \"H_z\"\n"
    << "set title (small ? \"H_q near its minimum (log)\" : \"H_q near its minimum (log axis)\") " << font_of(s, 0) << "\n"
    << "set xlabel \"t\"\n"
    << "set logscale y\nset format y \"10^{%L}\"\n"
    << "set xrange [" << num(lo_t) << ":" << num(hi_t) << "]\n"
    << "set yrange [" << num(y_lo) << ":" << num(hq_max > y_lo ? 2 * hq_max : 10 * y_lo) << "]\n"
    << "set key bottom right vertical maxrows 3 box opaque\n"
    << "plot datafile index 0 using 1:($2 > 0 ? $2 : NaN) with lines lc rgb \"#1f77b4\" lw 1.2 notitle, \\\n"
    << "     '' index 1 using 1:($2 > 0 ? $2 : " << num(y_lo) << ") with points pt 7 ps 1.2 lc rgb \"#2ca02c\" "
    << "title sprintf(\"min H_q = %.4g\", h_min), \\\n"
    << "     NaN with lines dt 2 lw 1.5 lc rgb \"black\" title sprintf(\"" << first_label << " = %.5g\", t_first), \\\n"
    << "     NaN with lines dt 4 lw 1.5 lc rgb \"#9467bd\" title sprintf(\"proxy {/Symbol p}/n = %.5g\", t_proxy)\n"
    << "unset multiplot\n";
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
