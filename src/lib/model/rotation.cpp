// include/gyrores/model/rotation.hpp
#include <gyrores/model/rotation.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores {
namespace {

const quadratic_number one(1), half(1, 2);

bool in_unit_interval(const quadratic_number& v) { return v.sign() >= 0 && v < one; }

void check_arguments(const quadratic_number& alpha, const quadratic_number& beta, const big_int& K, const char* what) {
  if (!in_unit_interval(alpha) || !in_unit_interval(beta))
    throw usage_error(std::string(what) + ": alpha and beta must lie in [0, 1)");
  if (K < 0) throw usage_error(std::string(what) + ": K must be >= 0");
}

rotation_minimum min_frac(const quadratic_number& alpha, const quadratic_number& beta, const big_int& K) {
  rotation_minimum best{beta, 0};
  if (K == 0 || alpha.sign() == 0) return best;
  if (alpha + alpha <= one) {
    // Runs start where y_k crosses an integer j = 1..J: k_j = ceil((j - beta)/alpha), with
    // {y_{k_j}} = alpha {j alpha1 + beta1}. Candidates: k = 0 and the k_j.
    const big_int J = (quadratic_number(K) * alpha + beta).floor();
    if (J < 1) return best;
    const quadratic_number alpha1 = (-(one / alpha)).frac(), beta1 = (beta / alpha).frac();
    const rotation_minimum sub = min_frac(alpha1, (alpha1 + beta1).frac(), big_int(J - 1));
    const big_int j = sub.k + 1;
    const quadratic_number value = alpha * sub.value;
    if (value < best.value) best = {value, ((quadratic_number(j) - beta) / alpha).ceil()};
    return best;
  }
  // alpha > 1/2: with g = 1 - alpha, y_k = beta - k g (mod 1) decreases; a run ends at
  // k_j = floor((beta + j)/g), j = 0..J', with {y_{k_j}} = g {j alpha1 + beta1}; the run cut by K
  // ends at K itself.
  const quadratic_number g = one - alpha;
  best = {(beta - quadratic_number(K) * g).frac(), K};
  const big_int Jp = (quadratic_number(big_int(K + 1)) * g - beta).ceil() - 1;
  if (Jp < 0) return best;
  const quadratic_number alpha1 = (one / g).frac(), beta1 = (beta / g).frac();
  const rotation_minimum sub = min_frac(alpha1, beta1, Jp);
  const big_int k = ((beta + quadratic_number(sub.k)) / g).floor();
  const quadratic_number value = g * sub.value;
  if (value < best.value || (value == best.value && k < best.k)) best = {value, k};
  return best;
}

std::optional<big_int> first_frac(const quadratic_number& alpha, const quadratic_number& beta, const quadratic_number& w,
                                  const big_int& K) {
  if (beta <= w) return big_int(0);
  if (K == 0 || alpha.sign() == 0) return std::nullopt;
  if (alpha + alpha <= one) {
    // A run hits [0, w] iff its first element does (values increase along a run).
    const big_int J = (quadratic_number(K) * alpha + beta).floor();
    if (J < 1) return std::nullopt;
    big_int j = 1;
    if (w < alpha) {
      const quadratic_number alpha1 = (-(one / alpha)).frac(), beta1 = (beta / alpha).frac();
      auto sub = first_frac(alpha1, (alpha1 + beta1).frac(), w / alpha, big_int(J - 1));
      if (!sub) return std::nullopt;
      j = *sub + 1;
    }
    return ((quadratic_number(j) - beta) / alpha).ceil();
  }
  // alpha > 1/2: values decrease along a run; the first run whose last element is <= w holds the
  // first hit, at its first element <= w: k = max(run start, ceil((beta + j - w)/g)).
  const quadratic_number g = one - alpha;
  const big_int Jp = (quadratic_number(big_int(K + 1)) * g - beta).ceil() - 1;
  auto run_start = [&](const big_int& j) -> big_int {
    return j == 0 ? big_int(0) : big_int(((beta + quadratic_number(big_int(j - 1))) / g).floor() + 1);
  };
  auto first_in_run = [&](const big_int& j) -> big_int {
    const big_int k = ((beta + quadratic_number(j) - w) / g).ceil();
    const big_int s = run_start(j);
    return k < s ? s : k;
  };
  std::optional<big_int> j;
  if (Jp >= 0) {
    if (g <= w) j = big_int(0);  // the last element of run 0 is below g
    else if (auto sub = first_frac((one / g).frac(), (beta / g).frac(), w / g, Jp)) j = *sub;
  }
  if (j) return first_in_run(*j);
  // The run cut by K: j = J' + 1, from its start up to K.
  const big_int k = first_in_run(big_int(Jp + 1));
  if (k <= K && (beta - quadratic_number(k) * g).frac() <= w) return k;
  return std::nullopt;
}

void check_x(const quadratic_number& x, const char* what) {
  if (!(x.sign() > 0 && x < one)) throw usage_error(std::string(what) + ": x must lie in (0, 1)");
}

}  // namespace

rotation_minimum min_fractional_part(const quadratic_number& alpha, const quadratic_number& beta, const big_int& K) {
  check_arguments(alpha, beta, K, "min_fractional_part");
  return min_frac(alpha, beta, K);
}

std::optional<big_int> first_fractional_part_at_most(const quadratic_number& alpha, const quadratic_number& beta,
                                                     const quadratic_number& w, const big_int& K) {
  check_arguments(alpha, beta, K, "first_fractional_part_at_most");
  if (w.sign() < 0) throw usage_error("first_fractional_part_at_most: w must be >= 0");
  return first_frac(alpha, beta, w, K);
}

rotation_minimum min_distance_to_half(const quadratic_number& x, const big_int& K) {
  check_x(x, "min_distance_to_half");
  if (K < 0) throw usage_error("min_distance_to_half: K must be >= 0");
  // ||k x - 1/2|| = min({k x + 1/2}, {k (1 - x) + 1/2}): the two one-sided problems.
  const rotation_minimum up = min_frac(x, half, K), down = min_frac(one - x, half, K);
  if (up.value < down.value) return up;
  if (down.value < up.value) return down;
  return up.k <= down.k ? up : down;
}

std::optional<big_int> first_distance_to_half_at_most(const quadratic_number& x, const quadratic_number& delta,
                                                      const big_int& K) {
  check_x(x, "first_distance_to_half_at_most");
  if (K < 0) throw usage_error("first_distance_to_half_at_most: K must be >= 0");
  if (delta.sign() < 0) throw usage_error("first_distance_to_half_at_most: delta must be >= 0");
  if (delta >= half) return big_int(0);
  // ||y|| <= delta  <=>  {y + delta} <= 2 delta, with y = k x - 1/2.
  return first_frac(x, (half + delta).frac(), delta + delta, K);
}

quadratic_number distance_to_half(const quadratic_number& x, const big_int& k) {
  const quadratic_number f = (quadratic_number(k) * x - half).frac();
  const quadratic_number g = one - f;
  return f <= g ? f : g;
}

int lobe_offset_sign(const quadratic_number& x, const big_int& k) {
  return (half - (quadratic_number(k) * x).frac()).sign();
}

}  // namespace gyrores
