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
// Computation: the catalogue evaluates every pair with the lattice method in double (O(log tau)
// per pair; degenerate pairs are exact zeros by integer arithmetic). Decisions that double
// cannot make safely are refined in MPFR (256 bits): a time within a relative 1e-9 of T_max,
// and neighbouring r_res values within a relative 1e-11 among the reported ranks. The lattice
// method's minimiser location is *observed* (lattice.hpp STATUS); the CLI prints the reported
// pairs with verified digits from analyse_pair, which cross-checks the lattice against the
// global search for orders up to 20000.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/design/coupling.hpp>
#include <gyrores/model/enumerate.hpp>
#include <gyrores/inscribed/lattice.hpp>
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

inline std::string design_problem_name(design_problem p) { return p == design_problem::absorb ? "absorb" : "contain"; }
inline std::string design_time_name(design_time t) { return t == design_time::first_hit ? "t_first" : "proxy"; }

inline double design_time_of(const design_point& p, design_time t) {
  return t == design_time::first_hit ? p.t_first : p.t_proxy;
}

// One pair in double (lattice method; degenerate pairs exactly).
inline design_point design_point_of(const resonant_pair<std::int64_t>& p) {
  design_point d;
  d.tau = p.tau();
  d.sigma = p.sigma();
  const double st = std::sqrt(double(p.tau())) * std::sqrt(double(p.sigma()));
  d.n = double(p.delta()) / st;
  d.t_proxy = real_pi<double>() * st / double(p.delta());
  d.degenerate = p.degenerate();
  auto r = inscribed_lattice<double>(p, 1.0);
  d.r_res = r.r_res;
  d.t_first = r.t_first;
  return d;
}

// Largest order the catalogue accepts: 5000 is ~3.8e6 pairs (~200 MB, ~25 s in double).
inline constexpr std::int64_t design_max_order_limit = 5000;

// Every resonant pair with 3 <= tau + sigma <= max_order, in enumeration order (coprime_pairs).
// Cost: about 3 M^2/(2 pi^2) lattice evaluations in double, ~6.5 us each (M = 200: 6115 pairs,
// 0.04 s; M = 2000: ~6e5 pairs, ~4 s). Throws usage_error outside [3, design_max_order_limit].
inline std::vector<design_point> design_catalogue(std::int64_t max_order) {
  if (max_order < 3) throw usage_error("--max-order must be >= 3 (the smallest pair (2, 1) has order 3)");
  if (max_order > design_max_order_limit)
    throw usage_error("--max-order must be <= " + std::to_string(design_max_order_limit) + ", got " + std::to_string(max_order));
  std::vector<design_point> out;
  for (auto p : coprime_pairs(3, max_order)) out.push_back(design_point_of(p));
  return out;
}

// Filters shared by the design problems and the Pareto front.
struct pair_filter {
  std::optional<big_rational> beat_min;   // (tau + sigma)/(tau - sigma) >= beat_min
  std::int64_t exclude_low = 0;           // drop R_low(L): tau + sigma <= exclude_low (0: keep all)
  std::optional<std::int64_t> delta;      // keep only tau - sigma == delta
  bool exclude_degenerate = false;        // drop delta = 2 mod 4 (r_res = 0)
};

// Exact: beat = a/b >= B = num/den  <=>  a den >= num b (b, den > 0).
inline bool pair_filter_accepts(const pair_filter& f, const design_point& p) {
  if (f.exclude_low > 0 && p.order() <= f.exclude_low) return false;
  if (f.delta && p.delta() != *f.delta) return false;
  if (f.exclude_degenerate && p.degenerate) return false;
  if (f.beat_min) {
    big_int num = boost::multiprecision::numerator(*f.beat_min), den = boost::multiprecision::denominator(*f.beat_min);
    if (big_int(p.order()) * den < num * big_int(p.delta())) return false;
  }
  return true;
}

namespace detail {
// High-precision (256-bit) time and radius of one pair, for decisions double cannot make.
struct design_refined {
  mpfr_real r_res, t_first, t_proxy;
};
inline design_refined design_refine(const design_point& p) {
  scoped_digits d(digits10_for_bits(256));
  auto pr = p.pair();
  auto r = inscribed_lattice<mpfr_real>(pr, mpfr_real(1));
  auto c = resonant_constants_of<mpfr_real>(pr, mpfr_real(1));
  return {r.r_res, r.t_first, mpfr_real(c.pi * c.sqrt_ts / real_from_int<mpfr_real>(pr.delta()))};
}
inline mpfr_real rational_to_mpfr(const big_rational& q) {
  return real_from_int<mpfr_real>(big_int(boost::multiprecision::numerator(q))) /
         real_from_int<mpfr_real>(big_int(boost::multiprecision::denominator(q)));
}
}  // namespace detail

