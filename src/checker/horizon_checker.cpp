// The independent checker of coupling certificates (horizon_checker.hpp). What it proves, in
// order (proofs/horizon-theorem.md, "What a certificate needs from it", items 1-6):
//   1. the coupling n^2 = P/Q > 0 and the horizon T > 0 (exact rationals); D = P (P + 4Q) and
//      x = sqrt(D)/(P + 4Q), exact in Q(sqrt D) (rational iff D is a square);
//   2. cut_lobe k_c: k_c < S T/(2 pi) + 1/2 < k_c + 1, S = sqrt(n^2 + 4), in Arb (never a tie);
//   3. the cut lobe's minimiser u*_{k_c} = side H^{-1}(pi nu_{k_c}) from the bracket cut_root,
//      and the decision cut_lobe_reached (k_c pi + u* <= alpha_T, strict in Arb); hence K_T;
//   4. the Diophantine claim, re-derived: nu* and the smallest argmin k_f over 0 <= k <= K_T by
//      this file's own MinFrac on both sides (x and 1 - x, Step 8), exact; the certificate's lobe
//      must be k_f with j = floor(k_f x) and the side of mu_{k_f} (none iff K_T = -1);
//   5. the bracket root of u0 = H^{-1}(pi nu*) (H(lo) < pi nu* < H(hi); nu* = 0: exactly 0);
//   6. at_horizon_end: forced false when the cut lobe is reached, else R(T) against
//      [G(lo), G(hi)] strictly (true: R(T) < G(lo); false: R(T) > G(hi));
//   7. the claims h_min (R/2) and t_min contain the checker's enclosures and have relative width
//      <= 10^-digits (h_min of an exact zero: exactly ["0", "0"]).
// Undecided balls are retried at twice the precision (4 times), then the certificate fails.
#include "horizon_checker.hpp"

#include "checker_support.hpp"
#include "exact_field.hpp"

#include <arb.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace gyrores_checker {

