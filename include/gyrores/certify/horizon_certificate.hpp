// Certificates of a coupling's minimum of H_q over [0, T] ("gyrores-coupling-certificate/1";
// proofs/horizon-theorem.md, id horizon-theorem/1; docs/formats.md): for any coupling n^2 = P/Q.
//
// What it states (qdot0 = 1, so H_q = R/2):
//   n2, horizon       the coupling and T, exact rationals;
//   cut_lobe          k_c, the lobe holding t = T;
//   cut_root          decimals lo < hi with H(lo) < pi nu_{k_c} < H(hi): the cut lobe's minimiser
//                     u* = side H^{-1}(pi nu_{k_c}), and cut_lobe_reached (k_c pi + u* <= alpha_T);
//   lobe, root        the first lobe k_f with the smallest ||k x - 1/2|| over the admissible lobes
//                     0..K_T (k, j = floor(k x), side) and the bracket of H^{-1}(pi nu*); null when
//                     no lobe is admissible (K_T = -1);
//   at_horizon_end    the minimum is R(T) at t = T (strictly below the lobe's value);
//   h_min, t_min      decimal brackets of relative width <= 10^-digits.
// A certificate is written from a proof of theorem/horizon.hpp, the very proof a report rounded
// (report/horizon_report.hpp), never from a second computation: the proof's decisions and
// integers, its roots' brackets (proved there together with their decimals to
// certificate_digits(digits) digits) and its enclosures rounded outward to digits + 3 digits.
// Nothing is computed here but the decimal text and floor(k x). The independent checker
// (src/checker/horizon_checker.hpp) re-derives the lobe with its own continued-fraction
// recursion and re-proves every bracket.
#pragma once
#include <optional>
#include <string>
#include <utility>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/theorem/horizon.hpp>

namespace gyrores {

inline constexpr const char* coupling_certificate_format = "gyrores-coupling-certificate/1";

using decimal_bracket = std::pair<std::string, std::string>;

struct certificate_lobe {
  big_int k, j;  // the lobe and floor(k x)
  int side = 1;  // the first minimiser is at u = side H^{-1}(pi nu) in the lobe
  decimal_bracket root;
};

// The first time H_q <= E (horizon-theorem item 5), in one of four cases:
//   start  2E >= 1: t = 0;
//   zero   E = 0 reached at the centre of `lobe` (nu = 0, a degenerate pair), t = 2 k pi/S;
//   never  E = 0 and no lobe has nu = 0, or a resonant coupling none of whose lobes reaches E
//          (level_root, delta as below; the checker's FirstHit over one period finds none);
//   lobe   the first lobe k* reaching E: for k* >= 1, level_root brackets G^{-1}(2E) and delta
//          brackets delta = H(G^{-1}(2E))/pi (< 1/2), and k* is the first k with nu_k <= delta_hi;
//          for k* = 0 the lobe's root shows 2E > V(1/2). crossing brackets the u of R = 2E on the
//          lobe's descending branch, and t_below = 2 (k* pi + u)/S.
struct below_certificate {
  big_rational level;
  std::string kase;                      // "start", "zero", "never", "lobe"
  std::optional<certificate_lobe> lobe;  // in the cases zero and lobe (its root used in case lobe)
  std::optional<decimal_bracket> level_root, delta, crossing, t_below;
};

struct horizon_certificate {
  std::string format = coupling_certificate_format;
  std::string theorem;
  big_rational n2, horizon;
  unsigned digits = 0;
  big_int cut_lobe;
  bool cut_lobe_reached = false, at_horizon_end = false;
  decimal_bracket cut_root;
  std::optional<certificate_lobe> lobe;  // none iff no lobe's minimiser lies in [0, T]
  decimal_bracket h_min, t_min;
  std::optional<below_certificate> below;  // the first time below a level, when asked
};

// usage_error unless T is a rational > 0: the formats state the horizon as a rational (a
// multiple of pi, which a report accepts, is refused here, before any work); `what` names the
// certificate in the message.
void check_certificate_horizon(const horizon_time& T, const char* what = "a coupling certificate");

// The certificate of a proof of min H_q over [0, T] (made with at least `digits` digits), with
// `digits` correct digits in each claim. usage_error as check_certificate_horizon; compute_error
// if a claim is wider than 10^-digits (the proof was made with fewer digits).
horizon_certificate horizon_certificate_of(const coupling_spec& c, const horizon_minimum_proof& proof, unsigned digits);

// The certificate of a proof of the first time below E >= 0, likewise.
below_certificate below_certificate_of(const coupling_spec& c, const first_below_proof& proof, unsigned digits);

// Proves and certifies in one call (a proof made for the certificate alone).
horizon_certificate certify_horizon_minimum(const coupling_spec& c, const big_rational& horizon, unsigned digits);

}  // namespace gyrores
