// gnuplot for the figures (frontend/plots.hpp): running gnuplot on a script kept beside its
// figure (files are written atomically by io/files.hpp).
//
// Every figure is three files in one directory: NAME.dat (the data, gnuplot blocks separated by
// two blank lines, `index k`), NAME.gp (the script; it picks the terminal from the output
// name's extension: .svg -> svg, .png -> pngcairo at 100 pixels per inch, .pdf -> pdfcairo and
// .eps -> epscairo, the journal formats, at the printed size in inches) and the image. To restyle, edit NAME.gp and run
//     cd DIR && gnuplot -e "outfile='NAME.svg'" NAME.gp
// gnuplot is run the same way (no shell), writing into a private directory (mode 700, beside the
// image); the finished image is moved over the final name by io/files.hpp's rules (never through
// a link, onto a device or a directory; the replaced file's mode kept), so a failed or
// interrupted run never leaves a half-written image and nothing planted beside it is written.
// When gnuplot is missing (Debian: apt-get install gnuplot-nox), the data and script are still
// written and the caller says so.
#pragma once
#include <filesystem>
#include <string>

namespace gyrores::frontend {

namespace fs = std::filesystem;

// gnuplot string literal in double quotes (backslash and quote escaped).
std::string gnuplot_string(const std::string& s);

bool gnuplot_available();

enum class image_format { svg, png, pdf, eps };

// The format from the file name's extension (.svg, .png, .pdf or .eps); usage_error otherwise.
image_format image_format_of(const fs::path& p);

// The font size (points) of a figure `width` pixels wide: 12 from 1000 pixels down to 8 at 500,
// so that single-column sizes (500x350, 600x400) keep their labels apart.
int figure_font_size(int width);

// Script preamble: output name (overridable with -e "outfile='...'"), terminal by extension (SVG
// and PNG `width` x `height` pixels, PDF and EPS `width_in` x `height_in` inches), font size
// `font_pt` points, and the variables fs (the font size) and small (1 below 800 pixels wide:
// compact layouts).
std::string gnuplot_preamble(const std::string& default_image, int width, int height, double width_in, double height_in,
                             int font_pt);

struct render_result {
  bool rendered = false;
  std::string message;  // why not, when not rendered
};

// Run `gnuplot -e "outfile='PRIVATE/image.EXT'" SCRIPT` in `dir`, then install the image as
// `image` (a file name in `dir`). Never throws for a gnuplot failure: the result says what
// happened (the data and script stay, so the user can run it themselves). Throws usage_error
// when the image cannot be installed (io/files.hpp), `interrupted` when gnuplot was stopped by
// SIGINT or SIGTERM.
render_result gnuplot_render(const fs::path& dir, const std::string& script, const std::string& image);

}  // namespace gyrores::frontend
