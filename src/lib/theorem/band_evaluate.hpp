// The band theorem's evaluations at one precision (private to src/lib/theorem/band.cpp): the lobe
// values V_x(nu) at an interval's ends, the cut lobe and the reached tests (horizon-theorem.md
// Step 12 (a), (b)), the tests of a rising line's composite (band-theorem.md item 2), the end
// point R(T) over an interval (a mean value form), and the minimum over [0, T] at one coupling
// (the horizon theorem). Values are exact rationals, bounds outward; everything is in R = 2 H_q.
#pragma once
#include <arb.h>

#include <stdexcept>
#include <utility>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/theorem/band.hpp>

#include "../core/ball.hpp"

namespace gyrores::band_detail {

// This precision cannot decide a step: the band proof restarts at twice the bits.
class precision_shortfall : public std::runtime_error {
 public:
  explicit precision_shortfall(const char* why) : std::runtime_error(why), why_(why) {}
  const char* why() const { return why_; }  // static text (core/status.hpp reasons)

 private:
  const char* why_;
};

// [lo, hi] (exact rationals, lo <= hi) rounded outward to binary ends.
enclosure enclosure_of_rationals(const big_rational& lo, const big_rational& hi);

class band_arith {
 public:
  band_arith(const horizon_time& T, slong prec);

  // k_c: the lobe holding t = T at the coupling c (exact).
  big_int cut_lobe(const band_coupling& c) const;
  // Lobe k's minimiser lies in [0, T] wherever k is the cut lobe on [a, b] (reached), or after T
  // on all of it (not reached).
  bool reached_on(const big_int& k, const band_coupling& a, const band_coupling& b, bool reached) const;
  // Rational bounds of V_x(nu) at the coupling c (0 <= nu <= 1/2, exact).
  big_rational V_upper(const band_coupling& c, const quadratic_number& nu) const;
  big_rational V_lower(const band_coupling& c, const quadratic_number& nu) const;
  // On [a, b], where nu_k rises from na to nb: g > 0 throughout (the composite increases) is
  // g_signed(k, a, nb, b, true), g < 0 throughout (it decreases) g_signed(k, b, na, a, false);
  // false when not proved.
  bool g_signed(const big_int& k, const band_coupling& root_at, const quadratic_number& nu, const band_coupling& at,
                bool upper_end) const;
  // [inf, sup] of R(T) over the couplings of [a, b].
  std::pair<big_rational, big_rational> end_point_range(const band_coupling& a, const band_coupling& b) const;
  // The minimum of R over [0, T] at c, an enclosure [lo, hi] (the horizon theorem).
  std::pair<big_rational, big_rational> minimum_at(const band_coupling& c, const stop_token& stop) const;
  // The first time H_q <= E at c, an enclosure [lo, hi]; none when never (the horizon theorem).
  std::optional<std::pair<big_rational, big_rational>> first_below_at(const band_coupling& c, const big_rational& E,
                                                                      const stop_token& stop) const;
  // Two rationals at about a third and two thirds of [a, b].
  std::pair<big_rational, big_rational> middle_third(const band_coupling& a, const band_coupling& b) const;

 private:
  void lobe_root(arb_t out, const band_coupling& c, const arb_t target) const;  // H_x^{-1}(target)
  void signed_root(arb_t out, const band_coupling& c, const quadratic_number& signed_nu) const;
  void alpha_T(arb_t out, const band_coupling& c) const;
  void V(arb_t out, const band_coupling& c, const quadratic_number& nu) const;

  horizon_time T_;
  slong prec_;
  arb_support::ball pi_;
};

}  // namespace gyrores::band_detail
