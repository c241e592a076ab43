// include/gyrores/sweep/evaluate.hpp: the double path (theorem_minimum_double, the paper's error
// by Newton's method in double), the checks from the enclosures, float128 conversion.
#include <gyrores/sweep/evaluate.hpp>

#include <gmp.h>

#include <cmath>
#include <numbers>

#include <gyrores/core/error.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

const char* sweep_status_text(sweep_status s) {
  return s == sweep_status::pass ? "pass" : s == sweep_status::fail ? "fail" : "";
}

namespace detail {
namespace {

constexpr double pi = std::numbers::pi;

void add_note(std::string& note, const std::string& what) { note += std::string(note.empty() ? "" : "; ") + what; }

void set_status(sweep_row_info& r, sweep_check c, bool ok) {
  r.status[int(c)] = ok ? sweep_status::pass : sweep_status::fail;
}

// P5 (non-degenerate pairs): first_at_paper_node, paper_lobe_min and, if asked, the verdict,
// from the minimisers' lobes k (in [0, a), theta order): alpha = k pi + u with |u| < pi/2.
void check_paper_node(sweep_row_info& r, const resonant_pair<std::int64_t>& p, std::span<const std::int64_t> ks,
                      bool check) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const auto node = paper_fast_node(a, b);  // on a tie (b = 1) both k and k + 1
  const std::int64_t kp0 = int_mod(node.k, a), kp1 = node.tie ? int_mod(node.k + 1, a) : kp0;
  auto in_paper = [&](std::int64_t k) { return k == kp0 || k == kp1; };
  r.first_at_paper_node = in_paper(ks.front()) ? 1 : 0;
  r.paper_lobe_min = 0;
  for (std::int64_t k : ks)
    if (in_paper(k)) r.paper_lobe_min = 1;
  if (check) set_status(r, sweep_check::paper_node, r.paper_lobe_min == 1);
}

// P7 in double (x < 1/2): the columns of the row as the header comment defines them.
void check_asy_double(sweep_row<double>& r, std::int64_t a, std::int64_t b) {
  const sweep_asy_double v = sweep_asy_double_of(a, b, sweep_asy_offset(a, b));
  r.has_asy = true;
  r.asy_constant = v.constant;
  r.asy_error = v.error;
  r.asy_bound = v.bound;
  r.asy_ratio = v.ratio;
  set_status(r, sweep_check::asy_bound, r.asy_ratio <= 1);
}

// P3 in double: R(pi/2) from the exact integer 4 a^2 R(pi/2), against delta mod 4 and r_res.
void check_degeneracy_double(sweep_row_info& r, const resonant_pair<std::int64_t>& p, double r_res) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const int128 N = sweep_quarter_R_scaled(a, b);
  const bool degenerate = p.delta_mod4() == 2;
  bool ok = (N == 0) == degenerate;
  if (ok) ok = degenerate ? r_res == 0 : r_res > 0 && sweep_r_below_quarter_R(p, r_res, N);
  set_status(r, sweep_check::degeneracy, ok);
  if (!ok)
    add_note(r.note, "degeneracy: 4 a^2 R(pi/2) = " + to_decimal(N) + ", r_res = " + sweep_double_text(r_res));
}

}  // namespace

std::int64_t sweep_asy_offset(std::int64_t a, std::int64_t b) {
  const auto node = paper_fast_node(a, b);  // the smaller k on a tie
  const std::int64_t m = a - 2 * node.k * b;
  return m < 0 ? -m : m;
}

sweep_asy_double sweep_asy_double_of(std::int64_t a, std::int64_t b, std::int64_t am) {
  const double x = double(b) / double(a), x2 = x * x, pi3 = pi * pi * pi;
  const double d = am == 0 ? 0.0 : sweep_asy_difference(x, pi * double(am) / double(2 * b));
  sweep_asy_double v;
  v.constant = 2 * (d / x2);
  v.error = v.constant * x2 / double(a);
  v.bound = pi3 * x2 / double(a);
  v.ratio = v.constant / pi3;
  return v;
}

