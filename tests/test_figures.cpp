// Figures (include/gyrores/figures.hpp; `gyrores plot`) and the report (`gyrores report`).
// Library: the data obey the mathematics (trajectory inside the envelope and touching it,
// inscribed circle = smallest radius, maximal circle = qdot0, H_q + H_z = H).
// CLI: every PNG has the requested size and is not blank (decoded with zlib, pixels compared);
// every SVG is well-formed XML (a minimal checker); data and script sit beside each figure; without
// gnuplot the command says so and still writes them; the report runs end to end and every file
// it links exists.
#include <catch2/catch.hpp>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <gyrores/app/figures.hpp>
#include <gyrores/design/figures.hpp>
#include <gyrores/gyrores.hpp>

#include "cli_checks.hpp"
#include "reference/envelope.hpp"
#include "reference/horizon_scan.hpp"
#include "report_summary_checks.hpp"
#include "testing/cli_run.hpp"

using namespace gyrores;
using gyrores::test::cli_available;
using gyrores::test::check_rejected;
using gyrores::test::cli_json;
using gyrores::test::cli_run;
namespace fs = std::filesystem;

TEST_CASE("figures: phase portrait data of a pair obey the geometry", "[figures]") {
  for (auto [t, s] : {std::pair{6, 5}, std::pair{11, 9}, std::pair{4, 3}, std::pair{9, 4}}) {
    resonant_pair<std::int64_t> p(t, s);
    auto f = phase_portrait_of_pair(p);
    INFO(p.str());
    REQUIRE(f.trajectory.size() > 1000);
    auto c = resonant_constants_of<double>(p, 1.0);
    // Inside the envelope: p . u(phi) <= h(phi) for 360 directions; the maximum touches it.
    double worst = -1;
    for (int k = 0; k < 360; ++k) {
      double phi = 2 * M_PI * k / 360, h = envelope_support(c.n, 1.0, phi), best = -1e9;
      for (const auto& q : f.trajectory) best = std::max(best, q.x * std::cos(phi) + q.y * std::sin(phi));
      CHECK(best <= h + 1e-12);
      worst = std::max(worst, best - h);
    }
    CHECK(worst > -1e-3);  // touches (to sampling resolution)
    // Radii: min over samples >= r_res (up to rounding), close to it; max = qdot0 at t = 0.
    double rmin = 1e9, rmax = 0;
    for (const auto& q : f.trajectory) {
      double r = std::hypot(q.x, q.y);
      rmin = std::min(rmin, r);
      rmax = std::max(rmax, r);
    }
    for (const auto& seg : f.near_minimisers)
      for (const auto& q : seg) rmin = std::min(rmin, std::hypot(q.x, q.y));
    CHECK(rmin >= f.r_inscribed - 1e-12);
    CHECK(rmin <= f.r_inscribed + 1e-6);
    CHECK(rmax == Approx(1.0).epsilon(1e-12));
    CHECK(f.r_max == 1.0);
    CHECK(std::hypot(f.first_min.x, f.first_min.y) == Approx(f.r_inscribed).margin(1e-9));
    CHECK(f.near_minimisers.size() == (p.degenerate() || p.delta() % 2 == 1 ? 2u : 4u));
    // Envelope points: on the support line in their own direction.
    for (std::size_t k = 0; k < f.envelope.size(); k += 97) {
      double phi = 2 * M_PI * double(k) / double(f.envelope.size() - 1);
      CHECK(f.envelope[k].x * std::cos(phi) + f.envelope[k].y * std::sin(phi) ==
            Approx(envelope_support(c.n, 1.0, phi)).epsilon(1e-12));
    }
  }
}

TEST_CASE("figures: energy series conserve H and mark the exact first minimum", "[figures]") {
  auto e = energy_of_pair(resonant_pair<std::int64_t>(6, 5));
  REQUIRE(e.samples.size() > 1000);
  for (const auto& s : e.samples) CHECK(s.h_q + s.h_z == Approx(0.5).epsilon(1e-12));
  CHECK(e.t_first == Approx(16.3510779751).margin(1e-9));
  CHECK(e.t_proxy == Approx(17.2072116286).margin(1e-9));
  double hmin = 1;
  for (const auto& s : e.samples) hmin = std::min(hmin, s.h_q);
  CHECK(hmin >= e.h_min - 1e-15);
  CHECK(hmin <= e.h_min + 1e-5);
  const auto n2 = app::figure_subject_of(coupling_spec::from_n(big_rational(2)));
  auto en = app::energy_figure(n2, 1.0, 20.0);
  for (const auto& s : en.samples) CHECK(s.h_q + s.h_z == Approx(0.5).epsilon(1e-12));
  auto pn = app::phase_figure(n2, 1.0, 200 * M_PI / 2);
  CHECK(pn.t_first > 0);
  CHECK(pn.r_inscribed < 1e-3);  // dense: small radius over the span
}

// A coupling's marks are the horizon theorem's minimum over the span, scaled by qdot0^2: against
// the scan of every critical point (tests/reference/horizon_scan.hpp, long double), for a
// non-resonant n and an impulse other than 1.
TEST_CASE("figures: a coupling's marked minimum is the theorem's, against the scan", "[figures]") {
  for (const auto& [n, span] : {std::pair{2.0, 50.0}, {0.3, 200.0}, {0.2, 40.0}}) {
    INFO("n = " << n << " over [0, " << span << "]");
    const auto s = app::figure_subject_of(coupling_spec::from_n(big_rational(n)));
    const auto e = app::energy_figure(s, 0.5, span);
    const auto p = app::phase_figure(s, 0.5, span);
    const auto ref = horizon_minimum<long double>(n, 0.5L, span);
    CHECK(e.h_min == Approx(double(ref.h_min)).epsilon(1e-9));
    CHECK(e.t_first == Approx(double(ref.t_min)).epsilon(1e-12));
    CHECK(p.r_inscribed == Approx(std::sqrt(2 * double(ref.h_min))).epsilon(1e-9));
    CHECK(p.t_first == e.t_first);
  }
}

