// src/cli/plots.hpp
#include "plots.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/io/files.hpp>

#include "gnuplot.hpp"

namespace gyrores::cli {
namespace {

// Writes the data and script, then draws every image (a failure is reported, not thrown).
figure_output figure_finish(const figure_spec& s, const std::string& data, const std::string& script) {
  figure_output o;
  o.data = s.dir / (s.stem + ".dat");
  o.script = s.dir / (s.stem + ".gp");
  write_file_atomically(o.data, data);
  write_file_atomically(o.script, script);
  for (const auto& img : s.images) {
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
    << "set xlabel \"q\"\nset ylabel \"dq/dt\"\nset bmargin 8\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "set key below box opaque maxrows 3 width -2\n"
    << "set title \"trajectory, envelope, maximal circle\"\n"
    << "set object 1 rect from -zoom,-zoom to zoom,zoom fs empty border lc rgb \"#444444\" dt 2\n"
    << "plot datafile index 0 with lines lc rgb \"#1f77b4\" lw 0.6 title \"trajectory\", \\\n"
    << "     '' index 1 with lines lc rgb \"#d62728\" lw 2 title \"envelope x_d({/Symbol f})\", \\\n"
    << "     '' index 3 with lines dt 3 lc rgb \"#555555\" lw 1.6 title \"maximal circle (r = dq/dt(0))\"\n"
    << "unset object 1\n"
    << "set title sprintf(\"zoom: |q|, |dq/dt| <= %.3g\", zoom)\n"
    << "set xrange [-zoom:zoom]\nset yrange [-zoom:zoom]\n"
    << "set xtics zoom/2\nset ytics zoom/2\nset format xy \"%.2g\"\n"
    << "plot datafile index 0 with lines lc rgb \"#1f77b4\" lw 0.6 notitle, \\\n"
    << "     '' index 5 with lines lc rgb \"#1f77b4\" lw 1.2 title \"trajectory near the minimisers\", \\\n";
  if (f.r_inscribed > 0)
    g << "     '' index 2 with lines dt 2 lc rgb \"black\" lw 1.6 title sprintf(\""
      << (f.inscribed_is_infimum ? "inscribed circle r_{res}" : "min radius on the span") << " = %.4g\", r_in), \\\n";
  else
    g << "     '' index 4 using (0):(0) with points pt 6 ps 2.5 lc rgb \"black\" title \"r_{res} = 0 (degenerate)\", \\\n";
  g << "     '' index 4 with points pt 7 ps 1.6 lc rgb \"#2ca02c\" title sprintf(\"first minimiser, t = %.5g\", t_first)\n"
    << "unset multiplot\n";
  return g.str();
}

// Pareto data: every pair with r_res > 0, the degenerate pairs, the front, labelled front points.
std::string pareto_data(const std::vector<design_point>& all, const std::vector<design_point>& front, design_time which,
                        const std::string& title) {
  const std::string tname = which == design_time::first_hit ? "t_first" : "pi/n";
  auto row = [&](std::ostringstream& d, const design_point& p) {
    d << num(design_time_of(p, which)) << " " << num(p.r_res) << " " << p.tau << " " << p.sigma << "\n";
  };
  std::ostringstream d;
  d << "# gyrores Pareto front: " << title << "\n# index 0: every pair with r_res > 0: " << tname << " r_res tau sigma\n";
  for (const auto& p : all)
    if (p.r_res > 0) row(d, p);
  d << "\n\n# index 1: degenerate pairs (r_res = 0 exactly): " << tname << " r_res tau sigma\n";
  bool any_deg = false;
  for (const auto& p : all)
    if (p.r_res == 0) {
      d << num(design_time_of(p, which)) << " 0 " << p.tau << " " << p.sigma << "\n";
      any_deg = true;
    }
  if (!any_deg) d << "NaN NaN 0 0\n";
  d << "\n\n# index 2: the front: " << tname << " r_res tau sigma\n";
  for (const auto& p : front) row(d, p);
  d << "\n\n# index 3: labelled front points (ends, and steps of half a decade in r_res): " << tname << " r_res label\n";
  double last = 0;
  for (std::size_t i = 0; i < front.size(); ++i) {
    double lr = front[i].r_res > 0 ? std::log10(front[i].r_res) : -99;
    if (i == 0 || i + 1 == front.size() || std::fabs(lr - last) >= 0.5) {
      d << num(design_time_of(front[i], which)) << " " << num(front[i].r_res) << " \"(" << front[i].tau << ","
        << front[i].sigma << ")\"\n";
      last = lr;
    }
  }
  return d.str();
}

std::string pareto_script(const figure_spec& s, const std::vector<design_point>& all, design_time which,
                          const std::string& title) {
  double rmin = 0;
  for (const auto& p : all)
    if (p.r_res > 0 && (rmin == 0 || p.r_res < rmin)) rmin = p.r_res;
  const double floor = rmin > 0 ? rmin / 3 : 1e-6;
  std::ostringstream g;
  g << script_head("Pareto front", title, s) << "r_floor = " << num(floor) << "   # where r_res = 0 is drawn (log axis)\n"
    << "set title " << gnuplot_string(title) << " noenhanced\n"
    << "set logscale xy\n"
    << "set format y \"10^{%L}\"\n"
    << "set xlabel " << gnuplot_string(which == design_time::first_hit ? "exact first-hit time t_{first}" : "paper proxy {/Symbol p}/n") << "\n"
    << "set ylabel \"r_{res} (dq/dt(0) = 1)\"\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "set key below box opaque maxrows 2\n"
    << "set label 1 \"r_{res} = 0 (delta = 2 mod 4) drawn on this line\" at graph 0.98, first r_floor*1.7 right font \",9\" tc rgb \"#8c564b\"\n"
    << "plot datafile index 0 using 1:2 with points pt 7 ps 0.35 lc rgb \"#999999\" title \"resonant pairs\", \\\n"
    << "     '' index 1 using 1:(r_floor) with points pt 2 ps 0.5 lc rgb \"#8c564b\" title \"degenerate pairs (r_{res} = 0)\", \\\n"
    << "     '' index 2 using 1:($2 > 0 ? $2 : r_floor) with linespoints pt 7 ps 0.8 lw 1.5 lc rgb \"#d62728\" title \"Pareto front\", \\\n"
    << "     '' index 3 using 1:($2 > 0 ? $2 : r_floor):3 with labels left offset 0.6,0.6 font \",9\" notitle\n";
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
  return s;
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
  std::ostringstream g;
  g << script_head("energy exchange", title, s)
    << "t_first = " << num(e.t_first) << "\nt_proxy = " << num(e.t_proxy) << "\nh_min = " << num(e.h_min) << "\n"
    << "set title " << gnuplot_string(title) << " noenhanced\n"
    << "set xlabel \"t\"\nset ylabel \"energy\"\n"
    << "set xrange [0:" << num(e.t_end) << "]\nset yrange [0:*]\n"
    << "set grid lc rgb \"#dddddd\"\n"
    << "set key outside right top box opaque\n"
    << "set arrow 1 from t_first, graph 0 to t_first, graph 1 nohead dt 2 lw 1.5 lc rgb \"black\"\n"
    << "set arrow 2 from t_proxy, graph 0 to t_proxy, graph 1 nohead dt 4 lw 1.5 lc rgb \"#9467bd\"\n"
    << "plot datafile index 0 using 1:2 with lines lc rgb \"#1f77b4\" lw 1.2 title \"H_q\", \\\n"
    << "     '' index 0 using 1:3 with lines lc rgb \"#ff7f0e\" lw 1.2 title \"H_z\", \\\n"
    << "     '' index 1 using 1:2 with points pt 7 ps 1.4 lc rgb \"#2ca02c\" title sprintf(\"min H_q = %.4g\", h_min), \\\n"
    << "     NaN with lines dt 2 lw 1.5 lc rgb \"black\" title sprintf(\"" << first_label << " = %.5g\", t_first), \\\n"
    << "     NaN with lines dt 4 lw 1.5 lc rgb \"#9467bd\" title sprintf(\"paper proxy {/Symbol p}/n = %.5g\", t_proxy)\n";
  return figure_finish(s, d.str(), g.str());
}

figure_output write_pareto_figure(const figure_spec& s, const std::vector<design_point>& all,
                                  const std::vector<design_point>& front, design_time which,
                                  const std::string& title) {
  return figure_finish(s, pareto_data(all, front, which, title), pareto_script(s, all, which, title));
}

std::string pareto_orientation_caption(pareto_orientation o) {
  return o == pareto_orientation::absorb ? "absorb: min r_res, min time" : "contain: max r_res, min time";
}

}  // namespace gyrores::cli
