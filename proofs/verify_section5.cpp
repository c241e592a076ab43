// verify_section5: the paper's Section V (docs/mathematics.md §2, P8) with exact values.
//
// 1. Every number printed in Section V (and the pair named in Fig. 1) is recomputed from the
//    paper's own definitions as an MPFI enclosure (or exact integers) and compared with the
//    printed text: a printed decimal with d digits after the point is RIGHT if the exact value
//    lies within half a unit of its last digit, WRONG if it certainly lies outside
//    (decide_less on the enclosure), undecided otherwise. Claims "p8.*" are reported (the paper's
//    text), so a wrong number does not fail the run; the program asserts that every item is
//    decided.
// 2. Case A (absorption, delta = 2 mod 4, beat condition (tau + sigma)/(tau - sigma) >= 10): for
//    delta = 2 and 6 the admissible pairs in increasing sigma, each with its exact first-zero time
//    t_first = sqrt(tau sigma) pi/2 (certify_by_theorem: integer argument) beside the paper's proxy
//    T_min = pi/|n|; the best pair is the smallest admissible sigma (t_first increases with sigma).
//    Then, for every delta = 2 mod 4 with some admissible pair of order <= --caseA-order (default
//    max(--max-order, 100)), the best
//    pair and its t_first; asserted: (11, 9) is the fastest of all (t_first >= (pi/4) sqrt(99) delta
//    for every admissible pair, proofs/README.md P8), and the best t_first increases with delta over the
//    range (reported).
// 3. Case B (containment): asserted for every beat pair (a >= 10 b) of order <= --max-order: its
//    certified r_res is below that of (6, 5). For orders a >= 62 this follows from
//    r_res <= pi m_min/(2a) <= pi/a < r_res(6, 5) (proofs/README.md P8), so --max-order 61 completes the proof
//    that (6, 5) is the best containment pair under the beat condition.
#include <numeric>

#include <gyrores/certify/theorem_certificate.hpp>

#include "lobe_roots.hpp"
#include "verify_common.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using namespace gyrores::proofs;

namespace {

I enclosure(const std::pair<std::string, std::string>& c) { return interval_from_decimal(c.first, c.second); }

// The certified first-zero (or first-minimum) time of a pair, at `digits` digits.
I t_first_of(std::int64_t tau, std::int64_t sigma, unsigned digits) {
  return enclosure(certify_by_theorem(resonant_pair<big_int>(tau, sigma), digits).t_first);
}

// Point Newton steps at the working precision (the double guesses carry 53 bits only; interval
// Newton then starts from a point accurate to the working precision).
template <class F, class DF> P polish(P u, F f, DF df) {
  for (int it = 0; it < 12; ++it) {
    I U = interval_point(u);
    u = interval_mid_point(I(U - f(U) / df(U)));
  }
  return u;
}

bool beat(std::int64_t t, std::int64_t s) { return t + s >= 10 * (t - s); }

// The run with its claims, pi at the working precision (192 bits), and the two kinds of
// decided item.
struct section5 {
  run& R;
  claim &print, &decided, &caseA, &monotone, &caseB;
  I pi = real_pi<I>();  // constructed within the working precision's scope (verify)

  I n_of(std::int64_t t, std::int64_t s) const { return I(t - s) / sqrt(I(t) * I(s)); }

  // A printed number: RIGHT iff |v - printed| <= half a unit of its last printed digit.
  void item(const std::string& id, const std::string& what, const std::string& printed, const I& v,
            const std::string& half_unit) {
    I pr = interval_from_decimal(printed, printed), h = interval_from_decimal(half_unit, half_unit);
    I dev = interval_abs(v - pr);
    verdict d = verdict::undecided;
    if (interval_upper(dev) <= interval_lower(h)) d = verdict::proved;
    else if (interval_lower(dev) > interval_upper(h)) d = verdict::refuted;
    print.add(d, id, what);
    decided.add(d == verdict::undecided ? verdict::undecided : verdict::proved, id);
    R.log(id + " | " + what + " | printed " + printed + " | exact " + enc(v, 10) + " | " +
          (d == verdict::proved ? "RIGHT" : d == verdict::refuted ? "WRONG" : "undecided"));
  }

