// One pair of a sweep: the exact quantities and the checks of the paper's claims.
//
// Per pair (sweep_evaluate<T>, amplitude v = 1; r_res is linear in v):
//  - the exact quantities from the lattice method (inscribed/lattice.hpp): r_res, theta_first,
//    t_first, the global minimisers; the paper's proxy t_min_paper = pi/|n| and
//    t_first/t_min_paper (= theta_first b/pi);
//  - the checks named in sweep_config::checks (each pass, fail, or not applicable):
//    degeneracy  (P3) R(pi/2) = 0 iff delta = 2 mod 4, evaluated in lobe coordinates
//                (model/resonant.hpp: theta = pi/2 is the frame nearest pi/2, u = pi (a - 4k)/4),
//                not by the integer test the library uses to decide degenerate pairs; and for
//                non-degenerate pairs the lattice's numerical r_res satisfies
//                0 < r_res <= sqrt(R(pi/2)).
//    paper-node  (P5, non-degenerate pairs) one of the global minimisers lies in the paper's lobe
//                alpha = a theta/2 in (k pi - pi/2, k pi + pi/2), k = round(a/(2b)) (either k on
//                a tie, b = 1). Integer arithmetic on the minimiser frames. The row also says
//                whether the *first* minimiser is there (first_at_paper_node).
//    asy-bound   (P7, pairs with x = b/a < 1/2) |theta_c - theta_asy| <= pi^3 x^2/a in the lobe
//                k = round(a/(2b)) (the smaller k on a tie; the other is its mirror image), with
//                the error computed without cancellation (inscribed/asymptotic.hpp);
//                ratio = error/bound, constant = error a/x^2 (its sup over a sweep estimates the
//                sharp constant).
//    structure   (docs/mathematics.md §3) the number of global minimisers is 2 for delta odd, 4
//                for delta = 0 mod 4 (2 for degenerate pairs: pi/2, 3 pi/2), and the strand
//                offset p.strand_offset_min() equals min over N of |a - 4N|. The lattice builds
//                its minimisers from that structure, so beyond the cross-check range this check
//                is a consistency check; within it, the cross-check confirms the count
//                independently (the global search counts ties itself).
//    cross-check the lattice method against the global search (inscribed/cross_check.hpp), for
//                non-degenerate pairs of order <= cross_check_max_order (default 300: the global
//                search costs O(order) per pair, ~0.1 ms at order 300 in double).
//  With cfg.certified (`gyrores sweep --certified`) degeneracy, paper-node, structure and
//  asy-bound are decided by sweep_prove_pair (sweep/certified.hpp: exact integers, the lattice
//  theorem, MPFI) instead of in T: a pass is a proof. structure also requires the row's lattice
//  values to agree with the proved ones (count, first lobe, r_res and theta_first within 2^-42
//  relative of their enclosures); the asy columns hold proved upper bounds (asy_bound a lower
//  bound). A check that could not be decided (a resource limit) fails with "not proved" in the
//  note. cross-check stays a floating-point comparison of two methods.
//  A pair whose computation throws (compute_error, usage_error, domain_error) is an error row:
//  counted and listed, never silently dropped.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <gyrores/core/real.hpp>
#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/inscribed/cross_check.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/model/resonant.hpp>
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/real_text.hpp>

