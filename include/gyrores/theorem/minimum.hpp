// The global minimum of R for a resonant pair, from the lattice theorem (proofs/lattice-theorem.md,
// item 5): r_res = v sqrt(G(u*)), the minimisers theta = 2 (k pi + sign(m) u*)/a of the lobes of
// theorem/lobes.hpp, theta_first the smallest, t_first = sqrt(tau sigma) theta_first; H_q min =
// r_res^2/2 and H_z max = v^2/2 - H_q min (H = v^2/2 is conserved). Degenerate pairs (m_min = 0):
// r_res = 0 exactly at theta = pi/2 and 3 pi/2.
//
// Two forms: in double (v = 1; the fast paths: sweep rows, the design catalogue, figures):
// r_res, theta_first and t_first within one ulp of the exact value (formed in double-double and
// rounded once, with the error bounds of core/double_double.hpp and theorem/root.hpp; the other
// minimisers a few ulps), and as enclosures at an explicit precision (everything the tool prints;
// report/pair_report.hpp).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

// ---- double ----

template <class L> struct minimum_double_of {
  int m_min = 0;
  double u_star = 0;                          // 0 for degenerate pairs
  double r_res = 0, theta_first = 0, t_first = 0;
  // Ascending, `count` of them, and their lobes (k in [0, a)) in the same order; the entries
  // from `count` on are 0 in a result (left uninitialised by default construction, which the
  // double path's result skips: `minimum_double_of r{};` zeroes them).
  std::array<double, 4> minimisers;
  std::array<lobe_frame<L>, 4> lobes;
  std::size_t count = 0;
};
using minimum_double = minimum_double_of<std::int64_t>;

// The minimum of pair p in double, amplitude 1: pairs of order below 2^63 (the lobes' k < a fit
// in int64; usage_error above). compute_error only if the root solver fails (it does not for
// valid pairs).
minimum_double theorem_minimum_double(const resonant_pair<std::int64_t>& p);

// The same for pairs of order below 2^120 (the lobes in int128: Euclid's cofactors stay below
// 2a), with the same one-ulp guarantee; usage_error for larger orders.
minimum_double_of<int128> theorem_minimum_double(const resonant_pair<big_int>& p);

// ---- enclosures ----

// theta = 2 (k pi + U)/a (k an integer, U an enclosure of the lobe coordinate u).
void lobe_theta(fixed_mpfi& out, const theorem_constants& K, const big_int& k, const fixed_mpfi& U);

// theta = 2 (key pi + sign(m) U)/a of a minimiser lobe f of a pair of order a (k reduced; key =
// lobe_order_key), U an enclosure of u* (0 for degenerate lobes).
void minimiser_theta(fixed_mpfi& out, const theorem_constants& K, const big_int& a, const lobe_frame<big_int>& f,
                     const fixed_mpfi& U);

// Enclosures of the minimum at K's precision, amplitude v (an interval > 0).
struct minimum_enclosure {
  explicit minimum_enclosure(mpfr_prec_t p) : r_res(p), h_min(p), h_z_max(p), u_star(p) {}
  fixed_mpfi r_res, h_min, h_z_max;
  std::vector<std::unique_ptr<fixed_mpfi>> minimisers;  // ascending; [0] is theta_first
  std::vector<lobe_frame<big_int>> lobes;               // their lobes
  root_enclosure u_star;                                // U = [0, 0] for degenerate pairs
};

// Not proved when u* could not be proved at this precision (the caller doubles it).
proof_status prove_minimum(minimum_enclosure& out, const theorem_constants& K, const resonant_pair<big_int>& p,
                   const fixed_mpfi& v);

}  // namespace gyrores
