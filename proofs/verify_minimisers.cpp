// verify_minimisers: where and what the global minimisers of R are, for every pair up to
// --max-order: paper Thm. globalMinimiser (docs/mathematics.md §2, P4), the "first slow node" claim (P5) and the
// structure claims of docs/mathematics.md §3 (minimiser count, m_min, location at the pass).
//
// Each pair is certified by gyrores::certify_by_theorem (gyrores-certificate/2, the lattice
// theorem, proofs/lattice-theorem.md): the global minimisers of R are exactly the 2 or 4 lobes
// (k, j, m) it states, in theta order, each at u = sign(m) u* with 0 < u_lo < u* < u_hi < pi/2
// proved, theta = 2 (k pi + u)/a. (Up to commit 9cd03bc this program used the cover certificate
// instead, a proof without the theorem; its runs are the logs of proofs/README.md.) From the
// certificate (and only from it, plus exact integers and MPFI) the program decides:
//
//   S.count      the number of global minimisers is 2 for delta odd, 4 for delta = 0 mod 4, and
//                R has exactly 2 zeros for delta = 2 mod 4 (docs/mathematics.md §3).                  [asserted]
//   S.m_min      min_N |a - 4N| is 0, 1, 2 for delta = 2 mod 4, odd, 0 mod 4 (integers), and the
//                certificate's m_min.                                                      [asserted]
//   S.pass       every global minimiser lies in a frame whose strand offset |m| equals m_min, at
//                u in (-pi/2, pi/2): within half a fast lobe of the pass of that strand by
//                P+ or P- (closest approach at u = x mu/(1 + x^2)).                        [asserted]
//   P4.root      (Thm. globalMinimiser part 3) min R is attained at a root of q' = 0: q' changes
//                sign across the certified bracket of u (MPFI at both ends), and the
//                theorem makes that root the minimum.                                      [asserted]
//   P4.lobe      (part 1, the paper's definition) the minimiser's q-lobe (between consecutive
//                roots of q) is envelope-minimising, i.e. has a slow node (cos beta = 0) as an
//                end: decided from the bracket X of u and the exact node positions u/pi in Z
//                (fast) and (m + 2 N a)/(2 b) (slow).                                      [asserted]
//   P4.unimodal  (part 2, literal) in EVERY envelope-minimising lobe R decreases then increases.
//                Refuted for a pair by one node j with 0 < m_j < b: in frame (k_j, j) the long lobe
//                [s, pi], s = pi m_j/(2b), has q' < 0 at s and at pi/2, q' > 0 at pi, z' > 0 at s and
//                z' < 0 at pi/2 (MPFI signs), so R increases right after its start although its q'
//                root lies in (pi/2, pi). For b = 1 every such lobe is a short lobe, where the claim
//                holds (README, Lemma 4.2').                                              [reported]
//   P5.location  some global minimiser lies in the paper's lobe k0 = round(a/(2b)) around
//                theta0 = pi/b (both k0 on a tie).                                          [reported]
//   P5.first     the FIRST global minimiser (theta_first, which sets t_first) lies there.   [reported]
//   P5.first.x<1/2  the same, restricted to delta != 2 mod 4 and x < 1/2 (where the paper's
//                lobe asymptotics are meant to apply).                                      [reported]
//   cert.check   (with --check) the independent checker (src/checker/, Arb) re-proves the
//                certificate.                                                               [asserted]
//
// Options: --check (run the independent checker too); --digits D (default 6).
#include <optional>
#include <set>

#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/io/certificate_json.hpp>

#include "certificate_checker.hpp"
#include "reference/asymptotic.hpp"
#include "reference/lobe_intervals.hpp"
#include "verify_common.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using namespace gyrores::proofs;
using I = gyrores::proof::I;
using P = gyrores::proof::P;

