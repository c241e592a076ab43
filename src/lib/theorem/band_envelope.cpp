// src/lib/theorem/band_envelope.hpp; the argument is proofs/horizon-theorem.md, Step 12.
#include "band_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <gyrores/core/error.hpp>
#include <gyrores/core/quadratic.hpp>
#include <gyrores/model/rotation.hpp>

namespace gyrores::band_detail {
namespace {

// A centre p/q = (2j+1)/(2k) of lobe k (q = 2k > 0, p odd).
struct centre {
  std::int64_t p, q;
};

bool centre_less(const centre& a, const centre& b) { return int128(a.p) * b.q < int128(b.p) * a.q; }

big_rational value_of(const centre& c) { return big_rational(big_int(c.p), big_int(c.q)); }

big_int floor_of(const big_rational& v) {
  return int_floor_div(big_int(boost::multiprecision::numerator(v)), big_int(boost::multiprecision::denominator(v)));
}

// ||y||: the distance from y to the nearest integer.
big_rational distance_to_integer(const big_rational& y) {
  const big_rational f = y - big_rational(floor_of(y));
  const big_rational g = 1 - f;
  return f < g ? f : g;
}

// A piece's bound before the cap: an exact small fraction (num/den) or a rational.
struct interior_piece {
  int128 num, den;   // height = num/den, den > 0
  std::size_t left;  // the piece lies between centres left and left + 1 of the list
};

bool height_greater(const interior_piece& a, const interior_piece& b) { return a.num * b.den > b.num * a.den; }

const big_rational half(1, 2);

envelope_bound single_lobe(const big_rational& xa, const big_rational& xb, const big_int& K, const big_rational& cap) {
  envelope_bound out;
  const big_rational mid = (xa + xb) / 2;
  const big_int k = min_distance_to_half(quadratic_number(mid), K).k;
  const big_rational v = lobe_distance_max(xa, xb, k);
  out.value = v < cap ? v : cap;
  return out;
}

}  // namespace

big_rational lobe_distance_max(const big_rational& xa, const big_rational& xb, const big_int& k) {
  if (k == 0) return half;
  const big_rational fa = xa * big_rational(k), fb = xb * big_rational(k);
  // k x - 1/2 sweeps [fa - 1/2, fb - 1/2]; ||.|| is 1/2 exactly where k x is an integer, and
  // between two such points it is |k x - 1/2 - m|, whose maximum is at an end.
  big_int c = floor_of(fa);
  if (big_rational(c) < fa) c += 1;  // ceil(fa)
  if (big_rational(c) <= fb) return half;
  const big_rational a = distance_to_integer(fa - half), b = distance_to_integer(fb - half);
  return a < b ? b : a;
}

envelope_bound envelope_max(const big_rational& xa, const big_rational& xb, const big_int& K, const big_rational& cap_in,
                            std::size_t max_centres, std::size_t keep, const stop_token& stop) {
  if (!(xa > 0) || !(xb > xa) || !(xb < 1) || K < 0) throw usage_error("envelope_max: needs 0 < xa < xb < 1 and K >= 0");
  const big_rational cap = cap_in < half ? cap_in : half;
  envelope_bound out;
  out.value = cap;
  if (K == 0 || cap <= 0) return out;
  const double xa_d = xa.convert_to<double>(), xb_d = xb.convert_to<double>(), reach = cap.convert_to<double>() + 1e-9;
  const double Kd = K.convert_to<double>();
  // About K^2 (xb - xa)/2 centres lie inside, and up to 2 reach more per lobe outside.
  const double estimate = Kd * Kd * (xb_d - xa_d) / 2 + Kd * (2 * reach + 0.1);
  if (K > (big_int(1) << 26) || estimate > double(max_centres)) return single_lobe(xa, xb, K, cap);

  // Every lobe's centres within reach/k of the interval (a tent higher than the cap there never
  // matters). Floating point only selects them: a centre left out only weakens the bound.
  const std::int64_t Kn = K.convert_to<std::int64_t>();
  std::vector<centre> cs;
  cs.reserve(std::size_t(estimate) + 16);
  for (std::int64_t k = 1; k <= Kn; ++k) {
    if ((k & 0xffff) == 0) stop.throw_if_requested();
    const double margin = 1e-7 + double(k) * 1e-15;
    const double lo = double(k) * xa_d - 0.5 - reach - margin, hi = double(k) * xb_d - 0.5 + reach + margin;
    for (auto j = std::int64_t(std::ceil(lo)); double(j) <= hi; ++j) cs.push_back({2 * j + 1, 2 * k});
    if (cs.size() > 2 * max_centres) return single_lobe(xa, xb, K, cap);
  }
  // Sort by centre; at equal centres keep the smallest k (its tent is the lowest).
  std::sort(cs.begin(), cs.end(), [](const centre& a, const centre& b) {
    if (centre_less(a, b)) return true;
    if (centre_less(b, a)) return false;
    return a.q < b.q;
  });
  cs.erase(std::unique(cs.begin(), cs.end(), [](const centre& a, const centre& b) { return !centre_less(a, b) && !centre_less(b, a); }),
           cs.end());
  out.enumerated = true;
  out.centres = cs.size();

  // ia: the first centre > xa; ib: the first centre >= xb (exact comparisons).
  const big_int na = boost::multiprecision::numerator(xa), da = boost::multiprecision::denominator(xa);
  const big_int nb = boost::multiprecision::numerator(xb), db = boost::multiprecision::denominator(xb);
  const auto ia = std::size_t(std::partition_point(cs.begin(), cs.end(), [&](const centre& c) {
                                return big_int(c.p) * da <= na * big_int(c.q);
                              }) - cs.begin());
  const auto ib = std::size_t(std::partition_point(cs.begin(), cs.end(), [&](const centre& c) {
                                return big_int(c.p) * db < nb * big_int(c.q);
                              }) - cs.begin());
  // The pieces: between consecutive centres from the last one <= xa (if any) to the first one
  // >= xb (if any); a piece without a centre on one side ends at xa or xb.
  std::vector<envelope_piece> ends;  // pieces clipped by xa or xb, exact rationals
  std::vector<interior_piece> inner;
  auto clipped = [&](const centre* a, const centre* b) {
    envelope_piece pc;
    pc.lo = a && value_of(*a) > xa ? value_of(*a) : xa;
    pc.hi = b && value_of(*b) < xb ? value_of(*b) : xb;
    if (a && b) {
      const big_rational xs(big_int(a->p + b->p), big_int(a->q + b->q));
      if (xs < pc.lo) pc.at = pc.lo, pc.height = (big_rational(b->p) - big_rational(b->q) * pc.lo) / 2;
      else if (xs > pc.hi) pc.at = pc.hi, pc.height = (big_rational(a->q) * pc.hi - big_rational(a->p)) / 2;
      else pc.at = xs, pc.height = big_rational(to_big(int128(a->q) * b->p - int128(b->q) * a->p), to_big(2 * (int128(a->q) + b->q)));
    } else if (b) {  // only the falling side of b's tent: highest at xa
      pc.at = pc.lo;
      pc.height = (big_rational(b->p) - big_rational(b->q) * pc.lo) / 2;
    } else if (a) {  // only the rising side of a's tent: highest at xb
      pc.at = pc.hi;
      pc.height = (big_rational(a->q) * pc.hi - big_rational(a->p)) / 2;
    } else {
      pc.at = (xa + xb) / 2;
      pc.height = cap;
    }
    ends.push_back(pc);
  };
  if (cs.empty()) clipped(nullptr, nullptr);
  else {
    const std::size_t first = ia > 0 ? ia - 1 : 0, last = ib < cs.size() ? ib : cs.size() - 1;
    if (ia == 0) clipped(nullptr, &cs[0]);
    if (ib == cs.size()) clipped(&cs.back(), nullptr);
    for (std::size_t i = first; i < last; ++i) {
      if ((ia > 0 && i + 1 == ia) || (ib < cs.size() && i + 1 == ib)) clipped(&cs[i], &cs[i + 1]);
      else inner.push_back({int128(cs[i].q) * cs[i + 1].p - int128(cs[i + 1].q) * cs[i].p, 2 * (int128(cs[i].q) + cs[i + 1].q), i});
    }
  }
  // The highest pieces: sort the inner ones' first keep + 1 and merge with the clipped ones.
  const std::size_t want = std::min(inner.size(), keep + 1);
  std::partial_sort(inner.begin(), inner.begin() + std::ptrdiff_t(want), inner.end(), height_greater);
  std::vector<envelope_piece> all = ends;
  for (std::size_t i = 0; i < want; ++i) {
    const centre &a = cs[inner[i].left], &b = cs[inner[i].left + 1];
    all.push_back({big_rational(to_big(inner[i].num), to_big(inner[i].den)), value_of(a), value_of(b),
                   big_rational(big_int(a.p + b.p), big_int(a.q + b.q))});
  }
  for (auto& pc : all)
    if (pc.height > cap) pc.height = cap;
  std::sort(all.begin(), all.end(), [](const envelope_piece& a, const envelope_piece& b) { return a.height > b.height; });
  out.value = all.empty() ? cap : all.front().height;
  for (std::size_t i = 0; i < all.size() && i < keep; ++i) out.top.push_back(all[i]);
  out.rest = all.size() > keep ? all[keep].height : big_rational(0);
  // Inner pieces beyond the first keep + 1 are no higher than the (keep + 1)-th inner one, which
  // is in `all`: `rest` bounds them too.
  return out;
}

}  // namespace gyrores::band_detail