namespace {

using namespace support;
using namespace exact;

// ---- Reading.
Z integer_field(const json& j, const std::string& name) {
  if (!j.is_string()) throw malformed(name + " must be a decimal string");
  const std::string s = j.get<std::string>();
  if (s.size() > coupling_max_integer_digits || !all_digits(s, 0) || (s[0] == '0' && s.size() > 1))
    throw malformed(name + " is not a non-negative integer: '" + s.substr(0, 40) + "'");
  Z z;
  fmpz_set_str(z.v, s.c_str(), 10);
  return z;
}
// "p/q" or "p": a positive rational (p, q >= 1), reduced here.
void rational_field(const json& j, const std::string& name, Z& num, Z& den, bool allow_zero = false) {
  if (!j.is_string()) throw malformed(name + " must be a string \"p/q\"");
  const std::string s = j.get<std::string>();
  const auto slash = s.find('/');
  const std::string a = s.substr(0, slash), b = slash == std::string::npos ? "1" : s.substr(slash + 1);
  if (s.size() > coupling_max_rational_chars || !all_digits(a, 0) || !all_digits(b, 0) || (a[0] == '0' && a.size() > 1) || (b[0] == '0'))
    throw malformed(name + " is not a rational p/q: '" + s.substr(0, 40) + "'");
  fmpz_set_str(num.v, a.c_str(), 10);
  fmpz_set_str(den.v, b.c_str(), 10);
  if (fmpz_is_zero(num.v) && !allow_zero) throw fails(name + " must be > 0");
  Z g;
  fmpz_gcd(g.v, num.v, den.v);
  fmpz_divexact(num.v, num.v, g.v);
  fmpz_divexact(den.v, den.v, g.v);
}
// 10^-e <= num/den <= 10^e (num, den > 0), else malformed: the envelope of horizon_checker.hpp.
void within_powers(const Z& num, const Z& den, long e, const std::string& name) {
  Z p, a, b;
  fmpz_set_ui(p.v, 10);
  fmpz_pow_ui(p.v, p.v, ulong(e));
  fmpz_mul(a.v, den.v, p.v);  // num <= den 10^e
  fmpz_mul(b.v, num.v, p.v);  // den <= num 10^e
  if (fmpz_cmp(num.v, a.v) > 0 || fmpz_cmp(den.v, b.v) > 0)
    throw malformed(name + " lies outside [10^-" + std::to_string(e) + ", 10^" + std::to_string(e) + "], the limits this checker reads");
}
bool bool_field(const json& j, const std::string& name) {
  if (!j.is_boolean()) throw malformed(name + " must be true or false");
  return j.get<bool>();
}

struct lobe_data {
  Z k, j;
  long side = 0;
};
struct certificate {
  Z P, Q, Tn, Td, cut_lobe;
  long digits = 0;
  bool reached = false, at_end = false;
  bool has_lobe = false;
  lobe_data lobe;
  bracket cut_root, root, h_min, t_min;
  // The first time below a level (null when not stated): which case of horizon-theorem item 5.
  bool has_below = false;
  Z En, Ed;
  std::string below_case;
  bool below_has_lobe = false;
  lobe_data below_lobe;
  std::optional<bracket> level_root, delta, below_root, crossing, t_below;
};

std::optional<bracket> optional_bracket(const json& j, const std::string& name, std::size_t max_len) {
  if (j.is_null()) return std::nullopt;
  return bracket_field(j, name, max_len);
}
lobe_data lobe_field(const json& j, const std::string& name) {
  exact_keys(j, {"k", "j", "side"}, name);
  lobe_data l;
  l.k = integer_field(j["k"], name + ".k");
  l.j = integer_field(j["j"], name + ".j");
  l.side = integer_in(j["side"], name + ".side", -1, 1);
  return l;
}

certificate read(const std::string& text) {
  json j = parse_without_duplicate_keys(text);
  exact_keys(j, {"format", "theorem", "n2", "horizon", "digits", "minimum", "below"}, "the certificate");
  if (j["format"] != coupling_certificate_format) throw malformed(std::string("format is not ") + coupling_certificate_format);
  if (j["theorem"] != "horizon-theorem/1") throw fails("theorem is not horizon-theorem/1 (the one this checker knows)");
  certificate c;
  c.digits = integer_in(j["digits"], "digits", 1, 10000);
  rational_field(j["n2"], "n2", c.P, c.Q);
  rational_field(j["horizon"], "horizon", c.Tn, c.Td);
  within_powers(c.P, c.Q, coupling_n2_exponent, "n2");
  within_powers(c.Tn, c.Td, coupling_horizon_exponent, "horizon");
  const json& m = j["minimum"];
  exact_keys(m, {"cut_lobe", "cut_lobe_reached", "cut_root", "lobe", "root", "at_horizon_end", "h_min", "t_min"},
             "minimum");
  const std::size_t max_len = std::size_t(c.digits) + 80;
  c.cut_lobe = integer_field(m["cut_lobe"], "cut_lobe");
  c.reached = bool_field(m["cut_lobe_reached"], "cut_lobe_reached");
  c.at_end = bool_field(m["at_horizon_end"], "at_horizon_end");
  c.cut_root = bracket_field(m["cut_root"], "cut_root", max_len);
  c.has_lobe = !m["lobe"].is_null();
  if (c.has_lobe != !m["root"].is_null()) throw malformed("lobe and root must both be null or both be given");
  if (c.has_lobe) {
    c.lobe = lobe_field(m["lobe"], "lobe");
    c.root = bracket_field(m["root"], "root", max_len);
  }
  c.h_min = bracket_field(m["h_min"], "h_min", max_len);
  c.t_min = bracket_field(m["t_min"], "t_min", max_len);
  const json& b = j["below"];
  c.has_below = !b.is_null();
  if (c.has_below) {
    exact_keys(b, {"level", "case", "lobe", "level_root", "delta", "root", "crossing", "t_below"}, "below");
    rational_field(b["level"], "below.level", c.En, c.Ed, true);
    if (!fmpz_is_zero(c.En.v)) {  // E = 0, or 10^-e <= E (any E >= 1/2 is the case start)
      Z p, a;
      fmpz_set_ui(p.v, 10);
      fmpz_pow_ui(p.v, p.v, ulong(coupling_level_exponent));
      fmpz_mul(a.v, c.En.v, p.v);
      if (fmpz_cmp(c.Ed.v, a.v) > 0)
        throw malformed("below.level lies below 10^-" + std::to_string(coupling_level_exponent) + ", the limit this checker reads");
    }
    if (!b["case"].is_string()) throw malformed("below.case must be a string");
    c.below_case = b["case"].get<std::string>();
    if (c.below_case != "start" && c.below_case != "lobe" && c.below_case != "never" && c.below_case != "zero")
      throw malformed("below.case must be start, lobe, zero or never");
    c.below_has_lobe = !b["lobe"].is_null();
    if (c.below_has_lobe) c.below_lobe = lobe_field(b["lobe"], "below.lobe");
    // The fields each case uses (docs/formats.md); any other must be null, never an unread claim.
    const std::string& k = c.below_case;
    const bool lobe0 = k == "lobe" && c.below_has_lobe && fmpz_is_zero(c.below_lobe.k.v);
    std::set<std::string> used{"level", "case"};
    if (k != "never") used.insert("t_below");
    if (k == "zero" || k == "lobe") used.insert("lobe");
    if (k == "lobe") used.insert({"root", "crossing"});
    if ((k == "lobe" && !lobe0) || (k == "never" && !fmpz_is_zero(c.En.v))) used.insert({"level_root", "delta"});
    for (auto it = b.begin(); it != b.end(); ++it)
      if (!used.count(it.key()) && !it.value().is_null())
        throw malformed("below." + it.key() + " must be null: case " + k + (lobe0 ? " (lobe 0)" : "") + " does not use it");
    c.level_root = optional_bracket(b["level_root"], "below.level_root", max_len);
    c.delta = optional_bracket(b["delta"], "below.delta", max_len);
    c.below_root = optional_bracket(b["root"], "below.root", max_len);
    c.crossing = optional_bracket(b["crossing"], "below.crossing", max_len);
    c.t_below = optional_bracket(b["t_below"], "below.t_below", max_len);
  }
  return c;
}

// ---- The exact lobe data: x, j_k = floor(k x), nu_k = |1/2 + j_k - k x|, the minimiser's side.
struct rotation {
  field F;
  QD x;
};
rotation rotation_of(const certificate& c) {
  rotation R;
  Z r0, D, s;
  fmpz_mul_ui(r0.v, c.Q.v, 4);
  fmpz_add(r0.v, r0.v, c.P.v);
  fmpz_mul(D.v, c.P.v, r0.v);
  fmpz_sqrt(s.v, D.v);
  Z s2;
  fmpz_mul(s2.v, s.v, s.v);
  if (fmpz_equal(s2.v, D.v)) R.x.p = s;  // resonant: x rational (D stays 0)
  else {
    R.F.D = D;
    fmpz_one(R.x.q.v);
  }
  R.x.r = r0;
  normalise(R.x);
  return R;
}
struct lobe_exact {
  Z j;
  QD nu;
  long side = 0;
};
lobe_exact lobe_of(const rotation& R, const Z& k) {
  lobe_exact l;
  const QD kx = mul(R.F, integer(k), R.x);
  l.j = floor_of(R.F, kx);
  const QD mu = sub(add(integer(l.j), rational(1, 2)), kx);  // mu_k/pi in (-1/2, 1/2]
  const int s = sign(R.F, mu);
  l.nu = s < 0 ? neg(mu) : mu;
  l.side = s;
  // nu = 1/2 in a lobe k >= 1 (k x an integer): the first minimiser is -H^{-1}(pi/2) (Step 3).
  if (fmpz_sgn(k.v) > 0 && cmp(R.F, mu, rational(1, 2)) == 0) l.side = -1;
  return l;
}

// ---- Balls.
long bits_of(const Z& z) { return long(fmpz_bits(z.v)); }
B ball_of_q2(const field& F, const QD& a, long prec) { return exact::ball_of(F, a, prec); }
// The exact value of a decimal (as read by decimal_field), for the comparisons balls cannot make
// (two equal decimals, a decimal against the rational T).
using Qx = Q;
void exact_of(const std::string& s, Qx& out, const std::string& name) {
  if (!decimal_exact(s, 100000, out.v)) throw malformed(name + ": exponent out of range");
}
// lo <= hi exactly, or the bracket is refused naming its field.
void exact_order(const bracket& b, const std::string& name, bool strict) {
  Qx lo, hi;
  exact_of(b.lo, lo, name);
  exact_of(b.hi, hi, name);
  const int c = fmpq_cmp(lo.v, hi.v);
  if (c > 0 || (strict && c == 0)) throw fails(name + " must have lo " + (strict ? "<" : "<=") + " hi");
}

B ratio(const Z& n, const Z& d, long prec) {
  B a;
  arb_set_fmpz(a.v, n.v);
  arb_div_fmpz(a.v, a.v, d.v, prec);
  return a;
}

struct constants {
  long prec;
  B x, x2, one_m_x2, s, pi, alpha_T;
};
constants constants_of(const certificate& c, const rotation& R, long prec) {
  constants K;
  K.prec = prec;
  K.x = ball_of_q2(R.F, R.x, prec);
  Z r0;
  fmpz_mul_ui(r0.v, c.Q.v, 4);
  fmpz_add(r0.v, r0.v, c.P.v);
  K.x2 = ratio(c.P, r0, prec);  // x^2 = P/(P + 4Q)
  Z q4;
  fmpz_mul_ui(q4.v, c.Q.v, 4);
  K.one_m_x2 = ratio(q4, r0, prec);  // 1 - x^2 = 4Q/(P + 4Q)
  K.s = ratio(r0, c.Q, prec);        // n^2 + 4 = (P + 4Q)/Q
  arb_sqrt(K.s.v, K.s.v, prec);
  arb_const_pi(K.pi.v, prec);
  K.alpha_T = ratio(c.Tn, c.Td, prec);
  arb_mul(K.alpha_T.v, K.alpha_T.v, K.s.v, prec);
  arb_mul_2exp_si(K.alpha_T.v, K.alpha_T.v, -1);
  return K;
}
B H(const constants& K, const B& u) { return lobe_H(K.x, u, K.prec); }
B G(const constants& K, const B& u) { return lobe_G(K.x2, K.one_m_x2, u, K.prec); }
// R = (1 - x^2) sin^2 alpha cos^2 beta + (cos alpha cos beta - x sin alpha sin beta)^2, beta = x alpha.
B R_at(const constants& K, const B& alpha) {
  B b, sa, ca, sb, cb, q, qd, t;
  arb_mul(b.v, K.x.v, alpha.v, K.prec);
  arb_sin_cos(sa.v, ca.v, alpha.v, K.prec);
  arb_sin_cos(sb.v, cb.v, b.v, K.prec);
  arb_mul(q.v, sa.v, cb.v, K.prec);
  arb_sqr(q.v, q.v, K.prec);
  arb_mul(q.v, q.v, K.one_m_x2.v, K.prec);
  arb_mul(qd.v, ca.v, cb.v, K.prec);
  arb_mul(t.v, sa.v, sb.v, K.prec);
  arb_mul(t.v, t.v, K.x.v, K.prec);
  arb_sub(qd.v, qd.v, t.v, K.prec);
  arb_sqr(qd.v, qd.v, K.prec);
  arb_add(q.v, q.v, qd.v, K.prec);
  return q;
}

// A bracket of u0 = H^{-1}(pi nu) in [0, pi/2): 1 proved, 0 undecided; fails names the field.
int check_root(const constants& K, const rotation& R, const QD& nu, const bracket& br, const std::string& name, B& lo,
               B& hi) {
  lo = ball_of(br.lo, K.prec);
  hi = ball_of(br.hi, K.prec);
  if (sign(R.F, nu) != 0) exact_order(br, name, true);
  if (sign(R.F, nu) == 0) {
    if (!arb_is_zero(lo.v) || !arb_is_zero(hi.v)) throw fails(name + " must be [\"0\", \"0\"]: nu = 0, so u0 = 0");
    return 1;
  }
  B half_pi, target;
  arb_mul_2exp_si(half_pi.v, K.pi.v, -1);
  if (arb_is_negative(lo.v) || arb_ge(lo.v, hi.v) || arb_ge(hi.v, half_pi.v))
    throw fails(name + " must satisfy 0 <= lo < hi < pi/2");
  if (!arb_is_nonnegative(lo.v) || !arb_lt(lo.v, hi.v) || !arb_lt(hi.v, half_pi.v)) return 0;
  target = ball_of_q2(R.F, nu, K.prec);
  arb_mul(target.v, target.v, K.pi.v, K.prec);
  const B hlo = H(K, lo), hhi = H(K, hi);
  if (arb_ge(hlo.v, target.v) || arb_le(hhi.v, target.v))
    throw fails(name + " does not bracket H^{-1}(pi nu) (H(lo) < pi nu < H(hi) is false)");
  return arb_lt(hlo.v, target.v) && arb_lt(target.v, hhi.v) ? 1 : 0;
}

// k pi + side [lo, hi]: the minimiser's alpha, as one ball.
B alpha_of(const constants& K, const Z& k, long side, const B& lo, const B& hi) {
  B u, a;
  arb_union(u.v, lo.v, hi.v, K.prec);
  arb_mul_si(u.v, u.v, side, K.prec);
  arb_mul_fmpz(a.v, K.pi.v, k.v, K.prec);
  arb_add(a.v, a.v, u.v, K.prec);
  return a;
}

// A claim [lo, hi] with lo <= hi exactly holds the enclosure and is at most 10^-digits wide.
int check_claim(const bracket& claim, const B& enclosure, long digits, bool exact_zero, const std::string& name,
                long prec) {
  exact_order(claim, name, false);
  return claim_holds(claim, enclosure, digits, exact_zero ? " must be exactly [\"0\", \"0\"]" : nullptr, name, prec);
}

// t_min = T at the horizon's end: lo <= T <= hi and the width, exactly (T is rational).
int check_exact_claim(const bracket& claim, const Z& num, const Z& den, long digits, const std::string& name) {
  exact_order(claim, name, false);
  Qx lo, hi, t, w, p;
  exact_of(claim.lo, lo, name);
  exact_of(claim.hi, hi, name);
  fmpq_set_fmpz_frac(t.v, num.v, den.v);
  if (fmpq_cmp(lo.v, t.v) > 0 || fmpq_cmp(t.v, hi.v) > 0) throw fails(name + " does not contain the value");
  if (fmpq_sgn(lo.v) <= 0) throw fails(name + ": a positive quantity needs a positive lower end");
  Z ten;
  fmpz_set_ui(ten.v, 10);
  fmpz_pow_ui(ten.v, ten.v, ulong(digits));
  fmpq_sub(w.v, hi.v, lo.v);
  fmpq_mul_fmpz(w.v, w.v, ten.v);
  if (fmpq_cmp(w.v, lo.v) > 0) throw fails(name + " is wider than " + std::to_string(digits) + " digits");
  return 1;
}

// The exact facts that do not depend on the precision: K_T needs the cut lobe's decision, so
// this runs inside check_at; everything here is exact.
struct exact_facts {
  lobe_exact cut;
  bool has_winner = false;
  minimum winner;  // nu* and k_f
  lobe_exact winner_lobe;
};

// Step 4: nu* and the smallest argmin over 0 <= k <= K_T, both sides (Step 8).
minimum best_lobe(const rotation& R, const Z& K_T) {
  const QD half = rational(1, 2);
  minimum a = min_frac(R.F, R.x, half, K_T);
  minimum b = min_frac(R.F, sub(rational(1, 1), R.x), half, K_T);
  const int c = cmp(R.F, a.value, b.value);
  if (c < 0 || (c == 0 && fmpz_cmp(a.k.v, b.k.v) <= 0)) return a;
  return b;
}

// Steps 2-7 at one precision: 1 all proved, 0 something undecided.
int check_at(const certificate& c, const rotation& R, const exact_facts& X, const Z& K_T_if_reached,
             const Z& K_T_if_not, long prec, exact_facts& out) {
  const constants K = constants_of(c, R, prec);
  // Step 2: k_c < alpha_T/pi + 1/2 < k_c + 1.
  B v, kc, kc1;
  arb_div(v.v, K.alpha_T.v, K.pi.v, prec);
  B half;
  arb_set_d(half.v, 0.5);
  arb_add(v.v, v.v, half.v, prec);
  arb_set_fmpz(kc.v, c.cut_lobe.v);
  arb_add_ui(kc1.v, kc.v, 1, prec);
  if (arb_le(v.v, kc.v) || arb_ge(v.v, kc1.v)) throw fails("cut_lobe is not the lobe holding t = T");
  if (!arb_gt(v.v, kc.v) || !arb_lt(v.v, kc1.v)) return 0;
  // Step 3: the cut lobe's minimiser against alpha_T.
  B clo, chi;
  if (!check_root(K, R, X.cut.nu, c.cut_root, "cut_root", clo, chi)) return 0;
  const B cut_alpha = alpha_of(K, c.cut_lobe, X.cut.side, clo, chi);
  bool reached;
  if (arb_le(cut_alpha.v, K.alpha_T.v)) reached = true;
  else if (arb_gt(cut_alpha.v, K.alpha_T.v)) reached = false;
  else return 0;
  if (reached != c.reached) throw fails(std::string("cut_lobe_reached must be ") + (reached ? "true" : "false"));
  // Step 4: the winning lobe (exact; the same for every precision).
  const Z& K_T = reached ? K_T_if_reached : K_T_if_not;
  out = X;
  out.has_winner = fmpz_sgn(K_T.v) >= 0;
  if (!out.has_winner) {
    if (c.has_lobe) throw fails("lobe must be null: no lobe's minimiser lies in [0, T] (K_T = -1)");
    if (!c.at_end) throw fails("at_horizon_end must be true: no lobe's minimiser lies in [0, T]");
    const B r = R_at(K, K.alpha_T);
    B h;
    arb_mul_2exp_si(h.v, r.v, -1);
    return check_claim(c.h_min, h, c.digits, false, "h_min", prec) &&
           check_exact_claim(c.t_min, c.Tn, c.Td, c.digits, "t_min");
  }
  out.winner = best_lobe(R, K_T);
  out.winner_lobe = lobe_of(R, out.winner.k);
  if (!c.has_lobe) throw fails("lobe is missing: lobe " + text_of(out.winner.k) + " holds the minimum over admissible lobes");
  if (!fmpz_equal(c.lobe.k.v, out.winner.k.v))
    throw fails("lobe.k is " + text_of(c.lobe.k) + ", but the first lobe with the smallest ||k x - 1/2|| over 0 <= k <= " +
                text_of(K_T) + " is " + text_of(out.winner.k));
  if (!fmpz_equal(c.lobe.j.v, out.winner_lobe.j.v)) throw fails("lobe.j is not floor(k x)");
  if (c.lobe.side != out.winner_lobe.side) throw fails("lobe.side is not the side of the lobe's first minimiser");
  // Step 5: the root bracket of the winning lobe.
  B lo, hi;
  if (!check_root(K, R, out.winner.value, c.root, "root", lo, hi)) return 0;
  const bool zero = sign(R.F, out.winner.value) == 0;
  B g;
  arb_union(g.v, G(K, lo).v, G(K, hi).v, prec);  // G increases on [0, pi/2) (lattice-theorem.md Step C)
  // Step 6: the end point.
  bool at_end = false;
  if (!reached) {
    const B r = R_at(K, K.alpha_T);
    if (arb_lt(r.v, g.v)) at_end = true;
    else if (!arb_gt(r.v, g.v)) return 0;
    if (at_end) {
      if (!c.at_end) throw fails("at_horizon_end must be true: R(T) is below the best lobe's minimum");
      B h;
      arb_mul_2exp_si(h.v, r.v, -1);
      return check_claim(c.h_min, h, c.digits, false, "h_min", prec) &&
             check_exact_claim(c.t_min, c.Tn, c.Td, c.digits, "t_min");
    }
  }
  if (c.at_end) throw fails("at_horizon_end must be false: the best lobe's minimum is below R(T)");
  // Step 7: h_min = G(u0)/2, t_min = 2 (k pi + side u0)/S.
  B h, t;
  arb_mul_2exp_si(h.v, g.v, -1);
  t = alpha_of(K, out.winner.k, out.winner_lobe.side, lo, hi);
  arb_mul_2exp_si(t.v, t.v, 1);
  arb_div(t.v, t.v, K.s.v, prec);
  return check_claim(c.h_min, h, c.digits, zero, "h_min", prec) &&
         check_claim(c.t_min, t, c.digits, false, "t_min", prec);
}

// ---- The first time below a level E (horizon-theorem item 5; "What a certificate needs", First
// time below a level): the case from the level, the lobe by this file's FirstHit, the crossing.
int cmp_decimal(const std::string& a, const std::string& b, const std::string& name) {
  Qx x, y;
  exact_of(a, x, name);
  exact_of(b, y, name);
  return fmpq_cmp(x.v, y.v);
}
QD qd_of(const std::string& decimal, const std::string& name) {
  Qx q;
  exact_of(decimal, q, name);
  QD a;
  fmpz_set(a.p.v, fmpq_numref(q.v));
  fmpz_set(a.r.v, fmpq_denref(q.v));
  return a;
}
template <class T> const T& need(const std::optional<T>& v, const std::string& name) {
  if (!v) throw fails(name + " is needed in this case");
  return *v;
}
// t = 2 (k pi + [c_lo, c_hi])/S, with R(k pi + c_lo) > 2E > R(k pi + c_hi).
int check_crossing(const certificate& c, const constants& K, const B& level, const Z& k, B& t) {
  const bracket& cr = need(c.crossing, "below.crossing");
  if (cmp_decimal(cr.lo, cr.hi, "below.crossing") >= 0) throw fails("below.crossing must have lo < hi");
  B lo = ball_of(cr.lo, K.prec), hi = ball_of(cr.hi, K.prec), a, b;
  arb_mul_fmpz(a.v, K.pi.v, k.v, K.prec);
  arb_add(b.v, a.v, hi.v, K.prec);
  arb_add(a.v, a.v, lo.v, K.prec);
  const B ra = R_at(K, a), rb = R_at(K, b);
  if (arb_le(ra.v, level.v) || arb_ge(rb.v, level.v)) throw fails("below.crossing does not bracket R = 2E (R(lo) > 2E > R(hi) is false)");
  if (!arb_gt(ra.v, level.v) || !arb_lt(rb.v, level.v)) return 0;
  arb_union(t.v, a.v, b.v, K.prec);
  arb_mul_2exp_si(t.v, t.v, 1);
  arb_div(t.v, t.v, K.s.v, K.prec);
  return 1;
}
void check_lobe_integers(const rotation& R, const lobe_data& l, const Z& k, const std::string& name) {
  if (!fmpz_equal(l.k.v, k.v)) throw fails(name + ".k is " + text_of(l.k) + ", but the first lobe reaching the level is " + text_of(k));
  const lobe_exact e = lobe_of(R, k);
  if (!fmpz_equal(l.j.v, e.j.v)) throw fails(name + ".j is not floor(k x)");
  if (l.side != (fmpz_is_zero(k.v) ? 1 : e.side)) throw fails(name + ".side is not the side of the lobe's first minimiser");
}

int check_below(const certificate& c, const rotation& R, long prec) {
  const constants K = constants_of(c, R, prec);
  const field& F = R.F;
  Z twoE;
  fmpz_mul_ui(twoE.v, c.En.v, 2);
  B level = ratio(twoE, c.Ed, prec);
  const std::string& kase = c.below_case;
  const bool lobe_case = kase == "lobe" || kase == "zero";
  if (lobe_case != c.below_has_lobe)
    throw fails("below.lobe must be given exactly in the cases lobe and zero (below.case is " + kase + ")");
  if (fmpz_cmp(twoE.v, c.Ed.v) >= 0) {  // 2E >= 1 = R(0)
    if (kase != "start") throw fails("below.case must be start: H_q(0) = 1/2 <= E");
    return check_claim(need(c.t_below, "below.t_below"), B(), c.digits, true, "below.t_below", prec);
  }
  if (kase == "start") throw fails("below.case start needs E >= 1/2");
  B t;
  if (fmpz_is_zero(c.En.v)) {  // R = 0 exactly: a lobe with nu = 0, at its centre (degenerate pairs only)
    std::optional<Z> hit;
    if (fmpz_is_zero(F.D.v)) hit = first_lobe_at_most(F, R.x, QD(), R.x.r);  // period: the denominator of x
    if (!hit) {
      if (kase != "never") throw fails("below.case must be never: no lobe has nu = 0");
      return 1;
    }
    if (kase != "zero") throw fails("below.case must be zero: lobe " + text_of(*hit) + " reaches H_q = 0");
    check_lobe_integers(R, c.below_lobe, *hit, "below.lobe");
    arb_mul_fmpz(t.v, K.pi.v, hit->v, prec);
    arb_mul_2exp_si(t.v, t.v, 1);
    arb_div(t.v, t.v, K.s.v, prec);
    return check_claim(need(c.t_below, "below.t_below"), t, c.digits, false, "below.t_below", prec);
  }
  if (kase == "zero") throw fails("below.case zero needs E = 0");
  if (kase == "lobe" && fmpz_is_zero(c.below_lobe.k.v)) {
    // Lobe 0: 2E >= V(1/2) = G(u0) with u0 = H^{-1}(pi/2); the branch [0, u0].
    B lo, hi;
    if (!check_root(K, R, rational(1, 2), need(c.below_root, "below.root"), "below.root", lo, hi)) return 0;
    const B g = G(K, hi);
    if (arb_ge(g.v, level.v)) throw fails("below.lobe.k = 0 needs 2E > V(1/2) (G(root hi) < 2E is false)");
    if (!arb_lt(g.v, level.v)) return 0;
    check_lobe_integers(R, c.below_lobe, Z(0), "below.lobe");
    const bracket& cr = need(c.crossing, "below.crossing");
    if (cmp_decimal(cr.lo, "0", "below.crossing") < 0 || cmp_decimal(cr.hi, c.below_root->lo, "below.crossing") > 0)
      throw fails("below.crossing must lie in lobe 0's descending branch [0, u0]");
    if (!check_crossing(c, K, level, Z(0), t)) return 0;
    return check_claim(need(c.t_below, "below.t_below"), t, c.digits, false, "below.t_below", prec);
  }
  // 0 < 2E < V(1/2): delta = H(G^{-1}(2E))/pi in (d_lo, d_hi), d_hi < 1/2.
  if (kase == "lobe" && (!c.level_root || !c.delta))
    throw fails("below.lobe.k = " + text_of(c.below_lobe.k) + " (not 0) needs below.level_root and below.delta");
  const bracket& lr = need(c.level_root, "below.level_root");
  const bracket& d = need(c.delta, "below.delta");
  if (cmp_decimal(lr.lo, "0", "below.level_root") < 0 || cmp_decimal(lr.lo, lr.hi, "below.level_root") >= 0)
    throw fails("below.level_root must have 0 <= lo < hi");
  if (cmp_decimal(d.lo, "0", "below.delta") < 0 || cmp_decimal(d.lo, d.hi, "below.delta") >= 0 ||
      cmp_decimal(d.hi, "0.5", "below.delta") >= 0)
    throw fails("below.delta must have 0 <= lo < hi < 1/2");
  B glo = ball_of(lr.lo, prec), ghi = ball_of(lr.hi, prec), half_pi, Gl, Gh, Hl, Hh, dl, dh;
  arb_mul_2exp_si(half_pi.v, K.pi.v, -1);
  if (arb_ge(ghi.v, half_pi.v)) throw fails("below.level_root must lie below pi/2");
  if (!arb_lt(ghi.v, half_pi.v)) return 0;
  Gl = G(K, glo);
  Gh = G(K, ghi);
  if (arb_ge(Gl.v, level.v) || arb_le(Gh.v, level.v)) throw fails("below.level_root does not bracket G^{-1}(2E)");
  if (!arb_lt(Gl.v, level.v) || !arb_gt(Gh.v, level.v)) return 0;
  Hl = H(K, glo);
  Hh = H(K, ghi);
  arb_mul(dl.v, ball_of(d.lo, prec).v, K.pi.v, prec);
  arb_mul(dh.v, ball_of(d.hi, prec).v, K.pi.v, prec);
  if (arb_gt(dl.v, Hl.v) || arb_lt(dh.v, Hh.v)) throw fails("below.delta does not bracket H(G^{-1}(2E))/pi");
  if (!arb_lt(dl.v, Hl.v) || !arb_gt(dh.v, Hh.v)) return 0;
  // The first lobe with nu_k <= d_hi: every earlier lobe misses (nu_k > d_hi > delta).
  Z bound;
  if (kase == "never") {
    if (!fmpz_is_zero(F.D.v)) throw fails("below.case never needs a resonant coupling (x rational) when E > 0");
    bound = R.x.r;  // nu_{k + a} = nu_k
  } else bound = c.below_lobe.k;
  const auto hit = first_lobe_at_most(F, R.x, qd_of(d.hi, "below.delta"), bound);
  if (kase == "never") {
    if (hit) throw fails("below.case is never, but lobe " + text_of(*hit) + " has nu_k <= delta");
    return 1;
  }
  if (!hit) throw fails("below.lobe.k: no lobe k <= " + text_of(bound) + " has nu_k <= below.delta[1]");
  check_lobe_integers(R, c.below_lobe, *hit, "below.lobe");
  const lobe_exact e = lobe_of(R, *hit);
  B lo, hi;
  if (!check_root(K, R, e.nu, need(c.below_root, "below.root"), "below.root", lo, hi)) return 0;
  // The hit itself: nu_k <= d_lo exactly, or V(nu_k) <= G(root hi) < 2E.
  if (cmp(F, e.nu, qd_of(d.lo, "below.delta")) > 0) {
    const B g = G(K, hi);
    if (arb_ge(g.v, level.v)) throw fails("below.lobe: its minimum is not proved <= E");
    if (!arb_lt(g.v, level.v)) return 0;
  }
  // The descending branch [max(u_g, -pi/2), u*]: c_lo >= -pi/2 and H(c_lo) > mu - pi/2; c_hi <= u*.
  const bracket& cr = need(c.crossing, "below.crossing");
  B clo = ball_of(cr.lo, prec), mu = ball_of_q2(F, sub(add(integer(e.j), rational(1, 2)), mul(F, integer(*hit), R.x)), prec);
  arb_mul(mu.v, mu.v, K.pi.v, prec);
  arb_sub(mu.v, mu.v, half_pi.v, prec);
  B neg_half_pi;
  arb_neg(neg_half_pi.v, half_pi.v);
  const B hc = H(K, clo);
  if (arb_lt(clo.v, neg_half_pi.v) || arb_le(hc.v, mu.v)) throw fails("below.crossing starts before the lobe's descending branch");
  if (!arb_ge(clo.v, neg_half_pi.v) || !arb_gt(hc.v, mu.v)) return 0;
  const int end = e.side > 0 ? cmp_decimal(cr.hi, c.below_root->lo, "below.crossing")
                  : e.side < 0 ? (cmp_decimal(cr.hi, "-" + c.below_root->hi, "below.crossing"))
                               : cmp_decimal(cr.hi, "0", "below.crossing");
  if (end > 0) throw fails("below.crossing ends after the lobe's minimiser");
  if (!check_crossing(c, K, level, *hit, t)) return 0;
  return check_claim(need(c.t_below, "below.t_below"), t, c.digits, false, "below.t_below", prec);
}

}  // namespace

