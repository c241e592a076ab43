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
// Cost: each evaluation is two fused sine-cosine pairs (real_sin_cos, core/real.hpp: Arb's
// arb_sin_cos for mpfr_real), the per-pair constants are formed once per call, and the frame
// integers are int64 or int128 whenever they fit (also for pairs held as big_int), so that the
// exact result costs about what Arb's own Newton refinement of the root alone costs at 1000 and
// 10000 digits, and about the paper's theta_asy in double (bench/RESULTS.md, H1 and H5).
#pragma once
#include <algorithm>
#include <array>
#include <memory>
#include <tuple>
#include <vector>

#include "reference/degenerate.hpp"
#include "reference/global_search.hpp"
#include <gyrores/model/resonant.hpp>
#include "reference/lobe_frames.hpp"
#include "reference/inscribed_result.hpp"
#include <gyrores/core/roots.hpp>
#include <gyrores/theorem/lobes.hpp>
#include "testing/test_support.hpp"

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

// The pass frame: the frame with m = +m_min (m_min = 1 or 2), by one modular inverse.
//   delta odd:       2j+1 = a^{-1} mod 2b,        k = ((2j+1) a - 1)/(2b)
//   delta = 0 mod 4: 2j+1 = (a/2)^{-1} mod b,     k = ((2j+1) a/2 - 1)/b
// Precondition (not checked): delta != 2 mod 4.
template <class L> lobe_frame<L> pass_frame(const L& a, const L& b) {
  const bool odd = int_mod(b, L(2)) == 1;
  const L ah = odd ? a : L(a / 2), bh = odd ? b : L(b / 2);
  const L mod = 2 * bh;
  const L inverse = mod == 2 ? L(1) : int_inverse_mod(ah, mod);  // odd: ah * inverse = 1 mod an even number
  const L j = (inverse - 1) / 2;
  const L k = ((2 * j + 1) * ah - 1) / mod;
  return {k, j, L(odd ? 1 : 2)};
}

// theorem/lobes.hpp's minimiser_lobes formed independently, for its tests: the pass frame and its
// mirror (and shift) reduced to k in [0, a), then sorted by their place on [0, 2 pi).
template <class L> lobe_list<L> minimiser_lobes_modular(const L& a, const L& b) {
  lobe_list<L> out;
  if (theorem_m_min(a) == 0) {
    out.push_back(lobe_frame_of(a, b, L(a / 4), L((b - 2) / 4)));
    out.push_back(lobe_frame_of(a, b, L(3 * (a / 4)), L((3 * b - 2) / 4)));
    return out;
  }
  const auto pass = pass_frame(a, b);
  out.push_back(pass);
  out.push_back(lobe_mirror(pass, a, b));
  if (pass.m == 2) {
    const auto s = lobe_shift(pass, a, b);
    out.push_back(s);
    out.push_back(lobe_mirror(s, a, b));
  }
  for (auto& f : out) {  // k into [0, a): k -> k - t a keeps m when j -> j - t b
    const L t = int_floor_div(f.k, a);
    f = {L(f.k - t * a), L(f.j - t * b), f.m};
  }
  std::sort(out.begin(), out.end(),
            [&](const auto& x, const auto& y) { return lobe_order_key(x, a) < lobe_order_key(y, a); });
  return out;
}

