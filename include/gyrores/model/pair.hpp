// Resonant pairs (tau, sigma) and their number theory.
//
// A resonant pair is a coprime pair of integers tau > sigma >= 1; it fixes the coupling
// n = (tau - sigma)/sqrt(tau sigma) (docs/mathematics.md §1, paper Prop. resonance). Notation:
//   a = order = tau + sigma,  b = delta = tau - sigma,  x = b/a in (0, 1).
// The integer type I is std::int64_t (fast) or big_int (any size); sums are formed in
// wide_int<I> so they never overflow.
#pragma once
#include <string>

#include <gyrores/core/integer.hpp>

namespace gyrores {

// Tag of the resonant_pair constructor for pairs whose coprimality the caller has already
// established: enumerators that produce only coprime pairs (coprime_pairs, model/enumerate.hpp;
// the sweep's coprimality table, src/lib/sweep/engine.cpp), where the constructor's own gcd
// would be repeated work (about 4% of a sweep's time at order 2e4).
struct known_coprime_t {
  explicit known_coprime_t() = default;
};
inline constexpr known_coprime_t known_coprime{};

template <pair_integer I> class resonant_pair {
 public:
  using int_type = I;
  using wide_type = wide_int<I>;

  // Checks tau > sigma >= 1 and gcd(tau, sigma) = 1; throws usage_error otherwise. The message
  // for a non-coprime pair names the reduced pair.
  resonant_pair(const I& tau, const I& sigma) : tau_(tau), sigma_(sigma) {
    check_range();
    I g = int_gcd(tau, sigma);
    if (g != 1)
      throw usage_error("pair (" + to_decimal(tau) + ", " + to_decimal(sigma) + ") is not coprime: gcd " +
                        to_decimal(g) + ", reduced pair (" + to_decimal(I(tau / g)) + ", " +
                        to_decimal(I(sigma / g)) + ")");
  }
  // The same for a pair known to be coprime (see known_coprime_t): tau > sigma >= 1 is checked,
  // gcd(tau, sigma) = 1 is a precondition and NOT checked. Only for code that has proved it.
  resonant_pair(const I& tau, const I& sigma, known_coprime_t) : tau_(tau), sigma_(sigma) { check_range(); }

  const I& tau() const { return tau_; }
  const I& sigma() const { return sigma_; }
  // a = tau + sigma, exact (wide type).
  wide_type order() const { return wide_type(tau_) + wide_type(sigma_); }
  // b = delta = tau - sigma >= 1; fits in I.
  I delta() const { return I(tau_ - sigma_); }
  int delta_mod4() const { return int(int_mod(delta(), I(4))); }
  // 2-adic valuation of delta (delta >= 1, so always defined).
  unsigned v2_delta() const { return int_v2(delta()); }
  // r_res = 0 exactly iff delta = 2 mod 4 (paper Thm. degenerate; proved in proofs/).
  bool degenerate() const { return delta_mod4() == 2; }
  // Smallest strand offset |a - 4N| at the zeros P+- of the torus picture (docs/mathematics.md §3):
  // 0 iff delta = 2 mod 4, 1 iff delta odd, 2 iff delta = 0 mod 4.
  int strand_offset_min() const {
    int d = delta_mod4();
    return d == 2 ? 0 : (d % 2 == 1 ? 1 : 2);
  }
  std::string str() const {
    // Built by appending: GCC 12 reports a false -Wrestrict on "(" + std::string&&.
    std::string s(1, '(');
    s += to_decimal(tau_);
    s += ", ";
    s += to_decimal(sigma_);
    s += ')';
    return s;
  }

  friend bool operator==(const resonant_pair&, const resonant_pair&) = default;

 private:
  void check_range() const {
    if (sigma_ < 1) throw usage_error("sigma must be >= 1, got " + to_decimal(sigma_));
    if (tau_ <= sigma_)
      throw usage_error("tau must exceed sigma, got (" + to_decimal(tau_) + ", " + to_decimal(sigma_) + ")");
  }
  I tau_, sigma_;
};

// The resonant pair whose frequency ratio W1/W2 equals num/den (any positive fraction other
// than 1, in any order; it is reduced). Throws usage_error for ratio 1 or non-positive input.
inline resonant_pair<big_int> pair_from_ratio(big_int num, big_int den) {
  if (num <= 0 || den <= 0)
    throw usage_error("a frequency ratio must be positive, got " + num.str() + "/" + den.str());
  big_int g = int_gcd(num, den);
  num /= g;
  den /= g;
  if (num == den) throw usage_error("frequency ratio 1 means n = 0: no resonant pair with tau > sigma");
  if (num < den) std::swap(num, den);
  return resonant_pair<big_int>(num, den);
}

// Convert a pair to another integer type (throws usage_error if it does not fit).
template <pair_integer J, pair_integer I> resonant_pair<J> pair_cast(const resonant_pair<I>& p) {
  if constexpr (std::is_same_v<I, J>) {
    return p;
  } else if constexpr (std::is_same_v<J, big_int>) {
    return resonant_pair<big_int>(to_big(p.tau()), to_big(p.sigma()));
  } else {
    big_int lim = big_int(std::numeric_limits<std::int64_t>::max());
    if (to_big(p.tau()) > lim) throw usage_error("pair " + p.str() + " does not fit in 64 bits");
    return resonant_pair<std::int64_t>(std::int64_t(p.tau()), std::int64_t(p.sigma()));
  }
}

// True when both entries fit in int64 (the fast path can be used).
inline bool pair_fits_int64(const resonant_pair<big_int>& p) {
  return p.tau() <= big_int(std::numeric_limits<std::int64_t>::max());
}

}  // namespace gyrores