verdict check_coupling_certificate(const std::string& json_text) {
  return verdict_of<verdict>([&]() -> verdict {
    const certificate c = read(json_text);
    const rotation R = rotation_of(c);
    exact_facts X;
    X.cut = lobe_of(R, c.cut_lobe);
    if (fmpz_is_zero(c.cut_lobe.v)) X.cut.side = 1;  // lobe 0: only u >= 0 is in [0, T]
    Z K_reached = c.cut_lobe, K_not;
    fmpz_sub_ui(K_not.v, c.cut_lobe.v, 1);
    std::size_t longest = 0;
    for (const auto* b : {&c.cut_root, &c.root, &c.h_min, &c.t_min}) longest = std::max({longest, b->lo.size(), b->hi.size()});
    for (const auto& b : {c.level_root, c.delta, c.below_root, c.crossing, c.t_below})
      if (b) longest = std::max({longest, b->lo.size(), b->hi.size()});
    long prec = long(3.33 * double(longest)) + 2 * bits_of(c.cut_lobe) + bits_of(c.Tn) + bits_of(c.Td) +
                bits_of(c.P) + bits_of(c.Q) + 64;
    if (c.has_below) prec += 2 * bits_of(c.below_lobe.k) + bits_of(c.En) + bits_of(c.Ed);
    exact_facts out;
    return first_decided<verdict>(prec, [&](long p) {
      if (!check_at(c, R, X, K_reached, K_not, p, out) || (c.has_below && !check_below(c, R, p))) return std::string();
      return "certificate holds (horizon-theorem/1): min H_q over [0, T] " +
             (c.at_end ? "at t = T" : "in lobe " + text_of(c.lobe.k)) +
             (c.has_below ? "; first time below E: " + c.below_case + (c.below_case == "lobe" ? " " + text_of(c.below_lobe.k) : "")
                          : "") +
             "; every claim to " + std::to_string(c.digits) + " digits";
    });
  });
}

}  // namespace gyrores_checker
