// The lattice theorem (proofs/lattice-theorem.md, id "lattice-theorem/1") as computations.
//
// For every coprime pair with m_min >= 1 the global minimum of R is v^2 G(u*), where u* in
// (0, pi/2) is the unique solution of
//   H(u) = x u + arctan(x tan u) = mu_min = pi m_min/(2a),
//   G(u) = (1-x^2) x^2 sin^4 u/(cos^2 u + x^2 sin^2 u),
// and the global minimisers are the points u = sign(m) u* of exactly the lobes whose frame has
// |m| = m_min (2 lobes for delta odd, 4 for delta = 0 mod 4). H is odd, strictly increasing and
// convex on [0, pi/2]; nothing here is observed, everything is proved there.
//
// This header gives the integer part (the minimisers' lobes, in theta order, found by one
// modular inverse) and u* in any real type (safeguarded Newton in double, or MPFR at 64 bits
// beyond double's exponent range, then Newton with precision doubling in T).
#pragma once
#include <algorithm>
#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/core/roots.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

inline constexpr const char* lattice_theorem_id = "lattice-theorem/1";

// Frame (k, j, m) rewritten with k in [0, a): k -> k - t a keeps m when j -> j - t b.
template <class L> lobe_frame<L> lobe_frame_reduced(const lobe_frame<L>& f, const L& a, const L& b) {
  L t = int_floor_div(f.k, a);
  return {L(f.k - t * a), L(f.j - t * b), f.m};
}

// The lobes of the global minimisers over one period, k in [0, a), in increasing theta: the
// minimiser of a lobe is at u = sign(m) u*, so a k = 0 lobe with m < 0 comes last (theta near
// 2 pi). For m_min = 0 (degenerate) the two lobes of the zeros pi/2, 3 pi/2 (u = 0, m = 0).
template <class L> std::vector<lobe_frame<L>> minimiser_lobes(const L& a, const L& b) {
  std::vector<lobe_frame<L>> out;
  if (int_mod(a, L(4)) == 0) {
    out.push_back(lobe_frame_of(a, b, L(a / 4), L((b - 2) / 4)));
    out.push_back(lobe_frame_of(a, b, L(3 * (a / 4)), L((3 * b - 2) / 4)));
    return out;
  }
  auto pass = detail::lattice_pass_frame(a, b);
  out.push_back(pass);
  out.push_back(lobe_mirror(pass, a, b));
  if (pass.m == 2) {
    auto s = lobe_shift(pass, a, b);
    out.push_back(s);
    out.push_back(lobe_mirror(s, a, b));
  }
  for (auto& f : out) f = lobe_frame_reduced(f, a, b);
  auto key = [&](const lobe_frame<L>& f) { return f.k == 0 && f.m < 0 ? a : f.k; };
  std::sort(out.begin(), out.end(), [&](const auto& x, const auto& y) { return key(x) < key(y); });
  return out;
}

namespace detail {

// H(u) - mu and H'(u) = x + x (1 + t^2)/(1 + x^2 t^2), t = tan u.
template <class T> std::pair<T, T> theorem_h(const T& x, const T& mu, const T& u) {
  using std::atan;
  using std::tan;
  T t = tan(u);
  T xt = x * t;
  return {T(x * u + atan(xt) - mu), T(x + x * (1 + t * t) / (1 + xt * xt))};
}

// u* to about 53 bits (64 in MPFR) in S, by safeguarded Newton on [0, pi/2] (H(0) - mu < 0 <
// H(pi/2) - mu). Start: mu/(2x) (H ~ 2xu for small u and x; H ~ 2u as x -> 1); the safeguard
// keeps any start inside the bracket.
template <class S> S theorem_root_scout(const S& x, const S& mu) {
  const S h = real_pi<S>() / 2;
  S u0 = mu / (2 * x);
  if (u0 > h * S(0.9)) u0 = h * S(0.9);
  newton_result<S> nr;
  auto fdf = [&](const S& u) { return theorem_h(x, mu, u); };
  if (!root_newton_safeguarded(fdf, S(0), h, -1, u0, S(mu / 4), nr, 200))
    throw compute_error("lattice theorem: the root of x u + arctan(x tan u) = mu did not converge");
  return nr.root;
}

// x = b/a and mu = pi m/(2a) in R at R's current precision.
template <class R> std::pair<R, R> theorem_x_mu(const big_int& a, const big_int& b, int m, const R& pi) {
  R ar = real_from_int<R>(a);
  return {R(real_from_int<R>(b) / ar), R(pi * m / (2 * ar))};
}
template <class R> std::pair<R, R> theorem_x_mu(const big_int& a, const big_int& b, int m) {
  return theorem_x_mu(a, b, m, real_pi<R>());
}

}  // namespace detail