// u_c - u_a >= 0 in the paper's lobe with s = pi |m|/(2b) > 0, x < 1/2, in double, without
// cancellation (it is O(x^2 u^3) against u). f(u) = u + arctan(x tan u)/x - s has the root u_c
// and f' = 1 + (1 + tan^2 u)/(1 + x^2 tan^2 u) >= 2; with t = tan u_a = s - u_a, f(u_a) = -D,
// D = t - arctan(x t)/x = x^2 t^3 sum_n (-1)^n (x t)^(2n)/(2n + 3) (x t < 0.44: src/lib/sweep/
// certified.cpp). Newton's method on g(d) = f(u_a + d) = d + arctan(x Dt/(1 + x^2 t t'))/x - D,
// with t' = tan(u_a + d) and Dt = t' - t = sin d/(cos u_a cos(u_a + d)) (no difference of
// tangents is formed), from d = D/f'(u_a); g' = f'(u_a + d), |g''| < 4. Once a step is below
// 2^-26 d the next error is below 2^-52 d.
double sweep_asy_difference(double x, double s) {
  // u_a to about an ulp: paper_root_double's 4 ulps, then one Newton step on u + tan u - s (its
  // residual is accurate to an ulp of s, and 1/(2 + t^2) < 1/2 of it moves u).
  double ua = paper_root_double(s);
  const double tan_a = std::tan(ua);
  ua -= (ua + tan_a - s) / (2 + tan_a * tan_a);
  // The series' coefficients 1/(2n + 3), once; y2 < 0.2 needs fewer than 30 terms.
  static const std::array<double, 64> inverse_odd = [] {
    std::array<double, 64> c{};
    for (std::size_t n = 0; n < c.size(); ++n) c[n] = 1.0 / double(2 * n + 3);
    return c;
  }();
  const double t = s - ua, y2 = (x * t) * (x * t);
  double sum = 0, power = 1;
  for (std::size_t n = 0; n < inverse_odd.size(); ++n) {
    const double term = power * inverse_odd[n];
    sum += n % 2 ? -term : term;
    if (term <= 0x1p-56 * sum) break;
    power *= y2;
  }
  const double D = x * x * t * t * t * sum, cu = std::cos(ua);
  auto fprime = [x](double tan_u) { return 1 + (1 + tan_u * tan_u) / (1 + x * x * tan_u * tan_u); };
  double d = D / fprime(t);
  for (int it = 0; it < 40; ++it) {
    const double u = ua + d, tu = std::tan(u);
    const double dt = std::sin(d) / (cu * std::cos(u));
    const double g = d + std::atan(x * dt / (1 + x * x * t * tu)) / x - D;
    const double step = g / fprime(tu);
    d -= step;
    if (std::fabs(step) <= 0x1p-26 * d) return d;
  }
  throw compute_error("sweep: Newton's method for u_c - u_asy did not converge (x = " + std::to_string(x) +
                      ", s = " + std::to_string(s) + ")");
}

bool sweep_double_path(const resonant_pair<std::int64_t>& p) { return p.order() < (int128(1) << 31); }

bool sweep_r_below_quarter_R(const resonant_pair<std::int64_t>& p, double r_res, int128 N) {
  const double a = double(std::int64_t(p.order()));
  // N >= 0 (a sum of squares times 4 a^2); below 2^63 the int64 conversion is the cheap one.
  const double n = N < (int128(1) << 63) ? double(std::int64_t(N)) : double(N);
  const double R = n / (4 * (a * a)), r2 = r_res * r_res;
  // r_res is within one ulp of the exact value (theorem/minimum.hpp), so r2 within 3 ulps and a
  // rounding; R is N, a^2 and the quotient each rounded once (4 a^2 is exact beyond a^2): both
  // within 2^-49 relative of their exact values, far inside the band of 2^-40 around R.
  if (r2 <= R * (1 - 0x1p-40)) return true;
  if (r2 > R * (1 + 0x1p-40)) return false;
  // Inside the band the double comparison could be wrong: the proved enclosure decides.
  const sweep_proof pr = sweep_prove_pair(p);
  return pr.minimum && pr.r_below_R_half_pi;
}

void sweep_evaluate_double(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  const auto& ck = cfg.checks;
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const minimum_double M = theorem_minimum_double(p);
  r.r_res = M.r_res;
  r.theta_first = M.theta_first;
  r.t_first = M.t_first;
  r.t_min_paper = pi * std::sqrt(double(p.tau()) * double(p.sigma())) / double(b);
  r.minimiser_count = int(M.count);
  if (p.delta_mod4() != 2) {
    r.has_ratio = true;
    r.t_ratio = M.theta_first * double(b) / pi;
    std::array<std::int64_t, 4> ks{};
    for (std::size_t i = 0; i < M.count; ++i) ks[i] = M.lobes[i].k;
    check_paper_node(r, p, std::span(ks.data(), M.count), sweep_has_check(ck, sweep_check::paper_node));
  }
  if (sweep_has_check(ck, sweep_check::degeneracy)) check_degeneracy_double(r, p, M.r_res);
  if (sweep_has_check(ck, sweep_check::structure)) {
    const bool ok = sweep_lobes_hold<std::int64_t>(p, M.m_min, std::span(M.lobes.data(), M.count));
    set_status(r, sweep_check::structure, ok);
    if (!ok) add_note(r.note, "structure: the theorem's lobes do not check");
  }
  if (sweep_has_check(ck, sweep_check::asy_bound) && 2 * b < a) check_asy_double(r, a, b);
}