namespace {

I enclosure(const std::pair<std::string, std::string>& c) { return interval_from_decimal(c.first, c.second); }

std::string cert_text(const theorem_certificate& c) {
  std::string s = "#   certificate " + c.tau.str() + " " + c.sigma.str() + " (" + c.theorem + ", " +
                  std::to_string(c.bits) + " bits)\n";
  s += "#     r_res in [" + c.r_res.first + ", " + c.r_res.second + "]\n";
  s += "#     theta_first in [" + c.theta_first.first + ", " + c.theta_first.second + "]\n";
  s += "#     t_first in [" + c.t_first.first + ", " + c.t_first.second + "]\n";
  s += "#     u* in [" + c.u_star.first + ", " + c.u_star.second + "], m_min " + std::to_string(c.m_min) + ", lobes:";
  for (const auto& f : c.lobes) s += " (" + f.k.str() + "," + f.j.str() + "," + f.m.str() + ")";
  return s + "\n";
}

// floor of an interval if it is certain, else nullopt.
std::optional<big_int> certain_floor(const I& t) {
  P lo = floor(interval_lower(t)), hi = floor(interval_upper(t));
  if (lo != hi) return std::nullopt;
  return big_int(lo.convert_to<big_int>());
}

struct minimiser_claims {
  claim &count, &m_min, &pass, &root, &lobe, &unimodal, &location, &first, &first_small_x;
  claim* check;  // with --check only
};

minimiser_claims add_claims(run& R, bool check) {
  return {R.add_claim("S.count", "2 global minimisers (delta odd), 4 (delta = 0 mod 4), 2 zeros (delta = 2 mod 4)", true),
          R.add_claim("S.m_min", "min_N |a - 4N| = 0, 1, 2 for delta = 2 mod 4, odd, 0 mod 4", true),
          R.add_claim("S.pass",
                      "every global minimiser is a q' root in a frame with |m| = m_min, within half a fast lobe of the pass",
                      true),
          R.add_claim("P4.root", "min R is attained at a root of q' = 0 (Thm. globalMinimiser part 3)", true),
          R.add_claim("P4.lobe", "the minimiser's q-lobe is envelope-minimising: a slow node is one of its ends (part 1)",
                      true),
          R.add_claim("P4.unimodal", "R decreases then increases in every envelope-minimising lobe (part 2, literal)", false),
          R.add_claim("P5.location", "some global minimiser lies in the paper's lobe k0 = round(a/(2b)) around pi/b", false),
          R.add_claim("P5.first", "the first global minimiser lies in the paper's lobe k0 (so t_first ~ pi/|n|)", false),
          R.add_claim("P5.first.x<1/2", "P5.first for delta != 2 mod 4 and x < 1/2", false),
          check ? &R.add_claim("cert.check", "the independent checker re-proves the certificate", true) : nullptr};
}

// One certified pair: the pair, its certificate and the paper's lobe indices k0.
struct certified_pair {
  resonant_pair<big_int> p;
  std::string name;
  big_int a, b;
  theorem_certificate cert;
  std::vector<big_int> ks;  // paper_lobe_indices

