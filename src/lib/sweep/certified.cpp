// include/gyrores/sweep/certified.hpp: the theorem's prove_minimum and prove_paper_error at an
// explicit precision (Boost's MPFR wrappers keep one process-wide precision: not used here).
#include <gyrores/sweep/certified.hpp>

#include <mpfi.h>

#include <bit>

#include <gyrores/core/refine.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>

#include "row_parts.hpp"

namespace gyrores {

namespace {

// Every point of X rounds to the same value at opt.bits in direction rnd (exactly zero counts):
// the row then prints the exact value's rounding, whichever enclosure proved it (the certified
// filter, src/lib/sweep/certified_filter.cpp, prints the same).
bool rounds_alike(const fixed_mpfi& X, const sweep_proof_options& opt, mpfr_rnd_t rnd) {
  fixed_mpfr lo(mpfr_prec_t(opt.bits)), hi(mpfr_prec_t(opt.bits));
  mpfr_set(lo, X.left(), rnd);
  mpfr_set(hi, X.right(), rnd);
  return mpfr_equal_p(lo, hi) != 0;
}

// The minimum at K's precision (header comment); false if a step is not proved or too wide.
bool prove_minimum_at(sweep_proof& pr, sweep_minimum_enclosure& M, const theorem_constants& K,
                      const resonant_pair<big_int>& p, const sweep_proof_options& opt) {
  minimum_enclosure E(K.prec);
  fixed_mpfi one(K.prec);
  mpfi_set_ui(one, 1);
  if (!prove_minimum(E, K, p, one)) return false;
  mpfi_set(M.r_res, E.r_res);
  mpfi_set(M.theta_first, *E.minimisers.front());
  mpfi_mul(M.t_first, M.theta_first, K.sqrt_ts);
  mpfi_mul(M.t_min_paper, K.pi, K.sqrt_ts);
  mpfi_div(M.t_min_paper, M.t_min_paper, K.b);
  mpfi_mul(M.t_ratio, M.theta_first, K.b);
  mpfi_div(M.t_ratio, M.t_ratio, K.pi);
  // The printed values (t_ratio only for non-degenerate pairs), to nearest.
  for (const fixed_mpfi* X : {&M.r_res, &M.theta_first, &M.t_first, &M.t_min_paper})
    if (!rounds_alike(*X, opt, MPFR_RNDN)) return false;
  if (pr.m_min != 0 && !rounds_alike(M.t_ratio, opt, MPFR_RNDN)) return false;
  // r_res^2 <= R(pi/2) = N/(4 a^2).
  fixed_mpfi R(K.prec), r2(K.prec);
  mpfi_set_z(R, to_big(pr.quarter_R_scaled).backend().data());
  mpfi_div(R, R, K.a);
  mpfi_div(R, R, K.a);
  mpfi_div_ui(R, R, 4);
  mpfi_sqr(r2, M.r_res);
  pr.r_below_R_half_pi = mpfr_cmp(r2.right(), R.left()) <= 0;
  return true;
}

// The paper's error at K's precision, printed to nearest (uncertified wide rows) or outward
// (certified rows: the bound downward); false if not proved or too wide.
bool prove_asy_at(paper_error_enclosure& E, const theorem_constants& K, std::int64_t a, std::int64_t b,
                  const sweep_proof_options& opt) {
  if (!prove_paper_error(E, K, paper_offset(a, b), int(opt.bits) + 8)) return false;
  const bool up = opt.outward_asy;
  return rounds_alike(E.error, opt, up ? MPFR_RNDU : MPFR_RNDN) &&
         rounds_alike(E.bound, opt, up ? MPFR_RNDD : MPFR_RNDN) &&
         rounds_alike(E.ratio, opt, up ? MPFR_RNDU : MPFR_RNDN) &&
         rounds_alike(E.constant, opt, up ? MPFR_RNDU : MPFR_RNDN);
}

}  // namespace

sweep_proof sweep_prove_pair(const resonant_pair<std::int64_t>& p, const sweep_proof_options& opt) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  sweep_proof pr;
  pr.quarter_R_scaled = sweep_quarter_R_scaled(a, b);
  pr.m_min = theorem_m_min(a);
  pr.lobes = minimiser_lobes(int128(a), int128(b)).to_vector();
  pr.has_asy = opt.asy && 2 * b < a;
  const resonant_pair<big_int> pb(big_int(p.tau()), big_int(p.sigma()), known_coprime);
  // One precision for both (at sweep orders the extra bits of the asy error cost no more limbs).
  const mpfr_prec_t start = mpfr_prec_t(opt.bits) + 32 +
                            (pr.has_asy ? 2 * mpfr_prec_t(std::bit_width(std::uint64_t(a))) + 8 : 0);
  const precision_plan plan{start, 8 * start};
  // The one precision loop, ended at its cap with what is proved (the rest named in the note: a
  // row's error or a failed check, not an exception).
  refine(plan, {}, "", [&](mpfr_prec_t prec, proof_status&) -> std::optional<bool> {
    theorem_constants K(prec);
    set_theorem_constants(K, pb);
    if (!pr.minimum) {
      auto M = std::make_unique<sweep_minimum_enclosure>(prec);
      if (prove_minimum_at(pr, *M, K, pb, opt)) pr.minimum = std::move(M);
    }
    if (pr.has_asy && !pr.asy) {
      auto E = std::make_unique<paper_error_enclosure>(prec);
      if (prove_asy_at(*E, K, a, b, opt)) pr.asy = std::move(E);
    }
    if ((pr.minimum && (pr.asy || !pr.has_asy)) || 2 * prec > plan.cap) return true;
    return std::nullopt;
  });
  const std::string limit = std::to_string(plan.cap) + " bits";
  if (!pr.minimum) sweep_rows::add_note(pr.note, "not proved: the bracket of u* was not decided within " + limit);
  if (pr.has_asy && !pr.asy) sweep_rows::add_note(pr.note, "not proved: the asy error was not enclosed within " + limit);
  return pr;
}

}  // namespace gyrores
