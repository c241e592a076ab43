// Exact inscribed radius for any coprime pair in O(log tau): the lattice method (docs/mathematics.md §3).
//
// On the torus (p1, p2) = (tau theta, sigma theta), (q, q') vanishes only at P+ = (pi/2, -pi/2)
// and P- = (-pi/2, pi/2). The closed line passes P+ on strands at offsets (pi/2)(a - 4N)/|(tau,
// sigma)|; the smallest |a - 4N| = m_min is 0, 1 or 2 by a mod 4. In lobe-frame terms
// (resonant.hpp) a pass with offset m is a frame (k, j) with (2j+1) a - 2 k b = m; for m = m_min
// it is found by one modular inverse (extended Euclid):
//   delta odd:       2j+1 = a^{-1} mod 2b,            k = ((2j+1) a - 1)/(2b)
//   delta = 0 mod 4: 2j+1 = (a/2)^{-1} mod (b/2)*2,   k = ((2j+1) a/2 - 1)/b
// The global minimiser is the root of q' = 0 in u in [0, pi/2] of that frame: q' changes sign
// there (f(0) = sin mu > 0 > -x cos(mu - x pi/2) = f(pi/2)) and has no other root (the lattice
// theorem, proofs/lattice-theorem.md: the root is u* with x u + arctan(x tan u) = mu, and the
// global minimisers are exactly its images). The other minimisers are the exact images under
// theta -> 2 pi - theta (and theta -> theta + pi when tau, sigma are odd): 2 minimisers for
// delta odd, 4 for delta = 0 mod 4. PROVED for every pair (lattice-theorem/1); the cross-check
// against the global search (cross_check.hpp) remains as an independent test of the code.
// lattice_options::window_always instead solves the q' roots of the five intervals
// [i pi/tau, (i+1) pi/tau] around the pass and keeps the smallest R (a cross-check).
//
// Precision: the root is scouted in double (MPFR at 64 bits when the pair exceeds double's
// exponent range) with TOMS 748, then polished in T by Newton's method; for mpfr_real with
// precision doubling, so the last step is the only one at full precision.
#pragma once
#include <algorithm>
#include <memory>
#include <tuple>
#include <vector>

#include <gyrores/inscribed/degenerate.hpp>
#include <gyrores/inscribed/global_search.hpp>
#include <gyrores/model/resonant.hpp>
#include <gyrores/inscribed/result.hpp>
#include <gyrores/core/roots.hpp>