  bool in_paper_lobe(const big_int& k) const {
    for (auto& k0 : ks)
      if (int_mod(k, a) == k0) return true;
    return false;
  }
};

// S.m_min: exact, min over N of |a - 4N| from a mod 4, and the certificate's.
verdict m_min_verdict(const resonant_pair<big_int>& p, int certified) {
  big_int r = int_mod(p.order(), big_int(4));
  int mm = int(r > 2 ? big_int(4 - r) : r);
  int expect = p.delta_mod4() == 2 ? 0 : (p.delta_mod4() % 2 == 1 ? 1 : 2);
  return decide_bool(mm == expect && mm == p.strand_offset_min() && mm == certified);
}

// P4.lobe: the neighbours of X among the q roots, u/pi in Z (fast) and (m + 2 N a)/(2 b) (slow);
// proved when a slow node is one of the two ends. The detail names the ends.
std::pair<verdict, std::string> lobe_verdict(const I& X, const I& pi, const big_int& a, const big_int& b,
                                             const big_int& m) {
  I t = X / pi;  // u*/pi
  auto fl = certain_floor(t);
  // slow nodes: (m + 2 N a)/(2b) < t  <=>  N < (2 b t - m)/(2a)
  I ns = (2 * real_from_int<I>(b) * t - real_from_int<I>(m)) / (2 * real_from_int<I>(a));
  auto nfl = certain_floor(ns);
  if (!fl || !nfl) return {verdict::undecided, ""};
  big_int Mleft = *fl, Mright = *fl + 1;
  big_int Nleft = *nfl, Nright = *nfl + 1;
  // slow node values as fractions over 2b: sl = m + 2 Nleft a, sr = m + 2 Nright a
  big_int sl = m + 2 * Nleft * a, sr = m + 2 * Nright * a, den = 2 * b;
  bool left_slow = sl > Mleft * den;  // slow node to the right of the fast one: nearer
  bool right_slow = sr < Mright * den;
  return {decide_bool(left_slow || right_slow),
          std::string("lobe ends: ") + (left_slow ? "slow" : "fast") + "/" + (right_slow ? "slow" : "fast")};
}

// P4.unimodal (literal): the first node j with 0 < m_j < b decides it (refuted when its long
// lobe shows the MPFI signs below); b = 1: holds (Lemma 4.2').
std::pair<verdict, std::string> unimodal_verdict(const proof::constants& K, const big_int& a, const big_int& b) {
  if (b == 1) return {verdict::proved, "b = 1: both lobes at each slow node are short (Lemma 4.2')"};
  const I pi = K.c.pi, half_pi = pi / 2;
  for (big_int jj = 0; jj < b; ++jj) {
    big_int kj = int_floor_div(big_int((2 * jj + 1) * a + b), big_int(2 * b));
    big_int mj = (2 * jj + 1) * a - 2 * kj * b;
    if (!(mj > 0 && mj < b)) continue;
    I mu = proof::mu_of(K, mj);
    I s = pi * real_from_int<I>(mj) / (2 * real_from_int<I>(b));
    bool neg_fs = certainly_negative(proof::f_of(K, mu, s));
    bool pos_gs = certainly_positive(proof::g_of(K, mu, s));
    bool neg_fh = certainly_negative(proof::f_of(K, mu, half_pi));
    bool neg_gh = certainly_negative(proof::g_of(K, mu, half_pi));
    bool pos_fp = certainly_positive(proof::f_of(K, mu, pi));
    if (neg_fs && pos_gs && neg_fh && neg_gh && pos_fp)
      return {verdict::refuted, "node j = " + jj.str() + ", frame k = " + kj.str() + ", m = " + mj.str() +
                                    ": long lobe [s, pi], R increases after s, q' root in (pi/2, pi)"};
    break;
  }
  return {verdict::undecided, ""};
}

// P4.root: q' (f in the frame of offset m) has opposite signs at the two ends of the bracket X
// of u, so a root of q' lies in X.
verdict root_verdict(const proof::constants& K, const big_int& m, const I& X) {
  const I mu = proof::mu_of(K, m);
  const I flo = proof::f_of(K, mu, interval_point(interval_lower(X)));
  const I fhi = proof::f_of(K, mu, interval_point(interval_upper(X)));
  const bool change = (certainly_positive(flo) && certainly_negative(fhi)) || (certainly_negative(flo) && certainly_positive(fhi));
  return change ? verdict::proved : verdict::undecided;
}

// The run: claims, the counterexamples' certificates logged once, the range of t_first/(pi/n).
class minimisers_run {
 public:
  minimisers_run(run& R, bool check, unsigned digits) : R_(R), C_(add_claims(R, check)), digits_(digits) {}

  void pair(const resonant_pair<big_int>& p);
  std::string ratio_note() const {
    return "t_first/(pi/|n|) = theta_first b/pi ranges over [" + format_scientific(ratio_lo_, 6) + ", " +
           format_scientific(ratio_hi_, 6) + "] (the paper's proxy T_min ~ pi/|n| means ratio ~ 1)";
  }