// The curve reaches its mark: the sampled H_q at the marked time is the marked minimum (the
// samples are refined around it). Before, n = 2 over [0, 50] dipped only to ~1e-4 near a mark
// at 1.4e-7, and (6, 5)'s samples stopped 25% above its minimum.
TEST_CASE("figures: the sampled H_q reaches every marked minimum", "[figures]") {
  const auto lowest_near = [](const energy_series& e, double t, double half) {
    double lo = 1e300;
    for (const auto& s : e.samples)
      if (std::fabs(s.t - t) <= half) lo = std::min(lo, s.h_q);
    return lo;
  };
  const auto e2 = app::energy_figure(app::figure_subject_of(coupling_spec::from_n(big_rational(2))), 1.0, 50.0);
  REQUIRE(e2.h_min < 1e-6);
  CHECK(lowest_near(e2, e2.t_first, 0.5) == Approx(e2.h_min).epsilon(1e-6));
  const auto e65 = energy_of_pair(resonant_pair<std::int64_t>(6, 5));
  CHECK(lowest_near(e65, e65.t_first, 1e-3) == Approx(e65.h_min).epsilon(1e-9));
  // The same minimum again at t = 18.06 (the other minimiser of the period): reached too.
  CHECK(lowest_near(e65, 18.06, 0.05) == Approx(e65.h_min).epsilon(1e-9));
  for (const auto& s : e65.samples) CHECK(s.h_q >= e65.h_min * (1 - 1e-9));  // and never below it
  for (std::size_t i = 1; i < e65.samples.size(); ++i) CHECK(e65.samples[i].t > e65.samples[i - 1].t);
}

// ------------------------------------------------------------------------------------ images

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::uint32_t be32(const std::string& s, std::size_t i) {
  return (std::uint32_t((unsigned char)s[i]) << 24) | (std::uint32_t((unsigned char)s[i + 1]) << 16) |
         (std::uint32_t((unsigned char)s[i + 2]) << 8) | std::uint32_t((unsigned char)s[i + 3]);
}

struct png_info {
  std::uint32_t width = 0, height = 0;
  std::size_t distinct_pixels = 0;     // distinct RGB(A) values (capped)
  double non_background = 0;           // fraction of pixels differing from the top-left pixel
};

// Parse a PNG (8-bit truecolour/greyscale, with or without alpha, non-interlaced), inflate the
// IDAT stream with zlib, undo the row filters and look at the pixels.
png_info decode_png(const std::string& png) {
  png_info info;
  REQUIRE(png.size() > 33);
  REQUIRE(png.compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) == 0);
  std::string idat;
  int depth = 0, ctype = 0, interlace = 0;
  for (std::size_t i = 8; i + 8 <= png.size();) {
    std::uint32_t len = be32(png, i);
    std::string type = png.substr(i + 4, 4);
    REQUIRE(i + 12 + len <= png.size());
    if (type == "IHDR") {
      info.width = be32(png, i + 8);
      info.height = be32(png, i + 12);
      depth = (unsigned char)png[i + 16];
      ctype = (unsigned char)png[i + 17];
      interlace = (unsigned char)png[i + 20];
    } else if (type == "IDAT") {
      idat += png.substr(i + 8, len);
    } else if (type == "IEND") {
      break;
    }
    i += 12 + len;
  }
  REQUIRE(depth == 8);
  REQUIRE(interlace == 0);
  int bpp = ctype == 6 ? 4 : ctype == 2 ? 3 : ctype == 4 ? 2 : ctype == 0 ? 1 : 0;
  REQUIRE(bpp > 0);
  const std::size_t stride = std::size_t(info.width) * bpp;
  std::vector<unsigned char> raw((stride + 1) * info.height);
  uLongf out_len = raw.size();
  REQUIRE(uncompress(raw.data(), &out_len, reinterpret_cast<const Bytef*>(idat.data()), idat.size()) == Z_OK);
  REQUIRE(out_len == raw.size());
  std::vector<unsigned char> img(stride * info.height), prev(stride, 0);
  for (std::uint32_t y = 0; y < info.height; ++y) {
    const unsigned char* row = &raw[y * (stride + 1)];
    int filter = row[0];
    unsigned char* cur = &img[y * stride];
    for (std::size_t x = 0; x < stride; ++x) {
      int a = x >= std::size_t(bpp) ? cur[x - bpp] : 0, b = prev[x], c = x >= std::size_t(bpp) ? prev[x - bpp] : 0;
      int v = row[1 + x], pred = 0;
      switch (filter) {
        case 0: pred = 0; break;
        case 1: pred = a; break;
        case 2: pred = b; break;
        case 3: pred = (a + b) / 2; break;
        case 4: {
          int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
          pred = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
          break;
        }
        default: FAIL("bad PNG filter " << filter);
      }
      cur[x] = (unsigned char)(v + pred);
    }
    std::copy(cur, cur + stride, prev.begin());
  }
  std::set<std::uint32_t> colours;
  std::size_t differ = 0;
  auto pix = [&](std::size_t k) {
    std::uint32_t v = 0;
    for (int j = 0; j < bpp; ++j) v = (v << 8) | img[k * bpp + j];
    return v;
  };
  const std::uint32_t bg = pix(0);
  const std::size_t n = std::size_t(info.width) * info.height;
  for (std::size_t k = 0; k < n; ++k) {
    std::uint32_t v = pix(k);
    if (v != bg) ++differ;
    if (colours.size() < 1000) colours.insert(v);
  }
  info.distinct_pixels = colours.size();
  info.non_background = double(differ) / double(n);
  return info;
}

