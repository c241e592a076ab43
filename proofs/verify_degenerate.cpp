// verify_degenerate: paper Thm. degenerate (docs/mathematics.md §2, P3), for every pair up to --max-order.
//
// The theorem is proved in proofs/README.md (P3) and proofs/global-minimality.md §1. Per pair
// this program decides, with exact integers, MPFI and the lattice theorem's certificate
// (gyrores-certificate/2, proofs/lattice-theorem.md, re-proved by the independent checker of
// src/checker/):
//   P3.zero        delta = 2 mod 4  =>  q(pi/2) = q'(pi/2) = 0: tau, sigma odd and
//                  tau + sigma = 0 mod 4 (integers), so cos(tau pi/2) = cos(sigma pi/2) = 0 and
//                  sin(tau pi/2) = -sin(sigma pi/2) (exact); MPFI enclosures of the paper's
//                  q(pi/2), q'(pi/2) must contain 0 (consistency only).
//   P3.zero-set    delta = 2 mod 4  =>  the zeros of R in [0, 2 pi) are exactly pi/2 and 3 pi/2, so
//                  pi/2 is the first: the certificate states m_min = 0, r_res = 0 and exactly the
//                  two lobes (a/4, (b-2)/4) and (3a/4, (3b-2)/4) with m = 0 and u* = 0, i.e.
//                  theta = 2 k pi/a = pi/2, 3 pi/2: by the theorem these are all the global
//                  minimisers, the zeros of R.
//   P3.positive    delta != 2 mod 4  =>  R > 0 on all of [0, 2 pi): the certificate's r_res has a
//                  positive lower end.
//   P3.iff         r_res = 0 <=> delta = 2 mod 4: the conjunction of the above for the pair.
// A certificate the checker does not accept decides nothing (undecided). (Up to commit 9cd03bc
// this program proved the last three by interval covers of every lobe, without the theorem; its
// runs are the logs of proofs/README.md.)
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/io/certificate_json.hpp>

#include "certificate_checker.hpp"
#include "reference/lobe_intervals.hpp"
#include "verify_common.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using namespace gyrores::proofs;
using I = gyrores::proof::I;

