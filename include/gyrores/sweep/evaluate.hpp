// One pair of a sweep: the exact quantities and the checks of the paper's claims.
//
// Per pair (sweep_evaluate<T>, amplitude v = 1; r_res is linear in v), from the lattice theorem
// (proofs/lattice-theorem.md) and nothing else:
//  - the exact quantities r_res, theta_first, t_first, the minimisers' count; the paper's proxy
//    t_min_paper = pi/|n| and t_first/t_min_paper (= theta_first b/pi):
//      double rows (uncertified, order < 2^31): theorem_minimum_double (theorem/minimum.hpp),
//      r_res, theta_first, t_first within one ulp, the paper's columns a few ulps;
//      every other row (long double, float128, mpfr_real, --certified, and double beyond order
//      2^31, where the int64 lobe arithmetic of theorem_minimum_double would overflow): the
//      exact values rounded to T, from proved enclosures of sweep_prove_pair (sweep/certified.hpp)
//      at the row's precision + 32 bits or more; certified double rows first try the
//      double-double filter (sweep/certified_filter.hpp), which prints the same values. Nothing in a row reads or writes Boost's process-wide
//      MPFR precision: an mpfr_real row value carries sweep_bits<mpfr_real>(cfg) bits of its own;
//  - the checks named in sweep_config::checks (each pass, fail, or not applicable):
//    degeneracy  (P3) R(pi/2) = 0 iff delta = 2 mod 4, with R(pi/2) the exact integer
//                4 a^2 R(pi/2) of the model at theta = pi/2 (sweep_quarter_R_scaled), not the
//                integer test delta mod 4 the library uses; and for non-degenerate pairs
//                0 < r_res <= sqrt(R(pi/2)) (degenerate: r_res = 0). Double rows compare
//                r_res^2 with R(pi/2) in double, and by the enclosures where the two are
//                within 2^-40 of each other (sweep_r_below_quarter_R).
//    paper-node  (P5, non-degenerate pairs) one of the global minimisers lies in the paper's lobe
//                alpha = a theta/2 in (k pi - pi/2, k pi + pi/2), k = round(a/(2b)) (either k on
//                a tie, b = 1): integers, the minimisers' lobes (theorem/lobes.hpp). The row also
//                says whether the *first* minimiser is there (first_at_paper_node).
//    asy-bound   (P7, pairs with x = b/a < 1/2) |theta_c - theta_asy| <= pi^3 x^2/a in the lobe
//                k = round(a/(2b)) (the smaller k on a tie; the other is its mirror image);
//                ratio = error/bound, constant = error a/x^2 (its sup over a sweep estimates the
//                sharp constant). Double rows: d = u_c - u_asy by Newton's method on an equation
//                without cancellation (src/lib/sweep/evaluate.cpp); other rows: the enclosures.
//    structure   (docs/mathematics.md §3) the theorem's integer claims, checked
//                (sweep_lobes_hold): 2 minimisers for delta odd, 4 for delta = 0 mod 4 (2 for
//                degenerate pairs: pi/2, 3 pi/2), each lobe's frame satisfies its equation with
//                |m| = m_min, and m_min = p.strand_offset_min() = min over N of |a - 4N|.
//  With cfg.certified (`gyrores sweep --certified`) every row takes the enclosure path and the
//  checks are decided by proofs (exact integers, MPFI): a pass is a proof. The asy columns then
//  hold proved upper bounds (asy_bound a lower bound); a check that could not be decided (a
//  resource limit) fails with "not proved" in the note.
//  A pair whose computation throws (compute_error, usage_error, domain_error), or whose minimum
//  was not proved within the precision limit, is an error row: counted and listed, never
//  silently dropped.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/certified_filter.hpp>
#include <gyrores/sweep/checks.hpp>
#include <gyrores/sweep/real_text.hpp>