namespace detail {

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
  auto pass = pass_frame(a, b);
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

namespace detail {

// What one Newton step on q' needs, formed once from the per-pair constants: x, mu, 1 + x^2,
// 2x and v sqrt(1 - x^2) (|q| = that times |sin u sin w|).
template <class T> struct polish_constants {
  T x, mu, one_plus_x2, two_x, amp;
};
template <class T> polish_constants<T> polish_constants_of(const resonant_constants<T>& c, const T& mu) {
  return {c.x, mu, T(1 + c.x * c.x), T(2 * c.x), T(c.v * c.s1mx2)};
}
// The same constants rounded to the current default precision (mpfr_real's lower ladder levels:
// rounding the full-precision values is exact to the level's precision and recomputes nothing,
// pi included).
template <class T> polish_constants<T> polish_constants_rounded(const polish_constants<T>& k) {
  polish_constants<T> r = k;
  for (T* v : {&r.x, &r.mu, &r.one_plus_x2, &r.two_x, &r.amp}) set_working_precision(*v);
  return r;
}

// One Newton step u -= q'/q'' at the working precision: two fused sine-cosine evaluations
// (real_sin_cos) and ten products. rsq = q^2 at the old u. Returns the step.
template <class T> T polish_step(const polish_constants<T>& k, T& u, T& rsq) {
  const T w = k.mu - k.x * u;
  const auto a = real_sin_cos(u);
  const auto b = real_sin_cos(w);
  // f and q grouped as lobe_qdot_newton and lobe_eval (resonant.hpp) group them.
  const T f = a.c * b.s - k.x * a.s * b.c;
  const T df = -(k.one_plus_x2 * (a.s * b.s) + k.two_x * (a.c * b.c));
  const T q = k.amp * a.s * b.s;  // |q| alone at a q' root (resonant.hpp)
  rsq = q * q;
  T step = f / df;
  u -= step;
  return step;
}

}  // namespace detail

// The same polish with the per-pair constants c already formed in T at the working precision.
template <class T, class L>
lobe_polish_result<T> lobe_root_polish(const resonant_constants<T>& c, const lobe_frame<L>& f, const L& a, const T& u0,
                                       unsigned start_bits) {
  using std::fabs;
  using std::ldexp;
  std::uintmax_t evals = 0;
  T u = u0;
  const auto fr = lobe_frame_real_of(c, f, a);
  const auto k = detail::polish_constants_of(c, fr.mu);
  if constexpr (is_mpfr_v<T>) {
    // Lower levels: bits_full/2 + 16, its half + 16, ... down to the first level at or below
    // twice the start accuracy, so that each level starts from a root accurate to about half
    // its precision and ends accurate to its precision (as Arb's arb_calc_refine_root_newton
    // chooses them). Stopping one level higher leaves the doubling 53, 106, 212, ... short of
    // the levels, and then the full-precision step had to run twice (at 10000 digits).
    std::vector<unsigned> ladder;
    for (unsigned b = real_bits<T>() / 2 + 16; b > start_bits; b = b / 2 + 16) ladder.push_back(b);
    std::reverse(ladder.begin(), ladder.end());
    for (unsigned bits : ladder) {
      scoped_digits d(digits10_for_bits(bits));
      detail::set_working_precision(u);
      const auto kl = detail::polish_constants_rounded(k);
      T rsq;
      detail::polish_step(kl, u, rsq);
      ++evals;
    }
    detail::set_working_precision(u);
  }
  const T floor = lobe_root_floor(fr);
  const T half_eps = ldexp(T(1), -int(real_bits<T>() / 2) + 4);
  for (int it = 0; it < 8; ++it) {
    T rsq;
    T step = detail::polish_step(k, u, rsq);
    ++evals;
    T scale = fabs(u) > floor ? fabs(u) : floor;
    if (fabs(step) <= half_eps * scale) return {u, rsq, evals};
  }
  throw compute_error("lattice: Newton polish of q' = 0 did not converge in " + real_type_name<T>());
}

template <class T, class L, pair_integer I>
lobe_polish_result<T> lobe_root_polish(const resonant_pair<I>& p, const T& v, const lobe_frame<L>& f, const L& a, const T& u0,
                           unsigned start_bits) {
  return lobe_root_polish(resonant_constants_of<T>(p, v), f, a, u0, start_bits);
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
  // At most 4 minimisers: a fixed array and one allocation (the result's vector) per pair.
  std::array<lattice_minimiser<L>, 4> pts;
  std::size_t n = 0;
  pts[n++] = lattice_minimiser_of(f, f_negative, a, b);
  pts[n++] = lattice_minimiser_of(lobe_mirror(f, a, b), !f_negative, a, b);
  if (m_min == 2) {
    auto s = lobe_shift(f, a, b);
    pts[n++] = lattice_minimiser_of(s, f_negative, a, b);
    pts[n++] = lattice_minimiser_of(lobe_mirror(s, a, b), !f_negative, a, b);
  }
  std::sort(pts.begin(), pts.begin() + n, [](const auto& x, const auto& y) {
    if (x.key != y.key) return x.key < y.key;
    return x.negative && !y.negative;
  });
  std::vector<T> thetas;
  thetas.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    thetas.push_back(lattice_theta(c, pts[i].key, a, pts[i].negative ? T(-ustar) : ustar));
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

// The pair's integers in the lattice's integer type L (int128 when they fit, else big_int).
template <class L> struct lattice_ints {
  L tau, sigma, a, b;
  // The lobe-frame constants only: the lattice method uses no others (model/resonant.hpp).
  template <class S> resonant_constants<S> constants(const S& v) const {
    return resonant_constants_from<S>(a, b, tau, sigma, v, constants_scope::lobe);
  }
};
template <class L, class J> L lattice_int_cast(const J& v) {
  if constexpr (std::is_same_v<L, int128> && std::is_same_v<J, big_int>) return to_int128(v);
  else if constexpr (std::is_same_v<L, std::int64_t> && std::is_same_v<J, big_int>) return v.template convert_to<std::int64_t>();
  else return L(v);
}
template <class L, pair_integer I> lattice_ints<L> lattice_ints_of(const resonant_pair<I>& p) {
  return {lattice_int_cast<L>(p.tau()), lattice_int_cast<L>(p.sigma()), lattice_int_cast<L>(p.order()),
          lattice_int_cast<L>(p.delta())};
}

template <class S, class T, class L>
void lattice_scout_in(lattice_candidates<T>& out, const resonant_constants<S>& cs,
                      const std::vector<lattice_candidate_site<L>>& sites, const L& a) {
  for (const auto& s : sites) {
    auto sr = lattice_solve_site(cs, s, a);
    out.evaluations += sr.evaluations;
    out.u.push_back(T(sr.u));
    out.radius_sq.push_back(T(sr.radius_sq));
  }
}

// The scout: every site solved in double, or in MPFR at 64 bits when the pair is beyond double's
// exponent range (`huge`; then T is mpfr_real, checked by the caller). c: the constants in T.
template <class T, class L>
lattice_candidates<T> lattice_scout(const lattice_ints<L>& z, const resonant_constants<T>& c,
                                    const std::vector<lattice_candidate_site<L>>& sites, bool huge) {
  lattice_candidates<T> out;
  if constexpr (std::is_same_v<T, double>) {
    lattice_scout_in<double>(out, c, sites, z.a);
  } else if (!huge) {
    lattice_scout_in<double>(out, z.constants(1.0), sites, z.a);
  } else if constexpr (is_mpfr_v<T>) {
    scoped_digits d(20);
    out.bits = 64;
    lattice_scout_in<mpfr_real>(out, z.constants(mpfr_real(1)), sites, z.a);
  }
  return out;
}

// lattice_solver::toms748_full: every site solved by TOMS 748 in T directly.
template <class T, class L>
lattice_candidates<T> lattice_solve_full(const resonant_constants<T>& c,
                                         const std::vector<lattice_candidate_site<L>>& sites, const L& a) {
  lattice_candidates<T> out;
  out.bits = real_bits<T>();
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

// The default (one site: the pass frame, u in [0, pi/2]; scout and polish): no candidate lists.
// Returns the root u, R and the evaluations.
template <class T, class L>
lobe_polish_result<T> lattice_default_root(const lattice_ints<L>& z, const resonant_constants<T>& c,
                                           const lattice_candidate_site<L>& site, bool huge) {
  if constexpr (std::is_same_v<T, double>) {
    auto sr = lattice_solve_site(c, site, z.a);
    return {sr.u, sr.radius_sq, sr.evaluations};
  } else {
    unsigned bits = 53;
    std::uintmax_t evals = 0;
    T u;
    if (!huge) {
      auto sr = lattice_solve_site(z.constants(1.0), site, z.a);
      u = T(sr.u);
      evals = sr.evaluations;
    } else if constexpr (is_mpfr_v<T>) {
      {
        scoped_digits d(20);
        auto sr = lattice_solve_site(z.constants(mpfr_real(1)), site, z.a);
        u = sr.u;
        evals = sr.evaluations;
      }
      set_working_precision(u);
      bits = 64;
    }
    auto pol = lobe_root_polish(c, site.frame, z.a, u, bits);
    pol.evaluations += evals;
    return pol;
  }
}

// p.strand_offset_min() from b = delta in L (no GMP temporaries for big_int pairs): 1 for b
// odd, 2 for b = 0 mod 4 (b = 2 mod 4, degenerate, never reaches the lattice).
template <class L> int lattice_offset_min(const L& b) { return int_mod(b, L(2)) == 1 ? 1 : 2; }

template <class L> bool lattice_is_huge(const L& a) {
  if constexpr (std::is_same_v<L, big_int>) return mpz_sizeinbase(a.backend().data(), 2) > 901;  // a > 2^900
  else return false;
}

template <class T, class L, pair_integer I>
inscribed_result<T> inscribed_lattice_impl(const resonant_pair<I>& p, const T& v, const lattice_options& opt) {
  const auto z = lattice_ints_of<L>(p);
  const L& a = z.a;
  const L& b = z.b;
  const bool window = opt.window_always;
  const bool huge = lattice_is_huge(a);
  if (huge && !is_mpfr_v<T>)
    throw compute_error("pair " + p.str() + " exceeds the exponent range of " + real_type_name<T>() +
                        "; use mpfr_real (more digits)");
  const auto c = z.constants(v);  // once, at the working precision
  inscribed_result<T> r;
  r.method = inscribed_method::lattice;
  if (!window && opt.solver == lattice_solver::scout_and_polish) {
    const lattice_candidate_site<L> site{pass_frame(a, b), L(0), L(0), L(0)};
    const auto root = lattice_default_root(z, c, site, huge);
    r.critical_points = 1;
    r.evaluations = root.evaluations;
    lattice_fill(r, c, site.frame, a, b, root.u, root.radius_sq, lattice_offset_min(b));
    return r;
  }
  const auto sites = lattice_sites(z.tau, a, b, window, opt.window_always);
  const bool polish = opt.solver == lattice_solver::scout_and_polish && !std::is_same_v<T, double>;
  auto cand = opt.solver == lattice_solver::toms748_full ? lattice_solve_full(c, sites, a)
                                                          : lattice_scout(z, c, sites, huge);
  std::size_t best = lattice_smallest(cand);
  T u = cand.u[best], rsq = cand.radius_sq[best];
  if (polish) {
    // Polish every scout candidate within a relative 1e-8 of the best (normally just one).
    const T limit = cand.radius_sq[best] * (1 + T(1e-8));
    bool have = false;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      if (!(cand.radius_sq[i] <= limit)) continue;
      auto pol = lobe_root_polish(c, sites[i].frame, a, cand.u[i], cand.bits);
      cand.evaluations += pol.evaluations;
      if (!have || pol.radius_sq < rsq) {
        u = pol.u;
        rsq = pol.radius_sq;
        best = i;
        have = true;
      }
    }
  }
  r.critical_points = sites.size();
  r.evaluations = cand.evaluations;
  lattice_fill(r, c, sites[best].frame, a, b, u, rsq, lattice_offset_min(b));
  return r;
}

inline int bit_length(unsigned __int128 v) {
  int n = 0;
  while (v) { v >>= 1; ++n; }
  return n;
}
// An integer type of `bits` bits holds every intermediate when a b (and, in the window mode,
// a tau) stay below 2^(bits - 4): the largest products are (2j+1) a and 2 k b with j < b, k < a,
// and 2 k tau, a (2i+1) with i < 2 tau in the window mode. int64 where it suffices (every pair
// of a sweep up to order 2^30: int128 division is a library call), int128 up to 2^124.
inline bool lattice_fits(unsigned __int128 a, unsigned __int128 b, unsigned __int128 tau, bool window, int bits) {
  const int la = bit_length(a), lb = bit_length(b), lt = bit_length(tau);
  return la + lb <= bits - 4 && (!window || la + lt <= bits - 4);
}
// The pair's a, b, tau as unsigned 128-bit integers, or false when tau needs more than 120 bits.
inline bool lattice_abt(const resonant_pair<std::int64_t>& p, unsigned __int128 (&abt)[3]) {
  abt[0] = (unsigned __int128)p.order();
  abt[1] = (unsigned __int128)p.delta();
  abt[2] = (unsigned __int128)p.tau();
  return true;
}
inline bool lattice_abt(const resonant_pair<big_int>& p, unsigned __int128 (&abt)[3]) {
  if (mpz_sizeinbase(p.tau().backend().data(), 2) > 120) return false;  // then a < 2^122 too
  abt[2] = (unsigned __int128)to_int128(p.tau());
  abt[0] = abt[2] + (unsigned __int128)to_int128(p.sigma());
  abt[1] = (unsigned __int128)to_int128(p.delta());
  return true;
}

}  // namespace detail

// The inscribed radius of any coprime pair by the lattice method (see the header comment).
template <class T, pair_integer I>
inscribed_result<T> inscribed_lattice(const resonant_pair<I>& p, const T& v, const lattice_options& opt = {}) {
  check_amplitude(v);
  if (p.degenerate()) return inscribed_degenerate<T>(p, v);
  // int64 or int128 arithmetic whenever it holds every intermediate (detail::lattice_fits), also
  // for pairs given as big_int (e.g. (10^30+1, 10^30)): no GMP temporaries then.
  unsigned __int128 abt[3];
  if (detail::lattice_abt(p, abt)) {
    if (detail::lattice_fits(abt[0], abt[1], abt[2], opt.window_always, 64))
      return detail::inscribed_lattice_impl<T, std::int64_t>(p, v, opt);
    if (detail::lattice_fits(abt[0], abt[1], abt[2], opt.window_always, 128))
      return detail::inscribed_lattice_impl<T, int128>(p, v, opt);
  }
  if constexpr (std::is_same_v<I, std::int64_t>)
    return detail::inscribed_lattice_impl<T, big_int>(pair_cast<big_int>(p), v, opt);
  else
    return detail::inscribed_lattice_impl<T, big_int>(p, v, opt);
}

// Compiled once in tests/reference/ for double, long double, float128 and mpfr_real.
#define GYRORES_LATTICE_INSTANCES(PREFIX, T) \
  PREFIX template inscribed_result<T> inscribed_lattice<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&, const lattice_options&); \
  PREFIX template inscribed_result<T> inscribed_lattice<T, big_int>(const resonant_pair<big_int>&, const T&, const lattice_options&);
GYRORES_FOR_COMPILED_REALS(GYRORES_LATTICE_INSTANCES, extern)

}  // namespace gyrores