// Minimal XML well-formedness: balanced, properly nested tags; comments, CDATA, processing
// instructions and the doctype skipped; attribute values quoted.
bool xml_well_formed(const std::string& x, std::string& why) {
  std::vector<std::string> stack;
  std::size_t i = 0;
  bool root_seen = false;
  while (i < x.size()) {
    if (x[i] != '<') {
      ++i;
      continue;
    }
    if (x.compare(i, 4, "<!--") == 0) {
      auto e = x.find("-->", i + 4);
      if (e == std::string::npos) return why = "unterminated comment", false;
      i = e + 3;
    } else if (x.compare(i, 9, "<![CDATA[") == 0) {
      auto e = x.find("]]>", i + 9);
      if (e == std::string::npos) return why = "unterminated CDATA", false;
      i = e + 3;
    } else if (x.compare(i, 2, "<?") == 0) {
      auto e = x.find("?>", i + 2);
      if (e == std::string::npos) return why = "unterminated processing instruction", false;
      i = e + 2;
    } else if (x.compare(i, 2, "<!") == 0) {
      int depth = 0;
      std::size_t j = i + 2;
      for (; j < x.size(); ++j) {
        if (x[j] == '[') ++depth;
        else if (x[j] == ']') --depth;
        else if (x[j] == '>' && depth == 0) break;
      }
      if (j >= x.size()) return why = "unterminated declaration", false;
      i = j + 1;
    } else {
      // a tag: scan to '>' outside quotes
      std::size_t j = i + 1;
      char quote = 0;
      for (; j < x.size(); ++j) {
        if (quote) {
          if (x[j] == quote) quote = 0;
        } else if (x[j] == '"' || x[j] == '\'') {
          quote = x[j];
        } else if (x[j] == '>') {
          break;
        }
      }
      if (j >= x.size()) return why = "unterminated tag", false;
      std::string tag = x.substr(i + 1, j - i - 1);
      if (tag.empty()) return why = "empty tag", false;
      if (tag[0] == '/') {
        std::string name = tag.substr(1);
        while (!name.empty() && std::isspace((unsigned char)name.back())) name.pop_back();
        if (stack.empty() || stack.back() != name) return why = "mismatched </" + name + ">", false;
        stack.pop_back();
      } else {
        bool self = tag.back() == '/';
        std::string name = tag.substr(0, tag.find_first_of(" \t\r\n/"));
        if (name.empty()) return why = "tag without a name", false;
        if (stack.empty() && root_seen && !self) return why = "second root element <" + name + ">", false;
        if (stack.empty()) root_seen = true;
        if (!self) stack.push_back(name);
      }
      i = j + 1;
    }
  }
  if (!stack.empty()) return why = "unclosed <" + stack.back() + ">", false;
  if (!root_seen) return why = "no element", false;
  return true;
}

}  // namespace

TEST_CASE("figures: the XML checker accepts and rejects", "[figures]") {
  std::string why;
  CHECK(xml_well_formed("<?xml version=\"1.0\"?><!DOCTYPE svg [<!ENTITY a 'b'>]><svg a=\"x>y\"><g><path/></g><!-- c --></svg>", why));
  CHECK_FALSE(xml_well_formed("<svg><g></svg>", why));
  CHECK_FALSE(xml_well_formed("<svg><g>", why));
  CHECK_FALSE(xml_well_formed("<svg a=\"x></svg>", why));
}

TEST_CASE("cli plot: PNG of the requested size, not blank; SVG well-formed; data and script beside", "[figures][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("plot");
  const std::string dir = tmp.path();
  struct job {
    std::string args, image;
    unsigned w, h;
  };
  const std::vector<job> jobs = {
      {"plot phase 6 5 --size 640x480", "phase65.png", 640, 480},             // Fig. 3a
      {"plot energy 11 9 --size 700x400", "energy119.png", 700, 400},          // Fig. 2b
      {"plot phase --n 2", "phase-n2.png", 1200, 640},                        // Fig. 1a
      {"plot phase --n2 1/12", "phase-4-3.svg", 0, 0},                        // Fig. 1b
      {"plot phase 11 9", "phase119.svg", 0, 0},                              // Fig. 2a
      {"plot energy 6 5", "energy65.svg", 0, 0},                              // Fig. 3b
      {"plot pareto --max-order 80 --size 800x500", "pareto.png", 800, 500},  // Fig. 4
      {"plot energy --n 0.3", "energy-n03.png", 900, 500},
  };
  for (const auto& j : jobs) {
    INFO(j.args);
    auto r = cli_run(j.args + " --out " + dir + "/" + j.image);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    fs::path img = fs::path(dir) / j.image;
    REQUIRE(fs::exists(img));
    fs::path stem = img;
    stem.replace_extension();
    CHECK(fs::exists(stem.string() + ".dat"));
    CHECK(fs::exists(stem.string() + ".gp"));
    if (img.extension() == ".png") {
      auto info = decode_png(read_file(img));
      CHECK(info.width == j.w);
      CHECK(info.height == j.h);
      CHECK(info.distinct_pixels >= 8);       // lines in several colours, antialiasing
      CHECK(info.non_background > 0.01);      // something drawn
      CHECK(info.non_background < 0.9);
    } else {
      std::string why;
      std::string svg = read_file(img);
      CHECK(svg.find("<svg") != std::string::npos);
      CHECK(xml_well_formed(svg, why));
      INFO(why);
      CHECK(svg.find("<path") != std::string::npos);
    }
  }
  // No temporary files left behind.
  for (auto& e : fs::directory_iterator(dir)) CHECK(e.path().string().find(".tmp") == std::string::npos);
  // The script redraws the figure by itself (users restyle it).
  auto again = std::system(("cd " + dir + " && gnuplot -e \"outfile='again.png'\" phase65.gp 2>/dev/null").c_str());
  CHECK(again == 0);
  CHECK(fs::exists(fs::path(dir) / "again.png"));
}

