// The proof steps behind a certificate, shared by the producer (certify.hpp) and the checker
// (check.hpp). Every step is an interval (MPFI) computation with a tri-state outcome: it either
// proves its statement or reports that it could not; it never proves by rounding to nearest.
// The written argument is proofs/global-minimality.md; the step names below match it.
//
// Coordinates: a lobe frame (k, j) of resonant.hpp, m = (2j+1) a - 2 k b, mu = pi m/(2a),
// alpha = k pi + u, w = mu - x u, and
//   q = s v sqrt(1-x^2) sin u sin w,   q' = s v f(u),   f = cos u sin w - x sin u cos w,
//   z' = s v g(u),   g = x sin u sin w + cos u cos w,   s = (-1)^(k+j).
// R = q^2 + q'^2 does not depend on s.
#pragma once
#include <optional>
#include <vector>

#include <gyrores/core/interval.hpp>
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

inline constants constants_of(const resonant_pair<big_int>& p) {
  return {resonant_constants_of<I>(p, I(1)), p.tau(), p.sigma(), p.order(), big_int(p.delta())};
}

inline I mu_of(const constants& k, const big_int& m) {
  return k.c.pi * real_from_int<I>(m) / (2 * real_from_int<I>(k.a));
}

// f = q'/(s v), its u-derivative, g = z'/(s v), and R/v^2, on an interval U.
inline I f_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return cos(U) * sin(W) - k.c.x * sin(U) * cos(W);
}
inline I df_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return -(1 + k.c.x * k.c.x) * sin(U) * sin(W) - 2 * k.c.x * cos(U) * cos(W);
}
inline I g_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return k.c.x * sin(U) * sin(W) + cos(U) * cos(W);
}
inline I radius_sq_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  I su = sin(U), sw = sin(W);
  I q = k.c.s1mx2 * su * sw;
  I f = cos(U) * sw - k.c.x * su * cos(W);
  return interval_sqr(q) + interval_sqr(f);
}
// |q|/v at a point set U (used at the certified root, where R = q^2 exactly).
inline I abs_q_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return interval_abs(k.c.s1mx2 * sin(U) * sin(W));
}

// Rayleigh bound (paper Thm. globalMinimiser, part 1, with v = 1): for every theta,
//   R/v^2 >= (1-x^2) c^4 / (2 (1-x^2) c^2 + x^2),  c^2 = cos^2 beta = sin^2 w,
// and the right side increases with c^2. Returns a lower bound for c^2 >= c2_lower.
inline I rayleigh_lower(const constants& k, const I& c2_lower) {
  I omx2 = 1 - k.c.x * k.c.x;
  return omx2 * c2_lower * c2_lower / (2 * omx2 * c2_lower + k.c.x * k.c.x);
}

// Step "local-root": interval Newton on f in frame mu from a point guess. Proves a unique root
// of q' in the returned X (N(X) inside the interior of X) and tightens X while it shrinks.
inline std::optional<I> certify_root(const constants& k, const I& mu, const P& guess, const P& scale) {
  P delta = ldexp(scale, -int(real_bits<P>()) + 12);
  I X = interval_of(guess - delta, guess + delta);
  bool proved = false;
  for (int it = 0; it < 40; ++it) {
    I m = interval_mid(X);
    I dfX = df_of(k, mu, X);
    if (!certainly_nonzero(dfX)) break;
    I N = m - f_of(k, mu, m) / dfX;
    if (certainly_inside(N, X)) {
      proved = true;
      I next = interval_intersect(N, X);
      if (!(interval_upper(next) - interval_lower(next) < interval_upper(X) - interval_lower(X))) {
        X = next;
        break;
      }
      X = next;
    } else if (proved) {
      break;  // no further contraction: keep the proved enclosure
    } else {
      delta *= 4;  // the guess was too far for this radius: widen and retry
      X = interval_of(guess - delta, guess + delta);
    }
  }
  if (!proved) return std::nullopt;
  return X;
}

