// include/gyrores/theorem/band.hpp; the argument is proofs/band-theorem.md (cited "item k").
#include <gyrores/theorem/band.hpp>

#include <arb.h>

#include <algorithm>
#include <queue>
#include <set>
#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/core/refine.hpp>
#include <gyrores/model/fractions.hpp>
#include <gyrores/model/rotation.hpp>

#include "../core/ball.hpp"
#include "band_evaluate.hpp"

namespace gyrores {

band_coupling band_coupling::of_n(const big_rational& n) {
  band_coupling c{coupling_spec::from_n(n), {}};
  c.x = coupling_rotation_number(c.spec);
  return c;
}

band_coupling band_coupling::of_x(const big_int& p, const big_int& q) {
  if (!(p > 0) || !(q > p)) throw usage_error("band_coupling::of_x needs 0 < p/q < 1");
  return {coupling_spec::from_n2(big_rational(4 * p * p, big_int(q * q - p * p))), quadratic_number(p, q)};
}

namespace {

using namespace arb_support;
using band_detail::band_arith;
using band_detail::precision_shortfall;

// u < v for numbers of two quadratic fields (the band's ends lie in different ones), exactly.
bool less_than(const quadratic_number& u, const quadratic_number& v) { return compare(u, v) < 0; }
const quadratic_number& larger(const quadratic_number& u, const quadratic_number& v) { return less_than(u, v) ? v : u; }

// ---- intervals of the band and where to split them ----

struct interval {
  band_coupling a, b;
  big_rational bound;               // upper (absorption) or lower (containment) bound of M, R units
  std::vector<fraction> splits;     // where the structure says to split (empty: split near the middle)
  std::size_t serial = 0;           // creation order: ties of the bound go to the older interval
  band_cover_interval how;          // which bound of item 4, for a certificate
};

// An odd-denominator fraction at an interval's end that is a peak of f_K (Q <= 2K - 1, item 3).
std::optional<fraction> end_peak(const band_coupling& c, const big_int& K) {
  if (!c.x.is_rational()) return std::nullopt;
  const fraction f{c.x.p(), c.x.r()};  // p/r (q = 0 in c.x)
  if (f.q % 2 == 0 || f.q > 2 * K - 1) return std::nullopt;
  return f;
}

// The split points that the structure gives (item 3): the least-denominator fraction of (a, b)
// when its denominator is <= 2K (a centre, or a peak with its piece's two centres), and the piece
// ends of a peak at either end. Sorted, strictly inside (a, b), without repeats.
std::vector<fraction> structural_splits(const band_coupling& a, const band_coupling& b, const big_int& K) {
  std::vector<fraction> out;
  if (K < 1) return out;
  const simplest_fraction s = simplest_in(a.x, b.x);
  std::vector<fraction> peaks;
  if (s.simplest.q <= 2 * K) {
    out.push_back(s.simplest);
    if (s.simplest.q % 2 != 0) peaks.push_back(s.simplest);
  }
  for (const band_coupling* e : {&a, &b})
    if (auto p = end_peak(*e, K)) peaks.push_back(*p);
  for (const fraction& p : peaks) {
    const peak_piece piece = peak_piece_of(p, K);
    for (const fraction& c : {piece.left, piece.right})
      if (a.x < c.value() && c.value() < b.x) out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const fraction& u, const fraction& v) { return u.p * v.q < v.p * u.q; });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// ---- the branch and bound (one extreme) ----

enum class extreme { absorption, containment };

class search {
 public:
  search(const band_coupling& x1, const band_coupling& x2, const horizon_time& T, const band_options& opt, extreme which,
         slong prec)
      : arith_(T, prec), opt_(opt), which_(which), ends_{x1, x2} {}

  band_extreme run();
  // Item 4's bound of one interval, with the kind it took.
  band_cover_interval bound_only(const band_coupling& a, const band_coupling& b) { return cover_of(bound_of(a, b)); }

 private:
  bool absorption() const { return which_ == extreme::absorption; }
  // Better in the direction of the extreme.
  bool better(const big_rational& u, const big_rational& v) const { return absorption() ? u > v : u < v; }

