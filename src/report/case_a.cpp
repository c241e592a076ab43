// The report's Section 2: the paper's Case A (absorption), the pair (11, 9), and what a larger
// delta does with the exact time and with the paper's proxy.
#include <sstream>

#include "report/sections.hpp"

namespace gyrores::report {
namespace {

const char* const heading = "2. Case A (absorption): the pair (11, 9)";

std::string case_a_claims(context& c) {
  const auto v = c.values(11, 9);
  const auto v41 = c.values(41, 35);
  const auto d6 = c.smallest(6, 3);
  const auto& s6 = d6.front();
  const auto v6 = c.values(s6.tau, s6.sigma);
  const auto d2 = c.smallest(2, 1);
  {
    std::ostringstream f;
    f << "**Case A (absorption).** (11, 9) ";
    if (v.degenerate)
      f << "drains q completely (r_res = 0 exactly)";
    else
      f << "keeps r_res = " << v.r_res;
    f << " at t_first = " << v.t_first
      << (v.t_first.value == v.t_min_paper.value ? ", equal to the paper's proxy pi/n" : ", the paper's proxy pi/n being " + v.t_min_paper.value)
      << "; the smallest delta = 6 pair with beat >= 10 is " << pair_name(s6.tau, s6.sigma)
      << (s6.tau == 41 && s6.sigma == 35 ? ", as the paper says" : ", not the paper's (41, 35)") << ", and the exact first zero of (41, 35), t_first = "
      << v41.t_first << ", is " << (41 - 35) / 2 << " times its proxy pi/n = " << v41.t_min_paper << ".";
    c.findings.push_back({heading, f.str()});
  }
  std::ostringstream md;
  md << claims_table_head << "| delta = 2 and beat >= 10 give (11, 9) | smallest delta = 2 pair with beat >= 10: "
     << pair_name(d2.front().tau, d2.front().sigma) << " | "
     << verdict(d2.front().tau == 11 && d2.front().sigma == 9) << " |\n"
     << "| n = 0.201 | " << v.n << " | " << verdict(agrees_with_printed("0.201", v.n)) << " |\n"
     << "| r_min = 0 | r_res = 0 exactly (delta = 2 mod 4) | agrees |\n"
     << "| T_min ~ 15.6 s | proxy pi/n = " << v.t_min_paper << "; exact t_first = " << v.t_first
     << " (equal: for delta = 2 mod 4, t_first = (delta/2) pi/n) | "
     << verdict(agrees_with_printed("15.6", v.t_first)) << " |\n"
     << "| delta = 6: beat >= 10 gives tau >= 33 | tau + sigma >= 60 and tau - sigma = 6 give tau >= 33 | agrees |\n"
     << "| delta = 6: the smallest coprime pair is (41, 35) | smallest: " << pair_name(s6.tau, s6.sigma)
     << " (coprime, beat " << s6.order() << "/6 = " << num(double(s6.order()) / 6) << "); then "
     << (d6.size() > 1 ? pair_name(d6[1].tau, d6[1].sigma) : std::string("-")) << ", "
     << (d6.size() > 2 ? pair_name(d6[2].tau, d6[2].sigma) : std::string("-")) << " | "
     << verdict(s6.tau == 41 && s6.sigma == 35) << " |\n"
     << "| (41, 35): T_min ~ 19.8 s | proxy pi/n = " << v41.t_min_paper << " agrees, but the exact first zero is t_first = "
     << v41.t_first << " (3 pi/n) | proxy " << verdict(agrees_with_printed("19.8", v41.t_min_paper))
     << "; exact time **differs** |\n"
     << "| " << pair_name(s6.tau, s6.sigma) << " (not in the paper) | proxy pi/n = " << v6.t_min_paper << ", exact t_first = "
     << v6.t_first << " | - |\n\n";
  return md.str();
}

// Does a larger delta deteriorate? Fastest degenerate pair per delta (beat >= 10), by the proxy
// and by the exact time.
std::string delta_table(context& c) {
  std::ostringstream md;
  md << "The paper concludes that (11, 9) is best and that larger delta only deteriorates. With the exact time this "
        "holds, by a wide margin (t_first = (delta/2) pi/n for degenerate pairs). With the paper's own proxy it does "
        "not: the proxy of a pair with beat ratio exactly 10 does not depend on delta, so larger delta can have a "
        "smaller proxy than delta = 6. Fastest degenerate pair per delta (beat >= 10, tau + sigma <= "
     << c.catalogue.back().order() << "):\n\n"
     << "| delta | fastest by proxy | its pi/n | its exact t_first | fastest by exact time | its t_first |\n"
     << "|---|---|---|---|---|---|\n";
  design_options od;
  od.tmax = big_rational(100000);
  od.filter.beat_min = big_rational(10);
  od.candidates = 0;
  for (std::int64_t dl : {2, 6, 10, 14, 18}) {
    od.filter.delta = dl;
    od.time = design_time::proxy;
    auto by_proxy = design_solve(c.catalogue, od);
    od.time = design_time::first_hit;
    auto by_exact = design_solve(c.catalogue, od);
    if (!by_proxy.feasible_any()) continue;
    const auto& bp = by_proxy.ranked.front();
    const auto& be = by_exact.ranked.front();
    const auto vp = c.values(bp.tau, bp.sigma);
    const auto ve = c.values(be.tau, be.sigma);
    md << "| " << dl << " | " << pair_name(bp.tau, bp.sigma) << " | " << vp.t_min_paper << " | " << vp.t_first << " | "
       << pair_name(be.tau, be.sigma) << " | " << ve.t_first << " |\n";
  }
  md << "\n";
  return md.str();
}

}  // namespace

std::string case_a_section(context& c) {
  const std::string claims = case_a_claims(c), deltas = delta_table(c);
  return std::string("## ") + heading + "\n\n" + claims + deltas +
         draw_case_figures(c, resonant_pair<std::int64_t>(11, 9),
                           {2, "absorption", ", r_res = 0", "closed Lissajous curve through the origin (degenerate inscribed circle).",
                            "H_q(t) and H_z(t); exact t_first and the proxy pi/n coincide for delta = 2."});
}

}  // namespace gyrores::report
