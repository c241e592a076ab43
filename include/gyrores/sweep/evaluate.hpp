// One pair of a sweep: its row, the exact quantities and the checks of the paper's claims, from
// the lattice theorem (proofs/lattice-theorem.md) and nothing else (amplitude v = 1). Which
// kernel gives a row's reals and how close they are: docs/formats.md, "Sweep rows" (double rows:
// theorem_minimum_double; wider and certified rows: the enclosures of sweep_prove_pair,
// sweep/certified.hpp, a certified double row first through the double-double balls,
// sweep/filtered.hpp). No row reads or writes Boost's process-wide MPFR precision: an mpfr_real
// value carries sweep_bits<mpfr_real>(cfg) bits of its own. The checks (each pass, fail, or n/a):
//    degeneracy  (P3) R(pi/2) = 0 iff delta = 2 mod 4, with R(pi/2) the exact integer
//                4 a^2 R(pi/2) of the model at theta = pi/2 (sweep_quarter_R_scaled), not the
//                integer test delta mod 4 the library uses; and for non-degenerate pairs
//                0 < r_res <= sqrt(R(pi/2)) (degenerate: r_res = 0). Double rows compare
//                r_res^2 with R(pi/2) in double, and by the enclosures where the two are
//                within 2^-40 of each other (a filtered predicate, sweep/filtered.hpp).
//    paper-node  (P5, non-degenerate pairs) one of the global minimisers lies in the paper's lobe
//                alpha = a theta/2 in (k pi - pi/2, k pi + pi/2), k = round(a/(2b)) (either k on
//                a tie, b = 1): integers, the minimisers' lobes (theorem/lobes.hpp).
//    asy-bound   (P7, pairs with x = b/a < 1/2) |theta_c - theta_asy| <= pi^3 x^2/a in the lobe
//                k = round(a/(2b)) (the smaller k on a tie; the other is its mirror image);
//                ratio = error/bound, constant = error a/x^2. Double rows: d = u_c - u_asy by
//                Newton's method on an equation without cancellation; other rows: the
//                enclosures (both theorem/paper.hpp).
//    structure   (docs/mathematics.md §3) the theorem's integer claims (sweep_lobes_hold).
// With cfg.certified every check is decided by proofs (exact integers, MPFI): a pass is a proof,
// and one that could not be decided (a resource limit) fails with "not proved" in the note. A
// pair whose computation throws, or whose minimum was not proved within the precision limit, is
// an error row: counted and listed, never silently dropped.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <string>

#include <gyrores/core/real.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/sweep/checks.hpp>

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

// The working precision of a sweep in T, in bits: the type's own; mpfr_real: cfg.digits + 8
// decimal digits (Boost's digits-to-bits rule, as earlier run descriptions named it).
template <class T> unsigned sweep_bits(const sweep_config& cfg) {
  if constexpr (is_mpfr_v<T>) return unsigned(boost::multiprecision::detail::digits10_2_2(cfg.digits + 8));
  else return unsigned(std::numeric_limits<T>::digits);
}
// The working type's name in run descriptions ("double", ..., "mpfr(B bits)").
template <class T> std::string sweep_type_name(const sweep_config& cfg) {
  if constexpr (is_mpfr_v<T>) return "mpfr(" + std::to_string(sweep_bits<T>(cfg)) + " bits)";
  else return real_type_name<T>();
}

// Pair p's row into r, all of it overwritten (the engine's workers reuse one row). Never throws
// for a computation that fails: the row is marked `failed` with the message in `note`.
template <class T> void sweep_evaluate_to(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg);

template <class T> sweep_row<T> sweep_evaluate(const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  sweep_row<T> r;
  sweep_evaluate_to(r, p, cfg);
  return r;
}

// Compiled once in src/lib/sweep/evaluate.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_EVALUATE_INSTANCES(PREFIX, T)                                                  \
  PREFIX template void sweep_evaluate_to<T>(sweep_row<T>&, const resonant_pair<std::int64_t>&, const sweep_config&); \
  PREFIX template sweep_row<T> sweep_evaluate<T>(const resonant_pair<std::int64_t>&, const sweep_config&);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_EVALUATE_INSTANCES, extern)

}  // namespace gyrores
