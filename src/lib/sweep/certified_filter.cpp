// The certified double row in the theorem's double-double balls (theorem/minimum_dd_ball.hpp,
// theorem/paper.hpp), the filter tried before the MPFI proof (sweep/certified.hpp) through
// sweep/filtered.hpp. Printed values follow the row's rule (sweep_prove_pair's): each real is the
// exact value rounded to double, to nearest (the asy columns upward, asy_bound downward). The
// filter gives a row only if every point of each ball rounds to the same double, so the row is
// byte for byte the one the fallback prints; anything undecided (a rounding, a sign, a check that
// does not pass) leaves the row to the fallback.
#include <array>
#include <bit>
#include <cstdint>

#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/testing.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum_dd_ball.hpp>
#include <gyrores/theorem/paper.hpp>

#include "row_parts.hpp"

namespace gyrores {

// ---- the rounding of a value v known to lie in [X.m - X.r, X.m + X.r] (v > 0) ----
// With h = X.m.hi and v = h + e, |e| small: v rounds to h (to nearest) iff e lies in (-gb, ga),
// gb and ga half the spacings below and above h. Each comparison is of doubles: a rounded sum c
// of two doubles is compared through c (1 - 2^-52), at most its exact value.
namespace {
struct spacing {
  double below, above;  // h - prev(h), next(h) - h (exact)
};
spacing spacing_of(double h) {  // h > 0 finite: its neighbours are the adjacent bit patterns
  const auto bits = std::bit_cast<std::uint64_t>(h);
  return {h - std::bit_cast<double>(bits - 1), std::bit_cast<double>(bits + 1) - h};
}
double at_most(double c) { return c * (1 - 0x1p-52); }
// Upward: v in (h, next(h)] rounds to next(h), v in (prev(h), h] to h; downward: v in
// [h, next(h)) rounds to h, v in [prev(h), h) to prev(h). Whether every v of X lies in one of
// the two, with the ends the direction takes.
bool round_directed(const dd_ball& X, bool up, double& out) {
  const double h = X.m.hi;
  if (!(h > 0)) return false;
  const spacing g = spacing_of(h);
  if ((up ? X.r < X.m.lo : X.r <= X.m.lo) && X.r < at_most(g.above - X.m.lo)) {
    out = up ? h + g.above : h;
    return true;
  }
  if ((up ? X.r <= -X.m.lo : X.r < -X.m.lo) && X.r < at_most(X.m.lo + g.below)) {
    out = up ? h : h - g.below;
    return true;
  }
  return false;
}
}  // namespace

bool sweep_testing::round_nearest(const dd_ball& X, double& out) {
  const double h = X.m.hi;
  if (!(h > 0)) return false;
  const spacing g = spacing_of(h);
  if (!(X.r < at_most(X.m.lo + g.below / 2)) || !(X.r < at_most(g.above / 2 - X.m.lo))) return false;
  out = h;
  return true;
}
bool sweep_testing::round_up(const dd_ball& X, double& out) { return round_directed(X, true, out); }
bool sweep_testing::round_down(const dd_ball& X, double& out) { return round_directed(X, false, out); }

namespace sweep_rows {
namespace {

using sweep_testing::round_down;
using sweep_testing::round_nearest;
using sweep_testing::round_up;

// The minimisers' lobes (theorem/lobes.hpp): minimiser_lobes's Euclid in machine integers, at a
// tenth of the int128 version's cost; held as int128 frames for the checks. Its
// remainders, cofactors and frames stay below 2a, so int32 serves for a < 2^30 (32-bit divisions
// take half the time of 64-bit ones), int64 above.
template <class L> lobe_list<int128> lobes_as_int128(L a, L b) {
  lobe_list<int128> out;
  for (const auto& f : minimiser_lobes(a, b)) out.push_back({f.k, f.j, f.m});
  return out;
}
lobe_list<int128> lobes_of(std::int64_t a, std::int64_t b) {
  if (a < (std::int64_t(1) << 30)) return lobes_as_int128(std::int32_t(a), std::int32_t(b));
  return lobes_as_int128(a, b);
}

const proof_status undecided_rounding = proof_status::undecided("a rounding to double");

// The asy columns: the bound downward, the others upward; the check must pass (ratio < 1).
proof_status asy_columns(sweep_row<double>& r, const dd_ball_constants& K, std::int64_t am) {
  paper_error_dd_ball E;
  GYRORES_TRY_PROOF(prove_paper_error_dd_ball(E, K, am));
  if (!round_down(E.bound, r.asy_bound)) return undecided_rounding;
  if (am == 0) {  // s = 0: u_c = u_a = 0, every column 0; as the fallback prints the upper end of
    // MPFI's [0, 0], which MPFI holds as [+0, -0]: "-0"
    r.asy_error = r.asy_ratio = r.asy_constant = -0.0;
    return proof_status::proved();
  }
  if (!ddb::negative(ddb::sub(E.ratio, ddb::exact(1.0)))) return proof_status::undecided("asy ratio < 1");
  if (!round_up(E.error, r.asy_error) || !round_up(E.ratio, r.asy_ratio) || !round_up(E.constant, r.asy_constant))
    return undecided_rounding;
  return proof_status::proved();
}

}  // namespace

proof_status certified_filter_row(sweep_row<double>& row, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  dd_ball_constants K;
  if (!dd_ball_constants_of(K, p)) return proof_status::out_of_domain("order 2^31 or more");
  const int m_min = theorem_m_min(a);
  const lobe_list<int128> lobes = lobes_of(a, b);
  minimum_dd_ball M;
  GYRORES_TRY_PROOF(prove_minimum_dd_ball(M, K, m_min, lobes.front()));
  sweep_row<double> r = row;  // filled here, handed back only if all of it is proved
  const bool degenerate = m_min == 0;
  if (!round_nearest(M.t_min_paper, r.t_min_paper) || !round_nearest(M.theta_first, r.theta_first) ||
      !round_nearest(M.t_first, r.t_first) || (!degenerate && !round_nearest(M.r_res, r.r_res)) ||
      (!degenerate && !round_nearest(M.t_ratio, r.t_ratio)))
    return undecided_rounding;
  row_facts<int128> f;
  f.quarter_R_scaled = sweep_quarter_R_scaled(a, b);
  f.m_min = m_min;
  f.node = paper_fast_node(a, b);
  f.lobes = std::span(lobes.begin(), lobes.size());
  f.r_positive = ddb::positive(M.r_res);
  // r_res^2 4 a^2 < 4 a^2 R(pi/2): the ball's square against the exact integer.
  const dd_ball four_a2 = ddb::exact(dd::of_int(int128(4) * a * a)), N = ddb::exact(dd::of_int(f.quarter_R_scaled));
  f.r_below_R_half_pi = ddb::positive(ddb::sub(N, ddb::mul(ddb::mul(M.r_res, M.r_res), four_a2)));
  if (!degenerate && !(f.r_positive && f.r_below_R_half_pi)) return proof_status::undecided("the degeneracy check");
  f.has_asy = sweep_has_check(cfg.checks, sweep_check::asy_bound) && 2 * b < a;
  if (f.has_asy) GYRORES_TRY_PROOF(asy_columns(r, K, paper_offset(a, b, f.node)));
  f.asy_proved = f.asy_within_bound = f.has_asy;  // asy_columns proves ratio < 1
  checks_from_facts(r, p, f, cfg);
  row = std::move(r);
  return proof_status::proved();
}

}  // namespace sweep_rows

bool sweep_testing::certified_filter_row(sweep_row<double>& r, const resonant_pair<std::int64_t>& p,
                                         const sweep_config& cfg) {
  sweep_rows::row_reset(r, p);
  return bool(sweep_rows::certified_filter_row(r, p, cfg));
}

}  // namespace gyrores
