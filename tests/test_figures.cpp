// Figures (include/gyrores/figures.hpp; `gyrores plot`) and the report (`gyrores report`).
// Library: the data obey the mathematics (trajectory inside the envelope and touching it,
// inscribed circle = smallest radius, maximal circle = qdot0, H_q + H_z = H).
// CLI: every PNG has the requested size and is not blank (decoded with zlib, pixels compared);
// every SVG is well-formed XML (a minimal checker); data and script sit beside each figure; without
// gnuplot the command says so and still writes them; the report runs end to end and every file
// it links exists.
#include <catch2/catch.hpp>
#include <zlib.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <gyrores/design/figures.hpp>
#include <gyrores/gyrores.hpp>

#include "cli_checks.hpp"
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
  auto en = energy_of_coupling(2.0, 1.0, 20.0);
  for (const auto& s : en.samples) CHECK(s.h_q + s.h_z == Approx(0.5).epsilon(1e-12));
  auto pn = phase_portrait_of_coupling(2.0, 1.0, 200 * M_PI / 2);
  CHECK(pn.t_first > 0);
  CHECK(pn.r_inscribed < 1e-3);  // dense: small radius over the span
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
  REQUIRE(!dir.empty());
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
                          "plot pareto --out x.svg", "plot"})
    check_rejected(bad);
}

TEST_CASE("cli report: runs end to end; every linked file exists", "[report][cli]") {
  if (!cli_available()) return;
  gyrores::test::temp_dir tmp("report");
  const std::string dir = tmp.path();
  REQUIRE(!dir.empty());
  auto t0 = std::chrono::steady_clock::now();
  auto r = cli_run("report --out " + dir + "/out");
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out == dir + "/out/REPORT.md\n");
  CHECK(secs < 60);
  std::string md = read_file(fs::path(dir) / "out" / "REPORT.md");
  REQUIRE(!md.empty());
  std::regex link(R"(\]\(([^)\s]+)\))");
  int links = 0, pngs = 0;
  for (std::sregex_iterator it(md.begin(), md.end(), link), end; it != end; ++it) {
    std::string target = (*it)[1];
    INFO(target);
    CHECK(fs::exists(fs::path(dir) / "out" / target));
    ++links;
    if (target.size() > 4 && target.substr(target.size() - 4) == ".png") {
      ++pngs;
      auto info = decode_png(read_file(fs::path(dir) / "out" / target));
      CHECK(info.non_background > 0.01);
    }
  }
  CHECK(links >= 20);
  CHECK(pngs >= 7);
  // The paper's findings appear, with exact values.
  CHECK(md.find("(35, 29)") != std::string::npos);
  CHECK(md.find("1.635107798e+01") != std::string::npos);  // (6, 5) exact t_first, 10 digits
  // Every number proved, the one verified quantity named as such.
  CHECK(md.find("each the correct rounding of an enclosure proved by interval arithmetic") != std::string::npos);
  CHECK(md.find("verified digits, not proved") != std::string::npos);
  for (auto& e : fs::recursive_directory_iterator(fs::path(dir) / "out"))
    CHECK(e.path().string().find(".tmp") == std::string::npos);
}
