// include/gyrores/design/design.hpp
#include <gyrores/design/design.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

#include <gyrores/core/error.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/model/enumerate.hpp>
#include <gyrores/theorem/minimum.hpp>

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
  const auto m = theorem_minimum_double(p);
  d.r_res = m.r_res;
  d.t_first = m.t_first;
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

// Proved enclosures of one pair's r_res, t_first and proxy time pi sqrt(tau sigma)/delta at
// 256 bits (theorem/minimum.hpp), for the decisions double cannot make.
constexpr mpfr_prec_t refine_bits = 256;
struct design_refined {
  design_refined() : r_res(refine_bits), t_first(refine_bits), t_proxy(refine_bits) {}
  fixed_mpfi r_res, t_first, t_proxy;
};

std::unique_ptr<design_refined> design_refine(const design_point& p) {
  const resonant_pair<big_int> pr(big_int(p.tau), big_int(p.sigma));
  theorem_constants K(refine_bits, pr);
  fixed_mpfi v(refine_bits);
  mpfi_set_ui(v, 1);
  minimum_enclosure m(refine_bits);
  if (!prove_minimum(m, K, pr, v))
    throw compute_error("design: the minimum of " + pr.str() + " was not proved at 256 bits");
  auto out = std::make_unique<design_refined>();
  mpfi_set(out->r_res, m.r_res);
  mpfi_mul(out->t_first, K.sqrt_ts, *m.minimisers.front());
  mpfi_mul(out->t_proxy, K.pi, K.sqrt_ts);
  mpfi_div(out->t_proxy, out->t_proxy, K.b);
  return out;
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

// Re-orders ok[i, j) (near-equal r_res in double) by their proved 256-bit r_res; pairs whose
// enclosures overlap keep the double ranking.
void refine_group(std::vector<design_point>& ok, std::size_t i, std::size_t j, const design_order& better) {
  std::vector<std::pair<std::unique_ptr<design_refined>, design_point>> grp;
  for (std::size_t k = i; k < j; ++k) grp.emplace_back(design_refine(ok[k]), ok[k]);
  std::stable_sort(grp.begin(), grp.end(), [&](const auto& x, const auto& y) {
    const fixed_mpfi &rx = x.first->r_res, &ry = y.first->r_res;
    if (mpfr_cmp(rx.right(), ry.left()) < 0) return better.absorb;   // rx < ry, proved
    if (mpfr_cmp(ry.right(), rx.left()) < 0) return !better.absorb;  // ry < rx, proved
    return better(x.second, y.second);
  });
  for (std::size_t k = i; k < j; ++k) ok[k] = grp[k - i].second;
}

}  // namespace

bool design_time_within(const design_point& p, design_time which, const big_rational& tmax) {
  const double t = design_time_of(p, which);
  const double T = static_cast<double>(tmax.convert_to<long double>());
  if (std::fabs(t - T) > 1e-9 * T) return t <= T;
  const auto ref = design_refine(p);
  const fixed_mpfi& tt = which == design_time::first_hit ? ref->t_first : ref->t_proxy;
  fixed_mpfi TT(refine_bits);
  mpfi_set_q(TT, tmax.backend().data());
  if (mpfr_cmp(tt.right(), TT.left()) <= 0) return true;
  if (mpfr_cmp(tt.left(), TT.right()) > 0) return false;
  throw compute_error("cannot decide whether the time of (" + std::to_string(p.tau) + ", " + std::to_string(p.sigma) +
                      ") is <= " + rational_str(tmax) + " at 256 bits");
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