// time(p) <= tmax, decided in double when the margin is clear (relative 1e-9), else in MPFR at
// 256 bits; throws compute_error if even that cannot separate them (relative 2^-200).
inline bool design_time_within(const design_point& p, design_time which, const big_rational& tmax) {
  const double t = design_time_of(p, which);
  const double T = static_cast<double>(tmax.convert_to<long double>());
  if (std::fabs(t - T) > 1e-9 * T) return t <= T;
  scoped_digits d(digits10_for_bits(256));
  auto ref = detail::design_refine(p);
  mpfr_real tt = which == design_time::first_hit ? ref.t_first : ref.t_proxy;
  mpfr_real TT = detail::rational_to_mpfr(tmax);
  if (abs(tt - TT) <= ldexp(TT, -200))
    throw compute_error("cannot decide whether the time of (" + std::to_string(p.tau) + ", " + std::to_string(p.sigma) +
                        ") is <= " + rational_str(tmax) + " at 256 bits");
  return tt <= TT;
}

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
// are re-ordered with 256-bit values (see the header comment).
inline design_result design_solve(const std::vector<design_point>& catalogue, const design_options& opt) {
  if (!(opt.tmax > 0)) throw usage_error("--tmax must be > 0, got " + rational_str(opt.tmax));
  design_result res;
  res.examined = catalogue.size();
  std::vector<design_point> ok;
  for (const auto& p : catalogue) {
    if (p.order() > opt.max_order) continue;
    if (!pair_filter_accepts(opt.filter, p)) continue;
    if (!design_time_within(p, opt.time, opt.tmax)) continue;
    ok.push_back(p);
  }
  res.feasible = ok.size();
  const bool absorb = opt.problem == design_problem::absorb;
  auto better = [&](const design_point& x, const design_point& y) {
    if (x.r_res != y.r_res) return absorb ? x.r_res < y.r_res : x.r_res > y.r_res;
    double tx = design_time_of(x, opt.time), ty = design_time_of(y, opt.time);
    if (tx != ty) return tx < ty;
    if (x.order() != y.order()) return x.order() < y.order();
    return x.tau < y.tau;
  };
  std::sort(ok.begin(), ok.end(), better);
  const std::size_t keep = std::min(ok.size(), opt.candidates + 1);
  // Refine groups of near-equal non-zero r_res that reach into the reported ranks.
  for (std::size_t i = 0; i < keep;) {
    std::size_t j = i + 1;
    while (j < ok.size() && ok[i].r_res > 0 && std::fabs(ok[j].r_res - ok[j - 1].r_res) <= 1e-11 * ok[i].r_res) ++j;
    if (j - i > 1) {
      scoped_digits d(digits10_for_bits(256));
      std::vector<std::pair<mpfr_real, design_point>> grp;
      for (std::size_t k = i; k < j; ++k) grp.push_back({detail::design_refine(ok[k]).r_res, ok[k]});
      std::stable_sort(grp.begin(), grp.end(), [&](const auto& x, const auto& y) {
        mpfr_real tol = ldexp(abs(x.first), -200);
        if (abs(x.first - y.first) > tol) return absorb ? x.first < y.first : x.first > y.first;
        return better(x.second, y.second);
      });
      for (std::size_t k = i; k < j; ++k) ok[k] = grp[k - i].second;
    }
    i = j;
  }
  ok.resize(keep);
  res.ranked = std::move(ok);
  return res;
}

// Pareto front of (r_res, time) over a set of pairs.
//   absorb orientation:  lower r_res and lower time are better (the paper's trade-off: deep
//                        exchange costs time);
//   contain orientation: higher r_res and lower time are better.
// A pair is on the front iff no other pair is at least as good in both and strictly better in
// one. Returned by ascending time (then by the objective). Exact ties (same r_res and time) are
// all kept.
enum class pareto_orientation { absorb, contain };

inline std::vector<design_point> pareto_front(std::vector<design_point> pts, pareto_orientation o, design_time which) {
  const bool absorb = o == pareto_orientation::absorb;
  auto better_r = [&](double x, double y) { return absorb ? x < y : x > y; };
  std::sort(pts.begin(), pts.end(), [&](const design_point& x, const design_point& y) {
    double tx = design_time_of(x, which), ty = design_time_of(y, which);
    if (tx != ty) return tx < ty;
    if (x.r_res != y.r_res) return better_r(x.r_res, y.r_res);
    return x.order() < y.order();
  });
  std::vector<design_point> front;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    if (front.empty()) {
      front.push_back(p);
      continue;
    }
    const auto& last = front.back();
    double tp = design_time_of(p, which), tl = design_time_of(last, which);
    if (better_r(p.r_res, last.r_res)) front.push_back(p);               // slower but better radius
    else if (p.r_res == last.r_res && tp == tl) front.push_back(p);      // exact tie with a front point
  }
  return front;
}

}  // namespace gyrores
