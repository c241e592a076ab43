// src/frontend/gnuplot.hpp
#include "frontend/gnuplot.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gyrores/core/error.hpp>
#include <gyrores/io/files.hpp>

#include "frontend/process.hpp"

namespace gyrores::frontend {

std::string gnuplot_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

bool gnuplot_available() { return program_in_path("gnuplot"); }

image_format image_format_of(const fs::path& p) {
  std::string e = p.extension().string();
  for (auto& c : e) c = char(std::tolower((unsigned char)c));
  if (e == ".svg") return image_format::svg;
  if (e == ".png") return image_format::png;
  if (e == ".pdf") return image_format::pdf;
  if (e == ".eps") return image_format::eps;
  throw usage_error("--out must end in .svg, .png, .pdf or .eps, got '" + p.string() + "'");
}

int figure_font_size(int width) { return std::clamp(8 + (width - 500) / 125, 8, 12); }

std::string gnuplot_preamble(const std::string& default_image, int width, int height, double width_in, double height_in,
                             int font_pt) {
  const int fs = font_pt;
  char inches[64];
  std::snprintf(inches, sizeof inches, "%.4gin,%.4gin", width_in, height_in);
  std::ostringstream os;
  os << "if (!exists(\"outfile\")) outfile = " << gnuplot_string(default_image) << "\n"
     << "fs = " << fs << "   # font size (points)\n"
     << "small = " << (width < 800 ? 1 : 0) << "   # compact layout below 800 pixels\n"
     << "ext = strlen(outfile) > 3 ? outfile[strlen(outfile)-2:] : \"\"  # gnuplot substrings are 1-based, inclusive\n"
     << "if (ext eq \"svg\") {\n"
     << "  set terminal svg size " << width << "," << height
     << " dynamic enhanced font \"DejaVu Sans," << fs << "\" background rgb \"white\"\n"
     << "} else { if (ext eq \"pdf\") {\n"
     << "  set terminal pdfcairo size " << inches << " enhanced font \"DejaVu Sans," << fs << "\" background rgb \"white\"\n"
     << "} else { if (ext eq \"eps\") {\n"
     << "  set terminal epscairo size " << inches << " enhanced font \"DejaVu Sans," << fs << "\" background rgb \"white\"\n"
     << "} else {\n"
     << "  set terminal pngcairo size " << width << "," << height
     << " enhanced font \"DejaVu Sans," << fs - 1 << "\" background rgb \"white\"\n"
     << "}}}\n"
     << "set output outfile\n";
  return os.str();
}

render_result gnuplot_render(const fs::path& dir, const std::string& script, const std::string& image) {
  render_result r;
  if (!gnuplot_available()) {
    r.message = "gnuplot not found (Debian: apt-get install gnuplot-nox); data and script written, image not drawn";
    return r;
  }
  // gnuplot opens its output by name and follows links: it writes into a directory of our own
  // (mode 700, beside the image), and the finished image is moved over IMAGE by io/files's
  // rules (a link, device or directory there is refused, the replaced file's mode kept).
  const fs::path target = dir / image;
  const std::string priv = make_private_directory(target.string());
  const std::string name = "image" + fs::path(image).extension().string();
  const std::string tmp = (fs::path(priv) / name).string();
  const std::string outfile = (fs::path(priv).filename() / name).string();  // relative to dir
  std::string err;
  int st = -1;
  try {
    st = run_helper({"gnuplot", "-e", "outfile=" + gnuplot_string(outfile), script}, dir.string(), priv, tmp, err);
  } catch (...) {
    remove_private_directory(priv);
    throw;
  }
  std::error_code ec;
  if (st != 0 || !fs::is_regular_file(fs::symlink_status(tmp, ec)) || fs::file_size(tmp, ec) == 0) {
    remove_private_directory(priv);
    for (auto& c : err)
      if (c == '\n') c = ' ';
    r.message = "gnuplot failed on " + (dir / script).string() + (err.empty() ? "" : ": " + err.substr(0, 300));
    return r;
  }
  try {
    install_file(tmp, target.string());
  } catch (...) {
    remove_private_directory(priv);
    throw;
  }
  remove_private_directory(priv);
  r.rendered = true;
  return r;
}

}  // namespace gyrores::frontend
