// The horizon theorem (proofs/horizon-theorem.md, id "horizon-theorem/1"): for ANY coupling n,
// the minimum of H_q over [0, T] and the first time H_q falls to a level, proved, in O(log T).
//
// The lattice theorem's lobe argument never uses that x = n/sqrt(n^2 + 4) is rational. Lobe k
// (alpha = sqrt(n^2 + 4) t/2 in [k pi - pi/2, k pi + pi/2]) has offset |mu_k| = pi ||k x - 1/2||
// and minimum R = G(H^{-1}(|mu_k|)), increasing in ||k x - 1/2||. So the minimum over [0, T] is
// decided by integers: the lobe k <= k_c - 1 with the smallest ||k x - 1/2|| (model/rotation.hpp,
// exact), against the lobe k_c cut by T (its minimiser inside [0, T] or not) and the end point
// R(T). The first time below a level is the first lobe whose minimum reaches it, then one
// crossing on that lobe's descending branch. Only the final roots are real numbers: the lobe
// roots by the one solver of H(u) = mu (theorem/root.hpp), G(u) = 2E and the crossing by the
// proved root in Arb (src/lib/core/ball_root.hpp); the rest in Arb balls (impulse qdot0 = 1:
// H_q = R/2).
//
// What the proofs return is the proof itself: the integers and the enclosures (never text). A
// proof for a certificate (proof_use::certificate) proves every root's bracket together with its
// outward roundings to certificate_digits(D) digits, and takes its decisions and values on the
// brackets that hold those decimals (what the checker will read), so a certificate states the
// very proof a report rounded (certify/); when the decimals cannot decide something (a root
// within 10^-D of pi/2, delta as close to a lobe's ||k x - 1/2||: tiny couplings) it fails at
// once with compute_error, as no precision would help. The precision starts from the digits D
// asked and doubles (core/refine.hpp) until the proof holds and `accept` holds of it (a report's
// roundings decided, a double decided), up to tie_bits_cap: only a tie (the end point R(T) equal
// to a lobe's minimum, a level equal to one) needs more, and a tie is never decided.
#pragma once
#include <optional>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/quadratic.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/status.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>

namespace gyrores {

inline constexpr const char* horizon_theorem_id = "horizon-theorem/1";

// The digits to which a certificate's proof proves its brackets' decimal ends: the certificate's
// digits D plus 15 (docs/formats.md).
constexpr unsigned certificate_digits(unsigned digits) { return digits + 15; }

// What a proof is for: a report (the tightest enclosures), or a certificate too (above).
enum class proof_use { report, certificate };

// Which lobe (the integers a certificate carries).
struct horizon_lobe {
  big_int k;                 // the lobe
  quadratic_number nu;       // ||k x - 1/2||, exactly
  int side = 1;              // the minimiser is at u = side * H^{-1}(pi nu) in the lobe (-1, 0, +1)
};

// A proved bracket: exact binary ends lo < hi (a root's: on either side of it); decimals = D when
// their outward roundings to D digits are proved too (0 where such a decimal would leave the
// root's domain, e.g. a lobe root within 10^-D of pi/2 for a tiny coupling).
struct proved_bracket {
  enclosure ends;
  unsigned decimals = 0;
};

// A lobe and its root u0 = H^{-1}(pi nu) in [0, pi/2), proved: H(lo) < pi nu < H(hi) at the
// bracket's ends, and `u` holds the bracket (with its decimals); exactly 0 for nu = 0.
struct lobe_root {
  horizon_lobe lobe;
  proved_bracket bracket;
  enclosure u;
};

// min of H_q over [0, T].
struct horizon_minimum_proof {
  horizon_time horizon;          // T
  quadratic_number x;            // n/sqrt(n^2 + 4), exactly
  big_int cut_lobe;              // k_c = floor(sqrt(n^2 + 4) T/(2 pi) + 1/2): the lobe holding t = T
  bool cut_lobe_reached = false; // k_c's minimiser lies in [0, T]
  bool at_horizon_end = false;   // the minimum is R(T), at t = T (H_q still decreasing there)
  lobe_root cut;                 // the cut lobe's root: decides cut_lobe_reached
  std::optional<lobe_root> best; // the admissible lobe (0..K_T) with the smallest nu, the first on a
                                 // tie: the minimum unless at_horizon_end; none iff K_T = -1
  enclosure h_min, t_min;        // min of H_q over [0, T] and the first time it is attained
  enclosure r_min;               // the radius sqrt(2 h_min) = sqrt(q^2 + q'^2) there
  mpfr_prec_t bits = 0;          // the precision that proved it
};

// usage_error for T < 0 or digits outside [1, report_digits_max]; compute_error when not decided
// within tie_bits_cap; interrupted when `stop` is set.
horizon_minimum_proof prove_horizon_minimum(const coupling_spec& c, const horizon_time& horizon,
                                            const refine_goal<horizon_minimum_proof>& goal,
                                            proof_use use = proof_use::report, stop_token stop = {});

// The first time H_q <= E (horizon-theorem item 5), in one of four cases.
enum class below_case {
  start,  // 2E >= 1: t = 0
  zero,   // E = 0, reached at the centre of `lobe` (nu = 0: a degenerate pair)
  never,  // E = 0 and no lobe has nu = 0, or a resonant coupling none of whose lobes reaches E
  lobe    // the first lobe k* whose minimum reaches E, crossed once on its descending branch
};

struct first_below_proof {
  big_rational level;                   // E (an energy; qdot0 = 1, so the initial H_q is 1/2)
  below_case kase = below_case::start;
  bool resonant = false;                // x rational (why never)
  std::optional<lobe_root> lobe;        // cases zero and lobe
  // 2E < G(pi/2): u_E = G^{-1}(2E) and delta = H(u_E)/pi (cases lobe with k* >= 1, and never);
  // for a certificate, delta's decimals are "proved": the lobe was decided for every value within
  // a unit of their last digit (so the checker, reading them, finds the same lobe).
  std::optional<proved_bracket> level_root, delta;
  std::optional<proved_bracket> crossing; // the crossing's u in lobe k* (case lobe)
  enclosure t_below;                    // the first t with H_q(t) <= E (not for never)
  mpfr_prec_t bits = 0;
};

// The first time H_q <= E (E >= 0). Never only for a resonant coupling whose H_min exceeds E,
// or E = 0 for a coupling with no exact zero. Throws as prove_horizon_minimum.
first_below_proof prove_first_below(const coupling_spec& c, const big_rational& level,
                                    const refine_goal<first_below_proof>& goal, proof_use use = proof_use::report,
                                    stop_token stop = {});

// Lobe k's root H^{-1}(pi nu_k) alone, proved as for a certificate (any k >= 0; usage_error for
// k < 0): the certificate entry of any lobe (certify/horizon_certificate.hpp).
lobe_root certified_lobe_root(const coupling_spec& c, const big_int& k, unsigned digits);

}  // namespace gyrores
