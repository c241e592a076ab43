// The sections of REPORT.md: each is one function (one file each) that returns its markdown and
// records the figures it draws (frontend/plots.hpp). report/report.cpp runs them in order and
// writes the files.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gyrores/design/design.hpp>
#include <gyrores/report/pair_report.hpp>

#include "frontend/plots.hpp"

namespace gyrores::report {

namespace fs = std::filesystem;
using frontend::figure_output;
using frontend::figure_spec;
using frontend::num;

// The figures of the report (DIR/figures): which were drawn, and the notes when one was not.
struct figure_set {
  fs::path dir;
  std::vector<std::string> notes;
  struct images {
    bool png = false, svg = false, pdf = false;  // which were drawn
  };
  std::map<std::string, images> drawn;  // by stem

  // A PNG, an SVG and a PDF (for a paper: w/100 x h/100 inches) of the figure `stem`, w x h pixels.
  figure_spec spec(const std::string& stem, int w, int h) const;
  void record(const std::string& stem, const figure_output& o);
  // Markdown for one figure: embedded PNG, links to SVG, PDF, data and script (only files that exist).
  std::string md(const std::string& stem, const std::string& caption) const;
};

// The two figures of the paper's case of one pair, Figure <number>a (its phase portrait) and
// <number>b (its energy exchange): "Fig. 2a: absorption case (11, 9)<phase_note>" and the captions.
struct case_figures {
  int number;
  std::string name, phase_note, phase_caption, energy_caption;
};

// One bullet of the summary of findings (summary.cpp): a sentence whose numbers are strings its
// section prints, and the heading (without its #s) of the section it links to.
struct finding {
  std::string heading, text;
};

// What every section shares.
struct context {
  unsigned digits;                       // of every verified real printed
  fs::path dir;                          // the output directory
  figure_set figs;
  std::vector<design_point> catalogue;   // every pair up to max(Pareto order, 200), for sections 2-4
  std::vector<finding> findings;         // in the order of the sections

  // The first k pairs of the catalogue (enumeration order) with tau - sigma = delta and beat >= 10.
  std::vector<design_point> smallest(std::int64_t delta, std::size_t k) const;
  // prove_pair_values(t, s, digits): every real proved.
  pair_report values(std::int64_t t, std::int64_t s) const;
};

// Draws both figures of a case (recorded in c.figs) and returns their markdown.
std::string draw_case_figures(context& c, const resonant_pair<std::int64_t>& p, const case_figures& f);

// "(t, s)".
std::string pair_name(std::int64_t t, std::int64_t s);
// Whether our value agrees with a number the paper prints, to its last printed digit.
bool agrees_with_printed(const std::string& paper, double ours);
// Same, for one of our verified decimal strings.
bool agrees_with_printed(const std::string& paper, const std::string& ours);
// "agrees" or "**differs**".
std::string verdict(bool ok);
// The table head of the claims tables: "| claim (paper) | gyrores | verdict |".
extern const char* const claims_table_head;

// The GitHub anchor of a heading (its text without the #s): lower case, every character that is not
// a letter, digit, space, '-' or '_' dropped, spaces made '-'. For the summary's links.
std::string markdown_anchor(const std::string& heading);
// An energy as a share of H_q(0) = 1/2 (qdot0 = 1), from a proved enclosure [lo, hi] of it:
// "0.258% of H_q(0)", three significant digits in plain notation, the correct rounding of every
// value of the enclosure (else the outward range "0.257-0.258%").
// "P% of H_q(0)" for qdot0 = 1: of a proved energy, to 3 digits (a range when its rounding is not
// settled), or a share the pair report proved (pair_report::h_min_share).
std::string share_of_initial_energy(const enclosure& energy);
std::string share_of_initial_energy(const proved_real& share);
// "## Summary of findings": the findings, one bullet each, each linked to its section.
std::string summary_section(const std::vector<finding>& findings);

std::string title_section();
std::string intro_section(unsigned digits);
std::string figure1_section(context& c);
std::string case_a_section(context& c);
std::string case_b_section(context& c);
std::string design_section(context& c);
std::string pareto_section(context& c, std::int64_t max_order);
std::string sweep_section(context& c, std::int64_t max_order);
std::string coupling_section(context& c);
std::string band_section(context& c);
std::string files_section(const figure_set& figs);

}  // namespace gyrores::report