 private:
  void degenerate(const certified_pair& c);
  void non_degenerate(const certified_pair& c, const proof::constants& K, const I& ratio);
  void print_cert_once(const claim& cl, const certified_pair& c);

  run& R_;
  minimiser_claims C_;
  unsigned digits_;
  std::set<std::string> printed_;
  P ratio_lo_ = 1e9, ratio_hi_ = 0;
};

void minimisers_run::print_cert_once(const claim& cl, const certified_pair& c) {
  if (cl.first_refuted.rfind(c.name, 0) == 0 && !printed_.count(cl.id)) {
    printed_.insert(cl.id);
    R_.log("# smallest counterexample to " + cl.id + ": " + cl.first_refuted + "\n" + cert_text(c.cert));
  }
}

void minimisers_run::pair(const resonant_pair<big_int>& p) {
  certified_pair c{p, p.str(), p.order(), big_int(p.delta()), certify_by_theorem(p, digits_), paper_lobe_indices(p)};
  C_.m_min.add(m_min_verdict(p, c.cert.m_min), c.name);
  if (C_.check) {
    const auto v = gyrores_checker::check_theorem_certificate(certificate_to_json(c.cert).dump());
    C_.check->add(v.status == 0 ? verdict::proved : verdict::refuted, c.name, v.message);
  }
  scoped_digits sd(digits10_for_bits(c.cert.bits));
  auto K = proof::constants_of(p);
  // Ratio t_first/(pi/n) = theta_first b/pi.
  I ratio = enclosure(c.cert.theta_first) * real_from_int<I>(c.b) / K.c.pi;
  if (interval_lower(ratio) < ratio_lo_) ratio_lo_ = interval_lower(ratio);
  if (interval_upper(ratio) > ratio_hi_) ratio_hi_ = interval_upper(ratio);
  if (p.degenerate()) return degenerate(c);
  non_degenerate(c, K, ratio);
}

// Zeros pi/2 and 3 pi/2 in the m = 0 lobes (integer argument; verify_degenerate decides them too).
void minimisers_run::degenerate(const certified_pair& c) {
  const auto& name = c.name;
  const auto& lobes = c.cert.lobes;
  C_.count.add(decide_bool(lobes.size() == 2), name);
  bool at_pass = true;
  for (const auto& f : lobes) at_pass = at_pass && f.m == 0;
  C_.pass.add(decide_bool(at_pass), name, "m = 0 frames");
  for (auto* cl : {&C_.root, &C_.lobe, &C_.unimodal, &C_.first_small_x}) cl->add(verdict::not_applicable, name);
  const big_int k_first = lobes.front().k, k_second = lobes.back().k;
  bool loc = c.in_paper_lobe(k_first) || c.in_paper_lobe(k_second);
  C_.location.add(decide_bool(loc), name, loc ? "" : "zeros in lobes " + k_first.str() + ", " + k_second.str() + "; paper lobe " + c.ks[0].str());
  C_.first.add(decide_bool(c.in_paper_lobe(k_first)), name,
               "first zero pi/2 in lobe " + k_first.str() + ", paper lobe " + c.ks[0].str());
  print_cert_once(C_.first, c);
  R_.log(name + " degenerate | r_res = 0 | theta_first = pi/2 | 2 zeros, lobes " + k_first.str() + " " +
         k_second.str() + " k0 " + c.ks[0].str() + " | t_first/(pi/n) = b/2 = " + big_int(c.b / 2).str());
}

void minimisers_run::non_degenerate(const certified_pair& c, const proof::constants& K, const I& ratio) {
  const auto& name = c.name;
  const auto& lobes = c.cert.lobes;
  const auto& first = lobes.front();
  // The first minimiser's u = sign(m) u*, u* in the certificate's bracket.
  const I U = enclosure(c.cert.u_star), X = first.m < 0 ? I(-U) : U;
  std::size_t expect = (c.p.delta_mod4() % 2 == 1) ? 2 : 4;
  C_.count.add(decide_bool(lobes.size() == expect), name,
               "count " + std::to_string(lobes.size()) + ", expected " + std::to_string(expect));
  // S.pass: |m| = m_min in every lobe and u inside (-pi/2, pi/2).
  I half_pi = K.c.pi / 2;
  bool inside = certainly_less(-half_pi, X) && certainly_less(X, half_pi);
  bool mm = true;
  for (const auto& f : lobes) mm = mm && abs(f.m) == big_int(c.p.strand_offset_min());
  C_.pass.add(verdict_and(decide_bool(mm), inside ? verdict::proved : verdict::undecided), name,
              mm ? "" : "a frame with |m| != m_min");
  const verdict v_root = root_verdict(K, first.m, X);
  C_.root.add(v_root, name);
  auto [v_lobe, lobe_info] = lobe_verdict(X, K.c.pi, c.a, c.b, first.m);
  C_.lobe.add(v_lobe, name, v_lobe == verdict::proved ? "" : lobe_info);
  auto [v_uni, uni_info] = unimodal_verdict(K, c.a, c.b);
  C_.unimodal.add(v_uni, name, uni_info);
  bool some_in_paper_lobe = false;
  for (const auto& f : lobes) some_in_paper_lobe = some_in_paper_lobe || c.in_paper_lobe(f.k);
  C_.location.add(decide_bool(some_in_paper_lobe), name);
  const verdict v_first = decide_bool(c.in_paper_lobe(first.k));
  std::string fi = "first minimiser in lobe " + first.k.str() + ", paper lobe " + c.ks[0].str() +
                   (c.ks.size() > 1 ? "/" + c.ks[1].str() : "");
  C_.first.add(v_first, name, fi);
  C_.first_small_x.add(2 * c.b < c.a ? v_first : verdict::not_applicable, name, 2 * c.b < c.a ? fi : "");
  R_.log(name + " | r_res in [" + c.cert.r_res.first + ", " + c.cert.r_res.second + "] | theta_first in [" +
         c.cert.theta_first.first + ", " + c.cert.theta_first.second + "] | " + std::to_string(lobes.size()) + " (" +
         first.k.str() + "," + first.j.str() + "," + first.m.str() + ") k0 " + c.ks[0].str() + " | " + enc(ratio, 6) +
         " | " + verdict_name(decide_bool(lobes.size() == expect)) + " " +
         verdict_name(mm && inside ? verdict::proved : verdict::undecided) + " " + verdict_name(v_root) + " " +
         verdict_name(v_lobe) + " " + verdict_name(v_uni) + " " + verdict_name(v_first));
  for (const claim* cl : {&C_.unimodal, &C_.first, &C_.first_small_x}) print_cert_once(*cl, c);
}

int verify(const options& opt, bool check, unsigned digits) {
  run R("verify_minimisers",
        "global minimisers: paper Thm. globalMinimiser (P4), first slow node (P5), docs/mathematics.md §3 structure", opt);
  minimisers_run M(R, check, digits);
  R.log("# per pair: (tau,sigma) | r_res | theta_first | count frame(k,j,m) of the first k0 | t_first/(pi/n) | "
        "S.count S.pass P4.root P4.lobe P4.unimodal P5.first");
  for_each_pair(R, opt, [&](const resonant_pair<std::int64_t>& p64) { M.pair(big_pair(p64)); });
  R.note(M.ratio_note());
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  bool check = false;
  std::int64_t digits = 6;
  program_option check_opt{"--check", "", "re-prove every certificate with the independent checker"};
  check_opt.flag = &check;
  program_option digits_opt{"--digits", "D", "digits of every certificate", &digits, nullptr, 1, 10000, true};
  return run_program("verify_minimisers", "verify_minimisers: global minimisers (P4, P5, docs/mathematics.md §3)",
                     {check_opt, digits_opt}, argc, argv,
                     [&](const options& opt) { return verify(opt, check, unsigned(digits)); });
}
