// The proof steps behind a certificate, shared by the producer (certify.hpp), the checker
// (check.hpp) and the proof programs (proofs/). Every step is an interval (MPFI) computation
// with a tri-state outcome: it either proves its statement or reports that it could not; it
// never proves by rounding to nearest. The written argument is proofs/global-minimality.md; the
// step names below match it. Every function works at the current MPFI/MPFR precision
// (scoped_digits) and throws nothing of its own unless it says so.
//
// Coordinates: a lobe frame (k, j) of model/resonant.hpp, m = (2j+1) a - 2 k b,
// mu = pi m/(2a), alpha = k pi + u, w = mu - x u, and
//   q = s v sqrt(1-x^2) sin u sin w,   q' = s v f(u),   f = cos u sin w - x sin u cos w,
//   z' = s v g(u),   g = x sin u sin w + cos u cos w,   s = (-1)^(k+j).
// R = q^2 + q'^2 does not depend on s.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "reference/interval.hpp"
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores::proof {

using I = mpfi_real;
using P = mpfr_real;

// Per-pair constants as enclosures (pi, square roots and quotients enclosed, never rounded).
struct constants {
  resonant_constants<I> c;
  big_int tau, sigma, a, b;
};

constants constants_of(const resonant_pair<big_int>& p);

// mu = pi m/(2a) for the frame offset m.
I mu_of(const constants& k, const big_int& m);

// f = q'/(s v), its u-derivative, g = z'/(s v), and R/v^2, on an interval U of frame mu.
I f_of(const constants& k, const I& mu, const I& U);
I df_of(const constants& k, const I& mu, const I& U);
I g_of(const constants& k, const I& mu, const I& U);
I radius_sq_of(const constants& k, const I& mu, const I& U);
// |q|/v on U (used at the certified root, where R = q^2 exactly).
I abs_q_of(const constants& k, const I& mu, const I& U);

// Rayleigh bound (paper Thm. globalMinimiser, part 1, with v = 1): for every theta,
//   R/v^2 >= (1-x^2) c^4 / (2 (1-x^2) c^2 + x^2),  c^2 = cos^2 beta = sin^2 w,
// and the right side increases with c^2. Returns a lower bound for c^2 >= c2_lower >= 0.
I rayleigh_lower(const constants& k, const I& c2_lower);

// True when the relative width of x (absolute where x contains 0) is <= 10^-digits: x then
// certifies `digits` digits.
bool meets_digits(const I& x, unsigned digits);

// Step "local-root": interval Newton (tests/reference/interval_newton.hpp, 40 steps) on f in frame mu
// from a point guess; scale > 0 sets the first radius (typically |guess|). Returns X with a
// unique root of q' in X, or nullopt if not proved.
std::optional<I> certify_root(const constants& k, const I& mu, const P& guess, const P& scale);

// Step "basin": on Y, f' has no zero (so q' has at most one root), f changes sign at the ends
// (so exactly one), and g has no zero (z' != 0). Hence the root is the only critical point of R
// in Y (dR/dt = -2 n q' z'). False when any of the three is not certain.
bool certify_basin(const constants& k, const I& mu, const I& Y);

// A lobe to exclude: frame (k, j) with u in [-pi/2, pi/2].
struct lobe {
  big_int k, j;
};

struct cover_stats {
  std::uint64_t lobes = 0, boxes = 0, rayleigh_hits = 0;
};

// The frame of lobe k nearest its slow node: j = floor(b k / a).
lobe lobe_at(const constants& k, const big_int& kk);

// Step "cover" for one lobe: R/v^2 > bound on u in [-pi/2, pi/2] minus the basins (u-intervals
// of this lobe), by bisection with the Rayleigh bound as a first filter; counts lobes and boxes
// in st. Returns false if a box of width below 2^-(bits/2) could not be decided (the
// certificate then says "not proved").
bool exclude_lobe(const constants& k, const lobe& L, const std::vector<I>& basins, const I& bound, cover_stats& st);

// theta = 2 (k pi + U)/a with k reduced mod a, as an enclosure.
I theta_of(const constants& k, const big_int& kk, const I& U);

// The images of a minimiser frame under the exact symmetries (model/resonant.hpp): the frame
// itself, its mirror (a-k, b-1-j, -u) and, when with_shift (tau, sigma odd, delta = 0 mod 4),
// the shift theta + pi (k + a/2, j + b/2, u) and its mirror.
struct image {
  big_int k, j;
  bool negate_u;
};
std::vector<image> images_of(const constants& k, const big_int& kk, const big_int& jj, bool with_shift);

// Steps "local-root" and "symmetry" together, for a non-degenerate pair: the lattice method
// (tests/reference/lattice.hpp, in MPFR) gives the guess and the frame, interval Newton proves the q'
// root X, and the enclosures of r = |q| there, of every minimiser image's theta and of the
// first one (theta_first, t_first = sqrt(tau sigma) theta_first) follow.
struct minimiser_enclosures {
  lobe_frame<big_int> frame;
  I X, r, theta_first, t_first;
  std::vector<image> images;
  std::vector<I> thetas;  // one per image, same order
};
// Throws compute_error when interval Newton fails or two images' thetas overlap at this
// precision. Precondition (not checked): p is not degenerate.
minimiser_enclosures enclose_minimisers(const resonant_pair<big_int>& p, const constants& K);

}  // namespace gyrores::proof
