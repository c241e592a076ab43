// verify_error_bound: paper Thm. theta_asy and Thm. error_bound (docs/mathematics.md §2, P6, P7), rigorously
// for every pair up to --max-order.
//
// For x = b/a < 1/2 and each of the paper's fast nodes k = round(a/(2b)) (two on a tie, b = 1),
// with m = a - 2 k b (exact, |m| <= b), mu = pi m/(2a), s = pi m/(2b), in the lobe frame (k, 0):
//   u_c    the root of q' = 0, i.e. of f(u) = cos u sin(mu - x u) - x sin u cos(mu - x u), in
//          (-pi/2, pi/2): enclosed by interval Newton (proof::certify_root: N(X) inside X); it is
//          THE root of the lobe, since the lobe has exactly one (README, Lemma 6.1);
//   u_asy  the root of u + tan u = s in (-pi/2, pi/2): enclosed by interval Newton on
//          h(u) = u + tan u - s, h' = 2 + tan^2 u (unique: h is strictly increasing);
//   theta_c = 2 (k pi + u_c)/a,  theta_asy = 2 (k pi + u_asy)/a = pi/b + (2/a)(u_asy - s).
// Decisions per pair and lobe:
//   P6.root     interval Newton proves u_c (the paper's theta_c exists and is enclosed).  [asserted]
//   P6.form     the paper's theta_asy = pi/b + (2/a)(u_asy - s) is consistent with
//               2 (k pi + u_asy)/a (overlapping enclosures; the identity is exact algebra).  [asserted]
//   P7.bound    |theta_c - theta_asy| = 2 |u_c - u_asy|/a <= pi^3 x^2/a.                  [asserted]
//   P7.sharp    the README's sharper bound (Lemma 7.1):
//               |theta_c - theta_asy| <= (pi^3 x^2/a) S(pi x/2)/8,  S(y) = (tan y - y)/y^3,
//               i.e. ratio = error/bound <= S(pi x/2)/8 <= 0.0554.                        [asserted]
//   P7.x>=1/2   for x >= 1/2 (k = 1): every root of q' in the lobe (if any) satisfies the bound,
//               because 2 pi/a <= pi^3 x^2/a. Existence (P6.root) is decided by a sign change of
//               f on [-pi/2, pi/2] or an exact zero at an end (integers); n/a otherwise: the
//               lobe has an even number of roots, possibly none, and theta_c need not exist. [asserted]
// The log gives, per lobe, the enclosure of ratio = |theta_c - theta_asy|/(pi^3 x^2/a) and of
// its x -> 0 limit 2 C(s)/pi^3 = 2 tan^3 u/(3 pi^3 (1 + sec^2 u)) at u = u_asy (docs/mathematics.md §3).
// Option --every K: log only every K-th pair (and every pair with a new largest ratio).
#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/certify/certificate.hpp>

#include <optional>

#include "verify_common.hpp"

using namespace gyrores;
using namespace gyrores::proofs;
using I = gyrores::proof::I;
using P = gyrores::proof::P;

namespace {

// Interval Newton for h(u) = u + tan u - s from a point guess; nullopt if not proved.
std::optional<I> certify_u_plus_tan(const I& s, const P& guess) {
  P scale = abs(guess) > P("1e-300") ? abs(guess) : P(1);
  P delta = ldexp(scale, -int(real_bits<P>()) + 12);
  I X = interval_of(guess - delta, guess + delta);
  bool proved = false;
  for (int it = 0; it < 60; ++it) {
    I mid = interval_mid(X);
    I t = tan(X);
    I dh = 2 + interval_sqr(t);
    I N = mid - (mid + tan(mid) - s) / dh;
    if (certainly_inside(N, X)) {
      proved = true;
      I next = interval_intersect(N, X);
      bool shrinks = interval_upper(next) - interval_lower(next) < interval_upper(X) - interval_lower(X);
      X = next;
      if (!shrinks) break;
    } else if (proved) {
      break;
    } else {
      delta *= 4;
      X = interval_of(guess - delta, guess + delta);
    }
  }
  if (!proved) return std::nullopt;
  return X;
}

// S(y) = (tan y - y)/y^3 for an interval y inside (0, pi/2): the series sum_{n>=1} c_n y^(2n-2) has
// positive coefficients, so S is increasing in y > 0 and an enclosure at the point upper(y)
// bounds it from above. Evaluated directly (y is not tiny here: y = pi x/2 >= pi/(2a)).
I S_of(const I& y) { return (tan(y) - y) / (y * y * y); }

}  // namespace

