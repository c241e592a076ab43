// The largest value over an interval of x of nu*_K(x) = min over 0 <= k <= K of ||k x - 1/2||,
// the lobe distance that orders a coupling's lobes (proofs/horizon-theorem.md, Step 12), in
// exact integer and rational arithmetic (src/lib only, not installed; theorem/band.cpp uses it).
//
// Lobe k is 0 at the centres c = (2j+1)/(2k) and rises with slope k on either side, so
// nu_k(x) <= k |x - c| for every centre c of lobe k (a "tent"). Between two neighbouring centres
// c1 < c2 (of lobes k1, k2), nu*_K is below the rising side of c1's tent and the falling side of
// c2's, whose minimum peaks where they cross, at x* = (j1 + j2 + 1)/(k1 + k2), with height
// (k1 (2 j2 + 1) - k2 (2 j1 + 1))/(2 (k1 + k2)). So the pieces between consecutive centres,
// each with its peak (clipped to the interval at its two ends), bound nu*_K from above. Any set
// of centres gives a valid bound; with every centre of lobes 1..K that lies in the interval (and
// the nearest ones outside) it is the exact maximum in every case tried (the proof does not need
// that). The centres are found by a scan over k in floating point, which may only add or miss
// centres, never make the bound wrong: every height is computed exactly from the integers.
#pragma once
#include <cstddef>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>

namespace gyrores::band_detail {

// One piece [lo, hi] of the interval with an upper bound of nu*_K on it and where that bound is
// reached.
struct envelope_piece {
  big_rational height, lo, hi, at;
};

struct envelope_bound {
  big_rational value;                 // >= max over [xa, xb] of nu*_K (and <= the cap given)
  std::vector<envelope_piece> top;    // the highest pieces, highest first (enumerated only)
  big_rational rest;                  // >= the height of every piece not in `top` (0 if none)
  bool enumerated = false;            // false: one lobe's bound (too many centres to list)
  std::size_t centres = 0;            // centres listed
};

// An upper bound of max over x in [xa, xb] of nu*_K(x), 0 < xa < xb < 1, K >= 0. `cap` is an
// upper bound already known (at most 1/2, the value of lobe 0); the result never exceeds it.
// When more than `max_centres` centres would have to be listed (or K > 2^26), the bound of the
// single lobe that is best at the midpoint is returned instead: max over the interval of
// ||k x - 1/2|| is 1/2 if k [xa, xb] holds an integer, else the larger of its end values.
// `keep` pieces are returned in `top`.
envelope_bound envelope_max(const big_rational& xa, const big_rational& xb, const big_int& K, const big_rational& cap,
                            std::size_t max_centres, std::size_t keep, const stop_token& stop);

// max over x in [xa, xb] of ||k x - 1/2|| (exactly).
big_rational lobe_distance_max(const big_rational& xa, const big_rational& xb, const big_int& k);

}  // namespace gyrores::band_detail
