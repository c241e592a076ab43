// include/gyrores/sweep/evaluate.hpp: one row, by the double path (theorem_minimum_double), the
// certified filter (filtered, sweep/filtered.hpp) or the enclosures (sweep/certified.hpp); its
// checks from the facts whichever path established them.
#include <gyrores/sweep/evaluate.hpp>

#include <gmp.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include <gyrores/core/error.hpp>
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/filtered.hpp>
#include <gyrores/sweep/testing.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/paper.hpp>

#include "row_parts.hpp"

namespace gyrores {

const char* sweep_status_text(sweep_status s) {
  return s == sweep_status::pass ? "pass" : s == sweep_status::fail ? "fail" : "";
}

namespace sweep_rows {

void add_note(std::string& note, const std::string& what) { note += std::string(note.empty() ? "" : "; ") + what; }

void fail_note(sweep_row_info& r, sweep_check c, const int128& quarter_R_scaled) {
  if (c == sweep_check::degeneracy) add_note(r.note, "degeneracy: 4 a^2 R(pi/2) = " + to_decimal(quarter_R_scaled));
  if (c == sweep_check::structure) add_note(r.note, "structure: the theorem's lobes do not check");
}

// For double, field by field (every field of sweep_row_info and sweep_row, as their
// initialisers), and the note keeps its buffer: a fresh row moved in costs as much as the checks
// of a pair (callgrind). Wider reals are replaced by new ones, exactly as a new row holds them.
template <class T> void row_reset(sweep_row<T>& r, const resonant_pair<std::int64_t>& p) {
  if constexpr (std::is_same_v<T, double>) {
    r.failed = false;
    r.note.clear();
    r.has_ratio = false;
    r.first_at_paper_node = -1;
    r.paper_lobe_min = -1;
    r.has_asy = false;
    r.minimiser_count = 0;
    r.status = {};
    r.r_res = r.theta_first = r.t_first = r.t_min_paper = r.t_ratio = 0;
    r.asy_error = r.asy_bound = r.asy_ratio = r.asy_constant = 0;
  } else {
    r = sweep_row<T>{};
  }
  r.tau = p.tau();
  r.sigma = p.sigma();
  r.delta_mod4 = p.delta_mod4();
  r.strand_offset = p.strand_offset_min();
}
template void row_reset<double>(sweep_row<double>&, const resonant_pair<std::int64_t>&);

namespace {

constexpr double pi = std::numbers::pi;

// ---- the enclosure path ----

// float128 nearest v in direction rnd (exact through 113-bit MPFR rounding and an integer).
float128 float128_of(mpfr_srcptr v, mpfr_rnd_t rnd) {
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

// v as a T of `bits` bits (mpfr_real: exactly that precision, not the process-wide default),
// rounded in direction rnd.
template <class T> T real_of(mpfr_srcptr v, unsigned bits, mpfr_rnd_t rnd) {
  if constexpr (std::is_same_v<T, double>) {
    return mpfr_get_d(v, rnd);
  } else if constexpr (std::is_same_v<T, long double>) {
    return mpfr_get_ld(v, rnd);
  } else if constexpr (std::is_same_v<T, float128>) {
    return float128_of(v, rnd);
  } else {
    static_assert(is_mpfr_v<T>, "sweep rows are double, long double, float128 or mpfr_real");
    fixed_mpfr w(static_cast<mpfr_prec_t>(bits));
    mpfr_set(w, v, rnd);
    return T(typename T::backend_type(static_cast<mpfr_srcptr>(w)));
  }
}
template <class T> T mid(const fixed_mpfi& X, unsigned bits) {
  fixed_mpfr m(mpfi_get_prec(X));
  mpfi_mid(m, X);
  return real_of<T>(m, bits, MPFR_RNDN);
}

// Every field of the row from sweep_prove_pair (compute_error if the minimum was not proved): the
// checks from its facts, the reals from its enclosures (the certified asy columns outward: the
// claims the summary makes from them).
template <class T> void proved_row(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  sweep_proof_options o;
  o.bits = sweep_bits<T>(cfg);
  o.asy = sweep_has_check(cfg.checks, sweep_check::asy_bound);
  o.outward_asy = cfg.certified;
  const sweep_proof pr = sweep_prove_pair(p, o);
  if (!pr.minimum) throw compute_error(p.str() + ": " + pr.note);
  const auto& M = *pr.minimum;
  if (!pr.note.empty()) add_note(r.note, pr.note);
  row_facts<int128> f;
  f.quarter_R_scaled = pr.quarter_R_scaled;
  f.m_min = pr.m_min;
  f.node = paper_fast_node(std::int64_t(p.order()), p.delta());
  f.lobes = pr.lobes;
  f.r_positive = mpfr_sgn(M.r_res.left()) > 0;
  f.r_below_R_half_pi = pr.r_below_R_half_pi;
  f.has_asy = pr.has_asy;
  f.asy_proved = pr.asy != nullptr;
  f.asy_within_bound = pr.asy && mpfr_cmp_ui(pr.asy->ratio.right(), 1) <= 0;
  checks_from_facts(r, p, f, cfg);
  const unsigned bits = o.bits;
  r.r_res = mid<T>(M.r_res, bits);
  r.theta_first = mid<T>(M.theta_first, bits);
  r.t_first = mid<T>(M.t_first, bits);
  r.t_min_paper = mid<T>(M.t_min_paper, bits);
  if (r.has_ratio) r.t_ratio = mid<T>(M.t_ratio, bits);
  if (!r.has_asy) return;
  const auto& E = *pr.asy;
  const bool out = cfg.certified;
  r.asy_error = out ? real_of<T>(E.error.right(), bits, MPFR_RNDU) : mid<T>(E.error, bits);
  r.asy_bound = out ? real_of<T>(E.bound.left(), bits, MPFR_RNDD) : mid<T>(E.bound, bits);
  r.asy_ratio = out ? real_of<T>(E.ratio.right(), bits, MPFR_RNDU) : mid<T>(E.ratio, bits);
  r.asy_constant = out ? real_of<T>(E.constant.right(), bits, MPFR_RNDU) : mid<T>(E.constant, bits);
}

// ---- the double path ----

// P3's r_res^2 <= R(pi/2) for a non-degenerate pair, given r_res within one ulp (theorem/minimum.hpp)
// and N = 4 a^2 R(pi/2): in double, r2 within 3 ulps and a rounding, R = N/(4 a^2) from N, a^2
// and the quotient each rounded once (4 a^2 is exact beyond a^2): both within 2^-49 relative of
// their exact values, far inside the band of 2^-40 around R. Inside the band the double
// comparison could be wrong, and the proved enclosure decides.
proof_status r_below_in_double(bool& below, const resonant_pair<std::int64_t>& p, double r_res, int128 N) {
  const double a = double(std::int64_t(p.order()));
  // N >= 0 (a sum of squares times 4 a^2); below 2^63 the int64 conversion is the cheap one.
  const double n = N < (int128(1) << 63) ? double(std::int64_t(N)) : double(N);
  const double R = n / (4 * (a * a)), r2 = r_res * r_res;
  below = r2 <= R * (1 - 0x1p-40);
  if (below || r2 > R * (1 + 0x1p-40)) return proof_status::proved();
  return proof_status::undecided("r_res^2 within 2^-40 of R(pi/2)");
}
void r_below_by_proof(bool& below, const resonant_pair<std::int64_t>& p, double, int128) {
  const sweep_proof pr = sweep_prove_pair(p);
  below = pr.minimum && pr.r_below_R_half_pi;
}
filter_counts r_below_counts("P3 r_res^2 <= R(pi/2) of double rows");
const filtered r_below_quarter_R{r_below_counts, r_below_in_double, r_below_by_proof};

// theorem_minimum_double and the checks in double and integers (uncertified rows, order < 2^31).
void double_row(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  const auto& ck = cfg.checks;
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const minimum_double M = theorem_minimum_double(p);
  r.r_res = M.r_res;
  r.theta_first = M.theta_first;
  r.t_first = M.t_first;
  r.t_min_paper = pi * std::sqrt(double(p.tau()) * double(p.sigma())) / double(b);
  if (M.m_min != 0) r.t_ratio = M.theta_first * double(b) / pi;
  row_facts<std::int64_t> f;
  f.quarter_R_scaled = sweep_quarter_R_scaled(a, b);
  f.m_min = M.m_min;
  f.node = paper_fast_node(a, b);
  f.lobes = std::span(M.lobes.data(), M.count);
  f.r_positive = M.r_res > 0;
  if (sweep_has_check(ck, sweep_check::degeneracy) && M.m_min != 0 && f.quarter_R_scaled != 0 && f.r_positive)
    r_below_quarter_R(true, f.r_below_R_half_pi, p, M.r_res, f.quarter_R_scaled);
  if (sweep_has_check(ck, sweep_check::asy_bound) && 2 * b < a) {
    const paper_error_double v = paper_error_of(a, b, paper_offset(a, b, f.node));
    r.asy_constant = v.constant;
    r.asy_error = v.error;
    r.asy_bound = v.bound;
    r.asy_ratio = v.ratio;
    f.has_asy = f.asy_proved = true;
    f.asy_within_bound = v.ratio <= 1;
  }
  checks_from_facts(r, p, f, cfg);
}

filter_counts certified_counts("certified filter");
const filtered certified_double_row{certified_counts, certified_filter_row, proved_row<double>};

template <class T> void evaluate_into(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  if constexpr (std::is_same_v<T, double>) {
    // int64 lobe arithmetic and double-double balls below order 2^31
    const bool small = p.order() < (int128(1) << 31);
    if (!cfg.certified && small) return double_row(r, p, cfg);
    if (cfg.certified) return certified_double_row(cfg.certified_filter, r, p, cfg);
  }
  proved_row(r, p, cfg);
}

}  // namespace
}  // namespace sweep_rows

template <class T> void sweep_evaluate_to(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  sweep_rows::row_reset(r, p);
  auto failed = [&](const char* what) {
    sweep_rows::row_reset(r, p);
    r.failed = true;
    r.note = what;
  };
  try {
    sweep_rows::evaluate_into(r, p, cfg);
  } catch (const std::runtime_error& e) {
    failed(e.what());
  } catch (const std::logic_error& e) {
    failed(e.what());
  }
}

GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_EVALUATE_INSTANCES, )

bool sweep_testing::r_below_quarter_R(const resonant_pair<std::int64_t>& p, double r_res, int128 N) {
  bool below = false;
  sweep_rows::r_below_quarter_R(true, below, p, r_res, N);
  return below;
}

}  // namespace gyrores
