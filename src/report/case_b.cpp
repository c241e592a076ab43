// The report's Section 3: the paper's Case B (containment), the pair (6, 5), with the paper's
// asymptotic quantities of the lobe k = 6.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "report/sections.hpp"

namespace gyrores::report {
namespace {

const char* const heading = "3. Case B (containment): the pair (6, 5)";

// The paper's asymptotics for (6, 5), lobe k = 6 (theta_asy = 3.30), proved, 6 digits.
std::string asymptotic_claims(const paper_lobe_detail& l) {
  const double qdot_asy_rho0 = std::fabs(std::strtod(l.qdot_asy_over_rho0.value.c_str(), nullptr));
  std::ostringstream md;
  md << "| u_asy = -0.17 rad | lobe k = 6: u_asy = " << l.u_asy << " | "
     << verdict(agrees_with_printed("-0.17", l.u_asy)) << " (digits swapped? -0.71) |\n"
     << "| theta_asy = 3.30 rad | " << l.theta_asy << " | " << verdict(agrees_with_printed("3.30", l.theta_asy)) << " |\n"
     << "| q'(theta_asy) = 2.43e-4 | dq/dt at theta_asy (qdot0 = 1): " << l.qdot_asy << "; divided by rho0: "
     << l.qdot_asy_over_rho0 << " | " << verdict(agrees_with_printed("2.43e-4", l.qdot_asy)) << " as dq/dt; "
     << verdict(agrees_with_printed("2.43e-4", qdot_asy_rho0)) << " as |q'/rho0| |\n"
     << "| abs(theta_c - theta_asy) = 1.16e-4 | " << l.error << " (theta_c = " << l.theta_c << ") | "
     << verdict(agrees_with_printed("1.16e-4", l.error)) << " |\n"
     << "| bound pi^3 x^2/a = 2.33e-2 | " << l.bound << " | " << verdict(agrees_with_printed("2.33e-2", l.bound)) << " |\n";
  return md.str();
}

std::string case_b_claims(context& c) {
  const auto v = c.values(6, 5);
  const auto d1 = c.smallest(1, 1);
  const auto lobe = prove_paper_lobe(resonant_pair<big_int>(6, 5), big_int(6), 6);
  const double t_first = std::strtod(v.t_first.value.c_str(), nullptr), proxy = std::strtod(v.t_min_paper.value.c_str(), nullptr);
  c.findings.push_back({heading, "**Case B (containment).** (6, 5) keeps r_res = " + v.r_res.value + ", that is H_q min = " +
                                     v.h_min.value + " (" + share_of_initial_energy(v.h_min_share) +
                                     "), and its exact first minimum, t_first = " + v.t_first.value + ", comes " +
                                     (t_first < proxy ? "before" : t_first > proxy ? "after" : "at") +
                                     " the paper's proxy pi/n = " + v.t_min_paper.value + "."});
  std::ostringstream md;
  md << claims_table_head << "| delta = 1 and beat >= 10 give (6, 5) | smallest delta = 1 pair with beat >= 10: "
     << pair_name(d1.front().tau, d1.front().sigma) << " | "
     << verdict(d1.front().tau == 6 && d1.front().sigma == 5) << " |\n"
     << "| n = 0.183 | " << v.n << " | " << verdict(agrees_with_printed("0.183", v.n)) << " |\n"
     << "| T_min ~ 17.2 s | proxy pi/n = " << v.t_min_paper << " agrees; the exact first minimum is earlier, t_first = "
     << v.t_first << " (theta = " << v.theta_first << ", the mirror image of the paper's theta ~ 3.30) | proxy "
     << verdict(agrees_with_printed("17.2", v.t_min_paper)) << "; exact time **differs** |\n"
     << asymptotic_claims(lobe)
     << "| r_min = 5.075e-2 | r_res = " << v.r_res << " (H_q min = r_res^2/2 = " << v.h_min << ", "
     << share_of_initial_energy(v.h_min_share) << ") | " << verdict(agrees_with_printed("5.075e-2", v.r_res))
     << " |\n\n";
  return md.str();
}

}  // namespace

std::string case_b_section(context& c) {
  const std::string claims = case_b_claims(c);
  return std::string("## ") + heading + "\n\n" + claims +
         draw_case_figures(c, resonant_pair<std::int64_t>(6, 5),
                           {3, "containment", "", "trajectory, envelope and the non-zero inscribed circle (zoom), first minimiser marked.",
                            "H_q(t) and H_z(t); the exact first minimum comes before the proxy pi/n."});
}

}  // namespace gyrores::report