  void evaluate(const band_coupling& c);
  interval bound_of(const band_coupling& a, const band_coupling& b);
  interval absorption_bound(const band_coupling& a, const band_coupling& b);
  interval containment_bound(const band_coupling& a, const band_coupling& b);
  fraction middle(const interval& J) const;
  static band_cover_interval cover_of(const interval& J);
  void keep(const interval& J) { cover_.push_back(cover_of(J)); }  // into the final covering
  // [lo, hi] in R units as the extremes are reported: H_q = R/2 times energy_scale.
  enclosure reported(const big_rational& lo, const big_rational& hi) const {
    return band_detail::enclosure_of_rationals(lo * opt_.energy_scale / 2, hi * opt_.energy_scale / 2);
  }
  band_extreme result(const big_rational& lo, const big_rational& hi, bool interrupted, const std::string& why) const;

  band_arith arith_;
  const band_options& opt_;
  extreme which_;
  band_coupling ends_[2];
  std::size_t intervals_ = 0, couplings_ = 0, serial_ = 0;
  std::set<std::string> evaluated_;
  std::vector<band_cover_interval> cover_;  // pruned intervals (with record_cover)
  // The best evaluated coupling: its minimum's enclosure (R units).
  bool have_ = false;
  big_rational best_lo_, best_hi_;
  band_coupling best_at_;
};

void search::evaluate(const band_coupling& c) {
  if (!evaluated_.insert(c.spec.n2.str()).second) return;
  ++couplings_;
  const auto [lo, hi] = arith_.minimum_at(c, opt_.stop);
  // Absorption: the best lower end is a proved lower bound of W; containment: the best upper end
  // is a proved upper bound of B.
  if (!have_ || (absorption() ? lo > best_lo_ : hi < best_hi_)) {
    have_ = true;
    best_lo_ = lo;
    best_hi_ = hi;
    best_at_ = c;
  }
}

// Item 4 (upper): the lobes' bound V_a(max F_{K-}) or, on an interval without fractions of
// denominator <= 2K-, the one line's monotone bound; and the end point's sup.
interval search::absorption_bound(const band_coupling& a, const band_coupling& b) {
  interval J{a, b, 0, {}, ++serial_, {}};
  big_int K = arith_.cut_lobe(a) - 1;
  if (arith_.reached_on(big_int(K + 1), a, b, true)) K += 1, J.how.reached = true;
  J.how.K = K;
  std::optional<big_rational> lobes;  // none: no admissible lobe on all of J (K = -1)
  if (K == 0) lobes = arith_.V_upper(a, quadratic_number(1, 2));
  else if (K >= 1) {
    J.splits = structural_splits(a, b, K);
    const quadratic_number fa = min_distance_to_half(a.x, K, opt_.stop).value,
                           fb = min_distance_to_half(b.x, K, opt_.stop).value;
    if (J.splits.empty()) {
      // One line nu_k on J (item 4): its lobe found at an interior point, its slope by the ends.
      const fraction inner = simplest_in(a.x, b.x).simplest;
      const big_int k = min_distance_to_half(inner.value(), K, opt_.stop).k;
      const quadratic_number na = distance_to_half(a.x, k), nb = distance_to_half(b.x, k);
      J.how.k = k;
      if (!less_than(na, nb)) lobes = arith_.V_upper(a, fa), J.how.kind = band_bound_kind::line_falling;
      else if (arith_.g_signed(k, a, nb, b, true)) lobes = arith_.V_upper(b, fb), J.how.kind = band_bound_kind::line_rising;
      else if (arith_.g_signed(k, b, na, a, false)) lobes = arith_.V_upper(a, na), J.how.kind = band_bound_kind::line_turning;
      else lobes = arith_.V_upper(a, fb), J.how.kind = band_bound_kind::line_unproved;
    } else {
      quadratic_number top = larger(fa, fb);
      const fraction odd = least_of_parity_in(a.x, b.x, 1);
      if (odd.q <= 2 * K - 1 && less_than(top, quadratic_number(1, 2 * odd.q))) top = quadratic_number(1, 2 * odd.q);
      lobes = arith_.V_upper(a, top);
    }
  }
  const big_rational end = arith_.end_point_range(a, b).second;
  J.bound = lobes && *lobes < end ? *lobes : end;
  if (!(lobes && *lobes < end)) J.how.kind = band_bound_kind::end_point;
  return J;
}

// Item 4 (lower): the lobes 0..k_c(b) (the end point lies in lobe k_c) without a centre inside,
// their values at the two ends; or, when the cut lobe is not reached on J, the admissible lobes
// against the end point's inf.
interval search::containment_bound(const band_coupling& a, const band_coupling& b) {
  interval J{a, b, 0, {}, ++serial_, {}};
  const auto lobes_lower = [&](const big_int& K, std::vector<fraction>& splits) -> big_rational {
    if (K < 0) return big_rational(-1);  // no lobe: no bound from the lobes (the caller treats it)
    if (K == 0) return arith_.V_lower(b, quadratic_number(1, 2));
    const fraction centre = least_of_parity_in(a.x, b.x, 0);
    if (centre.q <= 2 * K) {
      splits.push_back(centre);
      return big_rational(0);
    }
    const big_rational va = arith_.V_lower(a, min_distance_to_half(a.x, K, opt_.stop).value);
    const big_rational vb = arith_.V_lower(b, min_distance_to_half(b.x, K, opt_.stop).value);
    return va < vb ? va : vb;
  };
  const big_int kcb = arith_.cut_lobe(b);
  std::vector<fraction> splits;
  big_rational bound = lobes_lower(kcb, splits);
  if (bound < 0) bound = 0;
  J.how.K = kcb;
  if (arith_.reached_on(kcb, a, b, false)) {  // then K_T <= k_c(b) - 1 on all of J (item 4)
    std::vector<fraction> inner;
    const big_rational lobes = lobes_lower(big_int(kcb - 1), inner);
    const big_rational end = arith_.end_point_range(a, b).first;
    const big_rational second = lobes < 0 || end < lobes ? end : lobes;
    if (second > bound) {
      bound = second;
      splits = inner;
      J.how.K = kcb - 1;
      J.how.unreached = true;
      J.how.kind = band_bound_kind::end_point;
    }
  }
  J.bound = bound;
  J.splits = splits;
  return J;
}

interval search::bound_of(const band_coupling& a, const band_coupling& b) {
  ++intervals_;
  return absorption() ? absorption_bound(a, b) : containment_bound(a, b);
}

// A split point near the middle of J: the simplest fraction of its middle third (exact rationals
// from the balls of its ends; the interval then shrinks geometrically).
fraction search::middle(const interval& J) const {
  const auto [lo, hi] = arith_.middle_third(J.a, J.b);
  const fraction f = simplest_in(quadratic_number(lo), quadratic_number(hi)).simplest;
  if (!(J.a.x < f.value() && f.value() < J.b.x)) throw precision_shortfall("an interval narrower than the precision");
  return f;
}

band_cover_interval search::cover_of(const interval& J) {
  band_cover_interval c = J.how;
  c.a = J.a;
  c.b = J.b;
  c.bound = J.bound;
  return c;
}

band_extreme search::result(const big_rational& lo, const big_rational& hi, bool interrupted, const std::string& why) const {
  band_extreme r;
  if (opt_.record_cover) {
    r.cover = cover_;
    std::sort(r.cover.begin(), r.cover.end(),
              [](const band_cover_interval& u, const band_cover_interval& v) { return less_than(u.a.x, v.a.x); });
  }
  r.value = reported(lo, hi);
  r.settled = !interrupted && why.empty() && r.value.rounded(opt_.digits).has_value();
  r.interrupted = interrupted;
  r.unsettled_reason = why;
  r.at = best_at_;
  r.at_value = reported(best_lo_, best_hi_);
  r.intervals = intervals_;
  r.couplings = couplings_;
  return r;
}

band_extreme search::run() {
  evaluate(ends_[0]);
  evaluate(ends_[1]);
  const auto cmp = [this](const interval& u, const interval& v) {
    return u.bound == v.bound ? u.serial > v.serial : better(v.bound, u.bound);
  };
  std::priority_queue<interval, std::vector<interval>, decltype(cmp)> open(cmp);
  open.push(bound_of(ends_[0], ends_[1]));
  const auto finish = [&](const big_rational& lo, const big_rational& hi, bool interrupted, const std::string& why) {
    for (; opt_.record_cover && !open.empty(); open.pop()) keep(open.top());
    return result(lo, hi, interrupted, why);
  };
  for (;;) {
    // The extreme lies between the best evaluated coupling and the best remaining bound.
    const big_rational& top = open.top().bound;
    const big_rational lo = absorption() ? best_lo_ : (top < best_lo_ ? top : best_lo_);
    const big_rational hi = absorption() ? (top > best_hi_ ? top : best_hi_) : best_hi_;
    if (opt_.progress) {
      band_progress p{absorption() ? "absorption" : "containment", intervals_, couplings_,
                      (lo * opt_.energy_scale / 2).convert_to<double>(), (hi * opt_.energy_scale / 2).convert_to<double>()};
      opt_.progress(p);
    }
    if (!absorption() && best_hi_ == 0) return finish(0, 0, false, "");  // an exact zero: B = 0
    if (!opt_.versus && reported(lo, hi).rounded(opt_.digits)) return finish(lo, hi, false, "");
    if (opt_.versus && (hi <= *opt_.versus * 2 || lo >= *opt_.versus * 2)) {
      band_extreme r = finish(lo, hi, false, "");
      r.decided = true;
      return r;
    }
    if (opt_.stop.requested()) return finish(lo, hi, true, "");
    if (intervals_ >= opt_.max_intervals)
      return finish(lo, hi, false, "the search reached its cap of " + std::to_string(opt_.max_intervals) + " intervals");
    interval J = open.top();
    open.pop();
    // The structure's split points, and the middle when none of them lies in the middle third
    // (fractions of small denominators can crowd one end, e.g. the centres 1 - 1/(2k) as x -> 1:
    // splitting only there would advance one fraction at a time).
    std::vector<fraction> points = J.splits;
    const std::pair<big_rational, big_rational> third = arith_.middle_third(J.a, J.b);
    if (std::none_of(points.begin(), points.end(), [&](const fraction& f) {
          return big_rational(f.p, f.q) >= third.first && big_rational(f.p, f.q) <= third.second;
        })) {
      const fraction m = middle(J);
      points.insert(std::upper_bound(points.begin(), points.end(), m,
                                     [](const fraction& u, const fraction& v) { return u.p * v.q < v.p * u.q; }),
                    m);
    }
    std::vector<band_coupling> cuts{J.a};
    std::vector<interval> children;
    try {
      for (const fraction& f : points) {
        cuts.push_back(band_coupling::of_x(f.p, f.q));
        evaluate(cuts.back());
      }
      cuts.push_back(J.b);
      for (std::size_t i = 0; i + 1 < cuts.size(); ++i) children.push_back(bound_of(cuts[i], cuts[i + 1]));
    } catch (const interrupted&) {  // a horizon proof or a bound's rotation minimum stopped: J's bound still holds
      open.push(std::move(J));
      return finish(lo, hi, true, "");
    }
    for (interval& child : children) {
      // A child that cannot beat the best evaluated coupling is dropped (item 5).
      if (absorption() ? child.bound > best_lo_ : child.bound < best_hi_) open.push(std::move(child));
      else if (opt_.record_cover) keep(child);
    }
    if (open.empty()) {
      // Every interval is beaten by the best coupling: its enclosure is the answer.
      return result(best_lo_, best_hi_, false, "");
    }
  }
}

// The working precision of a band proof: the digits asked and the phases' size (alpha_T grows
// like T/sqrt(1 - x^2): its integer part must be kept with the digits after it).
slong start_bits(unsigned digits, const big_rational& n2, const horizon_time& T) {
  const auto bits = [](const big_rational& v) {
    const big_int num = boost::multiprecision::numerator(v), den = boost::multiprecision::denominator(v);
    return slong(num == 0 ? 0 : boost::multiprecision::msb(num)) - slong(boost::multiprecision::msb(den));
  };
  const big_rational scale = (T.times_pi ? T.value * 4 : T.value) * (n2 + 4);
  return slong(digits10_to_bits(digits)) + 96 + 2 * std::max<slong>(0, bits(scale));
}

// refine from `start` bits up to the tie cap (core/refine.hpp), a precision_shortfall being an
// undecided attempt.
template <class T, class Attempt>
T refine_band(slong start, const stop_token& stop, const std::string& what, Attempt&& attempt) {
  const precision_plan plan{mpfr_prec_t(start), tie_bits_cap(mpfr_prec_t(start))};
  return refine(plan, stop, what, [&](mpfr_prec_t bits, proof_status& status) -> std::optional<T> {
    try {
      return attempt(slong(bits), status);
    } catch (const precision_shortfall& e) {
      status = proof_status::undecided(e.why());
      return std::nullopt;
    }
  });
}

void check_band_input(const big_rational& n1, const big_rational& n2, const band_options& opt) {
  check_band(n1, n2, "the band");
  check_report_digits(opt.digits);
}

band_extreme prove_extreme(const big_rational& n1, const big_rational& n2, const horizon_time& T, const band_options& opt,
                           extreme which) {
  check_band_input(n1, n2, opt);
  if (T.value < 0) throw usage_error("the horizon must be >= 0, got " + T.str());
  if (T.value == 0) {  // H_q = H_q(0) = 1/2 for every coupling
    band_extreme r;
    r.value = enclosure::exact(big_rational(1, 2));
    r.settled = true;
    r.at = band_coupling::of_n(n1);
    r.at_value = r.value;
    return r;
  }
  const std::string what = std::string("the band's ") + (which == extreme::absorption ? "absorption" : "containment");
  const auto attempt = [&](slong bits, proof_status& status) -> std::optional<band_extreme> {
    band_extreme r = search(band_coupling::of_n(n1), band_coupling::of_n(n2), T, opt, which, bits).run();
    if (r.settled || r.decided || r.interrupted || !r.unsettled_reason.empty()) return r;
    status = proof_status::undecided("the bounds did not settle the rounding");
    return std::nullopt;
  };
  return refine_band<band_extreme>(start_bits(opt.digits, n2 * n2, T), opt.stop, what + " guarantee", attempt);
}

// ---- the band-wide first time below a level (item 6) ----

// Some odd fraction p/q of the band with V_{p/q}(1/(2q)) > 2E (that pair never reaches E), or
// none when every one is proved below 2E: a best-first search over intervals, each bounded by
// V_a(1/(2 Q_o)) with Q_o its least odd denominator (items 1, 3).
std::optional<band_coupling> pair_above(const band_coupling& x1, const band_coupling& x2, const big_rational& two_E,
                                        const band_arith& arith, const stop_token& stop) {
  struct piece {
    band_coupling a, b;
    fraction odd;
  };
  std::vector<piece> open{{x1, x2, least_of_parity_in(x1.x, x2.x, 1)}};
  for (std::size_t steps = 0; !open.empty(); ++steps) {
    stop.throw_if_requested();
    if (steps > 100000) throw precision_shortfall("the pairs of the band were not all compared with the level");
    const piece J = open.back();
    open.pop_back();
    const quadratic_number nu(1, 2 * J.odd.q);
    if (!(arith.V_upper(J.a, nu) > two_E)) continue;  // no fraction of J reaches above 2E
    const band_coupling v = band_coupling::of_x(J.odd.p, J.odd.q);
    if (arith.V_lower(v, nu) > two_E) return v;
    open.push_back({J.a, v, least_of_parity_in(J.a.x, v.x, 1)});
    open.push_back({v, J.b, least_of_parity_in(v.x, J.b.x, 1)});
  }
  return std::nullopt;
}

// r holds the bracket reached so far, for an interrupted search.
void first_below_search(const big_rational& n1, const big_rational& n2, const big_rational& E, const band_options& opt,
                        slong prec, band_first_below& r, bool& bracketed) {
  r = band_first_below{};
  bracketed = false;
  r.level = E;
  const band_coupling x1 = band_coupling::of_n(n1), x2 = band_coupling::of_n(n2);
  const band_arith arith(horizon_time(big_rational(1)), prec);
  if (2 * E >= 1) {  // H_q(0) = 1/2 <= E already
    r.time = enclosure::exact(big_rational(0));
    r.settled = true;
    r.at = x1;
    r.at_time = r.time;
    r.reason = "H_q(0) = 1/2 is already <= E for every coupling";
    return;
  }
  if (E == 0) {
    r.never = true;
    r.settled = true;
    r.at = x1;
    r.reason = "a coupling with W1/W2 irrational (all but countably many in the band) never reaches H_q = 0";
    return;
  }
  if (auto v = pair_above(x1, x2, 2 * E, arith, opt.stop)) {
    r.never = true;
    r.settled = true;
    r.at = *v;
    r.reason = "the resonant coupling x = " + v->x.str() + " (n^2 = " + rational_str(v->spec.n2) +
               ") keeps H_q above E for all time";
    return;
  }
  // Lower end: the latest first time of an evaluated coupling; upper end: a horizon whose
  // absorption guarantee is proved <= E (item 6).
  big_rational lo = 0, hi;
  const auto witness = [&](const band_coupling& c) {
    ++r.couplings;
    const auto t = arith.first_below_at(c, E, opt.stop);
    if (!t) throw compute_error("band: a coupling never reaches E although every pair of the band does");
    if (t->first >= lo) {
      lo = t->first;
      r.at = c;
      r.at_time = band_detail::enclosure_of_rationals(t->first, t->second);
    }
  };
  witness(x1);
  witness(x2);
  band_options decide = opt;
  decide.versus = E;
  decide.progress = nullptr;
  decide.energy_scale = 1;  // compared with E, a unit-impulse level
  // W(T) <= E decided at T; the search's witness raises the lower end when it is not.
  const auto drains_by = [&](const big_rational& T) {
    const slong bits = std::max(prec, start_bits(opt.digits, n2 * n2, horizon_time(T)));
    band_extreme w = search(x1, x2, horizon_time(T), decide, extreme::absorption, bits).run();
    r.intervals += w.intervals;
    r.couplings += w.couplings;
    if (w.interrupted) throw interrupted();
    if (w.value.hi_rational() <= E) return true;
    if (w.value.lo_rational() >= E) {
      witness(w.at);
      return false;
    }
    throw precision_shortfall("the absorption guarantee at a trial horizon was not decided against the level");
  };
  hi = 2 * lo + 1;
  while (!drains_by(hi)) {
    if (hi > big_rational(big_int(1) << 400)) throw precision_shortfall("no horizon up to 2^400 drains every coupling to E");
    hi *= 2;
  }
  for (;;) {
    r.time = band_detail::enclosure_of_rationals(lo, hi);
    bracketed = true;
    opt.stop.throw_if_requested();
    if (opt.progress) opt.progress({"first time below", r.intervals, r.couplings, lo.convert_to<double>(), hi.convert_to<double>()});
    if (r.time.rounded(opt.digits)) break;
    // The simplest rational of the middle third (short numbers keep the trial horizons cheap).
    const big_rational third = (hi - lo) / 3;
    const big_rational scale = hi;
    const fraction f = simplest_in(quadratic_number((lo + third) / scale), quadratic_number((hi - third) / scale)).simplest;
    const big_rational T = big_rational(f.p, f.q) * scale;
    if (drains_by(T)) hi = T;
    else if (T > lo) lo = T;
  }
  r.settled = true;
  r.reason = "the latest first time is approached at or near the coupling n^2 = " + rational_str(r.at.spec.n2);
}

}  // namespace

band_first_below prove_band_first_below(const big_rational& n1, const big_rational& n2, const big_rational& level,
                                        const band_options& opt) {
  check_band_input(n1, n2, opt);
  if (level < 0) throw usage_error("the level E must be >= 0, got " + rational_str(level));
  band_first_below r;
  bool bracketed = false;  // r.time holds the latest first time (a draining horizon is known)
  try {
    return refine_band<band_first_below>(start_bits(opt.digits, n2 * n2, horizon_time(big_rational(1))), opt.stop,
                                         "the band's first time below a level", [&](slong bits, proof_status&) {
                                           first_below_search(n1, n2, level, opt, bits, r, bracketed);
                                           return std::optional(r);
                                         });
  } catch (const interrupted&) {
    if (!bracketed) throw;  // no horizon is proved to drain the band yet: no bracket to print
    r.interrupted = true;  // the bracket reached: [latest evaluated first time, last draining horizon]
    r.settled = false;
    return r;
  }
}

band_cover_interval band_interval_bound(const band_coupling& a, const band_coupling& b, const horizon_time& T,
                                        bool absorption, unsigned digits) {
  band_options opt;
  opt.digits = digits;
  const extreme which = absorption ? extreme::absorption : extreme::containment;
  return refine_band<band_cover_interval>(start_bits(digits, b.spec.n2, T), {}, "band: an interval's bound",
                                          [&](slong bits, proof_status&) {
                                            return std::optional(search(a, b, T, opt, which, bits).bound_only(a, b));
                                          });
}

band_extreme prove_band_absorption(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                   const band_options& opt) {
  return prove_extreme(n1, n2, T, opt, extreme::absorption);
}

band_extreme prove_band_containment(const big_rational& n1, const big_rational& n2, const horizon_time& T,
                                    const band_options& opt) {
  return prove_extreme(n1, n2, T, opt, extreme::containment);
}

}  // namespace gyrores
