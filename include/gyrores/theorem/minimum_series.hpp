// The theorem's first minimiser in double for blocks of pairs with delta >= 64: the form the
// sweeps that write no rows take (src/lib/sweep/fast.cpp), at a fraction of the cost of
// theorem_minimum_double (theorem/minimum.hpp), which made an order-20000 sweep 1.75 times slower
// there (measured on 2 cores). Like the rows' values, these are computed, not proved: theta_first
// within about an ulp of the exact value, the same bound as theorem_minimum_double's (the tests
// compare them), so the sweep summaries' quantiles agree with a run that writes rows.
//  - the pass frames' k of a block of pairs by batch inversion (one modular inverse per order),
//    and the lobes from them (minimiser_lobes_of_pass, theorem/lobes.hpp);
//  - u* = H^{-1}(pi m/(2a)) by its series in v = mu/(2x), u* <= v <= pi/128 for b >= 64;
//  - theta = 2 (k pi + sign(m) u*)/a in double-double, rounded once.
#pragma once
#include <cstdint>
#include <vector>

#include <gyrores/core/double_double.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

// The series below holds from this delta on.
inline constexpr std::int64_t series_min_delta = 64;

// H(u)/(2x) = (u + arctan(x tan u)/x)/2 = F(u) = v = mu/(2x) = pi m/(4b), and u* <= v (H(u) >=
// 2 x u: the tangent at 0 of the convex H, src/lib/theorem/root.cpp), so u* <= pi/128 here.
// F(u) = u + (1 - x^2) u^3/6 + ... (the series of tan and arctan), and its inverse series
//   u* = v (1 + c3 w + c5 w^2 + c7 w^3 + c9 w^4 + ...),  w = v^2,
//   c3 = -(1 - x^2)/6,  c5 = (1 - x^4)/60,  c7 = (2 - 7 x^2 + 7 x^4 - 2 x^6)/315,
//   c9 = (-143 + 290 x^2 - 290 x^6 + 143 x^8)/45360
// (by series reversion; each vanishes at x = 1, where F(u) = u). Truncated after v^9 its error,
// measured at 50 digits for v = pi/128 (the largest here) and x in (0, 1), is below 2^-65 u*
// (the next coefficient is below 2^-12, times w^5 < 2^-53). In double: x and v within two
// roundings (u* moves by at most their relative error, the sensitivity argument of
// src/lib/theorem/minimum.cpp), the correction v w (...) below 2^-12 v and formed to a few
// ulps of itself, then one rounding: u* within about 3 ulps.
GYRORES_DD_INLINE double theorem_root_series(double x, double v) {
  const double x2 = x * x, w = v * v;
  const double c3 = (x2 - 1) * (1.0 / 6), c5 = (1 - x2 * x2) * (1.0 / 60);
  const double c7 = (2.0 / 315) + x2 * (-1.0 / 45 + x2 * (1.0 / 45 - x2 * (2.0 / 315)));
  const double c9 = (-143.0 / 45360) + x2 * (29.0 / 4536 + x2 * x2 * (-29.0 / 4536 + x2 * (143.0 / 45360)));
  return v + v * w * (c3 + w * (c5 + w * (c7 + w * c9)));
}

// theta = 2 (k pi + su)/a (a = ad exact, inv_a = 1/ad rounded, k >= 1, |su| < pi/2): arc =
// k pi + su in double-double (pi to 2^-107, k < 2^53 exact: 2^-104 relative), then 2 arc/a by a
// quotient q = arc.hi (1/a) (a few ulps) and its exact remainder (Sterbenz: arc.hi - (q a).hi is
// exact, (q a).lo is q a's rounding error), so the sum q + r/a carries 2^-100 of the exact
// quotient before its one rounding. With k >= 1 and |su| < pi/2 the arc is above pi/2: an error
// of e ulps of su (su <= pi/128) is below 2^-5 e ulps of the arc, so theta is within half an ulp
// and e 2^-58 relative of the exact value.
GYRORES_DD_INLINE double lobe_theta_double(double ad, double inv_a, std::int64_t k, double su) {
  const double_double arc = dd::add(dd::mul(dd::pi, double(k)), su);
  const double q = arc.hi * inv_a;
  const double_double qa = dd::two_prod(q, ad);
  const double rem = ((arc.hi - qa.hi) - qa.lo) + arc.lo;
  return 2 * (q + rem * inv_a);
}

// The k of the pass frame (theorem/lobes.hpp: (2j+1) a - 2 k b = m_min, 0 < k < ah)
// of each pair of a block, ks[i] pairs[i]'s, by Montgomery's batch inversion over each run of one
// order: with ah = a (m_min = 1) or a/2 (m_min = 2), b = -2 sigma mod ah gives k = (4 sigma)^-1
// or (2 sigma)^-1 mod ah (minimum_series.cpp); 0 for degenerate pairs and orders from 2^31 on.
// Callers check the lobes built from it (the sweep's structure check): a wrong k costs them
// time, never a wrong result.
void pass_ks_of_block(const std::vector<resonant_pair<std::int64_t>>& pairs, std::vector<std::int64_t>& ks);

}  // namespace gyrores