// The texts of an SVG written by gnuplot: each <g transform="translate(x,y)[ rotate(..)]" ...
// font-size="F" ... text-anchor="A"> <text>...</text> (tspans joined, tags dropped).
struct svg_text {
  double x = 0, y = 0, size = 0;
  std::string anchor, text;
  bool rotated = false;
  // Horizontal extent, estimated at 0.55 em per character (DejaVu Sans averages about that).
  double width() const { return 0.55 * size * double(text.size()); }
  double left() const { return anchor == "middle" ? x - width() / 2 : anchor == "end" ? x - width() : x; }
};

std::vector<svg_text> svg_texts(const std::string& svg) {
  std::vector<svg_text> out;
  const std::string open = "<g transform=\"translate(";
  for (std::size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    const std::size_t head_end = svg.find('>', at);
    const std::string head = svg.substr(at, head_end - at);
    const std::size_t text_at = svg.find("<text>", head_end), text_end = svg.find("</text>", head_end);
    const std::size_t next_g = svg.find("<g", head_end);
    if (text_at == std::string::npos || text_end == std::string::npos || (next_g != std::string::npos && next_g < text_at))
      continue;
    svg_text t;
    t.x = std::stod(head.substr(open.size()));
    t.y = std::stod(head.substr(head.find(',') + 1));
    t.rotated = head.find("rotate(") != std::string::npos;
    const std::size_t fs = head.find("font-size=\"");
    t.size = fs == std::string::npos ? 12 : std::stod(head.substr(fs + 11));
    const std::size_t an = head.find("text-anchor=\"");
    t.anchor = an == std::string::npos ? "start" : head.substr(an + 13, head.find('"', an + 13) - an - 13);
    bool in_tag = false;
    for (char c : svg.substr(text_at + 6, text_end - text_at - 6)) {
      if (c == '<') in_tag = true;
      else if (c == '>') in_tag = false;
      else if (!in_tag) t.text += c;
    }
    while (!t.text.empty() && t.text.front() == ' ') t.text.erase(0, 1);
    if (!t.text.empty()) out.push_back(t);
  }
  return out;
}

TEST_CASE("cli plot: readable at single-column sizes (600x400, 500x350)", "[figures][cli]") {
  if (!cli_available() || std::system("command -v gnuplot >/dev/null 2>&1") != 0) return;
  gyrores::test::temp_dir tmp("plotsmall");
  const std::string dir = tmp.path();
  struct figure {
    std::string args;
    std::vector<std::string> legend;  // entries every key must show
  };
  const std::vector<figure> figures = {
      {"plot phase 6 5", {"trajectory", "envelope", "maximal circle", "first minimum", "inscribed"}},
      {"plot phase --n 2", {"trajectory", "envelope", "min radius on the span"}},
      {"plot energy 6 5", {"min H", "proxy", "near its minimum"}},
      {"plot pareto --max-order 200", {"resonant pairs", "Pareto front"}},
  };
  for (const auto& [w, h] : {std::pair{600, 400}, std::pair{500, 350}}) {
    for (const auto& f : figures) {
      INFO(f.args << " at " << w << "x" << h);
      const std::string out = dir + "/f.svg";
      auto r = cli_run(f.args + " --size " + std::to_string(w) + "x" + std::to_string(h) + " --out " + out);
      REQUIRE(r.status == 0);
      REQUIRE(r.out.find("note:") == std::string::npos);
      const auto texts = svg_texts(read_file(out));
      REQUIRE(texts.size() > 10);
      std::string all;
      for (const auto& t : texts) all += t.text + "\n";
      INFO(all);
      for (const auto& entry : f.legend) CHECK(all.find(entry) != std::string::npos);  // legends not emptied
      for (std::size_t i = 0; i < texts.size(); ++i) {
        const auto& a = texts[i];
        if (a.rotated) continue;
        INFO("text '" << a.text << "' at " << a.x << "," << a.y);
        CHECK(a.left() >= -1);           // not cut on the left
        CHECK(a.left() + a.width() <= w + 1);  // nor on the right (titles included)
        CHECK(a.y >= 0);
        CHECK(a.y <= h + 1);
        for (std::size_t j = i + 1; j < texts.size(); ++j) {
          const auto& b = texts[j];
          if (b.rotated || std::fabs(a.y - b.y) >= 0.8 * std::max(a.size, b.size)) continue;
          INFO("overlaps '" << b.text << "' at " << b.x << "," << b.y);
          CHECK((a.left() + a.width() <= b.left() + 1 || b.left() + b.width() <= a.left() + 1));  // tick labels apart
        }
      }
    }
  }
}

