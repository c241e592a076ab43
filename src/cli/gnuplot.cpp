// src/cli/gnuplot.hpp
#include "gnuplot.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gyrores/core/error.hpp>

namespace gyrores::cli {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

std::string gnuplot_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

bool gnuplot_available() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

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

std::string gnuplot_preamble(const std::string& default_image, int width, int height) {
  const int fs = figure_font_size(width);
  char inches[64];
  std::snprintf(inches, sizeof inches, "%.2fin,%.2fin", width / 100.0, height / 100.0);
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
  fs::path img(image);
  std::string tmp = img.stem().string() + ".tmp" + std::to_string(::getpid()) + img.extension().string();
  fs::path errf = dir / (img.stem().string() + ".gnuplot-stderr.tmp" + std::to_string(::getpid()));
  std::string cmd = "cd " + shell_quote(dir.string()) + " && gnuplot -e " + shell_quote("outfile='" + tmp + "'") + " " +
                    shell_quote(script) + " >/dev/null 2>" + shell_quote(errf.filename().string());
  int st = std::system(cmd.c_str());
  std::string err;
  {
    std::ifstream in(errf);
    std::ostringstream ss;
    ss << in.rdbuf();
    err = ss.str();
  }
  std::error_code ec;
  fs::remove(errf, ec);
  if (st != 0 || !fs::exists(dir / tmp) || fs::file_size(dir / tmp, ec) == 0) {
    fs::remove(dir / tmp, ec);
    for (auto& c : err)
      if (c == '\n') c = ' ';
    r.message = "gnuplot failed on " + (dir / script).string() + (err.empty() ? "" : ": " + err.substr(0, 300));
    return r;
  }
  fs::rename(dir / tmp, dir / image, ec);
  if (ec) {
    fs::remove(dir / tmp, ec);
    r.message = "cannot rename the image to " + (dir / image).string();
    return r;
  }
  r.rendered = true;
  return r;
}

}  // namespace gyrores::cli
