// Everything gyrores reports about one resonant pair (pair_analysis.hpp), with verified decimal
// digits: the library side of `gyrores pair`, and the lighter pair values of the design, Pareto,
// coupling and report commands.
//
// Exact fields (beat_ratio; qdot0 from its decimal text; n, rho0, omega1, omega2 when the square
// roots are rational; h_z_max of degenerate pairs) are rounded once from their exact rational
// value, to nearest with ties to even (core/rational.hpp), not verified in floating point.
// Diagnostics (the paper's asymptotics) that do not settle are printed with the digits that did
// and listed in verified_pair_report::unsettled; they never cause compute_error (asymptotics
// that cannot be computed are reported as not applicable, with the reason). The minimisers are
// ordered on their exact lobe frames (lattice.hpp), never on rounded angles.
// Other fields: every real field is printed with D significant digits accepted by the two-run
// test of core/verified_digits.hpp (the plan's type for D digits, then MPFR with 64 more bits;
// Ziv's test; the precision doubles, at most 5 rounds in all, then compute_error). That is a
// strong consistency check, not a proof (see that header); certificates (certify/) prove. Pairs
// whose order exceeds 2^180 run in MPFR whatever D (double's exponent range: r_res falls like
// a^-2.5, the asymptotics use x^2). The lattice result is cross-checked against the global
// search (cross_check.hpp) once, in the first run, for orders up to cross_check_max_order.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/precision.hpp>
#include <gyrores/inscribed/pair_analysis.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

struct verified_pair_options {
  unsigned digits = 17;                 // significant digits of every real, in [1, 10000]
  std::string qdot0 = "1";              // impulse amplitude > 0, decimal text (parsed in each type, correctly rounded)
  solver_choice solver = solver_choice::lattice;
  std::int64_t cross_check_max_order = cross_check_default_max_order;  // 0: no cross-check
};

// One lobe of the paper's asymptotics (asymptotic.hpp): exact integers and flags as computed in
// double (in MPFR at 40 digits for pairs beyond double's range), reals with verified digits.
struct verified_asymptotic_lobe {
  std::string k, m;  // decimal integers
  std::string s, u_asy, theta_asy, theta_c, error, bound, ratio;
  bool holds_global_min = false;
};

// The fields of analyse_pair (pair_analysis.hpp) as D-digit strings.
struct verified_pair_report {
  std::string beat_ratio, n, omega1, omega2, rho0, qdot0;
  std::string r_res, h_min, h_z_max, theta_first, t_first;
  std::vector<std::string> minimisers;  // every global minimiser theta in [0, 2 pi), ascending
  std::string t_min_paper;              // pi/|n|, the paper's proxy for the first-hit time
  bool asymptotic_applicable = false;
  std::string asymptotic_reason;
  std::vector<verified_asymptotic_lobe> lobes;
  std::optional<std::string> r_res_asy, r_res_asy_rel_error;  // when the asymptotics apply
  // Diagnostics (the paper's asymptotics: r_res_asy, r_res_asy_rel_error and the lobes' reals)
  // that did not settle to D digits, by name ("r_res_asy_rel_error", "asymptotic.lobes.<i>.<field>"):
  // d in [1, D) digits settled and the string has d digits, or 0: the string is an estimated
  // bound on |value| (core/verified_digits.hpp). They never block the main fields.
  std::map<std::string, unsigned> unsettled;
  bool degenerate = false;
  std::string method;           // "degenerate-exact", "lattice" or "global-search" (method_name)
  bool cross_checked = false;   // the lattice result was cross-checked against the global search
  unsigned digits = 0;
  precision_plan working_precision;  // the plan whose run produced the digits
};

// Throws usage_error naming `what` unless `text` is a decimal number > 0 (read in MPFR at 30
// digits): the check verify_pair makes on its qdot0, for callers that check their input first.
void check_qdot0_text(const std::string& text, const std::string& what);

// The report of `gyrores pair` for p. Throws usage_error for digits outside [1, 10000] or a
// qdot0 that is not a decimal number > 0; compute_error when the global search is asked beyond
// its order limit (inscribed_global: global_search_options::max_order) or the digits cannot be
// settled.
verified_pair_report verify_pair(const resonant_pair<big_int>& p, const verified_pair_options& opt = {});

// The subset the design, Pareto, coupling and report commands print: qdot0 = 1, the lattice
// method, cross-checked up to the default order. Computed (and verified) on these fields only.
struct verified_pair_values {
  std::string n, r_res, h_min, t_first, theta_first, t_min_paper;
  bool degenerate = false, cross_checked = false;
};

// Throws usage_error for digits outside [1, 10000]; compute_error as verify_pair.
verified_pair_values verify_pair_values(const resonant_pair<big_int>& p, unsigned digits);
verified_pair_values verify_pair_values(std::int64_t tau, std::int64_t sigma, unsigned digits);

// The paper's asymptotic quantities of lobe k of p (asymptotic.hpp), qdot0 = 1, verified to
// `digits` digits (the paper's Case B prints them for (6, 5), k = 6).
struct verified_paper_lobe {
  std::string u_asy, theta_asy, qdot_asy, qdot_asy_over_rho0, error, bound, theta_c, r_c;
};

// Throws usage_error for digits outside [1, 10000]; compute_error when p has no asymptotic lobe
// k (the asymptotics do not apply, or another lobe) or the digits cannot be settled.
verified_paper_lobe verify_paper_lobe(const resonant_pair<big_int>& p, const big_int& k, unsigned digits);

}  // namespace gyrores
