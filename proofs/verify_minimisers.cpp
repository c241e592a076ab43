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
#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/certify/certificate.hpp>

#include <optional>
#include <set>

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

}  // namespace

int main(int argc, char** argv) {
  return guarded_main("verify_minimisers", [&] {
    auto opt = parse_options(argc, argv, {"digits"}, {"check"});
    const bool check = opt.extra.count("check") > 0;
    const unsigned digits = opt.extra.count("digits") ? unsigned(std::stoul(opt.extra["digits"])) : 6u;
    run R("verify_minimisers",
          "global minimisers: paper Thm. globalMinimiser (P4), first slow node (P5), docs/mathematics.md §3 structure", opt);
    auto& c_count = R.add_claim("S.count", "2 global minimisers (delta odd), 4 (delta = 0 mod 4), 2 zeros (delta = 2 mod 4)", true);
    auto& c_mmin = R.add_claim("S.m_min", "min_N |a - 4N| = 0, 1, 2 for delta = 2 mod 4, odd, 0 mod 4", true);
    auto& c_pass = R.add_claim("S.pass", "every global minimiser is a q' root in a frame with |m| = m_min, within half a fast lobe of the pass", true);
    auto& c_root = R.add_claim("P4.root", "min R is attained at a root of q' = 0 (Thm. globalMinimiser part 3)", true);
    auto& c_lobe = R.add_claim("P4.lobe", "the minimiser's q-lobe is envelope-minimising: a slow node is one of its ends (part 1)", true);
    auto& c_uni = R.add_claim("P4.unimodal", "R decreases then increases in every envelope-minimising lobe (part 2, literal)", false);
    auto& c_loc = R.add_claim("P5.location", "some global minimiser lies in the paper's lobe k0 = round(a/(2b)) around pi/b", false);
    auto& c_first = R.add_claim("P5.first", "the first global minimiser lies in the paper's lobe k0 (so t_first ~ pi/|n|)", false);
    auto& c_first_s = R.add_claim("P5.first.x<1/2", "P5.first for delta != 2 mod 4 and x < 1/2", false);
    claim* c_check = check ? &R.add_claim("cert.check", "check_certificate re-proves the certificate", true) : nullptr;
    R.log("# per pair: (tau,sigma) strategy | r_res | theta_first | count frame(k,j,m) lobe(first) k0 | t_first/(pi/n) | "
          "S.count S.pass P4.lobe P4.unimodal P5.first");
    std::set<std::string> printed;
    auto print_cert_once = [&](const claim& c, const certificate& cert, const std::string& name) {
      if (c.first_refuted.rfind(name, 0) == 0 && !printed.count(c.id)) {
        printed.insert(c.id);
        R.log("# smallest counterexample to " + c.id + ": " + c.first_refuted + "\n" + cert_text(cert));
      }
    };
    P ratio_lo = 1e9, ratio_hi = 0;
    for (auto p64 : coprime_pairs(opt.min_order, opt.max_order)) {
      R.count_pair();
      resonant_pair<big_int> p(p64.tau(), p64.sigma());
      const std::string name = p.str();
      const big_int a = p.order(), b = big_int(p.delta());
      const bool deg = p.degenerate();
      const int m_min = p.strand_offset_min();
      // S.m_min: exact, min over N of |a - 4N| from a mod 4.
      {
        big_int r = int_mod(a, big_int(4));
        int mm = int(r > 2 ? big_int(4 - r) : r);
        int expect = p.delta_mod4() == 2 ? 0 : (p.delta_mod4() % 2 == 1 ? 1 : 2);
        c_mmin.add(decide_bool(mm == expect && mm == m_min), name);
      }
      certify_options copt;
      copt.max_lobes = std::numeric_limits<std::int64_t>::max();
      copt.max_nodes = a > 8 * b ? std::numeric_limits<std::int64_t>::max() : 0;
      certificate cert = certify_pair(p, digits, copt);
      if (c_check) {
        auto v = check_certificate(cert);
        c_check->add(v.holds ? verdict::proved : verdict::refuted, name, v.failure);
      }
      const auto ks = paper_lobe_indices(p);
      auto in_paper_lobe = [&](const big_int& k) {
        for (auto& k0 : ks)
          if (int_mod(k, a) == k0) return true;
        return false;
      };
      if (!cert.global_minimality) {
        for (auto* c : {&c_count, &c_pass, &c_root, &c_lobe, &c_loc, &c_first, &c_first_s})
          c->add(verdict::undecided, name, cert.global_minimality_note);
        c_uni.add(verdict::undecided, name);
        R.log(name + " | NOT PROVED: " + cert.global_minimality_note);
        continue;
      }
      scoped_digits sd(digits10_for_bits(cert.working_bits));
      auto K = proof::constants_of(p);
      const I pi = K.c.pi;
      // Ratio t_first/(pi/n) = theta_first b/pi.
      I th_first = interval_from_decimal(cert.theta_first.first, cert.theta_first.second);
      I ratio = th_first * real_from_int<I>(b) / pi;
      if (interval_lower(ratio) < ratio_lo) ratio_lo = interval_lower(ratio);
      if (interval_upper(ratio) > ratio_hi) ratio_hi = interval_upper(ratio);
      std::string line = name;
      if (deg) {
        // Zeros pi/2 and 3 pi/2 (integer argument; verify_degenerate re-proves them by a cover).
        c_count.add(decide_bool(cert.minimiser_count == 2), name);
        c_pass.add(verdict::proved, name, "m = 0 frame (a/4, (b-2)/4)");
        for (auto* c : {&c_root, &c_lobe, &c_uni, &c_first_s}) c->add(verdict::not_applicable, name);
        big_int k_first = a / 4, k_second = 3 * a / 4;
        bool loc = in_paper_lobe(k_first) || in_paper_lobe(k_second);
        c_loc.add(decide_bool(loc), name, loc ? "" : "zeros in lobes a/4, 3a/4; paper lobe " + ks[0].str());
        c_first.add(decide_bool(in_paper_lobe(k_first)), name,
                    "first zero pi/2 in lobe " + k_first.str() + ", paper lobe " + ks[0].str());
        line += " degenerate | r_res = 0 | theta_first = pi/2 | 2 zeros, lobes " + k_first.str() + " " + k_second.str() +
                " k0 " + ks[0].str() + " | t_first/(pi/n) = b/2 = " + big_int(b / 2).str();
        print_cert_once(c_first, cert, name);
        R.log(line);
        continue;
      }
      const auto& lr = need(cert, "local-root");
      const big_int k(lr.data.at("k")), j(lr.data.at("j")), m(lr.data.at("m"));
      I X = interval_from_decimal(lr.data.at("X_lo"), lr.data.at("X_hi"));
      const bool with_shift = m_min == 2;
      // S.count
      std::size_t expect = (p.delta_mod4() % 2 == 1) ? 2 : 4;
      c_count.add(decide_bool(cert.minimiser_count == expect), name,
                  "count " + std::to_string(cert.minimiser_count) + ", expected " + std::to_string(expect));
      // S.pass: |m| = m_min (images: mirror m -> -m, shift m -> m) and X inside (-pi/2, pi/2).
      I half_pi = pi / 2;
      bool inside = certainly_less(-half_pi, X) && certainly_less(X, half_pi);
      bool mm = abs(m) == big_int(m_min);
      c_pass.add(verdict_and(decide_bool(mm), inside ? verdict::proved : verdict::undecided), name,
                 mm ? "" : "frame m = " + m.str());
      c_root.add(verdict::proved, name);  // local-root + cover: the minimum is |q| at the q' root
      // P4.lobe: neighbours of X among the q roots u/pi in Z (fast) and (m + 2 N a)/(2 b) (slow).
      verdict v_lobe = verdict::undecided;
      std::string lobe_info;
      {
        I t = X / pi;  // u*/pi
        auto fl = certain_floor(t);
        // slow nodes: (m + 2 N a)/(2b) < t  <=>  N < (2 b t - m)/(2a)
        I ns = (2 * real_from_int<I>(b) * t - real_from_int<I>(m)) / (2 * real_from_int<I>(a));
        auto nfl = certain_floor(ns);
        if (fl && nfl) {
          big_int Mleft = *fl, Mright = *fl + 1;
          big_int Nleft = *nfl, Nright = *nfl + 1;
          // slow node values as fractions over 2b: sl = m + 2 Nleft a, sr = m + 2 Nright a
          big_int sl = m + 2 * Nleft * a, sr = m + 2 * Nright * a, den = 2 * b;
          bool left_slow = sl > Mleft * den;    // slow node to the right of the fast one: nearer
          bool right_slow = sr < Mright * den;
          v_lobe = decide_bool(left_slow || right_slow);
          lobe_info = std::string("lobe ends: ") + (left_slow ? "slow" : "fast") + "/" + (right_slow ? "slow" : "fast");
        }
      }
      c_lobe.add(v_lobe, name, v_lobe == verdict::proved ? "" : lobe_info);
      // P4.unimodal (literal): a node with 0 < m_j < b refutes it; b = 1: holds (Lemma 4.2').
      verdict v_uni = verdict::undecided;
      std::string uni_info;
      if (b == 1) {
        v_uni = verdict::proved;
        uni_info = "b = 1: both lobes at each slow node are short (Lemma 4.2')";
      } else {
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
          if (neg_fs && pos_gs && neg_fh && neg_gh && pos_fp) {
            v_uni = verdict::refuted;
            uni_info = "node j = " + jj.str() + ", frame k = " + kj.str() + ", m = " + mj.str() +
                       ": long lobe [s, pi], R increases after s, q' root in (pi/2, pi)";
          }
          break;
        }
      }
      c_uni.add(v_uni, name, uni_info);
      // P5: lobes of the minimisers (exact k mod a) and of the first one.
      auto imgs = proof::images_of(K, k, j, with_shift);
      bool loc = false;
      std::optional<std::size_t> first;
      std::vector<I> thetas;
      for (auto& im : imgs) {
        thetas.push_back(proof::theta_of(K, im.k, im.negate_u ? I(-X) : X));
        if (in_paper_lobe(im.k)) loc = true;
      }
      for (std::size_t i = 0; i < thetas.size(); ++i) {
        bool smallest = true;
        for (std::size_t i2 = 0; i2 < thetas.size(); ++i2)
          if (i2 != i && !certainly_less(thetas[i], thetas[i2])) smallest = false;
        if (smallest) first = i;
      }
      verdict v_first = verdict::undecided;
      big_int k_first = -1;
      if (first) {
        k_first = int_mod(imgs[*first].k, a);
        v_first = decide_bool(in_paper_lobe(k_first));
        // Consistency with the certificate's theta_first (both enclose the same point; the
        // certificate's is rounded outward to its printed digits, this one is computed from X).
        if (certainly_less(thetas[*first], th_first) || certainly_less(th_first, thetas[*first]))
          v_first = verdict::undecided;
      }
      c_loc.add(decide_bool(loc), name);
      std::string fi = "first minimiser in lobe " + k_first.str() + ", paper lobe " + ks[0].str() +
                       (ks.size() > 1 ? "/" + ks[1].str() : "");
      c_first.add(v_first, name, fi);
      if (2 * b < a) c_first_s.add(v_first, name, fi);
      else c_first_s.add(verdict::not_applicable, name);
      line += std::string(" ") + (copt.max_nodes > 0 ? "slow-nodes" : "all-lobes") + " | r_res in [" + cert.r_res.first +
              ", " + cert.r_res.second + "] | theta_first in [" + cert.theta_first.first + ", " +
              cert.theta_first.second + "] | " + std::to_string(cert.minimiser_count) + " (" + k.str() + "," + j.str() +
              "," + m.str() + ") lobe " + k_first.str() + " k0 " + ks[0].str() + " | " + enc(ratio, 6) + " | " +
              verdict_name(decide_bool(cert.minimiser_count == expect)) + " " +
              verdict_name(mm && inside ? verdict::proved : verdict::undecided) + " " + verdict_name(v_lobe) + " " +
              verdict_name(v_uni) + " " + verdict_name(v_first);
      R.log(line);
      print_cert_once(c_uni, cert, name);
      print_cert_once(c_first, cert, name);
      print_cert_once(c_first_s, cert, name);
    }
    R.note("t_first/(pi/|n|) = theta_first b/pi ranges over [" + format_scientific(ratio_lo, 6) + ", " +
           format_scientific(ratio_hi, 6) + "] (the paper's proxy T_min ~ pi/|n| means ratio ~ 1)");
    return R.finish();
  });
}
