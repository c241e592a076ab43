// The report's introduction and Section 1 (the paper's Figure 1: n = 2 and n = 1/sqrt(12)).
#include <sstream>

#include <gyrores/app/figures.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/theorem/horizon.hpp>
#include <gyrores/report/horizon_report.hpp>

#include "report/sections.hpp"

namespace gyrores::report {

std::string title_section() { return "# gyrores report\n\n"; }

std::string intro_section(unsigned digits) {
  std::ostringstream md;
  md << "Recomputes the examples of *Shaping Energy Exchange with Gyroscopic Interconnections* (Juchem and "
        "Loccufier), Sections IV-V and Figures 1-4, with gyrores. All values are for the impulse qdot0 = 1 "
        "(r_res is proportional to qdot0; times do not depend on it). Every real number printed here has "
     << digits << " significant digits, each the correct rounding of an enclosure proved by interval arithmetic "
        "on the lattice theorem (the `gyrores pair` contract, proofs/lattice-theorem.md) or, for a coupling that is "
        "not resonant, on the horizon theorem (proofs/horizon-theorem.md); `r_res = 0` for delta = 2 mod 4 is exact (integer arithmetic). Certificates that an independent "
        "checker re-proves: `gyrores certify TAU SIGMA`, `gyrores check FILE`.\n\n"
     << "Conventions: `t_first` is the exact first time H_q reaches its minimum; `pi/n` is the paper's proxy "
        "T_min ~ pi/|n| (a heuristic). The inscribed radius comes from the lattice theorem: the minimisers' lobes "
        "by integers and one root u* enclosed by interval arithmetic, for every pair printed.\n\n";
  return md.str();
}

std::string figure1_section(context& c) {
  std::ostringstream md;
  const std::string heading = "1. Figure 1: n = 2 and n = 1/sqrt(12)";
  md << "## " << heading << "\n\n";
  const auto s2 = coupling_spec::from_n(big_rational(2)), s12 = coupling_spec::from_n2(big_rational(1, 12));
  const auto p2 = coupling_resonant_pair(s2);
  const auto p12 = coupling_resonant_pair(s12);
  // min of H_q over the paper's span [0, 200 pi/n] = [0, 100 pi], proved (the horizon theorem)
  const auto h = report_horizon_minimum(s2, horizon_time(big_rational(100), true), c.digits);
  md << claims_table_head
     << "| n = 2 is not resonant (dense trajectory, Fig. 1a) | n^2 (n^2 + 4) = 32 is not a rational square: "
     << (p2 ? "resonant" : "not resonant") << " | " << verdict(!p2) << " |\n"
     << "| n = 1/sqrt(12) is the pair (4, 3) (Fig. 1b) | n^2 (n^2 + 4) = 49/144 = (7/12)^2: "
     << (p12 ? "resonant, pair " + p12->str() : "not resonant") << " | "
     << verdict(p12 && p12->tau() == 4 && p12->sigma() == 3) << " |\n\n";
  md << "For n = 2 the infimum of H_q over all time is 0 (the torus line is dense and passes arbitrarily close to "
        "the zero of (q, q')), never attained. Over the paper's span t in [0, 200 pi/n] the minimum is H_q = "
     << h.h_min.value << " (radius " << h.r_min.value << "), first at t = " << h.t_min.value << ", in lobe "
     << (h.lobe ? h.lobe->k.str() : std::string("(the end point)"))
     << " (the horizon theorem: the lobe with the smallest ||k x - 1/2|| inside the span, proved; `gyrores "
        "coupling 2 --horizon 100pi`).\n\n";
  const auto v43 = c.values(4, 3);
  c.findings.push_back(
      {heading, std::string("**Figure 1.** n = 1/sqrt(12) is ") +
                    (p12 ? "the resonant pair " + p12->str() + " (r_res = " + v43.r_res.value + ")" : std::string("not resonant")) +
                    "; n = 2 is " + (p2 ? "resonant" : "not resonant") +
                    ": the infimum of its H_q over all time is 0, never attained, and over the paper's span [0, 200 pi/n] "
                    "its minimum is H_q = " + h.h_min.value + "."});
  md << "For (4, 3): n = " << v43.n << ", r_res = " << v43.r_res << ", H_q min = " << v43.h_min << ", t_first = " << v43.t_first
     << ", proxy pi/n = " << v43.t_min_paper << " (`gyrores coupling --n2 1/12`).\n\n";
  // Over the paper's span [0, 200 pi/n] (app::phase_figure's default) and over the period of (4, 3).
  c.figs.record("fig1a-phase-n2", frontend::write_phase_figure(c.figs.spec("fig1a-phase-n2", 1200, 640),
                                                                app::phase_figure(app::figure_subject_of(s2)),
                                                                "Fig. 1a: n = 2 (not resonant), t in [0, 200 pi/n]"));
  c.figs.record("fig1b-phase-4-3", frontend::write_phase_figure(c.figs.spec("fig1b-phase-4-3", 1200, 640),
                                                                 app::phase_figure(app::figure_subject_of(s12)),
                                                                 "Fig. 1b: n = 1/sqrt(12), the pair (4, 3)"));
  md << c.figs.md("fig1a-phase-n2", "Figure 1a: n = 2, trajectory over [0, 200 pi/n], envelope x_d, maximal circle; the zoom shows the smallest radius reached on that span.")
     << c.figs.md("fig1b-phase-4-3", "Figure 1b: n = 1/sqrt(12), the closed Lissajous curve of (4, 3) with its inscribed circle.");
  return md.str();
}

}  // namespace gyrores::report
