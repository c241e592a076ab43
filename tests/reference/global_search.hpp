// Exact inscribed radius by global search: the reference method, O(tau + sigma) per pair.
//
// Every critical point of R on [0, 2 pi) is a root of q' or of z' (dH_q/dt = -n q' z',
// docs/mathematics.md §1). Both are bracketed without any assumption on the structure of R:
//  - at theta = i pi/tau, cos(tau theta) = (-1)^i, so q'/rho0 = (-1)^i W1 + W2 cos(sigma theta)
//    has the sign (-1)^i (W1 > W2): each [i pi/tau, (i+1) pi/tau] holds a root of q', and as
//    q' is a trigonometric polynomial of degree tau (at most 2 tau roots per period), exactly one;
//  - likewise z' has exactly one root in each [(i - 1/2) pi/tau, (i + 1/2) pi/tau].
// Each of these 4 tau roots is solved with TOMS 748 in local coordinates (resonant.hpp), so the
// phases tau theta are never rounded; R is evaluated at each and the smallest values kept.
// Global minimisers: every critical point with R within a relative 2^(-3 bits/4) of the minimum
// (exact ties come from the symmetries theta -> 2 pi - theta and, for odd tau and sigma,
// theta -> theta + pi). Degenerate pairs are decided by integer arithmetic (degenerate.hpp).
#pragma once
#include <algorithm>
#include <vector>

#include <gyrores/core/roots.hpp>
#include <gyrores/model/resonant.hpp>
#include "reference/lobe_frames.hpp"

#include "reference/degenerate.hpp"
#include "reference/inscribed_result.hpp"

namespace gyrores {

struct global_search_options {
  // Documented limit: 4 tau root solves; 10^5 takes ~0.5 s in double. Larger orders are the
  // theorem's alone (theorem/).
  std::int64_t max_order = 100000;
};

namespace detail {

// Collect all global minimisers among (frame, u, R) candidates; fills the result.
template <class T, class L> struct critical_point {
  lobe_frame<L> frame;
  T u, radius_sq;
};

template <class T, class L>
void fill_minimisers(inscribed_result<T>& r, const resonant_constants<T>& c, const L& a,
                     std::vector<critical_point<T, L>>& pts) {
  using std::ldexp;
  auto best = std::min_element(pts.begin(), pts.end(),
                               [](const auto& p, const auto& q) { return p.radius_sq < q.radius_sq; });
  T rmin = best->radius_sq;
  T tie = rmin * (1 + ldexp(T(1), -int(3 * real_bits<T>() / 4)));
  std::vector<std::pair<T, const critical_point<T, L>*>> mins;
  bool have_next = false;
  for (const auto& p : pts) {
    if (p.radius_sq <= tie) {
      mins.push_back({lobe_theta(c, p.frame, a, p.u), &p});
    } else if (!have_next || p.radius_sq < r.next_radius_sq) {
      r.next_radius_sq = p.radius_sq;
      have_next = true;
    }
  }
  std::sort(mins.begin(), mins.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  std::vector<T> thetas;
  for (auto& m : mins) thetas.push_back(m.first);
  set_minimum(r, rmin, c.v, c.sqrt_ts, std::move(thetas));
  const auto* f = mins.front().second;
  r.first = {to_big(f->frame.k), to_big(f->frame.j), to_big(f->frame.m), f->u};
}
}  // namespace detail

template <class T, pair_integer I>
inscribed_result<T> inscribed_global(const resonant_pair<I>& p, const T& v, const global_search_options& opt = {}) {
  check_amplitude(v);
  if (p.degenerate()) return inscribed_degenerate<T>(p, v);
  if (to_big(p.order()) > big_int(opt.max_order))
    throw compute_error("global search is limited to order tau + sigma <= " + std::to_string(opt.max_order) +
                        "; pair " + p.str() + " is beyond the cross-validation (gyrores pair proves it)");
  using L = int128;
  const L tau = L(std::int64_t(p.tau())), a = L(std::int64_t(p.order())), b = L(std::int64_t(p.delta()));
  const L den = 2 * tau;
  auto c = resonant_constants_of<T>(p, v);

  std::vector<detail::critical_point<T, L>> pts;
  pts.reserve(std::size_t(4 * tau));
  std::uintmax_t evals = 0;
  for (L i = 0; i < 2 * tau; ++i) {
    for (int kind = 0; kind < 2; ++kind) {  // 0: q' root in [2i, 2i+2]; 1: z' root in [2i-1, 2i+1] (units pi/(2 tau))
      L centre = kind == 0 ? L(2 * i + 1) : L(2 * i);
      auto frame = lobe_frame_near(a, b, centre, den);
      auto fr = lobe_frame_real_of(c, frame, a);
      T ulo = lobe_u_at(c, frame, a, L(centre - 1), den);
      T uhi = lobe_u_at(c, frame, a, L(centre + 1), den);
      auto f = [&](const T& u) {
        using std::cos;
        using std::sin;
        T w = fr.mu - c.x * u;
        return kind == 0 ? T(cos(u) * sin(w) - c.x * sin(u) * cos(w)) : T(c.x * sin(u) * sin(w) + cos(u) * cos(w));
      };
      auto root = root_bracketed(f, ulo, uhi, f(ulo), f(uhi), default_root_tolerance<T>(lobe_root_floor(fr)),
                                 kind == 0 ? "global search (q' = 0)" : "global search (z' = 0)");
      evals += root.evaluations + 2;
      auto val = lobe_eval(c, fr, root.root);
      T rsq = kind == 0 ? T(val.q * val.q) : val.radius_sq();  // |q| alone at q' roots (resonant.hpp)
      pts.push_back({frame, root.root, rsq});
    }
  }
  inscribed_result<T> r;
  r.method = inscribed_method::global_search;
  r.critical_points = pts.size();
  r.evaluations = evals;
  detail::fill_minimisers(r, c, a, pts);
  return r;
}

// Compiled once in tests/reference/instances_*.cpp for double, long double, float128 and mpfr_real.
#define GYRORES_GLOBAL_SEARCH_INSTANCES(PREFIX, T) \
  PREFIX template inscribed_result<T> inscribed_global<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&, const global_search_options&); \
  PREFIX template inscribed_result<T> inscribed_global<T, big_int>(const resonant_pair<big_int>&, const T&, const global_search_options&);
GYRORES_FOR_COMPILED_REALS(GYRORES_GLOBAL_SEARCH_INSTANCES, extern)

}  // namespace gyrores
