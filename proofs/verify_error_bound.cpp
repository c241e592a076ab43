// verify_error_bound: paper Thm. theta_asy and Thm. error_bound (docs/mathematics.md §2, P6, P7), rigorously
// for every pair up to --max-order.
//
// For x = b/a < 1/2 and each of the paper's fast nodes k = round(a/(2b)) (two on a tie, b = 1),
// with m = a - 2 k b (exact, |m| <= b), mu = pi m/(2a), s = pi m/(2b), in the lobe frame (k, 0):
//   u_c    the root of q' = 0, i.e. of f(u) = cos u sin(mu - x u) - x sin u cos(mu - x u), in
//          (-pi/2, pi/2): enclosed by interval Newton (proof::certify_root: N(X) inside X); it is
//          THE root of the lobe, since the lobe has exactly one (proofs/README.md, Lemma 6.1);
//   u_asy  the root of u + tan u = s in (-pi/2, pi/2): enclosed by interval Newton on
//          h(u) = u + tan u - s, h' = 2 + tan^2 u (unique: h is strictly increasing);
//   theta_c = 2 (k pi + u_c)/a,  theta_asy = 2 (k pi + u_asy)/a = pi/b + (2/a)(u_asy - s).
// Decisions per pair and lobe:
//   P6.root     interval Newton proves u_c (the paper's theta_c exists and is enclosed).  [asserted]
//   P6.form     the paper's theta_asy = pi/b + (2/a)(u_asy - s) is consistent with
//               2 (k pi + u_asy)/a (overlapping enclosures; the identity is exact algebra).  [asserted]
//   P7.bound    |theta_c - theta_asy| = 2 |u_c - u_asy|/a <= pi^3 x^2/a.                  [asserted]
//   P7.sharp    the sharper bound of proofs/README.md (Lemma 7.1):
//               |theta_c - theta_asy| <= (pi^3 x^2/a) S(pi x/2)/8,  S(y) = (tan y - y)/y^3,
//               i.e. ratio = error/bound <= S(pi x/2)/8 < S(pi/4)/8 = 0.0554...          [asserted]
//   P6.count    for x >= 1/2 (k = 1, m < 0): a root exists between the slow node u = s and u = 0
//               (P6.root, by the signs of f there); the lobe holds exactly one root when
//               x <= 2/3 and exactly two when x > 2/3, so theta_c is not unique there
//               (proofs/README.md, Lemma 6.0; the sign patterns are checked per pair).     [asserted]
//   P7.x>=1/2   for x >= 1/2: every root of q' in the lobe satisfies the bound, because
//               2 pi/a <= pi^3 x^2/a.                                                      [asserted]
// The log gives, per lobe, the enclosure of ratio = |theta_c - theta_asy|/(pi^3 x^2/a) and of
// its x -> 0 limit 2 C(s)/pi^3 = 2 tan^3 u/(3 pi^3 (1 + sec^2 u)) at u = u_asy (docs/mathematics.md §3).
// Option --every K: log only every K-th pair (and every pair with a new largest ratio).
#include "reference/asymptotic.hpp"

#include <limits>

#include "lobe_roots.hpp"
#include "verify_common.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using namespace gyrores::proofs;