namespace gyrores {

enum class sweep_status : unsigned char { none = 0, pass = 1, fail = 2 };
// "pass", "fail", or "" for none (the rows' check columns).
const char* sweep_status_text(sweep_status s);

// Everything of a row but its reals.
struct sweep_row_info {
  std::int64_t tau = 0, sigma = 0;
  int delta_mod4 = 0;
  int strand_offset = 0;         // p.strand_offset_min()
  bool failed = false;           // the computation threw: `note` holds the message
  std::string note;              // error message, or why a check failed
  bool has_ratio = false;        // non-degenerate: t_ratio = t_first/t_min_paper
  int first_at_paper_node = -1;  // -1: not applicable (degenerate), 0/1
  int paper_lobe_min = -1;       // a global minimiser in the paper's lobe: -1/0/1
  bool has_asy = false;          // asy-bound requested, x < 1/2, and its values computed
  int minimiser_count = 0;
  std::array<sweep_status, sweep_check_count> status{};
};

template <class T> struct sweep_row : sweep_row_info {
  T r_res{}, theta_first{}, t_first{}, t_min_paper{};
  T t_ratio{};
  T asy_error{}, asy_bound{}, asy_ratio{}, asy_constant{};
};

// The working precision of a sweep in T, in bits: the type's own, and for mpfr_real
// cfg.digits + 8 decimal digits (Boost's digits-to-bits rule, as the run descriptions of
// earlier versions named it).
template <class T> unsigned sweep_bits(const sweep_config& cfg) {
  if constexpr (is_mpfr_v<T>) return unsigned(boost::multiprecision::detail::digits10_2_2(cfg.digits + 8));
  else return unsigned(std::numeric_limits<T>::digits);
}
// The working type's name in run descriptions: "double", "long double", "float128",
// "mpfr(B bits)".
template <class T> std::string sweep_type_name(const sweep_config& cfg) {
  if constexpr (is_mpfr_v<T>) return "mpfr(" + std::to_string(sweep_bits<T>(cfg)) + " bits)";
  else return real_type_name<T>();
}

namespace detail {

// float128 nearest v in direction rnd (exact through 113-bit MPFR rounding and an integer).
float128 sweep_float128_of(mpfr_srcptr v, mpfr_rnd_t rnd);

// v as a T of `bits` bits (mpfr_real: exactly that precision, not the process-wide default),
// rounded in direction rnd.
template <class T> T sweep_real_of(mpfr_srcptr v, unsigned bits, mpfr_rnd_t rnd) {
  if constexpr (std::is_same_v<T, double>) {
    return mpfr_get_d(v, rnd);
  } else if constexpr (std::is_same_v<T, long double>) {
    return mpfr_get_ld(v, rnd);
  } else if constexpr (std::is_same_v<T, float128>) {
    return sweep_float128_of(v, rnd);
  } else {
    static_assert(is_mpfr_v<T>, "sweep rows are double, long double, float128 or mpfr_real");
    fixed_mpfr w(static_cast<mpfr_prec_t>(bits));
    mpfr_set(w, v, rnd);
    return T(typename T::backend_type(static_cast<mpfr_srcptr>(w)));
  }
}
template <class T> T sweep_mid(const fixed_mpfi& X, unsigned bits) {
  fixed_mpfr m(mpfi_get_prec(X));
  mpfi_mid(m, X);
  return sweep_real_of<T>(m, bits, MPFR_RNDN);
}

// The double path: theorem_minimum_double and its checks in double and integers.
// Precondition: !cfg.certified and sweep_double_path(p).
bool sweep_double_path(const resonant_pair<std::int64_t>& p);
// P3's r_res^2 <= R(pi/2) for a non-degenerate pair p, given r_res within one ulp and the exact
// N = 4 a^2 R(pi/2) (sweep_quarter_R_scaled): in double where the comparison is decided beyond
// its rounding error, else by the proved enclosure of sweep_prove_pair (false if not proved).
bool sweep_r_below_quarter_R(const resonant_pair<std::int64_t>& p, double r_res, int128 N);
void sweep_evaluate_double(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg);
// P7's columns in double for x = b/a < 1/2: the paper's lobe offset |m| = |a - 2 k b|, k =
// round(a/(2b)) (the smaller k on a tie), and the error, bound, ratio and constant from it
// (sweep_asy_difference, sweep/certified_filter.hpp), as the double rows hold them.
struct sweep_asy_double {
  double error = 0, bound = 0, ratio = 0, constant = 0;
};
std::int64_t sweep_asy_offset(std::int64_t a, std::int64_t b);
sweep_asy_double sweep_asy_double_of(std::int64_t a, std::int64_t b, std::int64_t am);

// The enclosure path: pr = sweep_prove_pair(p, sweep_proof_options_of(...)); every field but
// the reals from pr (compute_error if the minimum was not proved); then the reals.
sweep_proof_options sweep_proof_options_of(const resonant_pair<std::int64_t>& p, const sweep_config& cfg, unsigned bits);
// What the certified checks are decided from: exact integers and proved facts (from
// sweep_prove_pair's enclosures, or from the filter's balls).
struct sweep_proved_facts {
  int128 quarter_R_scaled = 0;  // 4 a^2 R(pi/2)
  int m_min = 0;
  std::span<const lobe_frame<int128>> lobes;  // the minimisers' lobes, theta order
  bool r_positive = false;         // r_res > 0
  bool r_below_R_half_pi = false;  // r_res^2 <= R(pi/2)
  bool has_asy = false;            // asked for and x < 1/2
  bool asy_proved = false;         // its enclosures formed
  bool asy_within_bound = false;   // error/bound <= 1
};
// Every field of the row but the reals, from f.
void sweep_checks_from_facts(sweep_row_info& r, const resonant_pair<std::int64_t>& p, const sweep_proved_facts& f,
                             const sweep_config& cfg);
void sweep_checks_from_proof(sweep_row_info& r, const resonant_pair<std::int64_t>& p, const sweep_proof& pr,
                             const sweep_config& cfg);
template <class T> void sweep_reals_from_proof(sweep_row<T>& r, const sweep_proof& pr, unsigned bits, bool certified) {
  const auto& M = *pr.minimum;
  r.r_res = sweep_mid<T>(M.r_res, bits);
  r.theta_first = sweep_mid<T>(M.theta_first, bits);
  r.t_first = sweep_mid<T>(M.t_first, bits);
  r.t_min_paper = sweep_mid<T>(M.t_min_paper, bits);
  if (r.has_ratio) r.t_ratio = sweep_mid<T>(M.t_ratio, bits);
  if (!r.has_asy) return;
  const auto& E = *pr.asy;
  if (certified) {  // proved bounds, outward: the claims the summary makes from them
    r.asy_error = sweep_real_of<T>(E.error.right(), bits, MPFR_RNDU);
    r.asy_bound = sweep_real_of<T>(E.bound.left(), bits, MPFR_RNDD);
    r.asy_ratio = sweep_real_of<T>(E.ratio.right(), bits, MPFR_RNDU);
    r.asy_constant = sweep_real_of<T>(E.constant.right(), bits, MPFR_RNDU);
  } else {
    r.asy_error = sweep_mid<T>(E.error, bits);
    r.asy_bound = sweep_mid<T>(E.bound, bits);
    r.asy_ratio = sweep_mid<T>(E.ratio, bits);
    r.asy_constant = sweep_mid<T>(E.constant, bits);
  }
}

template <class T> void sweep_evaluate_into(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  if constexpr (std::is_same_v<T, double>) {
    if (!cfg.certified && sweep_double_path(p)) {
      sweep_evaluate_double(r, p, cfg);
      return;
    }
  }
  if constexpr (std::is_same_v<T, double>) {
    if (cfg.certified && cfg.certified_filter && sweep_certified_filter(r, p, cfg))
      return;
  }
  const unsigned bits = sweep_bits<T>(cfg);
  const sweep_proof pr = sweep_prove_pair(p, sweep_proof_options_of(p, cfg, bits));
  sweep_checks_from_proof(r, p, pr, cfg);
  sweep_reals_from_proof(r, pr, bits, cfg.certified);
}

// A fresh row of p with its identity columns (filled for every row, error rows included), in
// place. For double the note keeps its buffer, so that a worker reusing one row allocates
// nothing per pair; wider reals are replaced by new ones, exactly as a new row would hold them.
template <class T> void sweep_row_reset(sweep_row<T>& r, const resonant_pair<std::int64_t>& p) {
  if constexpr (std::is_same_v<T, double>) {
    // Field by field (every field of sweep_row_info and sweep_row, as their initialisers): a
    // fresh row moved in costs as much as the checks of a pair (callgrind).
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

template <class T> void sweep_failed_row(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const char* what) {
  sweep_row_reset(r, p);
  r.failed = true;
  r.note = what;
}

}  // namespace detail

// Evaluate one pair into r (see the header comment), overwriting all of it: the same row as
// sweep_evaluate<T>(p, cfg), without a new row per pair (the engine's workers reuse one).
// Never throws for a computation that fails: the row is marked `failed` with the message in
// `note`.
template <class T> void sweep_evaluate_to(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  detail::sweep_row_reset(r, p);
  try {
    detail::sweep_evaluate_into(r, p, cfg);
  } catch (const std::runtime_error& e) {
    detail::sweep_failed_row(r, p, e.what());
  } catch (const std::logic_error& e) {
    detail::sweep_failed_row(r, p, e.what());
  }
}

template <class T> sweep_row<T> sweep_evaluate(const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  sweep_row<T> r;
  sweep_evaluate_to(r, p, cfg);
  return r;
}

// Compiled once in src/lib/sweep/instances.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_EVALUATE_INSTANCES(PREFIX, T)                                                  \
  PREFIX template void sweep_evaluate_to<T>(sweep_row<T>&, const resonant_pair<std::int64_t>&, const sweep_config&); \
  PREFIX template sweep_row<T> sweep_evaluate<T>(const resonant_pair<std::int64_t>&, const sweep_config&);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_EVALUATE_INSTANCES, extern)

}  // namespace gyrores
