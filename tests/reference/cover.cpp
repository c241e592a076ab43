// The cover obligation of reference/cover.hpp.
#include "reference/cover.hpp"

#include <cmath>

namespace gyrores::proof {

basin_map basins_by_lobe(const constants& K, const std::vector<image>& images, const I& Y) {
  basin_map out;
  for (auto& im : images) out[int_mod(im.k, K.a)].push_back(im.negate_u ? I(-Y) : Y);
  return out;
}

namespace {

std::vector<I> basins_of_lobe(const constants& K, const basin_map& basins, const big_int& k) {
  auto it = basins.find(int_mod(k, K.a));
  return it == basins.end() ? std::vector<I>{} : it->second;
}

bool small_x(const constants& K) { return 2 * K.b < K.a; }

// The producer's choice of strategy, or "" with the reason in res.note.
std::string choose_strategy(const constants& K, const certify_options& opt, cover_result& res) {
  if (small_x(K) && K.b <= big_int(opt.max_nodes)) return "slow-nodes";
  if (K.a <= big_int(opt.max_lobes)) return "all-lobes";
  res.note = "not proved: order " + K.a.str() + " above max_lobes and (x >= 1/2 or " + K.b.str() +
             " slow nodes above max_nodes)";
  return "";
}

// "all-lobes": every fast lobe k = 0 .. a-1.
void cover_all_lobes(const constants& K, const basin_map& basins, const I& bound, cover_result& res) {
  for (big_int k = 0; k < K.a; ++k) {
    if (!exclude_lobe(K, lobe_at(K, k), basins_of_lobe(K, basins, k), bound, res.stats)) {
      res.note = "not proved: an undecided box in lobe k = " + k.str();
      return;
    }
  }
  res.proved = true;
}

// The Rayleigh cut-off w1 = t x: for |w| >= w1 (|cos beta| >= sin w1), R >= lambda(sin^2 w1),
// which must exceed the bound, with w1 < pi/2. t is read from t_text, or doubled from 1 until
// the bound holds when t_text is empty. nullopt (reason in res.note) when no t works.
std::optional<P> rayleigh_parameter(const constants& K, const I& bound, const std::string& t_text, cover_result& res) {
  P t = 1;
  if (!t_text.empty() && (mpfr_set_str(t.backend().data(), t_text.c_str(), 10, MPFR_RNDN) != 0 || !(t > 0))) {
    res.note = "bad Rayleigh parameter t = '" + t_text + "'";
    return std::nullopt;
  }
  for (;;) {
    I w1 = I(t) * K.c.x;
    bool below_half_pi = certainly_less(w1, K.c.pi / 2);
    I c2 = interval_sqr(sin(w1));
    if (below_half_pi && certainly_less(bound, rayleigh_lower(K, interval_point(interval_lower(c2))))) return t;
    if (!t_text.empty() || !below_half_pi) {
      res.note = "not proved: the Rayleigh bound at w1 = t x (t = " + format_scientific(t, 6) +
                 ") does not exceed r_hi^2";
      return std::nullopt;
    }
    t *= 2;
  }
}

// "slow-nodes": the lobes around node j, alpha/pi in [c_j - t/pi, c_j + t/pi] with
// c_j = (2j+1) a/(2b) in [Q, Q+1), for every slow node j = 0 .. b-1.
void cover_slow_nodes(const constants& K, const basin_map& basins, const I& bound, const P& t, cover_result& res) {
  big_int spread = big_int(static_cast<long>(std::floor(static_cast<double>(t) / 3.0))) + 3;
  for (big_int j = 0; j < K.b; ++j) {
    big_int Q = int_floor_div(big_int((2 * j + 1) * K.a), big_int(2 * K.b));
    for (big_int k = Q - spread; k <= Q + spread + 1; ++k) {
      if (!exclude_lobe(K, lobe{k, j}, basins_of_lobe(K, basins, k), bound, res.stats)) {
        res.note = "not proved: an undecided box in lobe k = " + k.str() + " at node j = " + j.str();
        return;
      }
    }
  }
  res.proved = true;
}

}  // namespace

cover_result run_cover(const constants& K, const basin_map& basins, const I& bound,
                       const certify_options& opt, const std::string& strategy, const std::string& t_text) {
  cover_result res;
  res.strategy = strategy.empty() ? choose_strategy(K, opt, res) : strategy;
  if (res.strategy.empty()) return res;
  if (res.strategy == "all-lobes") {
    cover_all_lobes(K, basins, bound, res);
  } else if (res.strategy != "slow-nodes") {
    res.note = "unknown cover strategy '" + res.strategy + "'";
  } else if (!small_x(K)) {
    res.note = "slow-nodes cover needs x < 1/2";
  } else if (auto t = rayleigh_parameter(K, bound, t_text, res)) {
    res.rayleigh_t = format_scientific(*t, 6);
    cover_slow_nodes(K, basins, bound, *t, res);
  }
  return res;
}

}  // namespace gyrores::proof
