// Controller design over resonant pairs (paper §IV, eqs. design-absorb and design-contain) and
// the Pareto front of (r_res, first-hit time).
//
// Every resonant pair (tau, sigma) fixes a coupling n = (tau - sigma)/sqrt(tau sigma) > 0, an
// inscribed radius r_res and a first-hit time (impulse qdot0 = 1; r_res is linear in qdot0 and
// the times do not depend on it). The design problems, over all pairs up to order M:
//   absorb:  minimise r_res  subject to  time <= T_max
//   contain: maximise r_res  subject to  time <= T_max
// with optional constraints: beat (tau + sigma)/(tau - sigma) >= B (decided exactly, in
// integers), exclusion of the paper's low-order set R_low(L) = {tau + sigma <= L}, and a fixed
// delta = tau - sigma (to follow the paper's Case A reasoning). "time" is the exact first-hit
// time t_first = sqrt(tau sigma) theta_first (default) or the paper's proxy pi/|n|
// (design_time::proxy), so the two choices can be compared.
// Ties in r_res (e.g. r_res = 0 for every delta = 2 mod 4 pair) are broken by the smaller time,
// then the smaller order tau + sigma, then the smaller tau. This tie-break is gyrores' choice;
// the paper's Case A ("preferably as fast as possible") implies it.
//
// Computation: the catalogue evaluates every pair from the lattice theorem in double
// (theorem/minimum.hpp: O(log tau) integers and one root per pair; degenerate pairs are exact
// zeros by integer arithmetic). Decisions that double cannot make safely are made on proved
// 256-bit enclosures (theorem/minimum.hpp): a time within a relative 1e-9 of T_max, and
// neighbouring r_res values within a relative 1e-11 among the reported ranks. The application
// layer (app/design.hpp, report/pair_report.hpp) lists the reported pairs' values proved and correctly rounded.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/rational.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// One resonant pair with the quantities the design problems use (double, qdot0 = 1).
struct design_point {
  std::int64_t tau = 0, sigma = 0;
  double n = 0;         // (tau - sigma)/sqrt(tau sigma)
  double r_res = 0;     // inscribed radius (exactly 0 for degenerate pairs)
  double t_first = 0;   // exact first-hit time sqrt(tau sigma) theta_first
  double t_proxy = 0;   // the paper's proxy pi/|n| = pi sqrt(tau sigma)/(tau - sigma)
  bool degenerate = false;
  std::int64_t order() const { return tau + sigma; }
  std::int64_t delta() const { return tau - sigma; }
  resonant_pair<std::int64_t> pair() const { return resonant_pair<std::int64_t>(tau, sigma); }
};

enum class design_problem { absorb, contain };
enum class design_time { first_hit, proxy };

std::string design_problem_name(design_problem p);  // "absorb", "contain"
std::string design_time_name(design_time t);        // "t_first", "proxy"

// p.t_first or p.t_proxy.
double design_time_of(const design_point& p, design_time t);

// One pair in double (the theorem's minimum; degenerate pairs exactly).
design_point design_point_of(const resonant_pair<std::int64_t>& p);

// Largest order the catalogue accepts: 5000 is ~3.8e6 pairs (~200 MB, ~25 s in double).
inline constexpr std::int64_t design_max_order_limit = 5000;

// Every resonant pair with 3 <= tau + sigma <= max_order, in enumeration order (coprime_pairs).
// Cost: about 3 M^2/(2 pi^2) pairs, each one root in double, ~6.5 us each (M = 200: 6115 pairs,
// 0.04 s; M = 2000: ~6e5 pairs, ~4 s). Throws usage_error outside [3, design_max_order_limit].
std::vector<design_point> design_catalogue(std::int64_t max_order);

// Filters shared by the design problems and the Pareto front.
struct pair_filter {
  std::optional<big_rational> beat_min;   // (tau + sigma)/(tau - sigma) >= beat_min
  std::int64_t exclude_low = 0;           // drop R_low(L): tau + sigma <= exclude_low (0: keep all)
  std::optional<std::int64_t> delta;      // keep only tau - sigma == delta
  bool exclude_degenerate = false;        // drop delta = 2 mod 4 (r_res = 0)
};

// Whether p passes every filter; the beat ratio is compared exactly: a/b >= B = num/den <=>
// a den >= num b (b, den > 0).
bool pair_filter_accepts(const pair_filter& f, const design_point& p);

// time(p) <= tmax, decided in double when the margin is clear (relative 1e-9), else on the proved
// 256-bit enclosure of the time; throws compute_error if even that cannot separate them.
bool design_time_within(const design_point& p, design_time which, const big_rational& tmax);

struct design_options {
  design_problem problem = design_problem::absorb;
  design_time time = design_time::first_hit;
  big_rational tmax = 0;          // > 0 (usage_error otherwise)
  std::int64_t max_order = 200;   // pairs with tau + sigma <= max_order
  pair_filter filter;
  std::size_t candidates = 5;     // how many runners-up to report after the chosen pair
};

struct design_result {
  std::vector<design_point> ranked;  // best first: ranked[0] is the chosen pair; empty if none feasible
  std::size_t examined = 0;          // pairs in the catalogue
  std::size_t feasible = 0;          // pairs meeting every constraint
  bool feasible_any() const { return !ranked.empty(); }
};

// Ranking: the objective (r_res ascending for absorb, descending for contain), then the time
// used by the constraint, then order, then tau. Near-equal r_res among the first `keep` ranks
// are re-ordered with 256-bit values (see the header comment). Throws usage_error unless
// opt.tmax > 0.
design_result design_solve(const std::vector<design_point>& catalogue, const design_options& opt);

// Pareto front of (r_res, time) over a set of pairs.
//   absorb orientation:  lower r_res and lower time are better (the paper's trade-off: deep
//                        exchange costs time);
//   contain orientation: higher r_res and lower time are better.
// A pair is on the front iff no other pair is at least as good in both and strictly better in
// one. Returned by ascending time (then by the objective). Exact ties (same r_res and time) are
// all kept.
enum class pareto_orientation { absorb, contain };

std::vector<design_point> pareto_front(std::vector<design_point> pts, pareto_orientation o, design_time which);

}  // namespace gyrores