namespace gyrores {

enum class sweep_status : unsigned char { none = 0, pass = 1, fail = 2 };
// "pass", "fail", or "" for none (the rows' check columns).
const char* sweep_status_text(sweep_status s);

template <class T> struct sweep_row {
  std::int64_t tau = 0, sigma = 0;
  int delta_mod4 = 0;
  int strand_offset = 0;        // p.strand_offset_min()
  bool failed = false;          // the computation threw: `note` holds the message
  std::string note;             // error message, or why a check failed
  T r_res{}, theta_first{}, t_first{}, t_min_paper{};
  bool has_ratio = false;       // non-degenerate: t_ratio = t_first/t_min_paper
  T t_ratio{};
  int first_at_paper_node = -1;  // -1: not applicable (degenerate), 0/1
  int paper_lobe_min = -1;       // a global minimiser in the paper's lobe: -1/0/1
  bool has_asy = false;          // asy-bound requested and x < 1/2
  T asy_error{}, asy_bound{}, asy_ratio{}, asy_constant{};
  int minimiser_count = 0;
  std::array<sweep_status, sweep_check_count> status{};
};

namespace detail {

// Lobe index (mod a) of the point (k, u) of a lobe frame, |u| < pi: the paper's lobe is
// alpha = a theta/2 in (k pi - pi/2, k pi + pi/2).
template <class T> std::int64_t sweep_lobe_of(std::int64_t k, const T& u, std::int64_t a) {
  T h = real_pi<T>() / 2;
  if (u > h) ++k;
  if (u < -h) --k;
  return int_mod(k, a);
}

// The lobes (mod a) of the global minimisers: the first one and its images under the symmetries
// theta -> -theta and, for delta = 0 mod 4 (m_min = 2), theta -> theta + pi.
struct sweep_lobes {
  std::array<std::int64_t, 4> lobe{};
  std::size_t count = 0;
};
template <class T>
sweep_lobes sweep_minimiser_lobes(const resonant_pair<std::int64_t>& p, const inscribed_result<T>& lr) {
  const std::int64_t a = std::int64_t(p.order());
  sweep_lobes m;
  if (p.degenerate()) {
    m.lobe = {a / 4, 3 * a / 4};
    m.count = 2;
    return m;
  }
  const std::int64_t k1 = sweep_lobe_of(std::int64_t(lr.first.k), lr.first.u, a);
  m.lobe[m.count++] = k1;
  m.lobe[m.count++] = int_mod(a - k1, a);
  if (p.strand_offset_min() == 2) {
    const std::int64_t ks = int_mod(k1 + a / 2, a);
    m.lobe[m.count++] = ks;
    m.lobe[m.count++] = int_mod(a - ks, a);
  }
  return m;
}

inline void sweep_add_note(std::string& note, const std::string& what) {
  note += std::string(note.empty() ? "" : "; ") + what;
}

// The row's exact quantities from the lattice result.
template <class T>
void sweep_fill_values(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const resonant_constants<T>& c,
                       const inscribed_result<T>& lr) {
  r.r_res = lr.r_res;
  r.theta_first = lr.theta_first;
  r.t_first = lr.t_first;
  r.t_min_paper = c.pi / c.n;
  r.minimiser_count = int(lr.minimisers.size());
  if (!p.degenerate()) {
    r.has_ratio = true;
    r.t_ratio = lr.theta_first * real_from_int<T>(p.delta()) / c.pi;
  }
}

// P5 (non-degenerate pairs): first_at_paper_node, paper_lobe_min and, if asked, the verdict.
template <class T>
void sweep_check_paper_node(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_lobes& m, bool check) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const std::int64_t twob = 2 * b, rem = int_mod(a, twob);
  const bool tie = rem == b;  // a/(2b) is a half-integer: both neighbours
  const std::int64_t k0 = tie ? (a - b) / twob : int_floor_div(a + b, twob);
  const std::int64_t kp0 = int_mod(k0, a), kp1 = tie ? int_mod(k0 + 1, a) : kp0;
  auto in_paper = [&](std::int64_t k) { return k == kp0 || k == kp1; };
  r.first_at_paper_node = in_paper(m.lobe[0]) ? 1 : 0;
  r.paper_lobe_min = 0;
  for (std::size_t i = 0; i < m.count; ++i)
    if (in_paper(m.lobe[i])) r.paper_lobe_min = 1;
  if (check) r.status[int(sweep_check::paper_node)] = r.paper_lobe_min ? sweep_status::pass : sweep_status::fail;
}

// R(pi/2) in lobe coordinates: the frame nearest theta = pi * 1/2, integers in L (the largest
// intermediate is 4 a + 4).
template <class L, class T> T sweep_radius_sq_half_pi(const resonant_constants<T>& c, const L& A, const L& B) {
  auto f = lobe_frame_near(A, B, L(1), L(2));
  auto fr = lobe_frame_real_of(c, f, A);
  T u = lobe_u_at(c, f, A, L(1), L(2));
  return lobe_eval(c, fr, u).radius_sq();
}

// P3: R(pi/2) in lobe coordinates (the frame nearest theta = pi * 1/2) against delta mod 4 and r_res.
template <class T>
void sweep_check_degeneracy(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const resonant_constants<T>& c,
                            const inscribed_result<T>& lr, unsigned digits) {
  // int64 below a = 2^60 (every sweep in practice: int128 division is a library call), else int128.
  const int128 a = p.order();
  const T R = a < (int128(1) << 60) ? sweep_radius_sq_half_pi(c, std::int64_t(a), p.delta())
                                    : sweep_radius_sq_half_pi(c, a, int128(p.delta()));
  bool ok = (R == 0) == (p.delta_mod4() == 2);
  if (ok && !p.degenerate()) ok = lr.r_res > 0 && lr.r_res * lr.r_res <= R * (1 + 16 * real_epsilon<T>());
  if (ok && p.degenerate()) ok = lr.r_res == 0;
  r.status[int(sweep_check::degeneracy)] = ok ? sweep_status::pass : sweep_status::fail;
  if (!ok)
    r.note = "degeneracy: R(pi/2) = " + sweep_real_text(R, digits) + ", r_res = " + sweep_real_text(lr.r_res, digits);
}

// docs/mathematics.md §3: the count of global minimisers and the strand offset m_min.
template <class T>
void sweep_check_structure(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const inscribed_result<T>& lr) {
  const int amod = int(int_mod(std::int64_t(p.order()), std::int64_t(4)));
  const int m_indep = std::min(amod, 4 - amod);
  const std::size_t expected = p.strand_offset_min() == 2 ? 4 : 2;
  const bool ok = m_indep == p.strand_offset_min() && lr.minimisers.size() == expected;
  r.status[int(sweep_check::structure)] = ok ? sweep_status::pass : sweep_status::fail;
  if (!ok)
    sweep_add_note(r.note, "structure: " + std::to_string(lr.minimisers.size()) + " minimisers (expected " +
                               std::to_string(expected) + "), m_min " + std::to_string(p.strand_offset_min()) +
                               " vs min|a - 4N| = " + std::to_string(m_indep));
}

// P7 (x < 1/2): the asymptotic error in the paper's lobe k = round(a/(2b)) (the smaller on a
// tie), m = a - 2 k b, s = pi m/(2b), against the bound pi^3 x^2/a.
template <class T>
void sweep_check_asy_bound(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const resonant_constants<T>& c) {
  using std::fabs;
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const std::int64_t twob = 2 * b, rem = int_mod(a, twob);
  const std::int64_t k = rem == b ? (a - b) / twob : int_floor_div(a + b, twob);
  const std::int64_t m = a - 2 * k * b;
  const T s = c.pi * real_from_ratio<T>(m, twob);
  const T u_asy = u_plus_tan_u_root(s);
  const T e = asymptotic_error_scaled(c.x, s, u_asy, c.pi);
  const T at = real_from_int<T>(a), x2 = c.x * c.x, pi3 = c.pi * c.pi * c.pi;
  r.has_asy = true;
  r.asy_constant = 2 * fabs(e);
  r.asy_error = r.asy_constant * x2 / at;
  r.asy_bound = pi3 * x2 / at;
  r.asy_ratio = r.asy_constant / pi3;
  r.status[int(sweep_check::asy_bound)] = r.asy_ratio <= 1 ? sweep_status::pass : sweep_status::fail;
}

// The lattice result against the global search; a disagreement is a failed check, not an error row.
template <class T>
void sweep_check_cross(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const T& v, const inscribed_result<T>& lr) {
  try {
    cross_check_lattice(p, v, lr);
    r.status[int(sweep_check::cross_check)] = sweep_status::pass;
  } catch (const compute_error& e) {
    r.status[int(sweep_check::cross_check)] = sweep_status::fail;
    sweep_add_note(r.note, e.what());
  }
}

// v inside [lo, hi] widened by 2^-42 relative (the proved enclosures are about 2^-50 wide; the
// lattice values in T carry a few ulps of rounding).
template <class T> bool sweep_near_enclosure(const T& v, double lo, double hi) {
  using std::fabs;
  const double tol = 0x1p-42;
  return v >= T(lo - tol * fabs(lo)) && v <= T(hi + tol * fabs(hi));
}

// The certified checks (see the header comment), from the proofs of sweep_prove_pair.
template <class T>
void sweep_check_certified(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const inscribed_result<T>& lr,
                           const sweep_config& cfg) {
  const auto& ck = cfg.checks;
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const sweep_proof pr = sweep_prove_pair(p, sweep_has_check(ck, sweep_check::asy_bound));
  if (!pr.note.empty()) sweep_add_note(r.note, pr.note);
  const bool degenerate = p.delta_mod4() == 2;
  if (!degenerate) {
    sweep_lobes m;
    for (const auto& f : pr.lobes) m.lobe[m.count++] = std::int64_t(f.k);  // alpha = k pi + sign(m) u*, u* < pi/2
    sweep_check_paper_node(r, p, m, sweep_has_check(ck, sweep_check::paper_node));
  }
  if (sweep_has_check(ck, sweep_check::degeneracy)) {
    // P3: R(pi/2) = 0 exactly iff delta = 2 mod 4; r_res = 0 there by the theorem (m_min = 0),
    // else 0 < r_res <= sqrt(R(pi/2)) from the enclosure.
    bool ok = (pr.quarter_R_scaled == 0) == degenerate;
    if (ok) ok = degenerate ? pr.m_min == 0 : pr.enclosed && pr.r_lo > 0 && pr.r_below_R_half_pi;
    r.status[int(sweep_check::degeneracy)] = ok ? sweep_status::pass : sweep_status::fail;
    if (!ok) sweep_add_note(r.note, "degeneracy: 4 a^2 R(pi/2) = " + to_decimal(pr.quarter_R_scaled));
  }
  if (sweep_has_check(ck, sweep_check::structure)) {
    const std::size_t expected = pr.m_min == 2 ? 4 : 2;
    bool theorem = pr.lobes.size() == expected && pr.m_min == p.strand_offset_min();
    for (const auto& f : pr.lobes)
      theorem = theorem && (2 * f.j + 1) * a - 2 * f.k * b == f.m && (f.m == pr.m_min || f.m == -pr.m_min) &&
                f.k >= 0 && f.k < a;
    // (lr.first is not set for degenerate pairs; their theta_first = pi/2 is compared instead.)
    bool agree = pr.enclosed && lr.minimisers.size() == expected &&
                 (degenerate || sweep_lobe_of(std::int64_t(lr.first.k), lr.first.u, a) == std::int64_t(pr.lobes.front().k)) &&
                 sweep_near_enclosure(lr.theta_first, pr.theta_lo, pr.theta_hi) &&
                 (degenerate ? lr.r_res == 0 : sweep_near_enclosure(lr.r_res, pr.r_lo, pr.r_hi));
    r.status[int(sweep_check::structure)] = theorem && agree ? sweep_status::pass : sweep_status::fail;
    if (!theorem) sweep_add_note(r.note, "structure: the theorem's lobes do not check");
    else if (!agree && pr.enclosed) sweep_add_note(r.note, "structure: the lattice values are outside the proved enclosures");
  }
  if (sweep_has_check(ck, sweep_check::asy_bound) && pr.has_asy) {
    r.has_asy = true;
    r.asy_error = T(pr.asy_error_hi);
    r.asy_bound = T(pr.asy_bound_lo);
    r.asy_ratio = T(pr.asy_ratio_hi);
    r.asy_constant = T(pr.asy_constant_hi);
    const bool ok = pr.asy_enclosed && pr.asy_ratio_hi <= 1;
    r.status[int(sweep_check::asy_bound)] = ok ? sweep_status::pass : sweep_status::fail;
  }
}

// The checks in T (uncertified runs).
template <class T>
void sweep_evaluate_checks(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const resonant_constants<T>& c,
                           const inscribed_result<T>& lr, const sweep_config& cfg) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const auto& ck = cfg.checks;
  if (!p.degenerate())
    sweep_check_paper_node(r, p, sweep_minimiser_lobes(p, lr), sweep_has_check(ck, sweep_check::paper_node));
  if (sweep_has_check(ck, sweep_check::degeneracy)) sweep_check_degeneracy(r, p, c, lr, cfg.digits);
  if (sweep_has_check(ck, sweep_check::structure)) sweep_check_structure(r, p, lr);
  if (sweep_has_check(ck, sweep_check::asy_bound) && 2 * b < a) sweep_check_asy_bound(r, p, c);
}