namespace gyrores {

// How the q' root at each candidate bracket is found.
enum class lattice_solver {
  scout_and_polish,  // default: scout in double (safeguarded Newton or TOMS 748), polish in T by Newton
  toms748_full,      // TOMS 748 in T at every bracket, no scout, no Newton (slower; a cross-check
                     // and the benchmark's "TOMS 748 in local coordinates")
};

struct lattice_options {
  // Solve the q' roots in the five intervals around the pass (for any x) and keep the smallest R,
  // instead of the single bracket of the default.
  bool window_always = false;
  lattice_solver solver = lattice_solver::scout_and_polish;
};

namespace detail {

// The pass frame with offset m = +m_min (m_min = 1 or 2). L: int128 or big_int.
template <class L> lobe_frame<L> lattice_pass_frame(const L& a, const L& b) {
  if (int_mod(b, L(2)) == 1) {
    L mod = 2 * b;
    L odd = mod == 2 ? L(1) : int_inverse_mod(a, mod);  // odd since a * odd = 1 mod an even number
    L j = (odd - 1) / 2;
    L k = ((2 * j + 1) * a - 1) / (2 * b);
    return {k, j, L(1)};
  }
  // delta = 0 mod 4: a = 2a', b = 2b', a' odd, b' even; (2j+1) a' - 2 k b' = 1.
  L ah = a / 2, bh = b / 2;
  L mod = 2 * bh;
  L odd = int_inverse_mod(ah, mod);
  L j = (odd - 1) / 2;
  L k = ((2 * j + 1) * ah - 1) / (2 * bh);
  return {k, j, L(2)};
}

template <class S> struct scout_root {
  S u, radius_sq;
  std::uintmax_t evaluations;
};

// Solve q' = 0 in frame f on [ulo, uhi] in the scout type S.
template <class S, class L>
scout_root<S> lattice_solve(const resonant_constants<S>& c, const lobe_frame<L>& f, const L& a, const S& ulo,
                            const S& uhi) {
  auto fr = lobe_frame_real_of(c, f, a);
  auto fn = [&](const S& u) {
    using std::cos;
    using std::sin;
    S w = fr.mu - c.x * u;
    return S(cos(u) * sin(w) - c.x * sin(u) * cos(w));
  };
  auto root = root_bracketed(fn, ulo, uhi, fn(ulo), fn(uhi), default_root_tolerance<S>(lobe_root_floor(fr)),
                             "lattice (q' = 0)");
  S q = lobe_eval(c, fr, root.root).q;  // |q| alone at a q' root (resonant.hpp)
  return {root.root, q * q, root.evaluations + 2};
}

template <class L> struct lattice_candidate_site {
  lobe_frame<L> frame;
  L lo_num, hi_num, den;  // bracket as theta = pi * num / den (window mode), or den = 0: u in [0, pi/2]
};

// Candidate brackets for the minimiser (see the header comment).
template <class L> std::vector<lattice_candidate_site<L>> lattice_sites(const L& tau, const L& a, const L& b,
                                                                        bool window, bool five = true) {
  auto pass = lattice_pass_frame(a, b);
  if (!window) return {{pass, L(0), L(0), L(0)}};
  // Interval containing theta_pass = 2 k pi/a, in units pi/tau: i = floor(2 k tau / a).
  L ic = int_floor_div(L(2 * pass.k * tau), a);
  std::vector<lattice_candidate_site<L>> out;
  L den = 2 * tau;
  const L reach = five ? L(2) : L(0);
  for (L i = ic - reach; i <= ic + reach; ++i) {
    L centre = 2 * i + 1;
    out.push_back({lobe_frame_near(a, b, centre, den), L(centre - 1), L(centre + 1), den});
  }
  return out;
}

template <class S, class L>
scout_root<S> lattice_solve_site(const resonant_constants<S>& c, const lattice_candidate_site<L>& s, const L& a) {
  if (s.den == 0) {
    // f(0) = sin mu > 0 > f(pi/2) (m = m_min > 0; header comment). Safeguarded Newton from
    // u ~ mu/(2x) (u + tan u ~ 2u = mu/x for small u; for x -> 1 also H(u) ~ 2u = mu), TOMS 748
    // if it does not converge.
    S h = c.pi / 2;
    auto fr = lobe_frame_real_of(c, s.frame, a);
    S floor = lobe_root_floor(fr);
    S u0 = fr.mu / (2 * c.x);
    if (u0 > h * S(0.9)) u0 = h * S(0.9);
    S q_last = 0;
    auto fdf = [&](const S& u) {
      auto e = lobe_qdot_newton(c, fr.mu, u);
      q_last = c.v * c.s1mx2 * e.su * e.sw;
      return std::pair<S, S>{e.f, e.df};
    };
    newton_result<S> nr;
    if (root_newton_safeguarded(fdf, S(0), h, +1, u0, floor, nr))
      return {nr.root, q_last * q_last, nr.evaluations};  // |q| at the last point: stationary
    return lattice_solve(c, s.frame, a, S(0), h);
  }
  return lattice_solve(c, s.frame, a, lobe_u_at(c, s.frame, a, s.lo_num, s.den), lobe_u_at(c, s.frame, a, s.hi_num, s.den));
}

template <class T> void set_working_precision(T& v) {
  if constexpr (is_mpfr_v<T>) v.precision(T::default_precision());
}

}  // namespace detail

// Newton polish of q' = 0 in lobe frame f (a = tau + sigma) from u0, a root accurate to about
// start_bits bits, in T. For mpfr_real the precision doubles up to the current default, so only
// the last step runs at full precision; other types take plain Newton steps. Returns u and R;
// R comes from the last evaluation, at a point within |step| of the root, and R is stationary
// there (q' = 0), so its error is O(step^2). Precondition (not checked): u0 is in the root's
// basin of Newton convergence (e.g. the lattice method's double scout). compute_error if 8
// full-precision steps do not reach half the working precision.
template <class T> struct lobe_polish_result {
  T u, radius_sq;
  std::uintmax_t evaluations;
};


template <class T, class L, pair_integer I>
lobe_polish_result<T> lobe_root_polish(const resonant_pair<I>& p, const T& v, const lobe_frame<L>& f, const L& a, const T& u0,
                           unsigned start_bits) {
  using std::fabs;
  using std::ldexp;
  std::uintmax_t evals = 0;
  T u = u0;
  auto newton_step = [&](const resonant_constants<T>& c, const T& mu, T& rsq) {
    auto e = lobe_qdot_newton(c, mu, u);
    ++evals;
    T q = c.v * c.s1mx2 * e.su * e.sw;  // |q| alone at a q' root (resonant.hpp)
    rsq = q * q;
    T step = e.f / e.df;
    u -= step;
    return step;
  };
  if constexpr (is_mpfr_v<T>) {
    // Lower levels: bits_full/2 + 16, its half + 16, ... down to twice the start accuracy.
    std::vector<unsigned> ladder;
    for (unsigned b = real_bits<T>() / 2 + 16; b > 2 * start_bits; b = b / 2 + 16) ladder.push_back(b);
    std::reverse(ladder.begin(), ladder.end());
    for (unsigned bits : ladder) {
      scoped_digits d(digits10_for_bits(bits));
      detail::set_working_precision(u);
      auto c = resonant_constants_of<T>(p, T(v));
      T rsq;
      newton_step(c, lobe_frame_real_of(c, f, a).mu, rsq);
    }
    detail::set_working_precision(u);
  }
  auto c = resonant_constants_of<T>(p, v);
  const auto fr = lobe_frame_real_of(c, f, a);
  const T mu = fr.mu, floor = lobe_root_floor(fr);
  const T half_eps = ldexp(T(1), -int(real_bits<T>() / 2) + 4);
  for (int it = 0; it < 8; ++it) {
    T rsq;
    T step = newton_step(c, mu, rsq);
    T scale = fabs(u) > floor ? fabs(u) : floor;
    if (fabs(step) <= half_eps * scale) return {u, rsq, evals};
  }
  throw compute_error("lattice: Newton polish of q' = 0 did not converge in " + real_type_name<T>());
}

namespace detail {

// A minimiser as an exact lobe frame (k reduced to [0, a)) and the sign of its u = +-u*, u* in
// (0, pi/2): theta = 2 (k pi + u)/a. Its place in [0, 2 pi) is decided by integers alone: by
// k, then by the sign of u (|u| < pi/2 keeps every lobe inside (k - 1/2, k + 1/2) pi 2/a), and
// a k = 0 lobe with u < 0 lies just below 2 pi (theta = 2 pi + 2u/a), so it comes last. No
// theta formed in floating point is compared, reduced mod 2 pi or subtracted from 2 pi: a
// minimiser at 2 pi - 1e-50 must not round to 2 pi and wrap to 0 (issue 12).
template <class L> struct lattice_minimiser {
  lobe_frame<L> frame;  // k in [0, a)
  bool negative;        // u = -u*
  L key;                // k, or a for the wrapped lobe (k = 0, u < 0)
};

template <class L> lattice_minimiser<L> lattice_minimiser_of(const lobe_frame<L>& f, bool negative, const L& a,
                                                            const L& b) {
  L t = int_floor_div(f.k, a);
  lobe_frame<L> g{L(f.k - t * a), L(f.j - t * b), f.m};
  return {g, negative, (g.k == 0 && negative) ? a : g.k};
}

// theta = 2 (key pi + u)/a from the exact key; only formed for output.
template <class T, class L> T lattice_theta(const resonant_constants<T>& c, const L& key, const L& a, const T& u) {
  T at = real_from_int<T>(a);
  return 2 * (c.pi * real_from_int<T>(key) + u) / at;
}

template <class T, class L>
void lattice_fill(inscribed_result<T>& r, const resonant_constants<T>& c, const lobe_frame<L>& f, const L& a,
                  const L& b, const T& u, const T& rsq, int m_min) {
  using std::fabs;
  // u* > 0 and the frame's u has the sign of its m (the theorem: u = sign(m) u*).
  const bool f_negative = u < 0;
  const T ustar = fabs(u);
  std::vector<lattice_minimiser<L>> pts;
  pts.push_back(lattice_minimiser_of(f, f_negative, a, b));
  pts.push_back(lattice_minimiser_of(lobe_mirror(f, a, b), !f_negative, a, b));
  if (m_min == 2) {
    auto s = lobe_shift(f, a, b);
    pts.push_back(lattice_minimiser_of(s, f_negative, a, b));
    pts.push_back(lattice_minimiser_of(lobe_mirror(s, a, b), !f_negative, a, b));
  }
  std::sort(pts.begin(), pts.end(), [](const auto& x, const auto& y) {
    if (x.key != y.key) return x.key < y.key;
    return x.negative && !y.negative;
  });
  std::vector<T> thetas;
  for (const auto& p : pts) thetas.push_back(lattice_theta(c, p.key, a, p.negative ? T(-ustar) : ustar));
  set_minimum(r, rsq, c.v, c.sqrt_ts, std::move(thetas));
  const auto& g = pts.front();
  r.first = {to_big(g.frame.k), to_big(g.frame.j), to_big(g.frame.m), g.negative ? T(-ustar) : ustar};
}

// The q' root and R at every candidate site, before the choice of the minimiser.
template <class T> struct lattice_candidates {
  std::vector<T> u, radius_sq;
  std::uintmax_t evaluations = 0;
  unsigned bits = 53;  // accuracy of the roots (the scout type's precision)
};

template <class S, class T, class L, pair_integer I>
void lattice_scout_in(lattice_candidates<T>& out, const resonant_pair<I>& p, const S& v,
                      const std::vector<lattice_candidate_site<L>>& sites, const L& a) {
  auto cs = resonant_constants_of<S>(p, v);
  for (const auto& s : sites) {
    auto sr = lattice_solve_site(cs, s, a);
    out.evaluations += sr.evaluations;
    out.u.push_back(T(sr.u));
    out.radius_sq.push_back(T(sr.radius_sq));
  }
}

// The scout: every site solved in double, or in MPFR at 64 bits when the pair is beyond double's
// exponent range (`huge`; then T is mpfr_real, checked by the caller).
template <class T, class L, pair_integer I>
lattice_candidates<T> lattice_scout(const resonant_pair<I>& p, const T& v,
                                    const std::vector<lattice_candidate_site<L>>& sites, const L& a, bool huge) {
  lattice_candidates<T> out;
  if constexpr (std::is_same_v<T, double>) {
    lattice_scout_in<double>(out, p, v, sites, a);
  } else if (!huge) {
    lattice_scout_in<double>(out, p, 1.0, sites, a);
  } else if constexpr (is_mpfr_v<T>) {
    scoped_digits d(20);
    out.bits = 64;
    lattice_scout_in<mpfr_real>(out, p, mpfr_real(1), sites, a);
  }
  return out;
}

// lattice_solver::toms748_full: every site solved by TOMS 748 in T directly.
template <class T, class L, pair_integer I>
lattice_candidates<T> lattice_solve_full(const resonant_pair<I>& p, const T& v,
                                         const std::vector<lattice_candidate_site<L>>& sites, const L& a) {
  lattice_candidates<T> out;
  out.bits = real_bits<T>();
  auto c = resonant_constants_of<T>(p, v);
  for (const auto& s : sites) {
    const T h = c.pi / 2;
    auto sr = s.den == 0 ? lattice_solve(c, s.frame, a, T(0), h)
                         : lattice_solve(c, s.frame, a, lobe_u_at(c, s.frame, a, s.lo_num, s.den),
                                         lobe_u_at(c, s.frame, a, s.hi_num, s.den));
    out.evaluations += sr.evaluations;
    out.u.push_back(sr.u);
    out.radius_sq.push_back(sr.radius_sq);
  }
  return out;
}

template <class T> std::size_t lattice_smallest(const lattice_candidates<T>& c) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < c.radius_sq.size(); ++i)
    if (c.radius_sq[i] < c.radius_sq[best]) best = i;
  return best;
}

