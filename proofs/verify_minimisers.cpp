// verify_minimisers: where and what the global minimisers of R are, for every pair up to
// --max-order: paper Thm. globalMinimiser (docs/mathematics.md §2, P4), the "first slow node" claim (P5) and the
// structure claims of docs/mathematics.md §3 (minimiser count, m_min, location at the pass).
//
// Each pair is certified by gyrores::certify_pair (proofs/global-minimality.md: interval Newton,
// basin, symmetry images, cover of [0, 2 pi) by interval bisection), which proves that the
// global minimisers of R are exactly the symmetry images of one q' root u* in X, in the lobe
// frame (k, j, m). Undecided if the certificate does not prove global minimality. From the
// certificate (and only from it, plus exact integers and MPFI) the program decides:
//
//   S.count      the number of global minimisers is 2 for delta odd, 4 for delta = 0 mod 4, and
//                R has exactly 2 zeros for delta = 2 mod 4 (docs/mathematics.md §3).                  [asserted]
//   S.m_min      min_N |a - 4N| is 0, 1, 2 for delta = 2 mod 4, odd, 0 mod 4 (integers).  [asserted]
//   S.pass       every global minimiser lies in a frame whose strand offset |m| equals m_min, at
//                u in (-pi/2, pi/2): within half a fast lobe of the pass of that strand by
//                P+ or P- (closest approach at u = x mu/(1 + x^2)), and it is a q' root.     [asserted]
//   P4.root      (Thm. globalMinimiser part 3) min R is attained at a root of q' = 0: r_res = |q| at
//                the certified root.                                                       [asserted]
//   P4.lobe      (part 1, the paper's definition) the minimiser's q-lobe (between consecutive
//                roots of q) is envelope-minimising, i.e. has a slow node (cos beta = 0) as an
//                end: decided from X and the exact node positions u/pi in Z (fast) and
//                (m + 2 N a)/(2 b) (slow).                                                [asserted]
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
//   cert.check   (with --check) gyrores::check_certificate re-proves the certificate.       [asserted]
//
// Options: --check (run the independent checker too, ~doubles the time); --digits D (default 6).
#include "reference/asymptotic.hpp"

#include <limits>
#include <optional>
#include <set>

#include "reference/certify.hpp"
#include "reference/check.hpp"
#include "reference/proof_steps.hpp"
#include "verify_common.hpp"

using namespace gyrores;
using namespace gyrores::proofs;
using I = gyrores::proof::I;
using P = gyrores::proof::P;

namespace {

const certificate_obligation& need(const certificate& c, const char* id) {
  const auto* o = find_obligation(c, id);
  if (!o) throw compute_error(std::string("certificate without obligation ") + id);
  return *o;
}

std::string cert_text(const certificate& c) {
  std::string s = "#   certificate " + c.tau.str() + " " + c.sigma.str() + ": global_minimality=" +
                  (c.global_minimality ? "true" : "false") + " (" + c.global_minimality_note + ")\n";
  s += "#     r_res in [" + c.r_res.first + ", " + c.r_res.second + "]\n";
  s += "#     theta_first in [" + c.theta_first.first + ", " + c.theta_first.second + "]\n";
  s += "#     t_first in [" + c.t_first.first + ", " + c.t_first.second + "]\n";
  s += "#     minimisers: " + std::to_string(c.minimiser_count) + ", working bits " + std::to_string(c.working_bits) +
       ", cover bits " + std::to_string(c.cover_bits) + "\n";
  for (auto& o : c.obligations) {
    s += "#     obligation " + o.id + ":";
    for (auto& [k, v] : o.data) s += " " + k + "=" + v;
    s += "\n";
  }
  return s;
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
          check ? &R.add_claim("cert.check", "check_certificate re-proves the certificate", true) : nullptr};
}

// One certified pair: the pair, its certificate and the paper's lobe indices k0.
struct certified_pair {
  resonant_pair<big_int> p;
  std::string name;
  big_int a, b;
  certificate cert;
  std::vector<big_int> ks;  // paper_lobe_indices

  bool in_paper_lobe(const big_int& k) const {
    for (auto& k0 : ks)
      if (int_mod(k, a) == k0) return true;
    return false;
  }
};

// S.m_min: exact, min over N of |a - 4N| from a mod 4.
verdict m_min_verdict(const resonant_pair<big_int>& p) {
  big_int r = int_mod(p.order(), big_int(4));
  int mm = int(r > 2 ? big_int(4 - r) : r);
  int expect = p.delta_mod4() == 2 ? 0 : (p.delta_mod4() % 2 == 1 ? 1 : 2);
  return decide_bool(mm == expect && mm == p.strand_offset_min());
}

