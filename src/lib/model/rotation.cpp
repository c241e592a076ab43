// include/gyrores/model/rotation.hpp
#include <gyrores/model/rotation.hpp>

#include <vector>

#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

// Built on first use, not at start-up: every run of the command would pay for them otherwise.
const quadratic_number& one() {
  static const quadratic_number v(1);
  return v;
}
const quadratic_number& half() {
  static const quadratic_number v(1, 2);
  return v;
}

bool in_unit_interval(const quadratic_number& v) { return v.sign() >= 0 && v < one(); }

void check_arguments(const quadratic_number& alpha, const quadratic_number& beta, const big_int& K, const char* what) {
  if (!in_unit_interval(alpha) || !in_unit_interval(beta))
    throw usage_error(std::string(what) + ": alpha and beta must lie in [0, 1)");
  if (K < 0) throw usage_error(std::string(what) + ": K must be >= 0");
}

// The descent of the Euclid-like recursion (rotation.hpp) is run as a loop: each level pushes
// what its caller needs to lift the inner answer back (its scale alpha or g = 1 - alpha, its beta
// and its own candidate), so the depth (about log2 K levels: K >= 10^5000 has 16600) costs heap,
// never stack. The stop token is looked at once per level.
struct min_level {
  bool low;                   // alpha <= 1/2 (runs start at integer crossings), else alpha > 1/2
  quadratic_number scale;     // alpha (low) or g = 1 - alpha
  quadratic_number beta;
  rotation_minimum best;      // this level's own candidate
};

rotation_minimum min_frac(quadratic_number alpha, quadratic_number beta, big_int K, const stop_token& stop) {
  std::vector<min_level> levels;
  rotation_minimum result;
  for (;;) {
    stop.throw_if_requested();
    rotation_minimum best{beta, 0};
    if (K == 0 || alpha.sign() == 0) {
      result = best;
      break;
    }
    if (alpha + alpha <= one()) {
      // Runs start where y_k crosses an integer j = 1..J: k_j = ceil((j - beta)/alpha), with
      // {y_{k_j}} = alpha {j alpha1 + beta1}. Candidates: k = 0 and the k_j.
      const big_int J = (quadratic_number(K) * alpha + beta).floor();
      if (J < 1) {
        result = best;
        break;
      }
      const quadratic_number alpha1 = (-(one() / alpha)).frac(), beta1 = (beta / alpha).frac();
      levels.push_back({true, alpha, beta, best});
      beta = (alpha1 + beta1).frac();
      alpha = alpha1;
      K = J - 1;
      continue;
    }
    // alpha > 1/2: with g = 1 - alpha, y_k = beta - k g (mod 1) decreases; a run ends at
    // k_j = floor((beta + j)/g), j = 0..J', with {y_{k_j}} = g {j alpha1 + beta1}; the run cut by K
    // ends at K itself.
    const quadratic_number g = one() - alpha;
    best = {(beta - quadratic_number(K) * g).frac(), K};
    const big_int Jp = (quadratic_number(big_int(K + 1)) * g - beta).ceil() - 1;
    if (Jp < 0) {
      result = best;
      break;
    }
    levels.push_back({false, g, beta, best});
    alpha = (one() / g).frac();
    beta = (beta / g).frac();
    K = Jp;
  }
  // The ascent: each level lifts the inner minimum (index j of its runs) to its own k.
  for (auto level = levels.rbegin(); level != levels.rend(); ++level) {
    const quadratic_number value = level->scale * result.value;
    rotation_minimum best = level->best;
    if (level->low) {
      const big_int j = result.k + 1;
      if (value < best.value) best = {value, ((quadratic_number(j) - level->beta) / level->scale).ceil()};
    } else {
      const big_int k = ((level->beta + quadratic_number(result.k)) / level->scale).floor();
      if (value < best.value || (value == best.value && k < best.k)) best = {value, k};
    }
    result = std::move(best);
  }
  return result;
}

// first_frac's levels: low ones map a hit j of the inner problem to its run's first element;
// high ones keep what the run cut by K needs when the inner problem has no hit.
struct first_level {
  bool low;
  quadratic_number scale, beta, w;  // alpha or g, beta, w
  big_int K, Jp;                    // high levels only
};

