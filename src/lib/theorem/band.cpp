// include/gyrores/theorem/band.hpp
#include <gyrores/theorem/band.hpp>

#include <arb.h>

#include <cmath>
#include <queue>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/model/coupling.hpp>

#include "arb_ball.hpp"

namespace gyrores {
namespace {

using namespace arb_support;

constexpr slong lip_prec = 128;

// sin and cos of a ball, each clipped to [-1, 1] (Arb may return wider balls for wide arguments).
void sin_cos_clipped(arb_t s, arb_t c, const arb_t a) {
  arb_sin_cos(s, c, a, lip_prec);
  ball unit;
  arb_zero_pm_one(unit);
  if (!arb_is_finite(s) || !arb_contains(unit, s)) arb_set(s, unit);
  if (!arb_is_finite(c) || !arb_contains(unit, c)) arb_set(c, unit);
}

// An upper bound of |dH_q/dn| for t in [0, T] and n in [n1, n2] (qdot0 = 1). With s = sqrt(n^2 + 4),
// x = n/s, c = 2/s, alpha = s t/2, beta = n t/2: q = c sin(alpha) cos(beta), q' = cos(alpha) cos(beta)
// - x sin(alpha) sin(beta), H_q = (q^2 + q'^2)/2, and d alpha/dn = x t/2, d beta/dn = t/2,
// dx/dn = 4/s^3, dc/dn = -2n/s^3, so dH_q/dn = q dq/dn + q' dq'/dn, evaluated over the box.
big_rational lipschitz_bound(const big_rational& n1, const big_rational& n2, const horizon_time& T) {
  const slong p = lip_prec;
  ball n, t, lo, hi, s, x, c, s3, dx, dc, a, b, da, db, sa, ca, sb, cb, q, qd, dq, dqd, tmp, out;
  set_rational(lo, n1, p);
  set_rational(hi, n2, p);
  arb_union(n, lo, hi, p);
  set_rational(hi, T.value, p);
  if (T.times_pi) {
    ball pi;
    arb_const_pi(pi, p);
    arb_mul(hi, hi, pi, p);
  }
  arb_zero(lo);
  arb_union(t, lo, hi, p);
  arb_mul(s, n, n, p);
  arb_add_si(s, s, 4, p);
  arb_sqrt(s, s, p);
  arb_div(x, n, s, p);
  arb_set_si(c, 2);
  arb_div(c, c, s, p);
  arb_mul(s3, s, s, p);
  arb_mul(s3, s3, s, p);
  arb_set_si(dx, 4);
  arb_div(dx, dx, s3, p);
  arb_mul_si(dc, n, -2, p);
  arb_div(dc, dc, s3, p);
  arb_mul(a, s, t, p);
  arb_mul_2exp_si(a, a, -1);
  arb_mul(b, n, t, p);
  arb_mul_2exp_si(b, b, -1);
  arb_mul(da, x, t, p);
  arb_mul_2exp_si(da, da, -1);
  arb_mul_2exp_si(db, t, -1);
  sin_cos_clipped(sa, ca, a);
  sin_cos_clipped(sb, cb, b);
  // q and dq/dn
  arb_mul(q, sa, cb, p);
  arb_mul(q, q, c, p);
  arb_mul(dq, sa, cb, p);
  arb_mul(dq, dq, dc, p);
  arb_mul(tmp, ca, cb, p);
  arb_mul(tmp, tmp, da, p);
  ball tmp2;
  arb_mul(tmp2, sa, sb, p);
  arb_mul(tmp2, tmp2, db, p);
  arb_sub(tmp, tmp, tmp2, p);
  arb_mul(tmp, tmp, c, p);
  arb_add(dq, dq, tmp, p);
  // q' and dq'/dn
  arb_mul(qd, ca, cb, p);
  arb_mul(tmp, sa, sb, p);
  arb_mul(tmp, tmp, x, p);
  arb_sub(qd, qd, tmp, p);
  arb_mul(dqd, sa, cb, p);
  arb_mul(dqd, dqd, da, p);
  arb_mul(tmp, ca, sb, p);
  arb_mul(tmp, tmp, db, p);
  arb_add(dqd, dqd, tmp, p);
  arb_neg(dqd, dqd);
  arb_mul(tmp, sa, sb, p);
  arb_mul(tmp, tmp, dx, p);
  arb_sub(dqd, dqd, tmp, p);
  arb_mul(tmp, ca, sb, p);
  arb_mul(tmp, tmp, da, p);
  arb_mul(tmp2, sa, cb, p);
  arb_mul(tmp2, tmp2, db, p);
  arb_add(tmp, tmp, tmp2, p);
  arb_mul(tmp, tmp, x, p);
  arb_sub(dqd, dqd, tmp, p);
  arb_mul(out, q, dq, p);
  arb_mul(tmp, qd, dqd, p);
  arb_add(out, out, tmp, p);
  arf_t bound;
  arf_init(bound);
  arb_get_abs_ubound_arf(bound, out, p);
  fmpz_holder man, exp;
  arf_get_fmpz_2exp(man, exp, bound);
  arf_clear(bound);
  const big_int m = man.value(), e = exp.value();
  if (!arb_is_finite(out)) throw compute_error("band: no finite bound of dH_q/dn");
  if (e >= 0) return big_rational(big_int(m << static_cast<unsigned>(e.convert_to<long>())));
  return big_rational(m, big_int(1) << static_cast<unsigned>((-e).convert_to<long>()));
}

// A degenerate pair in the band whose zero t = pi sqrt(4k^2 - o^2)/2 (x = o/(2k), o odd) lies in
// [0, T]: the smallest k with such an o, taking the largest o (the earliest zero for that k).
// Some k <= 1/(x2 - x1) + 1 holds an odd o in [2k x1, 2k x2]; larger k have later zeros, so the
// search ends there or at the last k whose zero could lie in [0, T].
std::optional<band_degenerate> find_degenerate(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                               const stop_token& stop) {
  const quadratic_number x1 = coupling_rotation_number(coupling_spec::from_n(n1)),
                         x2 = coupling_rotation_number(coupling_spec::from_n(n2));
  const double w = x2.approx() - x1.approx(), T_d = T.value.convert_to<double>() * (T.times_pi ? M_PI : 1.0);
  const double sqrt1mx2 = std::sqrt(std::max(0.0, 1 - x2.approx() * x2.approx()));
  // t ~ pi k sqrt(1 - x^2) >= pi k sqrt(1 - x2^2) (rounded generously).
  const double k_time = sqrt1mx2 > 0 ? T_d / (M_PI * sqrt1mx2 * (1 - 1e-9)) + 2 : 1e18;
  const double k_last = std::min(k_time, 1 / w + 2);
  for (long k = 1; double(k) <= k_last; ++k) {
    if (k % 4096 == 0) stop.throw_if_requested();
    big_int o = (quadratic_number(2 * k) * x2).floor();
    if (o % 2 == 0) o -= 1;
    if (o < 1 || quadratic_number(o, 2 * k) < x1) continue;
    // The zero's time pi sqrt(4k^2 - o^2)/2 against T, in Arb.
    const big_int r2 = big_int(4) * k * k - o * o;
    for (slong p = 128; p <= (slong(1) << 16); p *= 2) {
      ball t, hT, pi;
      set_int(t, r2);
      arb_sqrt(t, t, p);
      arb_mul_2exp_si(t, t, -1);
      arb_const_pi(pi, p);
      set_rational(hT, T.value, p);
      if (T.times_pi) arb_mul(hT, hT, pi, p);
      arb_mul(t, t, pi, p);
      if (arb_gt(t, hT)) break;
      if (arb_le(t, hT)) {
        const big_rational n2_exact(4 * o * o, r2);
        const auto pair = coupling_resonant_pair(coupling_spec::from_n2(n2_exact));
        if (!pair) throw compute_error("band: x = " + o.str() + "/" + std::to_string(2 * k) + " gave no pair");
        return band_degenerate{n2_exact, *pair, prove_pair_values(*pair, 12).t_first};
      }
    }
  }
  return std::nullopt;
}

struct box {
  big_rational a, b;
  big_rational m_lo, m_hi;  // enclosure of M at the midpoint
  big_rational bound;       // m_hi + L h/2 (worst) or m_lo - L h/2 (best)
};

std::pair<big_rational, big_rational> minimum_at(const big_rational& n, const horizon_time& T, const stop_token& stop) {
  const horizon_minimum_report r = prove_horizon_minimum(coupling_spec::from_n(n), T, 17, stop);
  return {parse_rational(r.h_min.enclosure.first, "h"), parse_rational(r.h_min.enclosure.second, "h")};
}

std::string rounding_of(const big_rational& lo, const big_rational& hi, unsigned digits) {
  const std::string a = format_rational_scientific(lo, digits), b = format_rational_scientific(hi, digits);
  return a == b ? a : std::string();
}

// Branch and bound for max (worst = true) or min of M over [n1, n2].
band_extreme extreme(const big_rational& n1, const big_rational& n2, const horizon_time& T, const big_rational& L,
                     const band_options& opt, bool worst, std::size_t& evaluations) {
  const std::size_t start = evaluations;
  auto cmp = [worst](const box& x, const box& y) { return worst ? x.bound < y.bound : x.bound > y.bound; };
  std::priority_queue<box, std::vector<box>, decltype(cmp)> open(cmp);
  band_extreme e;
  bool have = false;
  big_rational best_lo, best_hi;  // the best proved value's enclosure (max of m_lo / min of m_hi)
  auto consider_point = [&](const big_rational& n, const big_rational& lo, const big_rational& hi, const big_rational& a,
                            const big_rational& b) {
    const bool better = !have || (worst ? lo > best_lo : hi < best_hi);
    if (better) {
      have = true;
      best_lo = lo;
      best_hi = hi;
      e.n_at = n;
      e.n_box_lo = a;
      e.n_box_hi = b;
    }
  };
  auto push = [&](const big_rational& a, const big_rational& b) {
    const big_rational mid = (a + b) / 2;
    auto [lo, hi] = minimum_at(mid, T, opt.stop);
    ++evaluations;
    consider_point(mid, lo, hi, a, b);
    const big_rational slack = L * (b - a) / 2;
    box bx{a, b, lo, hi, worst ? big_rational(hi + slack) : big_rational(lo - slack)};
    if (!worst && bx.bound < 0) bx.bound = 0;
    open.push(bx);
  };
  // The band's ends are couplings too.
  for (const big_rational& n : {n1, n2}) {
    auto [lo, hi] = minimum_at(n, T, opt.stop);
    ++evaluations;
    consider_point(n, lo, hi, n, n);
  }
  push(n1, n2);
  const big_rational rel = big_rational(1, boost::multiprecision::pow(big_int(10), opt.digits));
  for (;;) {
    opt.stop.throw_if_requested();
    const box top = open.top();
    // The extreme lies between the best proved value and the best remaining bound.
    e.lo = worst ? best_lo : top.bound;
    e.hi = worst ? top.bound : best_hi;
    if (worst && e.hi < best_hi) e.hi = best_hi;
    if (!worst && e.lo > best_lo) e.lo = best_lo;
    const big_rational width = e.hi - e.lo, scale = worst ? e.hi : e.hi;
    if (width <= rel * scale || width <= 0) {
      e.converged = true;
      break;
    }
    if (evaluations - start + 2 > opt.max_evaluations) break;
    open.pop();
    // Where the bound comes from, the extreme may be: record the box.
    const big_rational mid = (top.a + top.b) / 2;
    push(top.a, mid);
    push(mid, top.b);
  }
  if (!worst && e.lo < 0) e.lo = 0;
  e.value = rounding_of(e.lo, e.hi, opt.digits);
  return e;
}

}  // namespace

void check_band(const big_rational& n1, const big_rational& n2, const std::string& what) {
  if (!(n1 > 0) || !(n2 > n1)) throw usage_error(what + " needs 0 < n1 < n2, got " + rational_str(n1) + ":" + rational_str(n2));
}

std::pair<big_rational, big_rational> parse_band(const std::string& text, const std::string& what) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw usage_error(what + " must be N1:N2, got " + text);
  return {parse_rational(text.substr(0, colon), what + " N1"), parse_rational(text.substr(colon + 1), what + " N2")};
}