// The certificate: "slow-nodes" cover for a > 8 b, "all-lobes" otherwise, at any order.
certificate certify_for_run(const resonant_pair<big_int>& p, unsigned digits) {
  certify_options copt;
  copt.max_lobes = std::numeric_limits<std::int64_t>::max();
  copt.max_nodes = p.order() > 8 * big_int(p.delta()) ? std::numeric_limits<std::int64_t>::max() : 0;
  return certify_pair(p, digits, copt);
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

// P5: the lobe (k mod a) of the first minimiser among the symmetry images of X, if the images'
// thetas are separated and the first agrees with the certificate's theta_first; and whether
// some image lies in the paper's lobe.
struct first_minimiser {
  bool some_in_paper_lobe = false;
  verdict first_in_paper_lobe = verdict::undecided;
  big_int k_first = -1;
};

first_minimiser locate_first(const certified_pair& c, const proof::constants& K, const I& X, const big_int& k,
                             const big_int& j, const I& th_first) {
  auto imgs = proof::images_of(K, k, j, c.p.strand_offset_min() == 2);
  first_minimiser out;
  std::vector<I> thetas;
  for (auto& im : imgs) {
    thetas.push_back(proof::theta_of(K, im.k, im.negate_u ? I(-X) : X));
    if (c.in_paper_lobe(im.k)) out.some_in_paper_lobe = true;
  }
  std::optional<std::size_t> first;
  for (std::size_t i = 0; i < thetas.size(); ++i) {
    bool smallest = true;
    for (std::size_t i2 = 0; i2 < thetas.size(); ++i2)
      if (i2 != i && !certainly_less(thetas[i], thetas[i2])) smallest = false;
    if (smallest) first = i;
  }
  if (!first) return out;
  out.k_first = int_mod(imgs[*first].k, c.a);
  out.first_in_paper_lobe = decide_bool(c.in_paper_lobe(out.k_first));
  // Consistency with the certificate's theta_first (both enclose the same point; the
  // certificate's is rounded outward to its printed digits, this one is computed from X).
  if (certainly_less(thetas[*first], th_first) || certainly_less(th_first, thetas[*first]))
    out.first_in_paper_lobe = verdict::undecided;
  return out;
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
  void not_proved(const certified_pair& c);
  void degenerate(const certified_pair& c);
  void non_degenerate(const certified_pair& c, const proof::constants& K, const I& th_first, const I& ratio);
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
  certified_pair c{p, p.str(), p.order(), big_int(p.delta()), {}, paper_lobe_indices(p)};
  C_.m_min.add(m_min_verdict(p), c.name);
  c.cert = certify_for_run(p, digits_);
  if (C_.check) {
    auto v = check_certificate(c.cert);
    C_.check->add(v.holds ? verdict::proved : verdict::refuted, c.name, v.failure);
  }
  if (!c.cert.global_minimality) return not_proved(c);
  scoped_digits sd(digits10_for_bits(c.cert.working_bits));
  auto K = proof::constants_of(p);
  // Ratio t_first/(pi/n) = theta_first b/pi.
  I th_first = interval_from_decimal(c.cert.theta_first.first, c.cert.theta_first.second);
  I ratio = th_first * real_from_int<I>(c.b) / K.c.pi;
  if (interval_lower(ratio) < ratio_lo_) ratio_lo_ = interval_lower(ratio);
  if (interval_upper(ratio) > ratio_hi_) ratio_hi_ = interval_upper(ratio);
  if (p.degenerate()) return degenerate(c);
  non_degenerate(c, K, th_first, ratio);
}

void minimisers_run::not_proved(const certified_pair& c) {
  for (auto* cl : {&C_.count, &C_.pass, &C_.root, &C_.lobe, &C_.location, &C_.first, &C_.first_small_x})
    cl->add(verdict::undecided, c.name, c.cert.global_minimality_note);
  C_.unimodal.add(verdict::undecided, c.name);
  R_.log(c.name + " | NOT PROVED: " + c.cert.global_minimality_note);
}

// Zeros pi/2 and 3 pi/2 (integer argument; verify_degenerate re-proves them by a cover).
void minimisers_run::degenerate(const certified_pair& c) {
  const auto& name = c.name;
  C_.count.add(decide_bool(c.cert.minimiser_count == 2), name);
  C_.pass.add(verdict::proved, name, "m = 0 frame (a/4, (b-2)/4)");
  for (auto* cl : {&C_.root, &C_.lobe, &C_.unimodal, &C_.first_small_x}) cl->add(verdict::not_applicable, name);
  big_int k_first = c.a / 4, k_second = 3 * c.a / 4;
  bool loc = c.in_paper_lobe(k_first) || c.in_paper_lobe(k_second);
  C_.location.add(decide_bool(loc), name, loc ? "" : "zeros in lobes a/4, 3a/4; paper lobe " + c.ks[0].str());
  C_.first.add(decide_bool(c.in_paper_lobe(k_first)), name,
               "first zero pi/2 in lobe " + k_first.str() + ", paper lobe " + c.ks[0].str());
  print_cert_once(C_.first, c);
  R_.log(name + " degenerate | r_res = 0 | theta_first = pi/2 | 2 zeros, lobes " + k_first.str() + " " +
         k_second.str() + " k0 " + c.ks[0].str() + " | t_first/(pi/n) = b/2 = " + big_int(c.b / 2).str());
}

void minimisers_run::non_degenerate(const certified_pair& c, const proof::constants& K, const I& th_first,
                                    const I& ratio) {
  const auto& name = c.name;
  const auto& lr = need(c.cert, "local-root");
  const big_int k(lr.data.at("k")), j(lr.data.at("j")), m(lr.data.at("m"));
  I X = interval_from_decimal(lr.data.at("X_lo"), lr.data.at("X_hi"));
  std::size_t expect = (c.p.delta_mod4() % 2 == 1) ? 2 : 4;
  C_.count.add(decide_bool(c.cert.minimiser_count == expect), name,
               "count " + std::to_string(c.cert.minimiser_count) + ", expected " + std::to_string(expect));
  // S.pass: |m| = m_min (images: mirror m -> -m, shift m -> m) and X inside (-pi/2, pi/2).
  I half_pi = K.c.pi / 2;
  bool inside = certainly_less(-half_pi, X) && certainly_less(X, half_pi);
  bool mm = abs(m) == big_int(c.p.strand_offset_min());
  C_.pass.add(verdict_and(decide_bool(mm), inside ? verdict::proved : verdict::undecided), name,
              mm ? "" : "frame m = " + m.str());
  C_.root.add(verdict::proved, name);  // local-root + cover: the minimum is |q| at the q' root
  auto [v_lobe, lobe_info] = lobe_verdict(X, K.c.pi, c.a, c.b, m);
  C_.lobe.add(v_lobe, name, v_lobe == verdict::proved ? "" : lobe_info);
  auto [v_uni, uni_info] = unimodal_verdict(K, c.a, c.b);
  C_.unimodal.add(v_uni, name, uni_info);
  auto f = locate_first(c, K, X, k, j, th_first);
  C_.location.add(decide_bool(f.some_in_paper_lobe), name);
  std::string fi = "first minimiser in lobe " + f.k_first.str() + ", paper lobe " + c.ks[0].str() +
                   (c.ks.size() > 1 ? "/" + c.ks[1].str() : "");
  C_.first.add(f.first_in_paper_lobe, name, fi);
  C_.first_small_x.add(2 * c.b < c.a ? f.first_in_paper_lobe : verdict::not_applicable, name,
                       2 * c.b < c.a ? fi : "");
  R_.log(name + " " + (c.a > 8 * c.b ? "slow-nodes" : "all-lobes") + " | r_res in [" + c.cert.r_res.first + ", " +
         c.cert.r_res.second + "] | theta_first in [" + c.cert.theta_first.first + ", " + c.cert.theta_first.second +
         "] | " + std::to_string(c.cert.minimiser_count) + " (" + k.str() + "," + j.str() + "," + m.str() + ") lobe " +
         f.k_first.str() + " k0 " + c.ks[0].str() + " | " + enc(ratio, 6) + " | " +
         verdict_name(decide_bool(c.cert.minimiser_count == expect)) + " " +
         verdict_name(mm && inside ? verdict::proved : verdict::undecided) + " " + verdict_name(v_lobe) + " " +
         verdict_name(v_uni) + " " + verdict_name(f.first_in_paper_lobe));
  for (const claim* cl : {&C_.unimodal, &C_.first, &C_.first_small_x}) print_cert_once(*cl, c);
}

int verify(const options& opt, bool check, unsigned digits) {
  run R("verify_minimisers",
        "global minimisers: paper Thm. globalMinimiser (P4), first slow node (P5), docs/mathematics.md §3 structure", opt);
  minimisers_run M(R, check, digits);
  R.log("# per pair: (tau,sigma) strategy | r_res | theta_first | count frame(k,j,m) lobe(first) k0 | t_first/(pi/n) | "
        "S.count S.pass P4.lobe P4.unimodal P5.first");
  for_each_pair(R, opt, [&](const resonant_pair<std::int64_t>& p64) { M.pair(big_pair(p64)); });
  R.note(M.ratio_note());
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  bool check = false;
  std::int64_t digits = 6;
  program_option check_opt{"--check", "", "re-prove every certificate with check_certificate"};
  check_opt.flag = &check;
  program_option digits_opt{"--digits", "D", "digits of every certificate", &digits, nullptr, 1, 10000, true};
  return run_program("verify_minimisers", "verify_minimisers: global minimisers (P4, P5, docs/mathematics.md §3)",
                     {check_opt, digits_opt}, argc, argv,
                     [&](const options& opt) { return verify(opt, check, unsigned(digits)); });
}
