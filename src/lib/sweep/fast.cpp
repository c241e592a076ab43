// The sweeps that write no rows (double, not --certified; docs/formats.md, "Without rows"): a
// pair's record (what the summary keeps of a row) from the theorem's series form
// (theorem/minimum_series.hpp), filtered (sweep/filtered.hpp) before the pair's row. The record
// needs the checks' verdicts, which must stay exact, and three computed values, so the filter
// forms every verdict from exact integers and from proved inequalities far from tight here
// (argued below), t_first/(pi/|n|) from u*'s series (within about an ulp, as the row's), and the
// asy ratio and constant (the row's own function) only where a proved bound says they could
// reach the largest constant already computed (the others cannot change either maximum: their
// record has has_asy = false). Any pair not decided this way takes the row's way, so its
// contribution, failures included, is exactly the row's.
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include <gyrores/core/double_double.hpp>
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/filtered.hpp>
#include <gyrores/sweep/testing.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum_series.hpp>
#include <gyrores/theorem/paper.hpp>

#include "row_parts.hpp"

namespace gyrores {
namespace sweep_rows {
namespace {

constexpr double pi = std::numbers::pi;

// r_res^2 = (1 - x^2) sin^2 u* sin^2 w*, w* = mu - x u* (theorem/minimum.hpp), with
// mu/(1 + x) <= u* <= mu/(2x) (the chord and the tangent at 0 of the convex H on [0, pi/2],
// src/lib/theorem/root.cpp), so 0 <= w* <= mu/(1 + x) and, by sin z <= z,
//   r_res^2 <= (1 - x^2) mu^4/(4 x^2 (1 + x)^2) = (sigma/tau) pi^4 m^4/(64 a^2 b^2)
// ((1 - x)/(1 + x) = sigma/tau, mu = pi m/(2a), x = b/a). With R(pi/2) = N/(4 a^2):
//   r_res^2 <= R(pi/2)   if   pi^4 m^4 sigma <= 16 b^2 tau N.
// Both sides in double: each within 5 ulps (integers below 2^53 exact, three or four
// roundings; pi^4 rounded up); decided only beyond a relative margin of 2^-40. For b >= 64 it
// always decides (odd a: N >= a^2 - b^2 = 4 tau sigma; a = 2 mod 4: N >= 1), but nothing here
// relies on that: false sends the pair the row's way. And 0 < r_res: u*, w* lie in (0, pi/2).
GYRORES_DD_INLINE bool r_below_bound(std::int64_t tau, std::int64_t sigma, int m, std::int64_t N) {
  constexpr double pi4_up = 97.40909103400245;  // pi^4 = 97.409091034002437...
  const double b = double(tau - sigma), m2 = double(m * m);
  const double lhs = pi4_up * (m2 * m2) * double(sigma);
  const double rhs = 16 * (b * b) * double(tau) * double(N);
  return lhs <= rhs * (1 - 0x1p-40);
}

// With c <= bound (1 + 2^-47) and bound <= known (1 - 2^-36): the computed constant (within
// 2^-47 of c: paper_difference_double's d to about 2^-50, then three roundings) is below
// known (1 - 2^-37), and its ratio fl(c/pi^3) below fl(known/pi^3) (one rounding each), so
// neither maximum of the summary can come from this pair, nor tie with the known one. (A known
// value from an enclosure row, order >= 2^31, has its ratio within 2^-80 of known/pi^3: the
// same holds.) For bound = num/den: num <= known (1 - 2^-36) den, one more rounding (2^-52)
// inside the margin.
GYRORES_DD_INLINE bool asy_below(paper_bound_fraction bound, double known) {
  return known > 0 && bound.num <= known * (1 - 0x1p-36) * bound.den;
}

// p's record (the summary's part of its row); not decided: the row's way. `known`: the largest
// asy constant computed so far; pass_k: p's from pass_ks_of_block.
GYRORES_DD_FAST proof_status summary_record(sweep_record& r, const resonant_pair<std::int64_t>& p,
                                            const sweep_config& cfg, double known, std::int64_t pass_k) {
  const std::int64_t tau = p.tau(), sigma = p.sigma(), a = tau + sigma, b = tau - sigma;
  const int m = theorem_m_min(a);
  const bool degenerate = m == 0;
  if (a >= (std::int64_t(1) << 28)) return proof_status::out_of_domain("order 2^28 or more");
  if (!degenerate && (b < series_min_delta || pass_k <= 0)) return proof_status::out_of_domain("delta below 64");
  const auto& ck = cfg.checks;
  const double ad = double(a), bd = double(b), inv_a = 1 / ad, inv_b = 1 / bd, x = bd * inv_a;
  // The lobes from the pass frame, 2j+1 = (1 + k d)/ah an exact quotient below 2 a < 2^29 found
  // by rounding its double (relative error 2^-51: below 1/2; positive, so rounding to nearest is
  // adding 1/2 and truncating). They are checked whether or not structure is asked for: the
  // frames' equations with |m| = m_min, k in [0, a), in theta order, 2 or 4 of them determine
  // the lobes uniquely, so what P5 and theta_first read is the theorem's lobes.
  std::array<lobe_frame<std::int64_t>, 4> frames;
  std::size_t count;
  if (degenerate) {
    count = minimiser_lobes_euclid_into(a, b, frames);  // no Euclid for them
  } else {
    const std::int64_t d = m == 1 ? 2 * b : b;
    const std::int64_t s = std::int64_t(double(1 + pass_k * d) * (m == 1 ? inv_a : 2 * inv_a) + 0.5);
    count = minimiser_lobes_of_pass(a, b, {pass_k, (s - 1) / 2, m}, frames);
  }
  row_facts<std::int64_t> f;
  f.m_min = m;
  f.node = paper_fast_node(a, b);
  f.lobes = std::span(frames.data(), count);
  if (!sweep_lobes_hold<std::int64_t>(p, m, f.lobes)) return proof_status::undecided("the pass frame's lobes");
  f.lobes_hold = true;
  if (sweep_has_check(ck, sweep_check::degeneracy)) {
    const std::int64_t N = sweep_quarter_R_scaled<std::int64_t>(a, b);
    if ((N == 0) != degenerate) return proof_status::undecided("R(pi/2) = 0");
    if (!degenerate && !r_below_bound(tau, sigma, m, N)) return proof_status::undecided("P3's bound");
    f.quarter_R_scaled = N;
    f.r_positive = f.r_below_R_half_pi = true;
  }
  bool asy_values = false;
  if (sweep_has_check(ck, sweep_check::asy_bound) && 2 * b < a) {
    const std::int64_t am = paper_offset(a, b, f.node);
    const paper_bound_fraction bound = paper_constant_bound(x, double(am) * inv_b);
    // pi^3 > 31: the ratio is below 1 with room far beyond the bound's roundings.
    if (!(bound.num <= 31 * bound.den)) return proof_status::undecided("the asy bound");
    f.has_asy = f.asy_proved = f.asy_within_bound = true;
    if (!asy_below(bound, known)) {
      const paper_error_double v = paper_error_of(a, b, am);
      if (!(v.ratio <= 1)) return proof_status::undecided("the asy ratio");  // never (the bound)
      r.asy_ratio = v.ratio;
      r.asy_constant = v.constant;
      asy_values = true;
    }
  }
  r.tau = tau;
  r.sigma = sigma;
  r.delta_mod4 = p.delta_mod4();
  r.failed = false;
  r.status = {};
  r.has_ratio = false;
  r.first_at_paper_node = -1;
  r.has_asy = false;
  checks_from_facts(r, p, f, cfg);
  r.has_asy = asy_values;  // the values of the others are not formed (they cannot reach the extremes)
  if (!degenerate) {
    const auto& first = frames[0];
    const double u = theorem_root_series(x, pi / 4 * double(m) * inv_b);
    r.t_ratio = lobe_theta_double(ad, inv_a, first.k, first.m < 0 ? -u : u) * bd / pi;  // as the row's
  }
  return proof_status::proved();
}

filter_counts fast_counts("sweep without rows");

}  // namespace

void fast_block(const std::vector<resonant_pair<std::int64_t>>& pairs, sweep_block& blk, const sweep_config& cfg,
                double& known) {
  std::vector<std::int64_t> pass_ks;
  pass_ks_of_block(pairs, pass_ks);
  // One row and one record for the whole block, overwritten pair by pair.
  sweep_row<double> row;
  sweep_record rec;
  const filtered fast_record{fast_counts, summary_record,
                             [&row](sweep_record& r, const resonant_pair<std::int64_t>& p, const sweep_config& c, double,
                                    std::int64_t) {
                               sweep_evaluate_to(row, p, c);
                               sweep_record_fill(r, row, c.digits);
                             }};
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    fast_record(true, rec, pairs[i], cfg, known, pass_ks[i]);
    blk.summary.add(rec);
    // A row's computed constant (paper_error_of, or an enclosure's midpoint) is a valid known
    // value: a pair of this run with it is in the summary (asy_below).
    if (rec.has_asy && !rec.failed && rec.asy_constant > known) known = rec.asy_constant;
  }
}

}  // namespace sweep_rows

bool sweep_testing::fast_r_below_quarter_R(std::int64_t tau, std::int64_t sigma, int m, std::int64_t N) {
  return sweep_rows::r_below_bound(tau, sigma, m, N);
}

bool sweep_testing::fast_asy_below(double bound, double known) {
  return sweep_rows::asy_below({bound, 1}, known);
}

}  // namespace gyrores
