// Design with a tolerance on the coupling: a pair's coupling n0 = (tau - sigma)/sqrt(tau sigma)
// is realised only within n0 (1 -+ p). The guarantee must then hold for every n of that band
// (theorem/band.hpp), over a horizon, since away from n0 the motion is not periodic:
//   absorb:  H_q <= E at some t <= T_max for every n in the band, i.e. the band's absorption
//            guarantee (its highest minimum of H_q over [0, T_max]) is <= E;
//   contain: H_q >= E on [0, H] for every n in the band, i.e. the band's containment guarantee
//            (its lowest minimum over [0, H]) is >= E (0 once a degenerate pair's zero lies in it).
// Each decision is proved from the band's enclosure; a pair whose enclosure straddles E is
// "undecided" (never counted as meeting it). The band is widened outward to rational ends.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include <gyrores/core/rational.hpp>
#include <gyrores/design/design.hpp>
#include <gyrores/theorem/band.hpp>

namespace gyrores {

struct tolerance_options {
  big_rational fraction;          // p in (0, 1): the band n0 (1 -+ p)
  big_rational level;             // E >= 0 (an energy; H_q(0) = 1/2)
  horizon_time horizon;           // T_max (absorb) or H (contain)
  std::size_t max_pairs = 20;     // ranked pairs examined at most, best first
  band_options band{6};           // the band proofs' digits (each stops as soon as E is decided) and stop token
};

enum class tolerance_verdict { meets, fails, undecided };

struct tolerance_check {
  design_point point;
  big_rational n1, n2;            // the band
  band_extreme guarantee;         // absorb: the absorption guarantee W/2; contain: the containment one B/2
  tolerance_verdict verdict = tolerance_verdict::undecided;
};

struct tolerance_result {
  std::vector<tolerance_check> checked;  // in rank order, up to the first that meets the guarantee
  std::optional<std::size_t> chosen;     // index into checked of the first pair that meets it
  bool interrupted = false;              // stopped by the stop token: the last check holds the bracket reached
};

// The band [n0 (1 - p), n0 (1 + p)] widened outward to rationals (12 digits).
std::pair<big_rational, big_rational> tolerance_band(const design_point& p, const big_rational& fraction);

// Walks `ranked` (design_solve's order) and returns the first pair whose band meets the guarantee.
// Throws usage_error unless 0 < p < 1 and E >= 0.
tolerance_result design_with_tolerance(const std::vector<design_point>& ranked, design_problem problem,
                                       const tolerance_options& opt);

std::string tolerance_verdict_name(tolerance_verdict v);  // "meets", "fails", "undecided"

}  // namespace gyrores
