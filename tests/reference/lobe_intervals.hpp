// The lobe functions of the resonant trajectory in MPFI, and their roots by interval Newton: the
// kernel the proof programs (proofs/verify_*.cpp) decide their claims with. Every function works
// at the current MPFI/MPFR precision (scoped_digits; the proof programs run single-threaded) and
// throws nothing of its own. (These are what remains of the retired cover certificate's proof
// steps, proofs/global-minimality.md.)
//
// Coordinates: a lobe frame (k, j) of model/resonant.hpp, m = (2j+1) a - 2 k b,
// mu = pi m/(2a), alpha = k pi + u, w = mu - x u, and
//   q' = s v f(u),   f = cos u sin w - x sin u cos w,
//   z' = s v g(u),   g = x sin u sin w + cos u cos w,   s = (-1)^(k+j).
#pragma once
#include <optional>

#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>

#include "reference/interval.hpp"
#include "testing/test_support.hpp"

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

// f = q'/(s v), its u-derivative, and g = z'/(s v), on an interval U of frame mu.
I f_of(const constants& k, const I& mu, const I& U);
I df_of(const constants& k, const I& mu, const I& U);
I g_of(const constants& k, const I& mu, const I& U);

// The root of q' near a point guess in frame mu: interval Newton (reference/interval_newton.hpp,
// 40 steps) on f; scale > 0 sets the first radius (typically |guess|). Returns X with a unique
// root of q' in X, or nullopt if not proved.
std::optional<I> certify_root(const constants& k, const I& mu, const P& guess, const P& scale);

}  // namespace gyrores::proof