// u* of pair p (m_min >= 1) in T, to T's precision: the scout, then Newton steps in T (for MPFR
// with doubling precision, the last step at full precision). compute_error if Newton does not
// settle; usage_error-free (p is a valid pair; degenerate pairs have u* = 0). With
// settle = false only one full-precision step is taken and not checked (for a caller that
// proves the result anyway, as the certificate's bracket does).
template <class T, pair_integer I> T theorem_root(const resonant_pair<I>& p, bool settle = true) {
  using std::fabs;
  using std::ldexp;
  if (p.degenerate()) return T(0);
  const big_int a = to_big(p.order()), b = to_big(p.delta());
  const int m = p.strand_offset_min();
  T u;
  unsigned have_bits = 53;
  if (a < (big_int(1) << 900)) {
    auto [x, mu] = detail::theorem_x_mu<double>(a, b, m);
    u = T(detail::theorem_root_scout(x, mu));
  } else {
    if constexpr (!is_mpfr_v<T>) {
      throw compute_error("pair " + p.str() + " exceeds the exponent range of " + real_type_name<T>() +
                          "; use mpfr_real (more digits)");
    } else {
      scoped_digits d(20);
      auto [x, mu] = detail::theorem_x_mu<mpfr_real>(a, b, m);
      mpfr_real s = detail::theorem_root_scout(x, mu);
      have_bits = 64;
      u = T(s);
    }
  }
  if constexpr (std::is_same_v<T, double>) return u;
  const unsigned full = real_bits<T>();
  // pi once at full precision: MPFR caches it for one precision only, so asking for it at every
  // level of the ladder would recompute it each time.
  const T pi_full = real_pi<T>();
  if constexpr (is_mpfr_v<T>) {
    std::vector<unsigned> ladder;
    // Levels down to just above the scout's bits: each Newton step doubles the accurate bits, so the
    // last level (>= have_bits + 8) leaves the full-precision step at least 2 (have_bits + 8) >= full
    // bits whenever full <= 2 have_bits + 16; higher full precisions get more levels.
    for (unsigned bits = full / 2 + 16; bits > have_bits + 8; bits = bits / 2 + 16) ladder.push_back(bits);
    std::reverse(ladder.begin(), ladder.end());
    for (unsigned bits : ladder) {
      scoped_digits d(digits10_for_bits(bits));
      T uu = u, pi;
      uu.precision(T::default_precision());
      mpfr_set(pi.backend().data(), pi_full.backend().data(), MPFR_RNDN);
      auto [x, mu] = detail::theorem_x_mu<T>(a, b, m, pi);
      auto [f, df] = detail::theorem_h(x, mu, uu);
      u = uu - f / df;
    }
    u.precision(T::default_precision());
  }
  auto [x, mu] = detail::theorem_x_mu<T>(a, b, m, pi_full);
  const T tol = ldexp(T(1), -int(full / 2) + 4);
  if (!settle) {
    auto [f, df] = detail::theorem_h(x, mu, u);
    return T(u - f / df);
  }
  for (int it = 0; it < 8; ++it) {
    auto [f, df] = detail::theorem_h(x, mu, u);
    T step = f / df;
    u -= step;
    if (fabs(step) <= tol * fabs(u)) return u;
  }
  throw compute_error("lattice theorem: Newton on x u + arctan(x tan u) = mu did not settle in " + real_type_name<T>());
}

}  // namespace gyrores
