// verify_degenerate: paper Thm. degenerate (docs/mathematics.md §2, P3), for every pair up to --max-order,
// independently of certify_pair (it reuses only the proof steps: lobe frames, basins, cover).
//
// The theorem is proved in proofs/README.md (P3) and proofs/global-minimality.md §1. Per pair
// this program decides, with exact integers and MPFI:
//   P3.zero        delta = 2 mod 4  =>  q(pi/2) = q'(pi/2) = 0: tau, sigma odd and
//                  tau + sigma = 0 mod 4 (integers), so cos(tau pi/2) = cos(sigma pi/2) = 0 and
//                  sin(tau pi/2) = -sin(sigma pi/2) (exact); MPFI enclosures of the paper's
//                  q(pi/2), q'(pi/2) must contain 0 (consistency only).
//   P3.zero-set    delta = 2 mod 4  =>  the zeros of R in [0, 2 pi) are exactly pi/2 and 3 pi/2, so
//                  pi/2 is the first: around each, in the lobe frame (a/4, (b-2)/4) (m = 0) and its
//                  mirror, a basin Y is proved (q' strictly monotone with a sign change, z' != 0:
//                  the zero is the only critical point of R in Y) and the cover proves R > 0 on
//                  [0, 2 pi) outside the two basins.
//   P3.positive    delta != 2 mod 4  =>  R > 0 on all of [0, 2 pi) (cover with bound 0, no basins),
//                  so r_res > 0.
//   P3.iff         r_res = 0 <=> delta = 2 mod 4: the conjunction of the above for the pair.
// Cover strategy: "all-lobes" (every fast lobe bisected) when a <= 8 b, "slow-nodes" (Rayleigh
// bound away from the slow nodes, the lobes at each node bisected) otherwise; both are
// proof::run_cover (reference/cover.hpp) with bound 0 (proofs/global-minimality.md §6, §7).
#include <limits>

#include "reference/cover.hpp"
#include "verify_common.hpp"

using namespace gyrores;
using namespace gyrores::proofs;
using I = gyrores::proof::I;
using P = gyrores::proof::P;

namespace {

struct degenerate_claims {
  claim &zero, &zero_set, &positive, &iff;
};

degenerate_claims add_claims(run& R) {
  return {R.add_claim("P3.zero", "delta = 2 mod 4 => q(pi/2) = q'(pi/2) = 0 (integers; MPFI consistent)", true),
          R.add_claim("P3.zero-set",
                      "delta = 2 mod 4 => the zeros of R in [0, 2 pi) are exactly pi/2, 3 pi/2 (basins + "
                      "cover with bound 0); pi/2 is the first zero",
                      true),
          R.add_claim("P3.positive", "delta != 2 mod 4 => R > 0 on [0, 2 pi) (cover with bound 0)", true),
          R.add_claim("P3.iff", "r_res = 0 <=> delta = 2 mod 4", true)};
}

// The cover with bound 0 outside the basins: its decision and the log's description.
struct zero_cover {
  verdict v = verdict::undecided;
  std::string info;
  std::uint64_t boxes = 0;
};

zero_cover cover_without_zeros(const proof::constants& K, const proof::basin_map& basins) {
  certify_options copt;
  copt.max_lobes = std::numeric_limits<std::int64_t>::max();
  copt.max_nodes = std::numeric_limits<std::int64_t>::max();
  const std::string strategy = (K.a <= 8 * K.b) ? "all-lobes" : "slow-nodes";
  auto cov = proof::run_cover(K, basins, interval_point(P(0)), copt, strategy, "");
  zero_cover out;
  out.boxes = cov.stats.boxes;
  out.v = cov.proved ? verdict::proved : verdict::undecided;
  out.info = strategy + " lobes " + std::to_string(cov.stats.lobes) + " boxes " + std::to_string(cov.stats.boxes);
  if (!cov.proved) out.info += " " + cov.note;
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

// A basin around u = 0 in a frame with m = 0 (mu = 0), or nullopt.
std::optional<I> zero_basin(const proof::constants& K) {
  I mu = proof::mu_of(K, big_int(0));
  for (P rho = P("0.5"); rho > P("1e-6"); rho /= 4) {
    I cand = interval_of(P(-rho), rho);
    if (proof::certify_basin(K, mu, cand)) return cand;
  }
  return std::nullopt;
}

// delta = 2 mod 4: P3.zero, then the basins of pi/2 and 3 pi/2 and the cover outside them.
zero_cover decide_degenerate(degenerate_claims& C, const resonant_pair<big_int>& p, const proof::constants& K) {
  const std::string name = p.str();
  bool zero = zero_at_half_pi(p, K);
  C.zero.add(decide_bool(zero), name);
  // The frame of pi/2: (a/4, (b-2)/4), where m = (2j+1) a - 2 k b is 0.
  big_int k = K.a / 4, j = (K.b - 2) / 4;
  const bool m_zero = (2 * j + 1) * K.a - 2 * k * K.b == 0;
  auto Y = m_zero ? zero_basin(K) : std::nullopt;
  zero_cover out;
  if (Y) out = cover_without_zeros(K, proof::basins_by_lobe(K, proof::images_of(K, k, j, false), *Y));
  else out.info = m_zero ? "no basin proved" : "frame m != 0";
  C.zero_set.add(out.v, name, out.v == verdict::proved ? "" : out.info);
  C.positive.add(verdict::not_applicable, name);
  C.iff.add(verdict_and(decide_bool(zero), out.v), name);
  return out;
}

// delta != 2 mod 4: R > 0 everywhere (no basins).
zero_cover decide_positive(degenerate_claims& C, const resonant_pair<big_int>& p, const proof::constants& K) {
  const std::string name = p.str();
  zero_cover out = cover_without_zeros(K, {});
  C.zero.add(verdict::not_applicable, name);
  C.zero_set.add(verdict::not_applicable, name);
  C.positive.add(out.v, name, out.v == verdict::proved ? "" : out.info);
  C.iff.add(out.v, name);
  return out;
}

int verify(const options& opt) {
  run R("verify_degenerate", "paper Thm. degenerate (P3): r_res = 0 <=> delta = 2 mod 4, zeros at pi/2 and 3 pi/2",
        opt);
  auto C = add_claims(R);
  R.log("# per pair: (tau,sigma) delta mod 4 | strategy lobes boxes | decision");
  std::uint64_t total_boxes = 0;
  for_each_pair(R, opt, [&](const resonant_pair<std::int64_t>& p64) {
    auto p = big_pair(p64);
    scoped_digits sd(digits10_for_bits(64u + unsigned(boost::multiprecision::msb(p.order()))));
    auto K = proof::constants_of(p);
    const bool deg = p.degenerate();
    zero_cover res = deg ? decide_degenerate(C, p, K) : decide_positive(C, p, K);
    total_boxes += res.boxes;
    R.log(p.str() + " delta_mod4=" + std::to_string(p.delta_mod4()) + " | " + res.info + " | " +
          (deg ? "zeros exactly {pi/2, 3pi/2}: " : "R > 0: ") + verdict_name(res.v));
  });
  R.note("cover boxes in total: " + std::to_string(total_boxes));
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  return run_program("verify_degenerate", "verify_degenerate: paper Thm. degenerate (P3)", {}, argc, argv, verify);
}