std::optional<big_int> first_frac(quadratic_number alpha, quadratic_number beta, quadratic_number w, big_int K,
                                  const stop_token& stop) {
  std::vector<first_level> levels;
  std::optional<big_int> result;  // the inner answer, lifted level by level below
  for (;;) {
    stop.throw_if_requested();
    if (beta <= w) {
      result = big_int(0);
      break;
    }
    if (K == 0 || alpha.sign() == 0) break;
    if (alpha + alpha <= one()) {
      // A run hits [0, w] iff its first element does (values increase along a run).
      const big_int J = (quadratic_number(K) * alpha + beta).floor();
      if (J < 1) break;
      if (!(w < alpha)) {  // the first run's first element {alpha + beta - 1} < alpha <= w
        result = ((one() - beta) / alpha).ceil();
        break;
      }
      const quadratic_number alpha1 = (-(one() / alpha)).frac(), beta1 = (beta / alpha).frac();
      levels.push_back({true, alpha, beta, w, 0, 0});
      beta = (alpha1 + beta1).frac();
      w = w / alpha;
      alpha = alpha1;
      K = J - 1;
      continue;
    }
    // alpha > 1/2: values decrease along a run; the first run whose last element is <= w holds the
    // first hit, at its first element <= w: k = max(run start, ceil((beta + j - w)/g)).
    const quadratic_number g = one() - alpha;
    const big_int Jp = (quadratic_number(big_int(K + 1)) * g - beta).ceil() - 1;
    levels.push_back({false, g, beta, w, K, Jp});
    if (Jp < 0) break;      // only the run cut by K (resolved on the way up)
    if (g <= w) {           // the last element of run 0 is below g
      result = big_int(0);  // j = 0, lifted by this level
      break;
    }
    alpha = (one() / g).frac();
    beta = (beta / g).frac();
    w = w / g;
    K = Jp;
  }
  for (auto level = levels.rbegin(); level != levels.rend(); ++level) {
    if (level->low) {
      if (result) result = ((quadratic_number(big_int(*result + 1)) - level->beta) / level->scale).ceil();
      continue;
    }
    const quadratic_number& g = level->scale;
    const quadratic_number& b = level->beta;
    auto run_start = [&](const big_int& j) -> big_int {
      return j == 0 ? big_int(0) : big_int(((b + quadratic_number(big_int(j - 1))) / g).floor() + 1);
    };
    auto first_in_run = [&](const big_int& j) -> big_int {
      const big_int k = ((b + quadratic_number(j) - level->w) / g).ceil();
      const big_int s = run_start(j);
      return k < s ? s : k;
    };
    if (result) {
      result = first_in_run(*result);
      continue;
    }
    // The run cut by K: j = J' + 1, from its start up to K.
    const big_int k = first_in_run(big_int(level->Jp + 1));
    if (k <= level->K && (b - quadratic_number(k) * g).frac() <= level->w) result = k;
  }
  return result;
}

void check_x(const quadratic_number& x, const char* what) {
  if (!(x.sign() > 0 && x < one())) throw usage_error(std::string(what) + ": x must lie in (0, 1)");
}

}  // namespace

rotation_minimum min_fractional_part(const quadratic_number& alpha, const quadratic_number& beta, const big_int& K,
                                     stop_token stop) {
  check_arguments(alpha, beta, K, "min_fractional_part");
  return min_frac(alpha, beta, K, stop);
}

std::optional<big_int> first_fractional_part_at_most(const quadratic_number& alpha, const quadratic_number& beta,
                                                     const quadratic_number& w, const big_int& K, stop_token stop) {
  check_arguments(alpha, beta, K, "first_fractional_part_at_most");
  if (w.sign() < 0) throw usage_error("first_fractional_part_at_most: w must be >= 0");
  return first_frac(alpha, beta, w, K, stop);
}

rotation_minimum min_distance_to_half(const quadratic_number& x, const big_int& K, stop_token stop) {
  check_x(x, "min_distance_to_half");
  if (K < 0) throw usage_error("min_distance_to_half: K must be >= 0");
  // ||k x - 1/2|| = min({k x + 1/2}, {k (1 - x) + 1/2}): the two one-sided problems.
  const rotation_minimum up = min_frac(x, half(), K, stop), down = min_frac(one() - x, half(), K, stop);
  if (up.value < down.value) return up;
  if (down.value < up.value) return down;
  return up.k <= down.k ? up : down;
}

std::optional<big_int> first_distance_to_half_at_most(const quadratic_number& x, const quadratic_number& delta,
                                                      const big_int& K, stop_token stop) {
  check_x(x, "first_distance_to_half_at_most");
  if (K < 0) throw usage_error("first_distance_to_half_at_most: K must be >= 0");
  if (delta.sign() < 0) throw usage_error("first_distance_to_half_at_most: delta must be >= 0");
  if (delta >= half()) return big_int(0);
  // ||y|| <= delta  <=>  {y + delta} <= 2 delta, with y = k x - 1/2.
  return first_frac(x, (half() + delta).frac(), delta + delta, K, stop);
}

quadratic_number distance_to_half(const quadratic_number& x, const big_int& k) {
  const quadratic_number f = (quadratic_number(k) * x - half()).frac();
  const quadratic_number g = one() - f;
  return f <= g ? f : g;
}

int lobe_offset_sign(const quadratic_number& x, const big_int& k) {
  return (half() - (quadratic_number(k) * x).frac()).sign();
}

}  // namespace gyrores