  // A printed statement decided by exact integers.
  void fact(const std::string& id, const std::string& what, bool right, const std::string& exact) {
    print.add(decide_bool(right), id, what);
    decided.add(verdict::proved, id);
    R.log(id + " | " + what + " | " + exact + " | " + (right ? "RIGHT" : "WRONG"));
  }
};

section5 add_claims(run& R) {
  return {R,
          R.add_claim("P8.printed", "each printed Section V number agrees with the exact value to its printed digits", false),
          R.add_claim("P8.decided", "every printed number is decided (right or wrong)", true),
          R.add_claim("P8.caseA.best", "(11, 9) has the smallest first-zero time of all beat pairs with delta = 2 mod 4", true),
          R.add_claim("P8.caseA.monotone", "the best first-zero time increases with delta (delta = 2 mod 4, over the range)",
                      false),
          R.add_claim("P8.caseB.best",
                      "r_res(tau, sigma) < r_res(6, 5) for every other beat pair: certified for orders <= max-order; "
                      "for orders >= 62 by r_res <= pi m_min/(2a) <= pi/a (README P8)",
                      true)};
}

// Fig. 1 and Case A, delta = 2: (11, 9), its n and T_min (proxy and exact).
void printed_case_a_delta2(section5& S) {
  // Fig. 1: n = 1/sqrt(12) is the pair (4, 3): n^2 = 1/12 = (4-3)^2/(4*3).
  S.fact("fig1.pair", "n = 1/sqrt(12) is the resonant pair (4, 3)", (4 - 3) * (4 - 3) * 12 == 4 * 3, "n^2 = 1/12 exactly");
  std::int64_t s = 1;
  while (!(beat(s + 2, s) && std::gcd(s + 2, s) == 1)) ++s;
  S.fact("A.delta2.bound", "delta = 2: beat gives tau >= 11, sigma >= 9", s + 2 == 11 && s == 9 && !beat(10, 8),
         "smallest tau with (2 tau - 2) >= 20: 11");
  S.fact("A.delta2.pair", "(11, 9) is coprime and the smallest admissible delta = 2 pair", s == 9 && std::gcd(11, 9) == 1,
         "(11, 9)");
  I n = S.n_of(11, 9);
  S.item("A.n", "n for (11, 9) = 2/sqrt(99)", "0.201", n, "0.0005");
  S.item("A.Tmin.proxy", "T_min ~ pi/n for (11, 9) (the proxy)", "15.6", S.pi / n, "0.05");
  S.item("A.Tmin.exact", "exact first zero t_first = sqrt(99) pi/2 of (11, 9) (= pi/n since delta = 2)", "15.6",
         t_first_of(11, 9, 30), "0.05");
}

// Case A, delta = 6: the paper's (41, 35) and the right pair (35, 29).
void printed_case_a_delta6(section5& S) {
  std::int64_t s = 1;
  while (!beat(s + 6, s)) ++s;
  S.fact("A.delta6.bound", "delta = 6: beat gives tau >= 33", s + 6 == 33, "smallest tau with 2 tau - 6 >= 60: 33");
  while (std::gcd(s + 6, s) != 1) ++s;
  S.fact("A.delta6.pair", "the smallest admissible coprime delta = 6 pair is (41, 35)", s + 6 == 41,
         "it is (" + std::to_string(s + 6) + ", " + std::to_string(s) + "): (33, 27) has gcd 3, (35, 29) is coprime");
  S.item("A.Tmin41.proxy", "T_min ~ pi/n for (41, 35) (the proxy the paper prints)", "19.8", S.pi / S.n_of(41, 35), "0.05");
  I t41 = t_first_of(41, 35, 30);
  S.item("A.Tmin41.exact", "exact first zero of (41, 35): sqrt(1435) pi/2 = 3 pi/n", "19.8", t41, "0.05");
  I t35 = t_first_of(35, 29, 30);
  S.R.log("A.delta6.correct | (35, 29): proxy pi/n " + enc(S.pi / S.n_of(35, 29), 10) + ", exact first zero " +
          enc(t35, 10) + " = sqrt(1015) pi/2");
  I t119 = t_first_of(11, 9, 30);
  S.fact("A.delta6.worse", "delta = 6 is slower than (11, 9) (true also with exact times)",
         certainly_less(t119, t35) && certainly_less(t119, t41), "t_first(35, 29) = " + enc(t35, 6) + " > t_first(11, 9)");
}

// Case B, (6, 5): the paper's lobe k = 6 (a/(2b) = 5.5 is a tie; m = 11 - 12 = -1, s = -pi/2),
// its u_asy, theta_asy, q'(theta_asy) and error, and the certified r_res and t_first.
void printed_case_b(section5& S) {
  S.fact("B.bound", "delta = 1: beat gives tau >= 5.5, so (6, 5)", beat(6, 5) && !beat(5, 4), "(6, 5)");
  const I pi = S.pi;
  I n = S.n_of(6, 5);
  S.item("B.n", "n for (6, 5) = 1/sqrt(30)", "0.183", n, "0.0005");
  S.item("B.Tmin.proxy", "T_min ~ pi/n for (6, 5) (the proxy)", "17.2", pi / n, "0.05");
  auto c = certify_by_theorem(resonant_pair<big_int>(6, 5), 30);
  S.item("B.Tmin.exact", "exact first-minimum time t_first of (6, 5) (mirror lobe k = 5)", "17.2", enclosure(c.t_first), "0.05");
  const big_int m = -1;
  auto K = proof::constants_of(resonant_pair<big_int>(6, 5));
  paper_lobe L = paper_lobe_of(K, m);
  auto guess = double_guesses(11, 1, -1);
  P ga = polish(P(guess.u_asy), [&](const I& u) { return I(u + tan(u) - L.s); },
                [&](const I& u) { return I(2 + interval_sqr(tan(u))); });
  P gc = polish(P(guess.u_c), [&](const I& u) { return proof::f_of(K, L.mu, u); },
                [&](const I& u) { return proof::df_of(K, L.mu, u); });
  auto Ua = certify_u_plus_tan(L.s, ga);
  auto Uc = proof::certify_root(K, L.mu, gc, abs(gc));
  if (!Ua || !Uc) throw compute_error("interval Newton failed for (6, 5)");
  S.item("B.u_asy", "u_asy, root of u + tan u = s = -pi/2 (lobe k = 6)", "-0.17", *Ua, "0.005");
  S.item("B.theta_asy", "theta_asy = pi/b + (2/a)(u_asy - s)", "3.30", pi / 1 + 2 * (*Ua - L.s) / 11, "0.005");
  // q'(theta_asy) for qdot0 = 1: frame (6, 0), sign (-1)^(6+0) = +1, q' = f(u_asy).
  I qd = proof::f_of(K, L.mu, *Ua);
  S.item("B.qdot", "q'(theta_asy) (qdot0 = 1)", "2.43e-4", qd, "0.005e-4");
  S.item("B.qdot.over.rho0", "|q'(theta_asy)|/rho0, rho0 = sqrt(30)/11 (what the paper printed)", "2.43e-4",
         interval_abs(qd) / K.c.rho0, "0.005e-4");
  S.item("B.err", "|theta_c - theta_asy|, theta_c the q' root of lobe k = 6", "1.16e-4", 2 * interval_abs(*Uc - *Ua) / 11,
         "0.005e-4");
  S.item("B.bound", "pi^3 x^2/a = pi^3/1331", "2.33e-2", pi * pi * pi / (121 * 11), "0.005e-2");
  S.item("B.r_min", "r_res of (6, 5) (certified, qdot0 = 1)", "5.075e-2", enclosure(c.r_res), "0.0005e-2");
  S.R.log("B.theta_c | theta_c = 2 (6 pi + u_c)/11 = " + enc(2 * (6 * pi + *Uc) / 11, 12) + ", theta_first = " +
          enc(enclosure(c.theta_first), 12) + " = 2 pi - theta_c (mirror lobe k = 5)");
}

// Case A design: the first admissible pairs for delta = 2 and 6, proxy beside exact time.
void case_a_table(section5& S) {
  S.R.log("## 2. Case A: admissible pairs (delta = 2 mod 4, a >= 10 b, coprime): pair | proxy pi/n | exact t_first = "
          "sqrt(tau sigma) pi/2");
  for (std::int64_t delta : {2, 6}) {
    int shown = 0;
    for (std::int64_t s = 1; shown < 4; ++s) {
      std::int64_t t = s + delta;
      if (!beat(t, s) || std::gcd(t, s) != 1) continue;
      S.R.log("A.delta" + std::to_string(delta) + " | (" + std::to_string(t) + ", " + std::to_string(s) + ") | " +
              enc(S.pi / S.n_of(t, s), 8) + " | " + enc(t_first_of(t, s, 20), 8) + (shown == 0 ? "  <- best" : ""));
      ++shown;
    }
  }
}

// The smallest admissible sigma for this delta (sigma odd: delta = 2 mod 4), if any of order
// <= max_order.
std::optional<std::int64_t> best_sigma(std::int64_t delta, std::int64_t max_order) {
  for (std::int64_t s = 1; 2 * s + delta <= max_order; s += 2)
    if (beat(s + delta, s) && std::gcd(s + delta, s) == 1) return s;
  return std::nullopt;
}

// Best pair per delta = 2 mod 4 with an admissible pair of order <= caseA_order.
void case_a_best_per_delta(section5& S, std::int64_t caseA_order) {
  I t_best_119 = sqrt(I(99)) * S.pi / 2;
  std::optional<I> prev;
  std::int64_t prev_delta = 0;
  S.R.log("## Case A: best pair per delta (smallest admissible sigma): delta | pair | exact t_first | lower bound (pi/4) "
          "sqrt(99) delta");
  for (std::int64_t delta = 2; 10 * delta <= caseA_order; delta += 4) {
    auto best = best_sigma(delta, caseA_order);
    if (!best) continue;
    S.R.count_pair();
    std::int64_t s = *best, t = s + delta;
    I tf = sqrt(I(t) * I(s)) * S.pi / 2;
    I lb = S.pi / 4 * sqrt(I(99)) * I(delta);
    // Every admissible pair has tau sigma = (a^2 - b^2)/4 >= 99 b^2/4 (a >= 10 b).
    bool lb_ok = 4 * t * s >= 99 * delta * delta;
    S.caseA.add(delta == 2 ? decide_bool(lb_ok && t == 11 && s == 9)
                           : verdict_and(decide_bool(lb_ok), decide_less(t_best_119, lb)),
                "delta=" + std::to_string(delta));
    if (prev) S.monotone.add(decide_less(*prev, tf), "delta " + std::to_string(prev_delta) + " -> " + std::to_string(delta));
    prev = tf;
    prev_delta = delta;
    S.R.log("A.best | " + std::to_string(delta) + " | (" + std::to_string(t) + ", " + std::to_string(s) + ") | " +
            enc(tf, 8) + " | " + enc(lb, 8));
  }
}

// Case B: (6, 5) against every beat pair of order <= max_order, then the tail a >= 62.
void case_b_all_pairs(section5& S, std::int64_t max_order) {
  I r65 = enclosure(certify_by_theorem(resonant_pair<big_int>(6, 5), 10).r_res);
  S.R.log("## 3. Case B: beat pairs (a >= 10 b) with r_res below r_res(6, 5) = " + enc(r65, 10));
  for (auto p64 : coprime_pairs(3, max_order)) {
    if (!beat(p64.tau(), p64.sigma()) || (p64.tau() == 6 && p64.sigma() == 5)) continue;
    S.R.count_pair();
    auto p = big_pair(p64);
    auto c = certify_by_theorem(p, 6);
    verdict v = decide_less(enclosure({"0", c.r_res.second}), r65);
    S.caseB.add(v, p.str());
    S.R.log("B.pair | " + p.str() + " | r_res <= " + c.r_res.second + " | " + verdict_name(v));
  }
  I tail = S.pi / 62;  // every beat pair of order >= 62: r_res <= pi/a <= pi/62
  verdict v = decide_less(tail, r65);
  S.caseB.add(v, "a >= 62 (bound pi/a)");
  S.R.log("B.tail | every beat pair of order >= 62: r_res <= pi/a <= pi/62 = " + enc(tail, 10) + " < r_res(6, 5) | " +
          verdict_name(v) + (max_order >= 61 ? " (with the certified orders <= 61: complete)" : ""));
}

int verify(const options& opt, std::int64_t caseA_order) {
  run R("verify_section5", "the paper's Section V numbers and design reasoning (P8), exact values", opt);
  scoped_digits sd(digits10_for_bits(192));
  auto S = add_claims(R);
  R.log("## 1. Printed numbers: id | what | printed | exact enclosure | verdict");
  printed_case_a_delta2(S);
  printed_case_a_delta6(S);
  printed_case_b(S);
  case_a_table(S);
  case_a_best_per_delta(S, caseA_order);
  case_b_all_pairs(S, opt.max_order);
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  std::int64_t caseA_order = 0;
  bool caseA_given = false;
  program_option caseA{"--caseA-order", "N", "Case A best pairs up to this order (default: max(--max-order, 100))",
                       &caseA_order};
  caseA.given = &caseA_given;
  return run_program("verify_section5", "verify_section5: the paper's Section V numbers and design reasoning (P8)",
                     {caseA}, argc, argv, [&](const options& opt) {
                       return verify(opt, caseA_given ? caseA_order : std::max<std::int64_t>(opt.max_order, 100));
                     });
}