std::pair<big_rational, big_rational> parse_tolerance_band(const big_rational& n, const std::string& tolerance,
                                                           const std::string& what) {
  std::string t = tolerance;
  if (t.empty() || t.back() != '%') throw usage_error(what + " must be a percentage such as 1%, got " + tolerance);
  t.pop_back();
  const big_rational p = parse_rational(t, what) / 100;
  if (!(p > 0) || !(p < 1)) throw usage_error(what + " must be in (0%, 100%), got " + tolerance);
  const big_rational an = n < 0 ? big_rational(-n) : n;
  return {big_rational(an * (1 - p)), big_rational(an * (1 + p))};
}

band_report prove_band(const big_rational& n1, const big_rational& n2, const horizon_time& T, const band_options& opt) {
  check_band(n1, n2, "a band");
  if (T.value < 0) throw usage_error("the horizon must be >= 0, got " + T.str());
  if (opt.digits < 1 || opt.digits > 12) throw usage_error("band digits must be in [1, 12], got " + std::to_string(opt.digits));
  band_report r;
  r.n1 = n1;
  r.n2 = n2;
  r.horizon = T;
  r.digits = opt.digits;
  const big_rational L = lipschitz_bound(n1, n2, T);
  r.lipschitz = format_rational_scientific(L, 6);
  if (opt.want_worst) r.worst = extreme(n1, n2, T, L, opt, true, r.evaluations);
  if (!opt.want_best) return r;
  r.zero = find_degenerate(n1, n2, T, opt.stop);
  if (r.zero) {
    r.best.lo = r.best.hi = 0;
    r.best.value = format_rational_scientific(big_rational(0), opt.digits);
    r.best.n_at = 0;
    r.best.converged = true;
  } else r.best = extreme(n1, n2, T, L, opt, false, r.evaluations);
  return r;
}

}  // namespace gyrores