// A tick label: a number as gnuplot prints one ("0.5", "-0.1", "10^{-3}" read as "10-3", "3·10-3").
static bool tick_label(const std::string& t) {
  static const std::regex number(R"(-?[0-9.]+(·10-?[0-9]+)?|10-?[0-9]+)");
  return std::regex_match(t, number);
}

// The labelled ticks of every axis in an SVG gyrores drew: x-axis labels (centred) grouped by
// their height and by the panel they sit under (`splits`: the figure's column boundaries as
// fractions of its width), y-axis labels (right-aligned) by their x. Each group is one axis.
static std::vector<std::size_t> labels_per_axis(const std::vector<svg_text>& texts, double width,
                                                const std::vector<double>& splits) {
  std::map<std::pair<long, int>, std::size_t> axes;
  for (const auto& t : texts) {
    if (t.rotated || !tick_label(t.text)) continue;
    if (t.anchor == "middle") {
      int column = 0;
      for (double s : splits) column += t.x > s * width;
      ++axes[{std::lround(t.y * 10), column}];
    } else if (t.anchor == "end") {
      ++axes[{std::lround(t.x * 10), -1}];
    }
  }
  std::vector<std::size_t> out;
  for (const auto& [where, count] : axes) out.push_back(count);
  return out;
}

// Every axis of every figure has at least three labelled ticks. Before, each phase figure had
// one per axis on its main panel (`set xtics (small ? 1 : 0.5)` is a one-tick list for
// gnuplot), and the Pareto inset two on its time axis.
TEST_CASE("cli plot: every axis has at least three labelled ticks", "[figures][cli]") {
  if (!cli_available() || std::system("command -v gnuplot >/dev/null 2>&1") != 0) return;
  gyrores::test::temp_dir tmp("plotticks");
  const std::string dir = tmp.path();
  struct figure {
    std::string args;
    std::vector<double> splits;  // column boundaries
    std::size_t axes;            // labelled axes at least
  };
  const std::vector<figure> figures = {
      {"plot phase 6 5", {0.5}, 4},          {"plot phase --n 2", {0.5}, 4},
      {"plot phase --n2 1/12", {0.5}, 4},    {"plot phase 5 3", {0.5}, 4},  // (5, 3): r_res = 0
      {"plot energy 6 5", {}, 3},            {"plot energy --n 2 --tmax 50", {}, 3},
      {"plot energy 11 9", {}, 3},           {"plot pareto --max-order 200", {0.64}, 4},
  };
  for (const auto& [w, h] : {std::pair{0, 0}, std::pair{500, 350}}) {
    for (const auto& f : figures) {
      INFO(f.args << " at " << w << "x" << h);
      const std::string size = w ? " --size " + std::to_string(w) + "x" + std::to_string(h) : "";
      auto r = cli_run(f.args + size + " --out " + dir + "/f.svg");
      REQUIRE(r.status == 0);
      const std::string svg = read_file(dir + "/f.svg");
      const double width = std::stod(svg.substr(svg.find("viewBox=\"0 0 ") + 13));
      const auto texts = svg_texts(svg);
      std::string labels;
      for (const auto& t : texts)
        if (tick_label(t.text)) labels += t.text + " (" + std::to_string(t.x) + "," + std::to_string(t.y) + ") ";
      INFO("tick labels: " << labels);
      const auto axes = labels_per_axis(texts, width, f.splits);
      CHECK(axes.size() >= f.axes);
      for (std::size_t n : axes) CHECK(n >= 3);
    }
  }
}

// The keys sit outside the plotted data (above, below or beside the graph), so that no key box
// covers a curve or a marked minimum; every mark lies inside its panel's ranges. Before, the
// energy figure's opaque keys sat inside both panels (top right, bottom right), over H_z's
// maxima and over (6, 5)'s second minimum at t = 18.06.
TEST_CASE("cli plot: keys off the data, marks inside their panels", "[figures][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("plotkeys");
  const std::string dir = tmp.path();
  for (const std::string args : {"plot phase 6 5", "plot phase --n 2", "plot energy 6 5", "plot energy --n 2",
                                 "plot energy --n 2 --tmax 50", "plot energy 11 9", "plot pareto --max-order 100"}) {
    INFO(args);
    REQUIRE(cli_run(args + " --out " + dir + "/k.svg", "PATH=/nonexistent").status == 0);
    const std::string gp = read_file(dir + "/k.gp");
    std::istringstream lines(gp);
    int keys = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("set key", 0) != 0) continue;
      ++keys;
      INFO(line);
      CHECK(std::regex_search(line, std::regex(R"(\b(above|below|outside|[lrtb]margin|off)\b)")));
    }
    CHECK(keys >= 1);
  }
}

