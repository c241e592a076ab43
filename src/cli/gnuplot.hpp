// gnuplot for the figure commands: running gnuplot on a script kept beside its figure (files
// are written atomically by io/files.hpp).
//
// Every figure is three files in one directory: NAME.dat (the data, gnuplot blocks separated by
// two blank lines, `index k`), NAME.gp (the script; it picks the terminal from the output
// name's extension, .svg -> svg, .png -> pngcairo) and the image. To restyle, edit NAME.gp and run
//     cd DIR && gnuplot -e "outfile='NAME.svg'" NAME.gp
// gnuplot is run the same way, writing to a temporary name that is renamed over the image when
// gnuplot succeeds, so a failed or interrupted run never leaves a half-written image.
// When gnuplot is missing (Debian: apt-get install gnuplot-nox), the data and script are still
// written and the caller says so.
#pragma once
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gyrores/core/error.hpp>
#include <gyrores/io/files.hpp>

namespace gyrores::cli {

namespace fs = std::filesystem;

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

// gnuplot string literal in double quotes (backslash and quote escaped).
inline std::string gnuplot_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

inline bool gnuplot_available() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

enum class image_format { svg, png };

// The format from the file name's extension (.svg or .png); usage_error otherwise.
inline image_format image_format_of(const fs::path& p) {
  std::string e = p.extension().string();
  for (auto& c : e) c = char(std::tolower((unsigned char)c));
  if (e == ".svg") return image_format::svg;
  if (e == ".png") return image_format::png;
  throw usage_error("--out must end in .svg or .png, got '" + p.string() + "'");
}

// Script preamble: output name (overridable with -e "outfile='...'") and terminal by extension.
inline std::string gnuplot_preamble(const std::string& default_image, int width, int height) {
  std::ostringstream os;
  os << "if (!exists(\"outfile\")) outfile = " << gnuplot_string(default_image) << "\n"
     << "if (strlen(outfile) > 3 && outfile[strlen(outfile)-2:] eq \"svg\") {  # gnuplot substrings are 1-based, inclusive\n"
     << "  set terminal svg size " << width << "," << height
     << " dynamic enhanced font \"DejaVu Sans,12\" background rgb \"white\"\n"
     << "} else {\n"
     << "  set terminal pngcairo size " << width << "," << height << " enhanced font \"DejaVu Sans,11\" background rgb \"white\"\n"
     << "}\n"
     << "set output outfile\n";
  return os.str();
}

struct render_result {
  bool rendered = false;
  std::string message;  // why not, when not rendered
};

// Run `gnuplot -e "outfile='IMAGE.tmp'" SCRIPT` in `dir`, then rename the temporary image to
// `image` (a file name in `dir`). Never throws for a gnuplot failure: the result says what
// happened (the data and script stay, so the user can run it themselves).
inline render_result gnuplot_render(const fs::path& dir, const std::string& script, const std::string& image) {
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