template <class T, class L, pair_integer I>
inscribed_result<T> inscribed_lattice_impl(const resonant_pair<I>& p, const T& v, const lattice_options& opt) {
  const L tau = L(p.tau()), a = L(p.order()), b = L(p.delta());
  const bool window = opt.window_always;
  const auto sites = lattice_sites(tau, a, b, window, opt.window_always);
  const bool huge = to_big(p.order()) > (big_int(1) << 900);
  if (huge && !is_mpfr_v<T>)
    throw compute_error("pair " + p.str() + " exceeds the exponent range of " + real_type_name<T>() +
                        "; use mpfr_real (more digits)");
  const bool polish = opt.solver == lattice_solver::scout_and_polish && !std::is_same_v<T, double>;
  auto cand = opt.solver == lattice_solver::toms748_full ? lattice_solve_full(p, v, sites, a)
                                                          : lattice_scout(p, v, sites, a, huge);
  std::size_t best = lattice_smallest(cand);
  T u = cand.u[best], rsq = cand.radius_sq[best];
  if (polish) {
    // Polish every scout candidate within a relative 1e-8 of the best (normally just one).
    const T limit = cand.radius_sq[best] * (1 + T(1e-8));
    bool have = false;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      if (!(cand.radius_sq[i] <= limit)) continue;
      auto pol = lobe_root_polish(p, v, sites[i].frame, a, cand.u[i], cand.bits);
      cand.evaluations += pol.evaluations;
      if (!have || pol.radius_sq < rsq) {
        u = pol.u;
        rsq = pol.radius_sq;
        best = i;
        have = true;
      }
    }
  }
  inscribed_result<T> r;
  r.method = inscribed_method::lattice;
  r.critical_points = sites.size();
  r.evaluations = cand.evaluations;
  auto c = resonant_constants_of<T>(p, v);
  lattice_fill(r, c, sites[best].frame, a, b, u, rsq, p.strand_offset_min());
  return r;
}