// Step "basin": on Y, f' has no zero (so q' has at most one root), f changes sign at the ends
// (so exactly one), and g has no zero (z' != 0). Hence the root is the only critical point of R
// in Y (dR/dt = -2 n q' z').
inline bool certify_basin(const constants& k, const I& mu, const I& Y) {
  I lo = interval_point(interval_lower(Y)), hi = interval_point(interval_upper(Y));
  I flo = f_of(k, mu, lo), fhi = f_of(k, mu, hi);
  bool sign_change = (certainly_positive(flo) && certainly_negative(fhi)) ||
                     (certainly_negative(flo) && certainly_positive(fhi));
  return sign_change && certainly_nonzero(df_of(k, mu, Y)) && certainly_nonzero(g_of(k, mu, Y));
}

// A lobe to exclude: frame (k, j) with u in [-pi/2, pi/2], minus basins (u-intervals of this lobe).
struct lobe {
  big_int k, j;
};

struct cover_stats {
  std::uint64_t lobes = 0, boxes = 0, rayleigh_hits = 0;
};

// The frame of lobe k nearest its slow node: j = floor(b k / a).
inline lobe lobe_at(const constants& k, const big_int& kk) {
  big_int j = int_floor_div(big_int(k.b * kk), k.a);
  return {kk, j};
}

// Step "cover" for one lobe: R/v^2 > bound on u in [-pi/2, pi/2] minus the basins, by
// bisection with the Rayleigh bound as a first filter. Returns false if a box of width below
// 2^-(bits/2) could not be decided (the certificate then says "not proved").
inline bool exclude_lobe(const constants& k, const lobe& L, const std::vector<I>& basins, const I& bound,
                         cover_stats& st) {
  big_int m = (2 * L.j + 1) * k.a - 2 * L.k * k.b;
  I mu = mu_of(k, m);
  I half_pi = k.c.pi / 2;
  std::vector<I> stack{interval_of(-interval_upper(half_pi), interval_upper(half_pi))};
  P min_width = ldexp(P(1), -int(real_bits<P>() / 2));
  ++st.lobes;
  while (!stack.empty()) {
    I U = stack.back();
    stack.pop_back();
    ++st.boxes;
    bool in_basin = false;
    for (const auto& Y : basins)
      if (certainly_subset(U, Y)) in_basin = true;
    if (in_basin) continue;
    I W = mu - k.c.x * U;
    I sw2 = interval_sqr(sin(W));
    if (certainly_less(bound, rayleigh_lower(k, interval_point(interval_lower(sw2))))) {
      ++st.rayleigh_hits;
      continue;
    }
    if (certainly_less(bound, radius_sq_of(k, mu, U))) continue;
    P lo = interval_lower(U), hi = interval_upper(U);
    if (hi - lo < min_width) return false;
    P mid = (lo + hi) / 2;
    // Split at a basin end inside U when there is one, so basins are cut out exactly.
    for (const auto& Y : basins) {
      P yl = interval_lower(Y), yh = interval_upper(Y);
      if (lo < yl && yl < hi) { mid = yl; break; }
      if (lo < yh && yh < hi) { mid = yh; break; }
    }
    stack.push_back(interval_of(lo, mid));
    stack.push_back(interval_of(mid, hi));
  }
  return true;
}

// theta = 2 (k pi + U)/a with k reduced mod a, as an enclosure.
inline I theta_of(const constants& k, const big_int& kk, const I& U) {
  big_int kr = int_mod(kk, k.a);
  return 2 * (k.c.pi * real_from_int<I>(kr) + U) / real_from_int<I>(k.a);
}

// The images of a minimiser frame under the exact symmetries (resonant.hpp): mirror always,
// shift (theta + pi) when tau and sigma are odd (delta = 0 mod 4 here).
struct image {
  big_int k, j;
  bool negate_u;
};
inline std::vector<image> images_of(const constants& k, const big_int& kk, const big_int& jj, bool with_shift) {
  std::vector<image> out{{kk, jj, false}, {k.a - kk, k.b - 1 - jj, true}};
  if (with_shift) {
    big_int ks = kk + k.a / 2, js = jj + k.b / 2;
    out.push_back({ks, js, false});
    out.push_back({k.a - ks, k.b - 1 - js, true});
  }
  return out;
}

}  // namespace gyrores::proof
