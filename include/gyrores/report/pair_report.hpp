// Everything `gyrores pair` (and the design, Pareto, coupling and report commands, and the Python
// module) prints about one resonant pair, every real proved.
//
// Each real is the correct rounding, to nearest with `digits` significant digits, of its exact
// value, read off a proved enclosure of the theorem (MPFI at an explicit precision,
// theorem/minimum.hpp, the roots by theorem/root.hpp): the enclosures are computed at a
// precision that starts with 32 guard bits (more where a field cancels, e.g. the paper's error
// theta_c - theta_asy), and the precision doubles (core/refine.hpp) until both ends of every
// enclosure round to the same text (core/decimal.hpp, enclosure_rounding). This file is where the
// pair's reals become digits. Fields whose exact value is a rational (the beat ratio a/b, qdot0, n and
// rho0 when tau sigma is a square, omega1 and omega2 when tau and sigma are, H_z max of a
// degenerate pair, and the zeros) are rounded once from that rational, ties to even (an exact
// tie could never be decided by an enclosure). Each real also carries its enclosure [lo, hi],
// rounded outward to digits + 3 significant digits.
//
// The paper's asymptotics (x = b/a < 1/2): per fast node k = round(a/(2b)) (both on a tie, b = 1)
// the integers k and m = a - 2kb, s = pi m/(2b), u_asy (u + tan u = s), theta_asy = 2 (k pi +
// u_asy)/a, the lobe root theta_c = 2 (k pi + u_c)/a with u_c = sign(m) H^{-1}(pi |m|/(2a)), the
// error |theta_c - theta_asy|, the paper's bound pi^3 x^2/a and their ratio; whether the lobe
// holds a global minimiser (|m| = m_min, by the theorem); and r_res_asy = v x |sin u_a tan u_a|
// (u_a + tan u_a = pi m_min/(2b), the x -> 0 limit) with its relative error against r_res. All of
// them are proved enclosures rounded, like the rest.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// One lobe of the paper's asymptotics.
struct paper_lobe_report {
  big_int k, m;
  bool holds_global_min = false;
  proved_real s, u_asy, theta_asy, theta_c, error, bound, ratio;
};

struct pair_report_options {
  unsigned digits = 17;      // significant digits of every real, in [1, report_digits_max]
  big_rational qdot0 = 1;    // impulse amplitude v > 0, exactly
  bool asymptotics = true;   // the paper's asymptotics (the pair values of design, Pareto, coupling skip them)
  bool enclosures = false;   // fill proved_real::enclosure (decimal text costs as much as the roundings)
  bool doubles = false;      // fill proved_real::nearest: the precision also rises until each double is decided
  stop_token stop;           // looked at before each precision (throws `interrupted`, core/stop.hpp)
};

struct pair_report {
  unsigned digits = 0;
  unsigned bits = 0;  // the precision of the enclosures that decided every rounding
  bool degenerate = false;
  int m_min = 0;
  proved_real beat_ratio, n, omega1, omega2, rho0, qdot0;
  proved_real r_res, h_min, h_z_max, theta_first, t_first;
  proved_real h_min_share;  // H_q min as a percentage of H_q(0) = qdot0^2/2, min(digits, share_digits) digits (report/scales.hpp)
  std::vector<proved_real> minimisers;  // every global minimiser theta in [0, 2 pi), ascending
  proved_real t_min_paper;              // pi/|n|: the paper's proxy for the first-hit time
  bool asymptotic_applicable = false;
  std::string asymptotic_reason;        // why not applicable, or remarks (tie, degenerate pair)
  std::vector<paper_lobe_report> lobes;
  std::optional<proved_real> r_res_asy, r_res_asy_rel_error;
};

// The report of p. usage_error for digits outside [1, report_digits_max] or qdot0 <= 0;
// compute_error only if some rounding is still undecided at report_bits_cap (a resource limit,
// named in the message), never a wrong digit; `interrupted` when opt.stop is requested (checked
// before each doubling of the precision).
pair_report prove_pair(const resonant_pair<big_int>& p, const pair_report_options& opt = {});

// The values the design, Pareto, coupling and report commands list: prove_pair without the
// asymptotics, with the enclosures.
pair_report prove_pair_values(const resonant_pair<big_int>& p, unsigned digits, const big_rational& qdot0 = 1,
                              stop_token stop = {});

// The paper's Case B quantities of its lobe k of p (qdot0 = 1): u_asy, theta_asy, q'(theta_asy)
// (= (-1)^k cos u_asy cos w (tan w - w), w = x tan u_asy), q'(theta_asy)/rho0, the error and
// bound, theta_c and r_c = sqrt(G(u_c)) (the lobe's candidate for r_res). usage_error for
// digits outside [1, report_digits_max]; compute_error when k is not a fast node of p (x >= 1/2, or another
// k) or as prove_pair.
struct paper_lobe_detail {
  proved_real u_asy, theta_asy, qdot_asy, qdot_asy_over_rho0, error, bound, theta_c, r_c;
};
paper_lobe_detail prove_paper_lobe(const resonant_pair<big_int>& p, const big_int& k, unsigned digits);

}  // namespace gyrores