// The constants a row uses: the lobe-frame ones (x, s1mx2, pi, v) and n for t_min_paper = pi/n,
// each formed exactly as resonant_constants_of forms it; omega1, omega2 and rho0 (two square
// roots and three divisions) are not used.
template <class T> resonant_constants<T> sweep_constants(const resonant_pair<std::int64_t>& p, const T& v) {
  using W = wide_int<std::int64_t>;
  auto c = resonant_constants_from<T>(p.order(), W(p.delta()), W(p.tau()), W(p.sigma()), v, constants_scope::lobe);
  c.n = real_from_int<T>(W(p.delta())) / c.sqrt_ts;
  return c;
}

template <class T>
void sweep_evaluate_into(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  const std::int64_t a = std::int64_t(p.order());
  const T v = T(1);
  const auto c = sweep_constants(p, v);
  const auto lr = inscribed_lattice<T>(p, v);
  const auto& ck = cfg.checks;
  sweep_fill_values(r, p, c, lr);
  if (cfg.certified) {
    sweep_check_certified(r, p, lr, cfg);
  } else {
    sweep_evaluate_checks(r, p, c, lr, cfg);
  }
  if (sweep_has_check(ck, sweep_check::cross_check) && !p.degenerate() && a <= cfg.cross_check_max_order)
    sweep_check_cross(r, p, v, lr);
}