sweep_proof_options sweep_proof_options_of(const resonant_pair<std::int64_t>& p, const sweep_config& cfg, unsigned bits) {
  sweep_proof_options o;
  o.bits = bits;
  o.asy = sweep_has_check(cfg.checks, sweep_check::asy_bound);
  o.outward_asy = cfg.certified;
  return o;
}

void sweep_checks_from_facts(sweep_row_info& r, const resonant_pair<std::int64_t>& p, const sweep_proved_facts& f,
                             const sweep_config& cfg) {
  const auto& ck = cfg.checks;
  const bool degenerate = p.delta_mod4() == 2;
  r.minimiser_count = int(f.lobes.size());
  if (!degenerate) {
    r.has_ratio = true;
    std::array<std::int64_t, 4> ks{};
    for (std::size_t i = 0; i < f.lobes.size() && i < ks.size(); ++i) ks[i] = std::int64_t(f.lobes[i].k);
    check_paper_node(r, p, std::span(ks.data(), f.lobes.size()), sweep_has_check(ck, sweep_check::paper_node));
  }
  if (sweep_has_check(ck, sweep_check::degeneracy)) {
    // P3: R(pi/2) = 0 exactly iff delta = 2 mod 4; r_res = 0 there by the theorem (m_min = 0),
    // else 0 < r_res <= sqrt(R(pi/2)) from the enclosure.
    bool ok = (f.quarter_R_scaled == 0) == degenerate;
    if (ok) ok = degenerate ? f.m_min == 0 : f.r_positive && f.r_below_R_half_pi;
    set_status(r, sweep_check::degeneracy, ok);
    if (!ok) add_note(r.note, "degeneracy: 4 a^2 R(pi/2) = " + to_decimal(f.quarter_R_scaled));
  }
  if (sweep_has_check(ck, sweep_check::structure)) {
    const bool ok = sweep_lobes_hold<int128>(p, f.m_min, f.lobes);
    set_status(r, sweep_check::structure, ok);
    if (!ok) add_note(r.note, "structure: the theorem's lobes do not check");
  }
  if (sweep_has_check(ck, sweep_check::asy_bound) && f.has_asy) {
    r.has_asy = f.asy_proved;
    set_status(r, sweep_check::asy_bound, f.asy_proved && f.asy_within_bound);
  }
}

void sweep_checks_from_proof(sweep_row_info& r, const resonant_pair<std::int64_t>& p, const sweep_proof& pr,
                             const sweep_config& cfg) {
  if (!pr.minimum) throw compute_error(p.str() + ": " + pr.note);
  const auto& M = *pr.minimum;
  if (!pr.note.empty()) add_note(r.note, pr.note);
  sweep_proved_facts f;
  f.quarter_R_scaled = pr.quarter_R_scaled;
  f.m_min = pr.m_min;
  f.lobes = pr.lobes;
  f.r_positive = mpfr_sgn(M.r_res.left()) > 0;
  f.r_below_R_half_pi = pr.r_below_R_half_pi;
  f.has_asy = pr.has_asy;
  f.asy_proved = pr.asy != nullptr;
  f.asy_within_bound = pr.asy && mpfr_cmp_ui(pr.asy->ratio.right(), 1) <= 0;
  sweep_checks_from_facts(r, p, f, cfg);
}

float128 sweep_float128_of(mpfr_srcptr v, mpfr_rnd_t rnd) {
  if (!mpfr_regular_p(v)) return float128(mpfr_get_d(v, rnd));  // 0, inf, NaN
  fixed_mpfr w(113);
  mpfr_set(w, v, rnd);
  mpz_t z;
  mpz_init(z);
  const mpfr_exp_t e = mpfr_get_z_2exp(z, w);  // w = z 2^e, |z| < 2^113
  const bool negative = mpz_sgn(z) < 0;
  unsigned long long limbs[2] = {0, 0};
  std::size_t count = 0;
  mpz_export(limbs, &count, -1, sizeof limbs[0], 0, 0, z);
  mpz_clear(z);
  const unsigned __int128 m = (static_cast<unsigned __int128>(limbs[1]) << 64) | limbs[0];
  float128 f = ldexp(float128(static_cast<__float128>(m)), int(e));  // exact: m has at most 113 bits
  return negative ? float128(-f) : f;
}

}  // namespace detail

}  // namespace gyrores
