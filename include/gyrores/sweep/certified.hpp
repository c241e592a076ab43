// The enclosures of a sweep row, from the lattice theorem (proofs/lattice-theorem.md), and the
// integer facts the checks rest on: `gyrores sweep --certified` decides its checks from them (a
// pass is a proof), and every row wider than double takes its values from them.
//
// sweep_prove_pair(p, opt) establishes, for one pair (amplitude v = 1):
//  - 4 a^2 R(pi/2), an integer (the phases at theta = pi/2 are multiples of pi/4), so its
//    vanishing is decided exactly (P3 in docs/mathematics.md);
//  - the minimisers' lobes and m_min (theorem/lobes.hpp; the theorem's items 4 and 5), which
//    sweep_lobes_hold checks against the pair independently;
//  - enclosures of r_res and theta_first (prove_minimum, theorem/minimum.hpp), t_first,
//    t_min_paper = pi/|n| and their ratio; and r_res^2 <= R(pi/2) against the exact integer;
//  - for x < 1/2 and opt.asy, the paper's error, bound, ratio and constant (theorem/paper.hpp).
// Precision: from opt.bits + 32 bits (with the asy error 2 log2(a) + 8 more, its d narrower than
// 2^-(opt.bits + 8) relative), doubling up to 8 times the start (core/refine.hpp), until every
// printed value's enclosure rounds to one value at opt.bits in the direction the row prints it
// (to nearest; certified asy columns outward): the row then holds the exact values' roundings,
// whatever proved them. Every object carries its own precision (core/fixed_precision.hpp), so
// it runs on any number of threads.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/integer.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>
#include <gyrores/theorem/paper.hpp>

namespace gyrores {

// 4 a^2 R(pi/2) (v = 1) for order a and delta b (a > b >= 1, a = b mod 2), exactly in I: int128
// for every sweep order, int64 below order 2^28. With alpha = a pi/4, beta = b pi/4
// (docs/mathematics.md §1): 4 a^2 R = 4 (a^2 - b^2) (sA cB)^2 + 4 (a cA cB - b sA sB)^2. The
// tables hold sqrt(2) sin(k pi/4), sqrt(2) cos(k pi/4) for odd k (odd a: each product is
// (+-1)/2), sin, cos for even k (0 or +-1).
template <class I = int128> I sweep_quarter_R_scaled(std::int64_t a, std::int64_t b) {
  static constexpr int sin_q[8] = {0, 1, 1, 1, 0, -1, -1, -1}, cos_q[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  const int sa = sin_q[a & 7], ca = cos_q[a & 7], sb = sin_q[b & 7], cb = cos_q[b & 7];
  const I A = a, B = b, diff = A * A - B * B, q = A * (ca * cb) - B * (sa * sb);
  if (a % 2 != 0) return diff + q * q;
  const I f = sa * cb;
  return 4 * diff * (f * f) + 4 * q * q;
}

// The theorem's integer claims about the minimisers of p, checked (docs/mathematics.md §3):
// m_min = p.strand_offset_min() = min over N of |a - 4N|; 2 lobes (delta odd or = 2 mod 4) or 4
// (delta = 0 mod 4); each a frame with (2j+1) a - 2 k b = m, |m| = m_min, 0 <= k < a; in strictly
// increasing theta order (lobe_order_key), hence distinct. Precondition (not checked): the
// products (2j+1) a fit in L.
template <class L>
bool sweep_lobes_hold(const resonant_pair<std::int64_t>& p, int m_min, std::span<const lobe_frame<L>> lobes) {
  const L a = L(std::int64_t(p.order())), b = L(p.delta());
  const int amod = int(int_mod(std::int64_t(p.order()), std::int64_t(4)));
  const int independent = amod < 4 - amod ? amod : 4 - amod;
  const std::size_t expected = m_min == 2 ? 4 : 2;
  if (m_min != independent || m_min != p.strand_offset_min() || lobes.size() != expected) return false;
  for (std::size_t i = 0; i < lobes.size(); ++i) {
    const auto& f = lobes[i];
    if ((2 * f.j + 1) * a - 2 * f.k * b != f.m || (f.m != m_min && f.m != -m_min) || f.k < 0 || f.k >= a) return false;
    const L key = f.k == 0 && f.m < 0 ? a : f.k;  // lobe_order_key (theorem/lobes.hpp), restated
    if (i > 0) {
      const auto& e = lobes[i - 1];
      if (!((e.k == 0 && e.m < 0 ? a : e.k) < key)) return false;
    }
  }
  return true;
}

struct sweep_proof_options {
  unsigned bits = 53;       // the row's working precision (sweep_bits, evaluate.hpp)
  bool asy = false;         // also the paper's error (pairs with x < 1/2)
  bool outward_asy = false; // the asy columns are printed outward (certified rows), not to nearest
};

struct sweep_minimum_enclosure {  // at `prec` bits
  explicit sweep_minimum_enclosure(mpfr_prec_t p)
      : prec(p), r_res(p), theta_first(p), t_first(p), t_min_paper(p), t_ratio(p) {}
  mpfr_prec_t prec;
  fixed_mpfi r_res, theta_first, t_first;  // r_res = [0, 0] for degenerate pairs
  fixed_mpfi t_min_paper;                   // pi/|n| = pi sqrt(tau sigma)/b
  fixed_mpfi t_ratio;                       // t_first/t_min_paper = theta_first b/pi
};

struct sweep_proof {
  int128 quarter_R_scaled = 0;            // 4 a^2 R(pi/2), exact
  int m_min = 0;                          // theorem_m_min(a)
  std::vector<lobe_frame<int128>> lobes;  // the minimisers' lobes (k in [0, a)), theta order
  std::unique_ptr<sweep_minimum_enclosure> minimum;  // null: not proved within the precision limit
  bool r_below_R_half_pi = false;         // r_res^2 <= R(pi/2), proved (non-degenerate pairs)
  bool has_asy = false;                   // asked for and x < 1/2
  std::unique_ptr<paper_error_enclosure> asy;  // null unless has_asy and proved
  std::string note;                       // what could not be proved (a resource limit)
};

// The proofs above for pair p (order <= 2^40). Throws only what the root solvers' double scouts
// throw (compute_error, never for valid pairs); what is not proved within the cap is left null
// and named in `note`.
sweep_proof sweep_prove_pair(const resonant_pair<std::int64_t>& p, const sweep_proof_options& opt = {});

}  // namespace gyrores