// The row's identity columns (filled for every row, error rows included).
template <class T> sweep_row<T> sweep_row_of(const resonant_pair<std::int64_t>& p) {
  sweep_row<T> r;
  r.tau = p.tau();
  r.sigma = p.sigma();
  r.delta_mod4 = p.delta_mod4();
  r.strand_offset = p.strand_offset_min();
  return r;
}

template <class T> sweep_row<T> sweep_failed_row(const resonant_pair<std::int64_t>& p, const char* what) {
  sweep_row<T> r = sweep_row_of<T>(p);
  r.failed = true;
  r.note = what;
  return r;
}

}  // namespace detail

// Evaluate one pair (see the header comment). Never throws for a computation that fails: the
// row is marked `failed` with the message in `note`.
template <class T> sweep_row<T> sweep_evaluate(const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  sweep_row<T> r = detail::sweep_row_of<T>(p);
  try {
    detail::sweep_evaluate_into(r, p, cfg);
  } catch (const std::runtime_error& e) {
    return detail::sweep_failed_row<T>(p, e.what());
  } catch (const std::logic_error& e) {
    return detail::sweep_failed_row<T>(p, e.what());
  }
  return r;
}

// Compiled once in src/lib/sweep/instances.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_EVALUATE_INSTANCES(PREFIX, T) \
  PREFIX template sweep_row<T> sweep_evaluate<T>(const resonant_pair<std::int64_t>&, const sweep_config&);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_EVALUATE_INSTANCES, extern)

}  // namespace gyrores
