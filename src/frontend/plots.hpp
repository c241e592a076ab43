// The three figure kinds (paper Figs. 1-4) of `gyrores plot`, `gyrores pareto --plot` and the
// report: phase portrait, energy exchange, Pareto front. Each writes NAME.dat and NAME.gp beside
// the image(s) and draws with gnuplot (frontend/gnuplot.hpp). The data come from the application
// layer, include/gyrores/app/figures.hpp (double, plotting resolution; the marked r_res and
// t_first come from the exact solvers).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <gyrores/design/design.hpp>
#include <gyrores/design/figures.hpp>
#include <gyrores/io/files.hpp>

namespace gyrores::frontend {

namespace fs = std::filesystem;

struct figure_spec {
  fs::path dir;                     // where NAME.dat, NAME.gp and the images go (.svg/.png/.pdf/.eps)
  std::string stem;                 // NAME
  int width = 800, height = 600;    // pixels of an SVG or PNG, at 100 per inch
  // The printed size of a PDF or EPS in inches; 0: width/100 by height/100. Kept apart from the
  // pixels so that 8.8cm is 3.4646 inches on the page, not 346 pixels' 3.46.
  double width_in = 0, height_in = 0;
  int font_pt = 0;                  // the font size in points; 0: figure_font_size(width)
  std::vector<std::string> images;  // image file names in dir (.svg / .png / .pdf / .eps)
  std::string default_image() const { return images.empty() ? stem + ".svg" : images.front(); }
  double inches_wide() const { return width_in > 0 ? width_in : width / 100.0; }
  double inches_high() const { return height_in > 0 ? height_in : height / 100.0; }
  int font() const;
};

// The figure's size from --size: "WxH" in pixels (100 <= W, H <= 10000, 100 per inch), or in
// inches or centimetres: a width alone ("3.5in", "8.8cm": the height keeps the default's
// proportions) or both ("3.5x2.5in", "8.8cmx6cm"), 1 to 100 inches. An empty text keeps the
// default. usage_error naming the flag otherwise.
void apply_figure_size(figure_spec& s, const std::string& size, int default_w, int default_h);

// --font-size in points: "" keeps the default (figure_font_size), else an integer 5..30 (usage_error).
int parse_font_size(const std::string& text);

struct figure_output {
  fs::path data, script;
  std::vector<fs::path> images;  // drawn images
  std::string message;           // non-empty when an image could not be drawn
  bool complete() const { return message.empty(); }
};

// --out FILE.svg|png|pdf|eps, --size (apply_figure_size) and --font-size (parse_font_size) into a
// spec (the directory is created, and its outputs checked: check_figure_outputs).
figure_spec figure_spec_from_out(const fs::path& out, const std::string& size, int default_w, int default_h,
                                 const std::string& font_size = "");

// Before any work: the figure's files (NAME.dat, NAME.gp, the images) and `more` name distinct
// files, and each can be written (io/files.hpp: no link, device or directory; usage_error).
void check_figure_outputs(const figure_spec& s, const std::vector<named_path>& more = {});

// %.10g: how figures and the report print doubles.
std::string num(double v);

// Phase portrait, two panels: the whole trajectory with the envelope x_d(phi) and the maximal
// circle (dashed, drawn over the envelope); and a zoom on the origin with the inscribed circle,
// dense samples near every minimiser and the first minimiser marked. Keys below the panels.
// Every axis of every figure has at least three labelled ticks (frontend/ticks.hpp).
figure_output write_phase_figure(const figure_spec& s, const phase_portrait& f, const std::string& title);

// Energy exchange: H_q(t), H_z(t), the exact first-hit time and the paper's proxy pi/|n| above;
// below, H_q on a log axis around its first minimum, marked, with the same minimum's other times
// in the window (e.t_minima). Keys above the panels, off the data.
figure_output write_energy_figure(const figure_spec& s, const energy_series& e, const std::string& title,
                                  const std::string& first_label);

// Pareto: every pair with r_res > 0 (grey) and the front (red, some pairs labelled) on log axes,
// the degenerate pairs (r_res = 0) on a strip of their own below, sharing the time axis, and the
// front alone on a panel of its own at the right, over its own ranges (on the whole time axis it
// is a sliver). The key sits above the upper panel, off the data.
// The points are app::pareto_figure_points_of's: thinned above app::pareto_thin_above pairs (said
// in the title and the data file), so that a vector image stays a few MB.
figure_output write_pareto_figure(const figure_spec& s, const std::vector<design_point>& all,
                                  const std::vector<design_point>& front, design_time which,
                                  const std::string& title);

// For figure kinds drawn outside this file (the report's own): the opening of a script (what it
// draws, how to redraw it, terminal, `datafile`), and writing NAME.dat and NAME.gp then drawing
// every image of `s` (a gnuplot failure is reported in the result, not thrown).
std::string figure_script_head(const std::string& kind, const std::string& title, const figure_spec& s);
figure_output write_figure_files(const figure_spec& s, const std::string& data, const std::string& script);

// "absorb: min r_res, min time" or "contain: max r_res, min time" (figure titles).
std::string pareto_orientation_caption(pareto_orientation o);

}  // namespace gyrores::frontend