inline int bit_length(unsigned __int128 v) {
  int n = 0;
  while (v) { v >>= 1; ++n; }
  return n;
}
inline bool lattice_fits_int128(const resonant_pair<std::int64_t>& p) {
  int la = bit_length((unsigned __int128)p.order()), lb = bit_length((unsigned __int128)p.delta()),
      lt = bit_length((unsigned __int128)p.tau());
  return la + lb <= 124 && la + lt <= 124;
}

}  // namespace detail

// The inscribed radius of any coprime pair by the lattice method (see the header comment).
template <class T, pair_integer I>
inscribed_result<T> inscribed_lattice(const resonant_pair<I>& p, const T& v, const lattice_options& opt = {}) {
  check_amplitude(v);
  if (p.degenerate()) return inscribed_degenerate<T>(p, v);
  // int128 holds every intermediate when a b and a tau stay below 2^124 (the largest products
  // are (2j+1) a and 2 k b with j < b, k < a, and 2 k tau in the window mode).
  if constexpr (std::is_same_v<I, std::int64_t>) {
    if (detail::lattice_fits_int128(p)) return detail::inscribed_lattice_impl<T, int128>(p, v, opt);
    return detail::inscribed_lattice_impl<T, big_int>(pair_cast<big_int>(p), v, opt);
  } else {
    if (pair_fits_int64(p)) {
      auto q = pair_cast<std::int64_t>(p);
      if (detail::lattice_fits_int128(q)) return detail::inscribed_lattice_impl<T, int128>(q, v, opt);
    }
    return detail::inscribed_lattice_impl<T, big_int>(p, v, opt);
  }
}

// Compiled once in src/lib/inscribed/ for double, long double, float128 and mpfr_real.
#define GYRORES_LATTICE_INSTANCES(PREFIX, T) \
  PREFIX template inscribed_result<T> inscribed_lattice<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&, const lattice_options&); \
  PREFIX template inscribed_result<T> inscribed_lattice<T, big_int>(const resonant_pair<big_int>&, const T&, const lattice_options&);
GYRORES_FOR_COMPILED_REALS(GYRORES_LATTICE_INSTANCES, extern)

}  // namespace gyrores
