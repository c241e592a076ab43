// A band of couplings [n1, n2] (a designer's tolerance): over every n in it, the largest and the
// smallest minimum of H_q over [0, T], and the degenerate pairs whose exact zero of H_q comes
// before T (proofs/horizon-theorem.md, "Bands").
//
// M(n) = min over [0, T] of H_q is continuous in n, with |M(n) - M(n')| <= L |n - n'| where L
// bounds |dH_q/dn| over t in [0, T] and n in the band (enclosed in Arb from the closed form of
// the derivative; it grows like T). Each M(n) at an exact rational n is proved by the horizon
// theorem, so a branch and bound over boxes of n gives proved enclosures of max M and min M:
// a box of width h around a proved M(mid) holds values within L h/2 of it; boxes that cannot
// beat the best proved value are dropped, the others halved. The best case is exactly 0 when
// the band holds a degenerate pair (x = (2j+1)/(2k)) whose zero, at t = 2 k pi/sqrt(n^2 + 4),
// lies in [0, T]: found exactly, by the smallest such k.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/theorem/horizon.hpp>

namespace gyrores {

struct band_options {
  unsigned digits = 6;                 // the relative width asked of each enclosure: 10^-digits
  std::size_t max_evaluations = 4000;  // proved horizon minima per extreme (then the enclosure reached is reported)
  bool want_worst = true, want_best = true;  // which extremes to prove (the other is left 0, unconverged)
  stop_token stop;
};

// One extreme of M over the band: a proved enclosure, and where it is attained.
struct band_extreme {
  big_rational lo, hi;            // lo <= the extreme <= hi (exact rationals)
  std::string value;              // the correct rounding to `digits` digits when lo and hi share it, else ""
  big_rational n_at;              // a coupling where M(n_at) lies within [lo, hi]
  big_rational n_box_lo, n_box_hi;  // the extreme is attained in this box of n (it holds n_at)
  bool converged = false;         // hi - lo reached the asked width
};

struct band_degenerate {
  big_rational n2;                      // the coupling's n^2, exactly
  resonant_pair<big_int> pair;
  proved_real t_zero;                   // its first zero of H_q
};

struct band_report {
  big_rational n1, n2;
  horizon_time horizon;
  unsigned digits = 6;
  std::string lipschitz;                // the bound L on |dH_q/dn| used (upper end, 6 digits)
  band_extreme worst;                   // max over n of M(n)
  band_extreme best;                    // min over n of M(n)
  std::optional<band_degenerate> zero;  // a degenerate pair whose zero lies in [0, T] (then best = 0)
  std::size_t evaluations = 0;          // proved horizon minima computed
};

// Throws usage_error unless 0 < n1 < n2 and T >= 0; interrupted when opt.stop is set.
band_report prove_band(const big_rational& n1, const big_rational& n2, const horizon_time& horizon,
                       const band_options& opt = {});

// The bands as `gyrores coupling` and the Python module take them (src/cli/cmd_coupling.cpp,
// python/src/bind_coupling.cpp); `what` names the argument in the usage_error messages.
// "N1:N2" -> (n1, n2), the ends parsed as `what N1` and `what N2` (their order is check_band's).
std::pair<big_rational, big_rational> parse_band(const std::string& text, const std::string& what);
// A tolerance "P%" around n: the band |n| (1 -+ P/100); usage_error unless 0 < P < 100.
std::pair<big_rational, big_rational> parse_tolerance_band(const big_rational& n, const std::string& tolerance,
                                                           const std::string& what);
// usage_error "<what> needs 0 < n1 < n2, got n1:n2" unless it holds (prove_band checks it too, as "a band").
void check_band(const big_rational& n1, const big_rational& n2, const std::string& what);

}  // namespace gyrores
