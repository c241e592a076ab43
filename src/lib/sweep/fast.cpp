// include/gyrores/sweep/fast.hpp: a pair's contribution to the summary without its row.
#include <gyrores/sweep/fast.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include <gyrores/core/double_double.hpp>
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/evaluate.hpp>
#include <gyrores/theorem/lobes.hpp>

namespace gyrores {
namespace detail {
namespace {

constexpr double pi = std::numbers::pi;

}  // namespace

// H(u)/(2x) = (u + arctan(x tan u)/x)/2 = F(u) = v = mu/(2x) = pi m/(4b), and u* <= v (H(u) >=
// 2 x u: the tangent at 0 of the convex H, src/lib/theorem/root.cpp), so u* <= pi/128 here.
// F(u) = u + (1 - x^2) u^3/6 + ... (the series of tan and arctan), and its inverse series
//   u* = v (1 + c3 w + c5 w^2 + c7 w^3 + c9 w^4 + ...),  w = v^2,
//   c3 = -(1 - x^2)/6,  c5 = (1 - x^4)/60,  c7 = (2 - 7 x^2 + 7 x^4 - 2 x^6)/315,
//   c9 = (-143 + 290 x^2 - 290 x^6 + 143 x^8)/45360
// (by series reversion; each vanishes at x = 1, where F(u) = u). Truncated after v^9 its error,
// measured at 50 digits for v = pi/128 (the largest here) and x in (0, 1), is below 2^-65 u*
// (the next coefficient is below 2^-12, times w^5 < 2^-53). In double: x and v within two
// roundings (u* moves by at most their relative error, the sensitivity argument of
// src/lib/theorem/minimum.cpp), the correction v w (...) below 2^-12 v and formed to a few
// ulps of itself, then one rounding: u* within about 3 ulps (tests/test_sweep.cpp compares it
// with theorem_minimum_double's).
GYRORES_DD_INLINE double root_of(double x, double v) {
  const double x2 = x * x, w = v * v;
  const double c3 = (x2 - 1) * (1.0 / 6), c5 = (1 - x2 * x2) * (1.0 / 60);
  const double c7 = (2.0 / 315) + x2 * (-1.0 / 45 + x2 * (1.0 / 45 - x2 * (2.0 / 315)));
  const double c9 = (-143.0 / 45360) + x2 * (29.0 / 4536 + x2 * x2 * (-29.0 / 4536 + x2 * (143.0 / 45360)));
  return v + v * w * (c3 + w * (c5 + w * (c7 + w * c9)));
}

GYRORES_DD_FAST double sweep_fast_root(std::int64_t a, std::int64_t b, int m) {
  return root_of(double(b) / double(a), pi / 4 * double(m) / double(b));
}

// arc = k pi + su in double-double (pi to 2^-107, k < 2^53 exact: 2^-104 relative), then
// 2 arc/a by a quotient q = arc.hi (1/a) (a few ulps) and its exact remainder (Sterbenz:
// arc.hi - (q a).hi is exact, (q a).lo is q a's rounding error), so the sum q + r/a carries
// 2^-100 of the exact quotient before its one rounding. With k >= 1 and |su| < pi/2 the arc is
// above pi/2: an error of e ulps of su (su <= pi/128) is below 2^-5 e ulps of the arc, so theta
// is within half an ulp and e 2^-58 relative of the exact value.
GYRORES_DD_INLINE double theta_of(double ad, double inv_a, std::int64_t k, double su) {
  const double_double arc = dd::add(dd::mul(dd::pi, double(k)), su);
  const double q = arc.hi * inv_a;
  const double_double qa = dd::two_prod(q, ad);
  const double rem = ((arc.hi - qa.hi) - qa.lo) + arc.lo;
  return 2 * (q + rem * inv_a);
}

GYRORES_DD_FAST double sweep_fast_theta(std::int64_t a, std::int64_t k, double su) {
  return theta_of(double(a), 1 / double(a), k, su);
}

// The same integer as sweep_quarter_R_scaled (src/lib/sweep/certified.cpp), restated in int64:
// sqrt(2) sin(k pi/4), sqrt(2) cos(k pi/4) for odd k, sin, cos for even k, from k mod 8 (k > 0).
// With a < 2^28: |q| <= a + b < 2^29 and N < 4 a^2 + 4 q^2 < 2^61.
std::int64_t sweep_fast_quarter_R_scaled(std::int64_t a, std::int64_t b) {
  static constexpr int sin_q[8] = {0, 1, 1, 1, 0, -1, -1, -1}, cos_q[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  const int sa = sin_q[a & 7], ca = cos_q[a & 7], sb = sin_q[b & 7], cb = cos_q[b & 7];
  const std::int64_t diff = a * a - b * b, q = a * (ca * cb) - b * (sa * sb);
  if (a % 2 != 0) return diff + q * q;
  const std::int64_t f = sa * cb;
  return 4 * diff * (f * f) + 4 * q * q;
}

// r_res^2 = (1 - x^2) sin^2 u* sin^2 w*, w* = mu - x u* (theorem/minimum.hpp), with
// mu/(1 + x) <= u* <= mu/(2x) (the chord and the tangent at 0 of the convex H on [0, pi/2],
// src/lib/theorem/root.cpp), so 0 <= w* <= mu/(1 + x) and, by sin z <= z,
//   r_res^2 <= (1 - x^2) mu^4/(4 x^2 (1 + x)^2) = (sigma/tau) pi^4 m^4/(64 a^2 b^2)
// ((1 - x)/(1 + x) = sigma/tau, mu = pi m/(2a), x = b/a). With R(pi/2) = N/(4 a^2):
//   r_res^2 <= R(pi/2)   if   pi^4 m^4 sigma <= 16 b^2 tau N.
// Both sides in double: each within 5 ulps (integers below 2^53 exact, three or four
// roundings; pi^4 rounded up); decided only beyond a relative margin of 2^-40. For b >= 64 it
// always decides (odd a: N >= a^2 - b^2 = 4 tau sigma; a = 2 mod 4: N >= 1), but nothing here
// relies on that: false sends the pair the row's way.
bool sweep_fast_r_below_quarter_R(std::int64_t tau, std::int64_t sigma, int m, std::int64_t N) {
  constexpr double pi4_up = 97.40909103400245;  // pi^4 = 97.409091034002437...
  const double b = double(tau - sigma), m2 = double(m * m);
  const double lhs = pi4_up * (m2 * m2) * double(sigma);
  const double rhs = 16 * (b * b) * double(tau) * double(N);
  return lhs <= rhs * (1 - 0x1p-40);
}

// The asy constant c = 2 d/x^2, d = u_c - u_a (src/lib/sweep/evaluate.cpp, sweep_asy_difference):
// d = D/f'(xi) for some xi in [u_a, u_c] with D = x^2 t^3 sum_n (-1)^n (x t)^(2n)/(2n + 3) <=
// x^2 t^3/3 (alternating, decreasing: x t < 1), t = tan u_a, and f'(u) = 1 + (1 + tan^2 u)/
// (1 + x^2 tan^2 u) increasing in u (x < 1), so f'(xi) >= f'(u_a) and, with y = x t,
//   c <= (2 t^3/3) (1 + y^2)/(2 + t^2 + y^2),
// increasing in t (its logarithmic derivative is >= 3/t - 2/t). And t <= t_hi = t_max s/(pi/2)
// = t_max |m|/b: t(s) = s - u_a(s) has t(0) = 0 and dt/ds = (1 + t^2)/(2 + t^2) increasing in t,
// hence in s, so t is convex and below its chord to s = pi/2 (s <= pi/2 as |m| <= b), where
// t_max = tan u_a(pi/2) = 0.86033358901937976... (rounded up here; tests/test_sweep.cpp checks
// it against the paper's root). The result: a few roundings (x and |m|/b from reciprocals
// included), within 2^-47 of the bound.
namespace {
// The bound as num/den (den in [2, 3.5]): compared by products, without the division.
struct fraction {
  double num, den;
};
GYRORES_DD_INLINE fraction asy_bound_of(double x, double am_over_b) {
  constexpr double t_max_up = 0.860333589019381;  // 1.2e-15 above t_max
  const double t = t_max_up * am_over_b;
  const double t2 = t * t, y2 = x * x * t2;
  return {(2.0 / 3) * (t2 * t) * (1 + y2), 2 + t2 + y2};
}
}  // namespace

double sweep_fast_asy_bound(std::int64_t a, std::int64_t b, std::int64_t am) {
  const fraction f = asy_bound_of(double(b) / double(a), double(am) / double(b));
  return f.num / f.den;
}

// With c <= bound (1 + 2^-47) and bound <= known (1 - 2^-36): the computed constant (within
// 2^-47 of c: sweep_asy_difference's d to about 2^-50, then three roundings) is below
// known (1 - 2^-37), and its ratio fl(c/pi^3) below fl(known/pi^3) (one rounding each), so
// neither maximum of the summary can come from this pair, nor tie with the known one. (A known
// value from an enclosure row, order >= 2^31, has its ratio within 2^-80 of known/pi^3: the
// same holds.)
bool sweep_fast_asy_below(double bound, double known) { return known > 0 && bound <= known * (1 - 0x1p-36); }

namespace {
// The same for bound = num/den: num <= known (1 - 2^-36) den, one more rounding (2^-52) inside
// the margin.
GYRORES_DD_INLINE bool asy_below(fraction bound, double known) {
  return known > 0 && bound.num <= known * (1 - 0x1p-36) * bound.den;
}
}  // namespace

void sweep_fast_publish(std::atomic<double>& shared, double known) {
  double seen = shared.load(std::memory_order_relaxed);
  while (known > seen && !shared.compare_exchange_weak(seen, known, std::memory_order_relaxed)) {
  }
}

namespace {

// x y mod A for x, y < A < 2^31 by Barrett's reduction with M = floor((2^64 - 1)/A): the
// estimate q = floor(z M/2^64) of floor(z/A) (z = x y < 2^62) is short by at most 2.
struct barrett {
  std::uint64_t A, M;
  explicit barrett(std::uint64_t mod) : A(mod), M(~std::uint64_t(0) / mod) {}
  std::uint64_t mul(std::uint64_t x, std::uint64_t y) const {
    const std::uint64_t z = x * y, q = std::uint64_t((unsigned __int128)z * M >> 64);
    std::uint64_t r = z - q * A;
    if (r >= A) r -= A;
    if (r >= A) r -= A;
    return r;
  }
};

// The pass frames' k of pairs[lo, hi), all of order a (odd or 2 mod 4, a < 2^31): c_i = 4 sigma
// (m_min = 1, ah = a) or 2 sigma (m_min = 2, ah = a/2) reduced mod ah, all invertible (sigma is
// coprime to a, ah is odd); k_i = c_i^-1 mod ah. The prefix products P_i = c_1 ... c_i, one
// inverse of P_n, then backwards c_i^-1 = P_n^-1 (c_n ... c_(i+1)) P_(i-1).
// Why k = c^-1: the pass frame has (2j+1) ah - k d = 1 with d = 2b (m = 1) or b (m = 2), so
// k d = -1 mod ah, and d = -4 sigma or -2 sigma mod ah (b = a - 2 sigma); 0 < k < ah.
void pass_ks_of_order(const std::vector<resonant_pair<std::int64_t>>& pairs, std::size_t lo, std::size_t hi,
                      std::int64_t a, std::vector<std::int64_t>& ks) {
  const bool odd = a % 2 != 0;
  const std::uint64_t ah = std::uint64_t(odd ? a : a / 2);
  const barrett B(ah);
  thread_local std::vector<std::uint64_t> c, prefix;
  c.resize(hi - lo);
  prefix.resize(hi - lo);
  std::uint64_t P = 1;
  for (std::size_t i = lo; i < hi; ++i) {
    std::uint64_t ci = std::uint64_t(pairs[i].sigma()) * (odd ? 4 : 2);  // < 2 ah
    if (ci >= ah) ci -= ah;
    prefix[i - lo] = P;  // P_(i-1)
    c[i - lo] = ci;
    P = B.mul(P, ci);
  }
  std::uint64_t inv = std::uint64_t(int_inverse_mod(std::int64_t(P), std::int64_t(ah)));  // (c_lo ... c_i)^-1
  for (std::size_t i = hi; i-- > lo;) {
    ks[i] = std::int64_t(B.mul(inv, prefix[i - lo]));
    inv = B.mul(inv, c[i - lo]);
  }
}

}  // namespace

void sweep_fast_pass_ks(const std::vector<resonant_pair<std::int64_t>>& pairs, std::vector<std::int64_t>& ks) {
  ks.assign(pairs.size(), 0);
  std::size_t lo = 0;
  while (lo < pairs.size()) {
    const std::int64_t a = std::int64_t(pairs[lo].order());
    std::size_t hi = lo + 1;
    while (hi < pairs.size() && std::int64_t(pairs[hi].order()) == a) ++hi;
    if (a % 4 != 0 && a < (std::int64_t(1) << 31)) pass_ks_of_order(pairs, lo, hi, a, ks);
    lo = hi;
  }
}

namespace {

// The minimisers' lobes, in theta order, from the pass frame's k, as minimiser_lobes_euclid
// (theorem/lobes.hpp) builds them from its Euclid: 2j+1 = (1 + k d)/ah, an exact quotient below
// 2 a < 2^29 found by rounding its double (relative error 2^-51: below 1/2); the mirror (a - k),
// for m_min = 2 the shift (k + a/2) and its mirror (a/2 - k); pass first iff 2k < ah. The
// structure check verifies every frame's equation, so an error here is caught, not printed.
// At most four frames, not zero-filled first (a lobe_list's array is, at a cost comparable to the
// frames' arithmetic).
struct fast_lobes {
  std::array<lobe_frame<std::int64_t>, 4> items;
  std::size_t count = 0;
  void push_back(const lobe_frame<std::int64_t>& f) { items[count++] = f; }
  const lobe_frame<std::int64_t>& front() const { return items[0]; }
  std::span<const lobe_frame<std::int64_t>> span() const { return {items.data(), count}; }
};

GYRORES_DD_INLINE void lobes_of(fast_lobes& out, std::int64_t a, std::int64_t b, int m, std::int64_t k, double inv_a) {
  using frame = lobe_frame<std::int64_t>;
  if (m == 0) {
    out.push_back({a / 4, (b - 2) / 4, 0});
    out.push_back({3 * (a / 4), (3 * b - 2) / 4, 0});
    return;
  }
  const std::int64_t ah = m == 1 ? a : a / 2, d = m == 1 ? 2 * b : b;
  // The quotient is positive: rounding to nearest is adding 1/2 and truncating.
  const std::int64_t s = std::int64_t(double(1 + k * d) * (m == 1 ? inv_a : 2 * inv_a) + 0.5);
  const frame pass{k, (s - 1) / 2, m}, mirror{a - k, b - 1 - pass.j, -m};
  const bool pass_first = 2 * k < ah;
  if (m == 1) {
    out.push_back(pass_first ? pass : mirror);
    out.push_back(pass_first ? mirror : pass);
    return;
  }
  const frame shift{k + a / 2, pass.j + b / 2, m}, shift_mirror{a / 2 - k, b / 2 - 1 - pass.j, -m};
  out.push_back(pass_first ? pass : shift_mirror);
  out.push_back(pass_first ? shift_mirror : pass);
  out.push_back(pass_first ? shift : mirror);
  out.push_back(pass_first ? mirror : shift);
}

// What the fast path found for one pair, before any of it goes into the summary.
struct fast_pair {
  std::array<sweep_status, sweep_check_count> status{};
  bool first_at_paper_node = false;
  double t_ratio = 0;
  bool asy_computed = false;
  sweep_asy_double asy;
};

// The paper's node k = round(a/(2b)) as paper_fast_node (theorem/lobes.hpp) by one division:
// q = floor((a + b)/(2b)); a tie (a = b mod 2b) is a + b = 0 mod 2b, and then k = q - 1 =
// (a - b)/(2b). 0 <= k < a (k <= (a + b)/2), and k + 1 < a on a tie (b = 1, k = (a - 1)/2), so
// the lobes' k in [0, a) compare with them directly.
struct node_of_pair {
  std::int64_t k;
  bool tie;
};
GYRORES_DD_INLINE node_of_pair paper_node(std::int64_t a, std::int64_t b) {
  const std::int64_t q = (a + b) / (2 * b);
  const bool tie = q * 2 * b == a + b;
  return {tie ? q - 1 : q, tie};
}

// P5 and first_at_paper_node as check_paper_node (src/lib/sweep/evaluate.cpp) decides them.
template <class Lobes> void paper_node_of(fast_pair& f, node_of_pair node, const Lobes& lobes, bool check) {
  auto in_paper = [&](std::int64_t k) { return k == node.k || (node.tie && k == node.k + 1); };
  f.first_at_paper_node = in_paper(lobes.front().k);
  bool any = false;
  for (const auto& l : lobes.span()) any = any || in_paper(l.k);
  if (check) f.status[int(sweep_check::paper_node)] = any ? sweep_status::pass : sweep_status::fail;
}

// Every verdict and value of p, or false if one is not decided here (or is a failure).
GYRORES_DD_FAST bool decide(fast_pair& f, const resonant_pair<std::int64_t>& p, const sweep_config& cfg,
                            double asy_known, std::int64_t pass_k) {
  const std::int64_t tau = p.tau(), sigma = p.sigma(), a = tau + sigma, b = tau - sigma;
  const int m = theorem_m_min(a);
  const bool degenerate = m == 0;
  if (a >= (std::int64_t(1) << 28) || (!degenerate && (b < sweep_fast_min_delta || pass_k <= 0))) return false;
  const auto& ck = cfg.checks;
  const double ad = double(a), bd = double(b), inv_a = 1 / ad, inv_b = 1 / bd, x = bd * inv_a;
  // The lobes are checked whether or not structure is asked for: the frames' equations with
  // |m| = m_min, k in [0, a), in theta order, 2 or 4 of them determine the lobes uniquely, so
  // what P5 and theta_first read is the theorem's lobes (a failure goes the row's way).
  fast_lobes lobes;
  lobes_of(lobes, a, b, m, pass_k, inv_a);
  if (!sweep_lobes_hold<std::int64_t>(p, m, lobes.span())) return false;
  if (sweep_has_check(ck, sweep_check::structure)) f.status[int(sweep_check::structure)] = sweep_status::pass;
  if (sweep_has_check(ck, sweep_check::degeneracy)) {
    const std::int64_t N = sweep_fast_quarter_R_scaled(a, b);
    if ((N == 0) != degenerate) return false;
    // Degenerate: r_res = 0 exactly (m_min = 0, the theorem); else 0 < r_res (u*, w* in
    // (0, pi/2): the bounds above sweep_fast_r_below_quarter_R) and the proved inequality.
    if (!degenerate && !sweep_fast_r_below_quarter_R(tau, sigma, m, N)) return false;
    f.status[int(sweep_check::degeneracy)] = sweep_status::pass;
  }
  const node_of_pair node = paper_node(a, b);
  if (!degenerate) {
    paper_node_of(f, node, lobes, sweep_has_check(ck, sweep_check::paper_node));  // exact: pass or fail
    const auto& first = lobes.front();
    const double u = root_of(x, pi / 4 * double(m) * inv_b);
    f.t_ratio = theta_of(ad, inv_a, first.k, first.m < 0 ? -u : u) * bd / pi;  // as the row's
  }
  if (sweep_has_check(ck, sweep_check::asy_bound) && 2 * b < a) {
    const std::int64_t m_paper = a - 2 * node.k * b, am = m_paper < 0 ? -m_paper : m_paper;  // sweep_asy_offset
    const fraction bound = asy_bound_of(x, double(am) * inv_b);
    // pi^3 > 31: the ratio is below 1 with room far beyond the bound's roundings.
    if (!(bound.num <= 31 * bound.den)) return false;
    f.status[int(sweep_check::asy_bound)] = sweep_status::pass;
    if (!asy_below(bound, asy_known)) {
      f.asy = sweep_asy_double_of(a, b, am);
      if (!(f.asy.ratio <= 1)) return false;  // never (the bound): the row's way would say why
      f.asy_computed = true;
    }
  }
  return true;
}

// f into acc, as sweep_accumulator::add adds the record of a row with these fields.
void add_fast(sweep_accumulator& acc, const resonant_pair<std::int64_t>& p, const fast_pair& f) {
  ++acc.pairs;
  const bool degenerate = p.delta_mod4() == 2;
  if (degenerate) ++acc.degenerate;
  for (int i = 0; i < sweep_check_count; ++i) {
    if (f.status[i] == sweep_status::pass) ++acc.checks[i].checked;  // the common case, inline
    else if (f.status[i] == sweep_status::fail) acc.add_check(i, f.status[i], {p.tau(), p.sigma()});
  }
  if (degenerate) return;  // no ratio, and the first minimiser is not applicable
  if (f.first_at_paper_node) ++acc.first_at_paper_node;
  acc.t_ratios.add(f.t_ratio);
}

// The asy extremes, from the pairs whose values were computed (the others cannot change them).
void add_fast_asy(sweep_accumulator& acc, const resonant_pair<std::int64_t>& p, const fast_pair& f, double& asy_known) {
  static const std::string shortest;  // a double run's extremes print the shortest form
  if (!f.asy_computed) return;
  const sweep_pair_id id{p.tau(), p.sigma()};
  acc.asy_ratio_max.offer(f.asy.ratio, shortest, id);
  acc.sharp_constant.offer(f.asy.constant, shortest, id);
  if (f.asy.constant > asy_known) asy_known = f.asy.constant;
}

}  // namespace

bool sweep_fast_add(sweep_accumulator& acc, const resonant_pair<std::int64_t>& p, const sweep_config& cfg,
                    double& asy_known, std::int64_t pass_k) {
  fast_pair f;
  if (!decide(f, p, cfg, asy_known, pass_k)) return false;
  add_fast(acc, p, f);
  add_fast_asy(acc, p, f, asy_known);
  return true;
}

}  // namespace detail
}  // namespace gyrores