int main(int argc, char** argv) {
  return guarded_main("verify_error_bound", [&] {
    auto opt = parse_options(argc, argv, {"every"});
    const std::int64_t every = opt.extra.count("every") ? std::stoll(opt.extra["every"]) : 1;
    run R("verify_error_bound", "paper Thm. theta_asy and Thm. error_bound (P6, P7)", opt);
    auto& c_root = R.add_claim("P6.root",
                               "the root theta_c of q' in the paper's lobe k exists (x < 1/2: interval Newton; x >= 1/2: "
                               "sign change or exact zero at a lobe end, else n/a)",
                               true);
    auto& c_form = R.add_claim("P6.form", "theta_asy = pi/b + (2/a)(u_asy - s) = 2 (k pi + u_asy)/a (consistent enclosures)", true);
    auto& c_bound = R.add_claim("P7.bound", "x < 1/2: |theta_c - theta_asy| <= pi^3 x^2/a", true);
    auto& c_sharp = R.add_claim("P7.sharp", "x < 1/2: |theta_c - theta_asy| <= (pi^3 x^2/a) S(pi x/2)/8 (README Lemma 7.1)", true);
    auto& c_large = R.add_claim("P7.x>=1/2",
                                "x >= 1/2: every root of q' in the paper's lobe k = 1 (if any) satisfies the bound, "
                                "as 2 pi/a <= pi^3 x^2/a",
                                true);
    R.log("# per lobe: (tau,sigma) k m | u_asy | u_c | ratio = |theta_c - theta_asy|/(pi^3 x^2/a) | x->0 limit "
          "2 C(s)/pi^3 | S(pi x/2)/8 | decisions");
    P max_ratio = 0;
    std::string max_ratio_at;
    std::uint64_t lobes = 0, index = 0;
    for (auto p64 : coprime_pairs(opt.min_order, opt.max_order)) {
      R.count_pair();
      ++index;
      resonant_pair<big_int> p(p64.tau(), p64.sigma());
      const std::string name = p.str();
      const std::int64_t a = p64.tau() + p64.sigma(), b = p64.delta();
      const unsigned bits = 64u + 2u * unsigned(boost::multiprecision::msb(big_int(a)));
      scoped_digits sd(digits10_for_bits(bits));
      auto K = proof::constants_of(p);
      const I pi = K.c.pi, x = K.c.x;
      const I A = real_from_int<I>(big_int(a)), B = real_from_int<I>(big_int(b));
      if (2 * b >= a) {
        // Paper's k = round(a/(2b)) = 1 here; f at the lobe ends.
        auto ks = paper_lobe_indices(p);
        big_int m = big_int(a) - 2 * ks[0] * b;
        I mu = proof::mu_of(K, m);
        I h = pi / 2;
        I flo = proof::f_of(K, mu, I(-h)), fhi = proof::f_of(K, mu, h);
        bool sign_change = (certainly_positive(flo) && certainly_negative(fhi)) ||
                           (certainly_negative(flo) && certainly_positive(fhi));
        // Exact zeros at the lobe ends: f(pi/2) = -x cos(pi (m - b)/(2a)), f(-pi/2) = x cos(pi (m + b)/(2a)).
        auto odd_quotient = [&](const big_int& num) {
          return int_mod(num, big_int(a)) == 0 && int_mod(big_int(num / a), big_int(2)) == 1;
        };
        bool edge_zero = odd_quotient(big_int(m - b)) || odd_quotient(big_int(m + b));
        I lhs = 2 * pi / A, rhs = pi * pi * pi * x * x / A;
        verdict v = decide_less(lhs, rhs);
        c_root.add(sign_change || edge_zero ? verdict::proved : verdict::not_applicable, name,
                   sign_change ? "x >= 1/2: f changes sign on the lobe"
                               : (edge_zero ? "x >= 1/2: exact root at a lobe end"
                                            : "x >= 1/2: no sign change, existence of theta_c not established"));
        c_form.add(verdict::not_applicable, name);
        c_bound.add(verdict::not_applicable, name);
        c_sharp.add(verdict::not_applicable, name);
        c_large.add(v, name);
        if (R.logging() && (index % every == 0))
          R.log(name + " k=" + ks[0].str() + " m=" + m.str() + " x>=1/2 | f(-pi/2) " + enc(flo, 6) + " f(pi/2) " +
                enc(fhi, 6) + " | " + verdict_name(v));
        continue;
      }
      c_large.add(verdict::not_applicable, name);
      for (const big_int& k : paper_lobe_indices(p)) {
        ++lobes;
        big_int m = big_int(a) - 2 * k * b;
        std::string lname = name + (b == 1 ? " k=" + k.str() : "");
        if (abs(m) > big_int(b)) throw compute_error("|m| > b for " + lname);
        I mu = proof::mu_of(K, m);
        I s = pi * real_from_int<I>(m) / (2 * B);
        std::optional<I> Uc, Ua;
        if (m == 0) {  // b = 2, a = 4k: f is odd and the unique root is 0; u + tan u = 0 at 0
          Uc = I(0);
          Ua = I(0);
        } else {
          double xd = double(b) / double(a), mud = M_PI * double(m) / (2.0 * double(a)),
                 sd_ = M_PI * double(m) / (2.0 * double(b));
          P gc = P(lobe_equation_root<double>(xd, mud, sd_, M_PI));
          P ga = P(u_plus_tan_u_root<double>(sd_));
          Uc = proof::certify_root(K, mu, gc, abs(gc));
          Ua = certify_u_plus_tan(s, ga);
        }
        if (!Uc || !Ua) {
          c_root.add(Uc ? verdict::proved : verdict::undecided, lname);
          for (auto* c : {&c_form, &c_bound, &c_sharp}) c->add(verdict::undecided, lname, "no enclosure");
          R.log(lname + " | interval Newton failed");
          continue;
        }
        c_root.add(verdict::proved, lname);
        // theta_asy both ways.
        I th_asy = 2 * (pi * real_from_int<I>(k) + *Ua) / A;
        I th_paper = pi / B + 2 * (*Ua - s) / A;
        bool overlap = !(certainly_less(th_asy, th_paper) || certainly_less(th_paper, th_asy));
        c_form.add(decide_bool(overlap), lname);
        I err = 2 * interval_abs(*Uc - *Ua) / A;
        I bound = pi * pi * pi * x * x / A;
        verdict vb = (m == 0) ? verdict::proved : decide_less(err, bound);
        c_bound.add(vb, lname);
        I ratio = err / bound;
        I y = pi * x / 2;
        I sharp = S_of(y) / 8;
        verdict vs = (m == 0) ? verdict::proved : decide_less(ratio, sharp);
        c_sharp.add(vs, lname);
        I tu = tan(*Ua);
        I limit = 2 * tu * tu * tu / (3 * pi * pi * pi * (2 + tu * tu));
        bool new_max = interval_upper(ratio) > max_ratio;
        if (new_max) {
          max_ratio = interval_upper(ratio);
          max_ratio_at = lname;
        }
        if (R.logging() && (index % every == 0 || new_max))
          R.log(lname + " m=" + m.str() + " | u_asy " + enc(*Ua, 10) + " | u_c " + enc(*Uc, 10) + " | ratio " +
                enc(interval_abs(ratio), 6) + " | limit " + enc(interval_abs(limit), 6) + " | " + enc(sharp, 4) + " | " +
                verdict_name(vb) + " " + verdict_name(vs) + (new_max ? " (largest ratio so far)" : ""));
      }
    }
    R.note("lobes examined (x < 1/2): " + std::to_string(lobes));
    R.note("largest upper bound of ratio |theta_c - theta_asy|/(pi^3 x^2/a): " + format_scientific(max_ratio, 8) + " at " +
           max_ratio_at);
    return R.finish();
  });
}
