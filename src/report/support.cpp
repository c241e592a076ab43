// src/report/sections.hpp: what the sections share.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <gyrores/app/figures.hpp>

#include "report/sections.hpp"

namespace gyrores::report {

figure_spec figure_set::spec(const std::string& stem, int w, int h) const {
  figure_spec s;
  s.dir = dir;
  s.stem = stem;
  s.width = w;
  s.height = h;
  s.images = {stem + ".png", stem + ".svg", stem + ".pdf"};
  frontend::check_figure_outputs(s);
  return s;
}

void figure_set::record(const std::string& stem, const figure_output& o) {
  images drawn_now;
  for (auto& im : o.images) {
    if (im.extension() == ".png") drawn_now.png = true;
    if (im.extension() == ".svg") drawn_now.svg = true;
    if (im.extension() == ".pdf") drawn_now.pdf = true;
  }
  drawn[stem] = drawn_now;
  if (!o.message.empty()) notes.push_back(stem + ": " + o.message);
}

std::string figure_set::md(const std::string& stem, const std::string& caption) const {
  std::ostringstream os;
  auto it = drawn.find(stem);
  const images im = it == drawn.end() ? images{} : it->second;
  if (im.png) os << "![" << caption << "](figures/" << stem << ".png)\n\n";
  os << "*" << caption << "* Files: ";
  if (im.svg) os << "[SVG](figures/" << stem << ".svg), ";
  if (im.pdf) os << "[PDF](figures/" << stem << ".pdf), ";
  if (im.png) os << "[PNG](figures/" << stem << ".png), ";
  os << "[data](figures/" << stem << ".dat), [gnuplot script](figures/" << stem << ".gp)";
  if (!im.png && !im.svg && !im.pdf) os << " (image not drawn: see the notes at the end)";
  os << "\n\n";
  return os.str();
}

std::vector<design_point> context::smallest(std::int64_t delta, std::size_t k) const {
  pair_filter f;
  f.delta = delta;
  f.beat_min = big_rational(10);
  std::vector<design_point> out;
  for (const auto& p : catalogue)
    if (out.size() < k && pair_filter_accepts(f, p)) out.push_back(p);
  return out;
}

pair_report context::values(std::int64_t t, std::int64_t s) const {
  return prove_pair_values(resonant_pair<big_int>(big_int(t), big_int(s)), digits);
}

std::string draw_case_figures(context& c, const resonant_pair<std::int64_t>& p, const case_figures& f) {
  const std::string fig = "Fig. " + std::to_string(f.number), figure = "Figure " + std::to_string(f.number);
  const std::string stem = std::to_string(p.tau()) + "-" + std::to_string(p.sigma());
  const std::string phase = "fig" + std::to_string(f.number) + "a-phase-" + stem, energy = "fig" + std::to_string(f.number) + "b-energy-" + stem;
  const app::figure_subject s{p};
  c.figs.record(phase, frontend::write_phase_figure(c.figs.spec(phase, 1200, 640), app::phase_figure(s),
                                                    fig + "a: " + f.name + " case " + p.str() + f.phase_note));
  c.figs.record(energy, frontend::write_energy_figure(c.figs.spec(energy, 900, 500), app::energy_figure(s),
                                                      fig + "b: " + f.name + " case " + p.str(), "exact t_{first}"));
  return c.figs.md(phase, figure + "a: " + p.str() + ", " + f.phase_caption) +
         c.figs.md(energy, figure + "b: " + p.str() + ", " + f.energy_caption);
}

std::string pair_name(std::int64_t t, std::int64_t s) {
  std::string out = "(";  // appended step by step: "(" + std::to_string(t) trips a GCC 12 -Wrestrict false positive
  out += std::to_string(t);
  out += ", ";
  out += std::to_string(s);
  return out + ")";
}

// |ours - paper| <= half a unit of the paper's last printed digit (plus a relative 1e-12 for the
// decimal conversion).
bool agrees_with_printed(const std::string& paper, double ours) {
  std::string mant = paper;
  int exp10 = 0;
  auto e = mant.find_first_of("eE");
  if (e != std::string::npos) {
    exp10 = std::stoi(mant.substr(e + 1));
    mant = mant.substr(0, e);
  }
  auto dot = mant.find('.');
  int decimals = dot == std::string::npos ? 0 : int(mant.size() - dot - 1);
  double unit = std::pow(10.0, exp10 - decimals);
  double p = std::strtod(paper.c_str(), nullptr);
  return std::fabs(ours - p) <= 0.5 * unit * (1 + 1e-9) + 1e-12 * std::fabs(p);
}

bool agrees_with_printed(const std::string& paper, const std::string& ours) {
  return agrees_with_printed(paper, std::strtod(ours.c_str(), nullptr));
}

std::string verdict(bool ok) { return ok ? "agrees" : "**differs**"; }

const char* const claims_table_head = "| claim (paper) | gyrores | verdict |\n|---|---|---|\n";

}  // namespace gyrores::report