// The rows of block `index` of a gnuplot data file (two blank lines between blocks).
static std::vector<std::vector<double>> data_block(const std::string& dat, int index) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(dat);
  int block = 0, blanks = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) {
      if (++blanks == 2) ++block;
      continue;
    }
    blanks = 0;
    if (line[0] == '#' || block != index) continue;
    std::istringstream cols(line);
    std::vector<double> row;
    for (std::string c; cols >> c;) row.push_back(c == "NaN" ? std::nan("") : std::strtod(c.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

// The energy figure's lower panel (H_q on a log axis) draws its curve through every mark: at the
// marked time, the drawn curve (straight between samples, in log H_q) is within 2 pixels of the
// mark, on a panel a third of the figure's height. Before, n = 2 over [0, 50] drew its dip down
// to ~1e-4 under a mark at 1.4e-7, 3 decades and 100 pixels off.
TEST_CASE("cli plot: the energy curve touches each marked minimum", "[figures][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("plottouch");
  const std::string dir = tmp.path();
  for (const std::string args : {"plot energy --n 2 --tmax 50", "plot energy 6 5", "plot energy 11 9", "plot energy --n 0.3",
                                 "plot energy 35 29", "plot energy --n 2"}) {
    INFO(args);
    REQUIRE(cli_run(args + " --out " + dir + "/e.svg", "PATH=/nonexistent").status == 0);
    const std::string gp = read_file(dir + "/e.gp"), dat = read_file(dir + "/e.dat");
    // The lower panel's ranges: the last `set xrange` and `set yrange` of the script.
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    const std::regex xrange(R"(set xrange \[([-+0-9.eE]+):([-+0-9.eE]+)\])"), yrange(R"(set yrange \[([-+0-9.eE]+):([-+0-9.eE]+)\])");
    for (std::sregex_iterator it(gp.begin(), gp.end(), xrange), end; it != end; ++it)
      x0 = std::stod((*it)[1]), x1 = std::stod((*it)[2]);
    for (std::sregex_iterator it(gp.begin(), gp.end(), yrange), end; it != end; ++it)
      y0 = std::stod((*it)[1]), y1 = std::stod((*it)[2]);
    REQUIRE(y1 > y0);
    REQUIRE(y0 > 0);
    const double px_per_log = (500.0 / 3) / std::log(y1 / y0);  // the default 900x500, panel about a third
    const auto curve = data_block(dat, 0);
    REQUIRE(curve.size() > 1000);
    std::vector<std::vector<double>> marks = data_block(dat, 1), more = data_block(dat, 2);
    marks.insert(marks.end(), more.begin(), more.end());
    int checked = 0;
    for (const auto& mark : marks) {
      if (mark.size() < 2 || std::isnan(mark[0]) || mark[0] < x0 || mark[0] > x1) continue;
      INFO("mark at t = " << mark[0] << ", H_q = " << mark[1]);
      CHECK(mark[1] <= y1);
      std::size_t i = 1;
      while (i + 1 < curve.size() && curve[i][0] < mark[0]) ++i;
      const auto& a = curve[i - 1];
      const auto& b = curve[i];
      REQUIRE(a[0] <= mark[0]);
      REQUIRE(b[0] >= mark[0]);
      ++checked;
      if (mark[1] == 0) {  // r_res = 0: the mark sits on the panel's floor, the curve runs off it there
        CHECK(std::min(a[1], b[1]) < y0);
        continue;
      }
      CHECK(mark[1] >= y0);
      const double u = b[0] > a[0] ? (mark[0] - a[0]) / (b[0] - a[0]) : 0;
      const double drawn = std::exp((1 - u) * std::log(a[1]) + u * std::log(b[1]));
      INFO("drawn curve there: " << drawn);
      CHECK(std::fabs(std::log(drawn / mark[1])) * px_per_log <= 2.0);
    }
    CHECK(checked >= 1);
  }
}

TEST_CASE("cli plot: PDF and EPS for journals", "[figures][cli]") {
  if (!cli_available() || std::system("command -v gnuplot >/dev/null 2>&1") != 0) return;
  gyrores::test::temp_dir tmp("plotpdf");
  const std::string dir = tmp.path();
  for (const std::string args : {"plot phase 6 5", "plot energy 11 9", "plot pareto --max-order 60"}) {
    INFO(args);
    REQUIRE(cli_run(args + " --size 500x350 --out " + dir + "/f.pdf").status == 0);
    const std::string pdf = read_file(dir + "/f.pdf");
    CHECK(pdf.rfind("%PDF-", 0) == 0);
    CHECK(pdf.find("%%EOF") != std::string::npos);
    // 500x350 pixels at 100 per inch: a 5 x 3.5 inch page (360 x 252 points).
    CHECK(pdf.find("/MediaBox [ 0 0 360 252 ]") != std::string::npos);
    // An IEEE column, 3.5 x 2.5 inches (252 x 180 points), and 8.8 x 6 cm (249.45 x 170.08 points,
    // which cairo writes rounded).
    REQUIRE(cli_run(args + " --size 3.5x2.5in --out " + dir + "/c.pdf").status == 0);
    CHECK(read_file(dir + "/c.pdf").find("/MediaBox [ 0 0 252 180 ]") != std::string::npos);
    REQUIRE(cli_run(args + " --size 8.8cmx6cm --font-size 8 --out " + dir + "/m.pdf").status == 0);
    const std::string cm = read_file(dir + "/m.pdf");
    CHECK(cm.find("/MediaBox [ 0 0 249 170 ]") != std::string::npos);
    REQUIRE(cli_run(args + " --out " + dir + "/f.eps").status == 0);
    const std::string eps = read_file(dir + "/f.eps");
    CHECK(eps.rfind("%!PS-Adobe-3.0 EPSF-3.0", 0) == 0);
    CHECK(eps.find("%%BoundingBox:") != std::string::npos);
  }
}

TEST_CASE("cli plot pareto: r_res = 0 on its own strip; large data thinned", "[figures][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("plotpareto");
  const std::string dir = tmp.path();
  REQUIRE(cli_run("plot pareto --max-order 80 --out " + dir + "/p.svg", "PATH=/nonexistent").status == 0);
  const std::string gp = read_file(dir + "/p.gp"), dat = read_file(dir + "/p.dat");
  CHECK(gp.find("r_floor") == std::string::npos);                   // no stand-in value on the log axis
  CHECK(gp.find("index 1 using 1:(0)") != std::string::npos);       // the zeros on the strip, at 0
  CHECK(gp.find("# right panel: the front alone") != std::string::npos);  // the front over its own ranges
  CHECK(dat.find("thinned") == std::string::npos);
  // Order 600: 109 000 pairs, thinned to at most one per 2x2 pixels of a 900x640 figure.
  REQUIRE(cli_run("plot pareto --max-order 600 --out " + dir + "/big.svg", "PATH=/nonexistent").status == 0);
  const std::string big = read_file(dir + "/big.dat");
  CHECK(big.find("# thinned: ") != std::string::npos);
  std::size_t rows = 0;
  for (std::size_t at = 0; (at = big.find('\n', at)) != std::string::npos; ++at) ++rows;
  CHECK(rows < 450 * 320 + 450 + 2000);
  CHECK(big.size() < 8u << 20);
}

TEST_CASE("cli plot: without gnuplot the data and script are still written", "[figures][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("nognuplot");
  const std::string dir = tmp.path();
  auto r = cli_run("plot phase 6 5 --out " + dir + "/p.svg", "PATH=/nonexistent");
  CHECK(r.status == 0);
  CHECK(r.out.find("gnuplot not found") != std::string::npos);
  CHECK(fs::exists(fs::path(dir) / "p.dat"));
  CHECK(fs::exists(fs::path(dir) / "p.gp"));
  CHECK_FALSE(fs::exists(fs::path(dir) / "p.svg"));
}

TEST_CASE("cli plot: bad input exits 2", "[figures][cli]") {
  if (!cli_available()) return;
  for (const char* bad : {"plot phase 6 5 --out x.jpg", "plot phase 6 4 --out x.svg", "plot phase --out x.svg",
                          "plot phase 6 5 --n 2 --out x.svg", "plot phase 6 5 --size 10x10 --out x.svg",
                          "plot pareto --out x.svg", "plot", "plot phase 6 5 --size 3inx8cm --out x.svg",
                          "plot phase 6 5 --size 0.5in --out x.svg", "plot phase 6 5 --size 300cm --out x.svg",
                          "plot phase 6 5 --size 3.5mm --out x.svg", "plot phase 6 5 --size 3.5 --out x.svg",
                          "plot phase 6 5 --font-size 2 --out x.svg", "plot phase 6 5 --font-size big --out x.svg"})
    check_rejected(bad);
}

// Section 7 of the report (couplings that are not resonant): its figures exist, and the values it
// prints and plots are those of `gyrores coupling ... --json`, an independent path through the CLI
// (the report calls the theorem layer directly; the CLI goes through the coupling report).
static void check_coupling_section(const std::string& md, const fs::path& out) {
  CHECK(md.find("## 7. Couplings that are not resonant") != std::string::npos);
  const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  for (const char* stem : {"fig-coupling-horizon", "fig-coupling-absorb"})
    for (const char* ext : {".dat", ".gp", ".png", ".svg"}) {
      const fs::path f = out / "figures" / (std::string(stem) + ext);
      INFO(f.string());
      const bool image = std::string(ext) == ".png" || std::string(ext) == ".svg";
      if (!image || gnuplot) CHECK(fs::exists(f));
      std::string why;
      if (std::string(ext) == ".svg" && gnuplot) CHECK(xml_well_formed(read_file(f), why));
      if (std::string(ext) == ".png" && gnuplot) CHECK(decode_png(read_file(f)).non_background > 0.01);
    }
  const auto integer_text = [](const nlohmann::json& j) { return j.is_null() ? std::string("-") : j.dump(); };
  const std::string horizon_dat = read_file(out / "figures" / "fig-coupling-horizon.dat");
  const std::string absorb_dat = read_file(out / "figures" / "fig-coupling-absorb.dat");
  // (a) the minimum over [0, 10^12] for n = 2 (a lobe) and over [0, 1] for n = 0.1832 (the end point).
  for (auto [n, e] : {std::pair{"2", 12}, std::pair{"0.1832", 6}, std::pair{"0.1832", 0}}) {
    const auto j = cli_json(std::string("coupling ") + n + " --horizon 1e" + std::to_string(e) + " --digits 10 --convergents 0 --json");
    const std::string lobe = j["min_at_horizon_end"].get<bool>() ? "-" : integer_text(j["horizon_lobe"]);
    const std::string row = std::string("| ") + n + " | 10^" + std::to_string(e) + " | " + lobe + " | " +
                            j["h_min_horizon"].get<std::string>() + " | " + j["t_min_horizon"].get<std::string>() + " |\n";
    INFO(row);
    CHECK(md.find(row) != std::string::npos);
    const std::string dat = "\n1e" + std::to_string(e) + " " + j["h_min_horizon"].get<std::string>() + " " +
                            j["t_min_horizon"].get<std::string>() + " " + (lobe == "-" ? "-1" : lobe) + "\n";
    CHECK(horizon_dat.find(dat) != std::string::npos);
  }
  CHECK(md.find("| 0.1832 | 10^0 | - |") != std::string::npos);  // the end point case is exercised
  // (b) the first time H_q <= 1% for n = 2 (table and figure data), and (2, 1), which never gets there.
  const auto j2 = cli_json("coupling 2 --below 1% --digits 10 --convergents 0 --json");
  const std::string t2 = j2["t_below"].get<std::string>(), lobe2 = integer_text(j2["below"]["lobe"]);
  CHECK(md.find("| decimal | 2 | " + lobe2 + " | " + t2 + " |\n") != std::string::npos);
  CHECK(absorb_dat.find("\n2 " + t2 + " " + lobe2 + "\n") != std::string::npos);
  const auto j21 = cli_json("coupling --n2 1/2 --below 1% --digits 10 --convergents 0 --json");
  REQUIRE(j21["below"]["never"].get<bool>());
  CHECK(md.find("| pair (2, 1) | " + j21["n"].get<std::string>() + " | - | never: H_q min = " +
                j21["pair_analysis"]["h_min"].get<std::string>() + " |\n") != std::string::npos);
}

// The summary of findings and the short Pareto table (report_summary_checks.hpp), on the report and
// on damaged copies of it that each check must refuse; the Case B bullet against `gyrores pair
// 6 5 --json`, which does not go through the report.
static void check_summary_and_pareto(const std::string& md, const fs::path& out) {
  using gyrores::test::pareto_table_problems;
  using gyrores::test::summary_problems;
  const std::string csv = read_file(out / "pareto-front.csv");
  for (const auto& p : summary_problems(md)) FAIL_CHECK(p);
  for (const auto& p : pareto_table_problems(md, csv)) FAIL_CHECK(p);
  const auto summary_end = md.find("\n## 1.");
  REQUIRE(summary_end != std::string::npos);
  const std::string summary = md.substr(0, summary_end);
  const auto j = cli_json("pair 6 5 --digits 10 --json");
  for (const char* key : {"r_res", "h_min", "t_first", "t_min_paper"}) {
    INFO(key);
    CHECK(summary.find(j[key].get<std::string>()) != std::string::npos);
  }
  // The pair report's proved share, as `gyrores pair 6 5` prints it: 200 x 1.287568403e-03 = 0.25751...
  CHECK(summary.find("(0.2575% of H_q(0))") != std::string::npos);
  // Damaged copies: a summary number off by one unit, a share off by one unit, a dead anchor,
  // the summary below section 1, a table row too many, a pair missing from the CSV.
  const auto damaged = [&](const std::string& from, const std::string& to, std::size_t limit) {
    std::string d = md;
    const auto at = d.find(from);
    REQUIRE(at != std::string::npos);
    REQUIRE(at < limit);
    return d.replace(at, from.size(), to);
  };
  CHECK_FALSE(summary_problems(damaged("1.635107798e+01", "1.635107799e+01", summary_end)).empty());
  CHECK_FALSE(summary_problems(damaged("0.258% of", "0.259% of", summary_end)).empty());
  CHECK_FALSE(summary_problems(damaged("](#3-case-b", "](#3-case-c", summary_end)).empty());
  {
    const auto start = md.find("## Summary of findings");
    std::string moved = md.substr(0, start) + md.substr(summary_end + 1);
    const auto after1 = moved.find("\n## 2.");
    moved.insert(after1 + 1, md.substr(start, summary_end + 1 - start));
    CHECK_FALSE(summary_problems(moved).empty());
  }
  const auto table_row = md.find("\n| (5, 1) | 4 |");
  REQUIRE(table_row != std::string::npos);
  const auto row_end = md.find('\n', table_row + 1);
  std::string longer = md;
  for (int i = 0; i < 15; ++i) longer.insert(row_end + 1, md.substr(table_row + 1, row_end - table_row));
  CHECK_FALSE(pareto_table_problems(longer, csv).empty());
  CHECK_FALSE(pareto_table_problems(md, csv.substr(0, csv.rfind('\n', csv.size() - 2) + 1)).empty());
}

TEST_CASE("cli report: runs end to end; every linked file exists", "[report][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("report");
  const std::string dir = tmp.path();
  auto r = cli_run("report --out " + dir + "/out");
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out == dir + "/out/REPORT.md\n");
  std::string md = read_file(fs::path(dir) / "out" / "REPORT.md");
  REQUIRE(!md.empty());
  std::regex link(R"(\]\(([^)\s]+)\))");
  int links = 0, pngs = 0, pdfs = 0;
  for (std::sregex_iterator it(md.begin(), md.end(), link), end; it != end; ++it) {
    std::string target = (*it)[1];
    INFO(target);
    if (target[0] == '#') continue;  // a section of the report: the summary's links, checked below
    CHECK(fs::exists(fs::path(dir) / "out" / target));
    ++links;
    if (target.size() > 4 && target.substr(target.size() - 4) == ".png") {
      ++pngs;
      auto info = decode_png(read_file(fs::path(dir) / "out" / target));
      CHECK(info.non_background > 0.01);
    }
    if (target.size() > 4 && target.substr(target.size() - 4) == ".pdf") {  // beside each PNG, for a paper
      ++pdfs;
      CHECK(read_file(fs::path(dir) / "out" / target).rfind("%PDF-", 0) == 0);
    }
  }
  CHECK(links >= 20);
  CHECK(pngs >= 7);
  CHECK(pdfs >= 7);
  // The paper's findings appear, with exact values.
  CHECK(md.find("(35, 29)") != std::string::npos);
  CHECK(md.find("1.635107798e+01") != std::string::npos);  // (6, 5) exact t_first, 10 digits
  // Every number proved, the horizon minimum of Fig. 1a by the horizon theorem.
  CHECK(md.find("each the correct rounding of an enclosure proved by interval arithmetic") != std::string::npos);
  CHECK(md.find("the horizon theorem") != std::string::npos);
  CHECK(md.find("verified digits, not proved") == std::string::npos);
  for (auto& e : fs::recursive_directory_iterator(fs::path(dir) / "out"))
    CHECK(e.path().string().find(".tmp") == std::string::npos);
  check_coupling_section(md, fs::path(dir) / "out");
  check_summary_and_pareto(md, fs::path(dir) / "out");
}
