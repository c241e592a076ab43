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
  int width = 800, height = 600;    // pixels
  std::vector<std::string> images;  // image file names in dir (.svg / .png)
  std::string default_image() const { return images.empty() ? stem + ".svg" : images.front(); }
};

struct figure_output {
  fs::path data, script;
  std::vector<fs::path> images;  // drawn images
  std::string message;           // non-empty when an image could not be drawn
  bool complete() const { return message.empty(); }
};

// --out FILE.svg|png and --size WxH into a spec (the directory is created, and its outputs
// checked: check_figure_outputs).
figure_spec figure_spec_from_out(const fs::path& out, const std::string& size, int default_w, int default_h);

// Before any work: the figure's files (NAME.dat, NAME.gp, the images) and `more` name distinct
// files, and each can be written (io/files.hpp: no link, device or directory; usage_error).
void check_figure_outputs(const figure_spec& s, const std::vector<named_path>& more = {});

// %.10g: how figures and the report print doubles.
std::string num(double v);

// Phase portrait, two panels: the whole trajectory with the envelope x_d(phi) and the maximal
// circle; and a zoom on the origin with the inscribed circle, dense samples near every
// minimiser and the first minimiser marked.
figure_output write_phase_figure(const figure_spec& s, const phase_portrait& f, const std::string& title);

// Energy exchange: H_q(t), H_z(t), the exact first-hit time and the paper's proxy pi/|n|.
figure_output write_energy_figure(const figure_spec& s, const energy_series& e, const std::string& title,
                                  const std::string& first_label);

// Pareto: every pair with r_res > 0 (grey) and the front (red, some pairs labelled) on log axes,
// an inset with the front alone over its own ranges (on the whole time axis it is a sliver), and
// the degenerate pairs (r_res = 0) on a strip of their own below, sharing the time axis.
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