namespace {

struct degenerate_claims {
  claim &zero, &zero_set, &positive, &iff;
};

degenerate_claims add_claims(run& R) {
  return {R.add_claim("P3.zero", "delta = 2 mod 4 => q(pi/2) = q'(pi/2) = 0 (integers; MPFI consistent)", true),
          R.add_claim("P3.zero-set",
                      "delta = 2 mod 4 => the zeros of R in [0, 2 pi) are exactly pi/2, 3 pi/2 (the theorem's "
                      "certificate: the two m = 0 lobes at u* = 0, r_res = 0); pi/2 is the first zero",
                      true),
          R.add_claim("P3.positive", "delta != 2 mod 4 => R > 0 on [0, 2 pi) (the certificate's r_res > 0)", true),
          R.add_claim("P3.iff", "r_res = 0 <=> delta = 2 mod 4", true)};
}

// The pair's certificate, with the checker's verdict: undecided (and why) unless it holds.
struct checked_certificate {
  theorem_certificate cert;
  verdict v = verdict::undecided;
  std::string info;
};

checked_certificate certify_and_check(const resonant_pair<big_int>& p) {
  checked_certificate out;
  out.cert = certify_by_theorem(p, 6);
  const auto check = gyrores_checker::check_theorem_certificate(certificate_to_json(out.cert).dump());
  out.v = check.status == 0 ? verdict::proved : verdict::undecided;
  out.info = check.status == 0 ? "certificate checked" : "certificate not accepted: " + check.message;
  return out;
}

// P3.zero: the integer facts, and the paper's q(pi/2)/rho0, q'(pi/2)/rho0 enclosures contain 0.
bool zero_at_half_pi(const resonant_pair<big_int>& p, const proof::constants& K) {
  bool ints = int_mod(p.tau(), big_int(2)) == 1 && int_mod(p.sigma(), big_int(2)) == 1 &&
              int_mod(K.a, big_int(4)) == 0 && int_mod(big_int(K.b), big_int(4)) == 2;
  I half = K.c.pi / 2;
  I Tq = real_from_int<I>(p.tau()), Sq = real_from_int<I>(p.sigma());
  I q = sin(Tq * half) + sin(Sq * half);
  I qd = K.c.omega1 * cos(Tq * half) + K.c.omega2 * cos(Sq * half);
  return ints && !certainly_nonzero(q) && !certainly_nonzero(qd);
}

// delta = 2 mod 4: P3.zero, then the zero lobes of the certificate.
verdict decide_degenerate(degenerate_claims& C, const resonant_pair<big_int>& p, const proof::constants& K,
                          checked_certificate& cc) {
  const std::string name = p.str();
  const bool zero = zero_at_half_pi(p, K);
  C.zero.add(decide_bool(zero), name);
  const auto& c = cc.cert;
  // The frames of pi/2 and 3 pi/2: (a/4, (b-2)/4) and (3a/4, (3b-2)/4), where m = (2j+1) a - 2 k b is 0.
  const bool lobes = c.lobes.size() == 2 && c.lobes[0].k == K.a / 4 && c.lobes[0].j == (K.b - 2) / 4 &&
                     c.lobes[1].k == 3 * K.a / 4 && c.lobes[1].j == (3 * K.b - 2) / 4 && c.lobes[0].m == 0 &&
                     c.lobes[1].m == 0;
  const bool at_zero = c.m_min == 0 && c.u_star == std::pair<std::string, std::string>{"0", "0"} &&
                       c.r_res == std::pair<std::string, std::string>{"0", "0"};
  const verdict v = verdict_and(cc.v, decide_bool(lobes && at_zero));
  if (!(lobes && at_zero)) cc.info += "; lobes or zero claims not those of pi/2, 3 pi/2";
  C.zero_set.add(v, name, v == verdict::proved ? "" : cc.info);
  C.positive.add(verdict::not_applicable, name);
  C.iff.add(verdict_and(decide_bool(zero), v), name);
  return v;
}

// delta != 2 mod 4: r_res > 0.
verdict decide_non_degenerate(degenerate_claims& C, const resonant_pair<big_int>& p, checked_certificate& cc) {
  const std::string name = p.str();
  const verdict v = verdict_and(cc.v, decide_positive(interval_from_decimal(cc.cert.r_res.first, cc.cert.r_res.second)));
  C.zero.add(verdict::not_applicable, name);
  C.zero_set.add(verdict::not_applicable, name);
  C.positive.add(v, name, v == verdict::proved ? "" : cc.info);
  C.iff.add(v, name);
  return v;
}

int verify(const options& opt) {
  run R("verify_degenerate", "paper Thm. degenerate (P3): r_res = 0 <=> delta = 2 mod 4, zeros at pi/2 and 3 pi/2",
        opt);
  auto C = add_claims(R);
  R.log("# per pair: (tau,sigma) delta mod 4 | r_res | certificate | decision");
  for_each_pair(R, opt, [&](const resonant_pair<std::int64_t>& p64) {
    auto p = big_pair(p64);
    checked_certificate cc = certify_and_check(p);
    scoped_digits sd(digits10_for_bits(cc.cert.bits));
    auto K = proof::constants_of(p);
    const bool deg = p.degenerate();
    const verdict v = deg ? decide_degenerate(C, p, K, cc) : decide_non_degenerate(C, p, cc);
    R.log(p.str() + " delta_mod4=" + std::to_string(p.delta_mod4()) + " | r_res in [" + cc.cert.r_res.first + ", " +
          cc.cert.r_res.second + "] | " + cc.info + " | " + (deg ? "zeros exactly {pi/2, 3pi/2}: " : "R > 0: ") +
          verdict_name(v));
  });
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  return run_program("verify_degenerate", "verify_degenerate: paper Thm. degenerate (P3)", {}, argc, argv, verify);
}
