// include/gyrores/core/real.hpp: real_sin_cos for mpfr_real through Arb's arb_sin_cos.
//
// Why Arb: one arb_sin_cos costs less than one mpfr_sin_cos at every precision the library uses
// (measured: 1.5x less at 1000 digits, 3x less at 10000; four separate mpfr_sin/mpfr_cos cost
// twice one mpfr_sin_cos), and the lattice method's Newton polish is two sine-cosine pairs per
// step. Arb returns a ball; when both of its ends round to the same value at the target
// precision, that value is the correctly rounded result (Ziv's test), so the results equal
// MPFR's mpfr_sin and mpfr_cos bit for bit. Otherwise Arb runs once more with the missing bits
// added, and if still undecided, MPFR's correctly rounded mpfr_sin_cos is used.
#include <gyrores/core/real.hpp>
#include <gyrores/core/thread_caches.hpp>

#include <algorithm>

#include <flint.h>

#include "ball.hpp"

namespace gyrores {

namespace {

// Bits Arb works with beyond the target precision: the ball's radius is then ~2^-extra ulp.
constexpr slong sin_cos_extra_bits = 24;

// Ziv's test: every point of ball b rounds to nearest to the same value at out's precision;
// then out holds it (the correctly rounded value of anything in b). tmp: scratch of out's precision.
bool round_ball(mpfr_ptr out, mpfr_ptr tmp, const arb_t b, arf_ptr lo, arf_ptr hi) {
  if (!arb_is_finite(b)) return false;
  arb_get_lbound_arf(lo, b, ARF_PREC_EXACT);
  arb_get_ubound_arf(hi, b, ARF_PREC_EXACT);
  arf_get_mpfr(out, lo, MPFR_RNDN);
  arf_get_mpfr(tmp, hi, MPFR_RNDN);
  return mpfr_equal_p(out, tmp) != 0;
}

}  // namespace

sin_cos_pair<mpfr_real> real_sin_cos(const mpfr_real& x) {
  sin_cos_pair<mpfr_real> out;  // both at the current default precision, as sin(x) would be
  mpfr_ptr s = out.s.backend().data(), c = out.c.backend().data();
  mpfr_srcptr xv = x.backend().data();
  const slong prec = slong(std::max(mpfr_get_prec(s), mpfr_get_prec(c)));
  if (mpfr_number_p(xv) && !mpfr_zero_p(xv)) {
    arb_support::ball ax, as, ac, lo, hi;  // lo, hi: the ends' storage (their midpoints)
    mpfr_real tmp;                         // default precision, as s and c
    arf_set_mpfr(arb_midref(ax.get()), xv);  // exact: an arf holds any mpfr value
    // Arb's error is absolute near 0, so sin of a tiny x loses -log2|x| bits of relative accuracy:
    // they are added up front (the lattice method's u and w are ~1e-30 for (10^30+1, 10^30)).
    const slong tiny = std::max<slong>(0, -slong(mpfr_get_exp(xv)));
    slong wp = prec + sin_cos_extra_bits + std::min(tiny, prec);
    for (int attempt = 0; attempt < 2; ++attempt) {
      arb_sin_cos(as, ac, ax, wp);
      arf_ptr l = arb_midref(lo.get()), h = arb_midref(hi.get());
      if (round_ball(s, tmp.backend().data(), as, l, h) && round_ball(c, tmp.backend().data(), ac, l, h)) return out;
      // Once more with the bits that were missing (or, for a value next to a rounding boundary,
      // 64 more).
      const slong acc = std::min(arb_rel_accuracy_bits(as), arb_rel_accuracy_bits(ac));
      wp += std::max<slong>(prec + 2 - acc, 0) + 64;
    }
  }
  mpfr_sin_cos(s, c, xv, MPFR_RNDN);  // zero, NaN, infinities, or Arb undecided twice
  return out;
}

void release_thread_caches() {
  mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
  flint_cleanup();
}

}  // namespace gyrores