namespace {

// S(y) = (tan y - y)/y^3 for an interval y inside (0, pi/2): the series sum_{n>=1} c_n y^(2n-2) has
// positive coefficients, so S is increasing in y > 0 and an enclosure at the point upper(y)
// bounds it from above. Evaluated directly (y is not tiny here: y = pi x/2 >= pi/(2a)).
I S_of(const I& y) { return (tan(y) - y) / (y * y * y); }

struct error_bound_claims {
  claim &root, &count, &form, &bound, &sharp, &large;
};

error_bound_claims add_claims(run& R) {
  return {R.add_claim("P6.root",
                      "the root theta_c of q' in the paper's lobe k exists (x < 1/2: interval Newton; x >= 1/2: "
                      "sign change between the slow node u = s and u = 0)",
                      true),
          R.add_claim("P6.count",
                      "x >= 1/2: the paper's lobe holds exactly one root of q' when x <= 2/3 and exactly two when "
                      "x > 2/3 (theta_c is then not unique)",
                      true),
          R.add_claim("P6.form", "theta_asy = pi/b + (2/a)(u_asy - s) = 2 (k pi + u_asy)/a (consistent enclosures)", true),
          R.add_claim("P7.bound", "x < 1/2: |theta_c - theta_asy| <= pi^3 x^2/a", true),
          R.add_claim("P7.sharp", "x < 1/2: |theta_c - theta_asy| <= (pi^3 x^2/a) S(pi x/2)/8 (README Lemma 7.1)", true),
          R.add_claim("P7.x>=1/2",
                      "x >= 1/2: every root of q' in the paper's lobe k = 1 (if any) satisfies the bound, "
                      "as 2 pi/a <= pi^3 x^2/a",
                      true)};
}

// The state of the run across pairs: what to log and the largest ratio so far.
struct progress {
  std::int64_t every = 1;
  std::uint64_t index = 0, lobes = 0;
  P max_ratio = 0;
  std::string max_ratio_at;
  bool log_this() const { return index % every == 0; }
};

// One pair of the run with its constants at 64 + 2 log2(a) bits.
struct pair_context {
  resonant_pair<big_int> p;
  std::string name;
  std::int64_t a, b;
  proof::constants K;
};

// x >= 1/2: the paper's k = round(a/(2b)) = 1 and m = a - 2b <= 0, so s = pi m/(2b) lies in
// (-pi/2, 0] and mu = x s; m = 0 only at x = 1/2 ((3, 1)), where u = 0 is an exact root. Existence (proofs/README.md, Lemma 6.0): f(0) = sin mu < 0 and
// f(s) = -x sin s > 0, so q' has a root between the slow node u = s and u = 0. Count: on each
// interval where cos w != 0 (w = mu - x u) the roots of f are those of phi = x tan u - tan w,
// which is strictly increasing; w reaches -pi/2 inside the lobe iff |m| + b > a (x > 2/3), at
// u_p = (pi/2 + mu)/x, and then f(u_p) = -cos u_p < 0 < f(pi/2) = -x cos(mu - x pi/2) gives the
// second root. Both sign patterns are checked here in interval arithmetic.
void decide_large_x(run& R, error_bound_claims& C, const progress& g, const pair_context& c) {
  const I pi = c.K.c.pi, x = c.K.c.x, A = real_from_int<I>(big_int(c.a));
  auto ks = paper_lobe_indices(c.p);
  const big_int m = big_int(c.a) - 2 * ks[0] * c.b;
  const paper_lobe L = paper_lobe_of(c.K, m);
  const I f0 = proof::f_of(c.K, L.mu, I(0)), fs = proof::f_of(c.K, L.mu, L.s);
  const bool first = ks.size() == 1 && ks[0] == 1 &&
                     (m == 0 || (m < 0 && certainly_negative(f0) && certainly_positive(fs)));
  C.root.add(decide_bool(first), c.name, first ? "" : "no sign change between the slow node and u = 0");
  const bool two_roots = abs(m) + c.b > big_int(c.a);  // exact: w reaches -pi/2 inside the lobe
  std::string count_text = "one root (x <= 2/3)";
  bool counted = first;
  if (two_roots) {
    const I up = (pi / 2 + L.mu) / x;
    const I fp = proof::f_of(c.K, L.mu, up), fe = proof::f_of(c.K, L.mu, pi / 2);
    counted = first && certainly_less(up, pi / 2) && certainly_negative(fp) && certainly_positive(fe);
    count_text = "two roots (x > 2/3), the second beyond u_p = " + enc(up, 6);
  }
  C.count.add(decide_bool(counted), c.name, count_text);
  verdict v = decide_less(2 * pi / A, pi * pi * pi * x * x / A);
  for (auto* cl : {&C.form, &C.bound, &C.sharp}) cl->add(verdict::not_applicable, c.name);
  C.large.add(v, c.name);
  if (R.logging() && g.log_this())
    R.log(c.name + " k=" + ks[0].str() + " m=" + m.str() + " x>=1/2 | f(0) " + enc(f0, 6) + " f(s) " + enc(fs, 6) +
          " | " + count_text + " | " + verdict_name(v));
}

// u_c and u_asy of the lobe with offset m (both 0 when m = 0: b = 2, a = 4k, f is odd).
std::pair<std::optional<I>, std::optional<I>> lobe_roots(const pair_context& c, const big_int& m, const paper_lobe& L) {
  if (m == 0) return {I(0), I(0)};
  auto guess = double_guesses(c.a, c.b, static_cast<std::int64_t>(m));
  P gc = P(guess.u_c), ga = P(guess.u_asy);
  return {proof::certify_root(c.K, L.mu, gc, abs(gc)), certify_u_plus_tan(L.s, ga)};
}

// x < 1/2: the lobe k, its two roots, the paper's form of theta_asy and both bounds.
void decide_lobe(run& R, error_bound_claims& C, progress& g, const pair_context& c, const big_int& k) {
  ++g.lobes;
  const I pi = c.K.c.pi, x = c.K.c.x;
  const I A = real_from_int<I>(big_int(c.a)), B = real_from_int<I>(big_int(c.b));
  big_int m = big_int(c.a) - 2 * k * c.b;
  std::string lname = c.name + (c.b == 1 ? " k=" + k.str() : "");
  if (abs(m) > big_int(c.b)) throw compute_error("|m| > b for " + lname);
  paper_lobe L = paper_lobe_of(c.K, m);
  auto [Uc, Ua] = lobe_roots(c, m, L);
  if (!Uc || !Ua) {
    C.root.add(Uc ? verdict::proved : verdict::undecided, lname);
    for (auto* cl : {&C.form, &C.bound, &C.sharp}) cl->add(verdict::undecided, lname, "no enclosure");
    R.log(lname + " | interval Newton failed");
    return;
  }
  C.root.add(verdict::proved, lname);
  I th_asy = 2 * (pi * real_from_int<I>(k) + *Ua) / A;
  I th_paper = pi / B + 2 * (*Ua - L.s) / A;
  C.form.add(decide_bool(!(certainly_less(th_asy, th_paper) || certainly_less(th_paper, th_asy))), lname);
  I err = 2 * interval_abs(*Uc - *Ua) / A;
  I bound = pi * pi * pi * x * x / A;
  verdict vb = (m == 0) ? verdict::proved : decide_less(err, bound);
  C.bound.add(vb, lname);
  I ratio = err / bound;
  I sharp = S_of(pi * x / 2) / 8;
  verdict vs = (m == 0) ? verdict::proved : decide_less(ratio, sharp);
  C.sharp.add(vs, lname);
  I tu = tan(*Ua);
  I limit = 2 * tu * tu * tu / (3 * pi * pi * pi * (2 + tu * tu));
  bool new_max = interval_upper(ratio) > g.max_ratio;
  if (new_max) {
    g.max_ratio = interval_upper(ratio);
    g.max_ratio_at = lname;
  }
  if (R.logging() && (g.log_this() || new_max))
    R.log(lname + " m=" + m.str() + " | u_asy " + enc(*Ua, 10) + " | u_c " + enc(*Uc, 10) + " | ratio " +
          enc(interval_abs(ratio), 6) + " | limit " + enc(interval_abs(limit), 6) + " | " + enc(sharp, 4) + " | " +
          verdict_name(vb) + " " + verdict_name(vs) + (new_max ? " (largest ratio so far)" : ""));
}

int verify(const options& opt, std::int64_t every) {
  run R("verify_error_bound", "paper Thm. theta_asy and Thm. error_bound (P6, P7)", opt);
  auto C = add_claims(R);
  R.log("# per lobe: (tau,sigma) k m | u_asy | u_c | ratio = |theta_c - theta_asy|/(pi^3 x^2/a) | x->0 limit "
        "2 C(s)/pi^3 | S(pi x/2)/8 | decisions");
  progress g;
  g.every = every;
  for_each_pair(R, opt, [&](const resonant_pair<std::int64_t>& p64) {
    ++g.index;
    auto p = big_pair(p64);
    scoped_digits sd(digits10_for_bits(64u + 2u * unsigned(boost::multiprecision::msb(p.order()))));
    pair_context c{p, p.str(), p64.tau() + p64.sigma(), p64.delta(), proof::constants_of(p)};
    if (2 * c.b >= c.a) return decide_large_x(R, C, g, c);
    C.large.add(verdict::not_applicable, c.name);
    C.count.add(verdict::not_applicable, c.name);
    for (const big_int& k : paper_lobe_indices(p)) decide_lobe(R, C, g, c, k);
  });
  R.note("lobes examined (x < 1/2): " + std::to_string(g.lobes));
  R.note("largest upper bound of ratio |theta_c - theta_asy|/(pi^3 x^2/a): " + format_scientific(g.max_ratio, 8) +
         " at " + g.max_ratio_at);
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  std::int64_t every = 1;
  program_option every_opt{"--every", "K", "log only every K-th pair (and each new largest ratio)", &every};
  every_opt.min = 1;
  every_opt.show_default = true;
  return run_program("verify_error_bound", "verify_error_bound: paper Thm. theta_asy and Thm. error_bound (P6, P7)",
                     {every_opt}, argc, argv, [&](const options& opt) { return verify(opt, every); });
}
