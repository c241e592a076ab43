// include/gyrores/design/design.hpp
#include <gyrores/design/design.hpp>

#include <algorithm>
#include <cmath>

#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/design/coupling.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/model/enumerate.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

std::string design_problem_name(design_problem p) { return p == design_problem::absorb ? "absorb" : "contain"; }
std::string design_time_name(design_time t) { return t == design_time::first_hit ? "t_first" : "proxy"; }

double design_time_of(const design_point& p, design_time t) {
  return t == design_time::first_hit ? p.t_first : p.t_proxy;
}

design_point design_point_of(const resonant_pair<std::int64_t>& p) {
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

std::vector<design_point> design_catalogue(std::int64_t max_order) {
  if (max_order < 3) throw usage_error("max_order must be >= 3 (the smallest pair (2, 1) has order 3), got " + std::to_string(max_order));
  if (max_order > design_max_order_limit)
    throw usage_error("max_order must be <= " + std::to_string(design_max_order_limit) + ", got " + std::to_string(max_order));
  std::vector<design_point> out;
  for (auto p : coprime_pairs(3, max_order)) out.push_back(design_point_of(p));
  return out;
}

bool pair_filter_accepts(const pair_filter& f, const design_point& p) {
  if (f.exclude_low > 0 && p.order() <= f.exclude_low) return false;
  if (f.delta && p.delta() != *f.delta) return false;
  if (f.exclude_degenerate && p.degenerate) return false;
  if (f.beat_min) {
    big_int num = boost::multiprecision::numerator(*f.beat_min), den = boost::multiprecision::denominator(*f.beat_min);
    if (big_int(p.order()) * den < num * big_int(p.delta())) return false;
  }
  return true;
}

namespace {

// High-precision (256-bit) time and radius of one pair, for decisions double cannot make.
struct design_refined {
  mpfr_real r_res, t_first, t_proxy;
};

design_refined design_refine(const design_point& p) {
  scoped_digits d(digits10_for_bits(256));
  auto pr = p.pair();
  auto r = inscribed_lattice<mpfr_real>(pr, mpfr_real(1));
  auto c = resonant_constants_of<mpfr_real>(pr, mpfr_real(1));
  return {r.r_res, r.t_first, mpfr_real(c.pi * c.sqrt_ts / real_from_int<mpfr_real>(pr.delta()))};
}

// The design ranking of two pairs in double: objective, then time, then order, then tau.
struct design_order {
  bool absorb;
  design_time time;
  bool operator()(const design_point& x, const design_point& y) const {
    if (x.r_res != y.r_res) return absorb ? x.r_res < y.r_res : x.r_res > y.r_res;
    double tx = design_time_of(x, time), ty = design_time_of(y, time);
    if (tx != ty) return tx < ty;
    if (x.order() != y.order()) return x.order() < y.order();
    return x.tau < y.tau;
  }
};

// Re-orders ok[i, j) (near-equal r_res in double) by their 256-bit r_res; pairs equal to 2^-200
// keep the double ranking.
void refine_group(std::vector<design_point>& ok, std::size_t i, std::size_t j, const design_order& better) {
  scoped_digits d(digits10_for_bits(256));
  std::vector<std::pair<mpfr_real, design_point>> grp;
  for (std::size_t k = i; k < j; ++k) grp.push_back({design_refine(ok[k]).r_res, ok[k]});
  std::stable_sort(grp.begin(), grp.end(), [&](const auto& x, const auto& y) {
    mpfr_real tol = ldexp(abs(x.first), -200);
    if (abs(x.first - y.first) > tol) return better.absorb ? x.first < y.first : x.first > y.first;
    return better(x.second, y.second);
  });
  for (std::size_t k = i; k < j; ++k) ok[k] = grp[k - i].second;
}

}  // namespace

bool design_time_within(const design_point& p, design_time which, const big_rational& tmax) {
  const double t = design_time_of(p, which);
  const double T = static_cast<double>(tmax.convert_to<long double>());
  if (std::fabs(t - T) > 1e-9 * T) return t <= T;
  scoped_digits d(digits10_for_bits(256));
  auto ref = design_refine(p);
  mpfr_real tt = which == design_time::first_hit ? ref.t_first : ref.t_proxy;
  mpfr_real TT = real_from_rational<mpfr_real>(tmax);
  if (abs(tt - TT) <= ldexp(TT, -200))
    throw compute_error("cannot decide whether the time of (" + std::to_string(p.tau) + ", " + std::to_string(p.sigma) +
                        ") is <= " + rational_str(tmax) + " at 256 bits");
  return tt <= TT;
}

design_result design_solve(const std::vector<design_point>& catalogue, const design_options& opt) {
  if (!(opt.tmax > 0)) throw usage_error("tmax must be > 0, got " + rational_str(opt.tmax));
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
  const design_order better{opt.problem == design_problem::absorb, opt.time};
  std::sort(ok.begin(), ok.end(), better);
  const std::size_t keep = std::min(ok.size(), opt.candidates + 1);
  // Refine groups of near-equal non-zero r_res that reach into the reported ranks.
  for (std::size_t i = 0; i < keep;) {
    std::size_t j = i + 1;
    while (j < ok.size() && ok[i].r_res > 0 && std::fabs(ok[j].r_res - ok[j - 1].r_res) <= 1e-11 * ok[i].r_res) ++j;
    if (j - i > 1) refine_group(ok, i, j, better);
    i = j;
  }
  ok.resize(keep);
  res.ranked = std::move(ok);
  return res;
}

std::vector<design_point> pareto_front(std::vector<design_point> pts, pareto_orientation o, design_time which) {
  const bool absorb = o == pareto_orientation::absorb;
  auto better_r = [&](double x, double y) { return absorb ? x < y : x > y; };
  std::sort(pts.begin(), pts.end(), [&](const design_point& x, const design_point& y) {
    double tx = design_time_of(x, which), ty = design_time_of(y, which);
    if (tx != ty) return tx < ty;
    if (x.r_res != y.r_res) return better_r(x.r_res, y.r_res);
    return x.order() < y.order();
  });
  std::vector<design_point> front;
  for (const auto& p : pts) {
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
