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
// bound away from the slow nodes, the lobes at each node bisected) otherwise; both are the
// library's proof::exclude_lobe with bound 0 (proofs/global-minimality.md §6, §7).
#include <gyrores/certify/certificate.hpp>

#include "verify_common.hpp"

using namespace gyrores;
using namespace gyrores::proofs;
using P = gyrores::proof::P;

int main(int argc, char** argv) {
  return guarded_main("verify_degenerate", [&] {
    auto opt = parse_options(argc, argv);
    run R("verify_degenerate", "paper Thm. degenerate (P3): r_res = 0 <=> delta = 2 mod 4, zeros at pi/2 and 3 pi/2",
          opt);
    auto& c_zero = R.add_claim("P3.zero", "delta = 2 mod 4 => q(pi/2) = q'(pi/2) = 0 (integers; MPFI consistent)", true);
    auto& c_set = R.add_claim("P3.zero-set",
                              "delta = 2 mod 4 => the zeros of R in [0, 2 pi) are exactly pi/2, 3 pi/2 (basins + "
                              "cover with bound 0); pi/2 is the first zero",
                              true);
    auto& c_pos = R.add_claim("P3.positive", "delta != 2 mod 4 => R > 0 on [0, 2 pi) (cover with bound 0)", true);
    auto& c_iff = R.add_claim("P3.iff", "r_res = 0 <=> delta = 2 mod 4", true);
    R.log("# per pair: (tau,sigma) delta mod 4 | strategy lobes boxes | decision");
    std::uint64_t total_boxes = 0;
    for (auto p64 : coprime_pairs(opt.min_order, opt.max_order)) {
      R.count_pair();
      resonant_pair<big_int> p(p64.tau(), p64.sigma());
      const std::string name = p.str();
      const bool deg = p.degenerate();
      const unsigned bits = 64u + unsigned(boost::multiprecision::msb(p.order()));
      scoped_digits sd(digits10_for_bits(bits));
      auto K = proof::constants_of(p);
      certify_options copt;
      copt.max_lobes = std::numeric_limits<std::int64_t>::max();
      copt.max_nodes = std::numeric_limits<std::int64_t>::max();
      const std::string strategy = (K.a <= 8 * K.b) ? "all-lobes" : "slow-nodes";
      std::map<big_int, std::vector<proof::I>> basins;
      verdict v_main;
      std::string info;
      if (deg) {
        // Integers: tau, sigma odd, a = 0 mod 4.
        bool ints = int_mod(p.tau(), big_int(2)) == 1 && int_mod(p.sigma(), big_int(2)) == 1 &&
                    int_mod(K.a, big_int(4)) == 0 && int_mod(big_int(K.b), big_int(4)) == 2;
        // Consistency: the paper's q(pi/2)/rho0, q'(pi/2)/rho0 contain 0.
        proof::I half = K.c.pi / 2;
        proof::I Tq = real_from_int<proof::I>(p.tau()), Sq = real_from_int<proof::I>(p.sigma());
        proof::I q = sin(Tq * half) + sin(Sq * half);
        proof::I qd = K.c.omega1 * cos(Tq * half) + K.c.omega2 * cos(Sq * half);
        bool consistent = !certainly_nonzero(q) && !certainly_nonzero(qd);
        c_zero.add(decide_bool(ints && consistent), name);
        // Basins around u = 0 in the frames of pi/2 and 3 pi/2.
        big_int k = K.a / 4, j = (K.b - 2) / 4;
        big_int m = (2 * j + 1) * K.a - 2 * k * K.b;
        std::optional<proof::I> Y;
        if (m == 0) {
          proof::I mu = proof::mu_of(K, m);
          for (P rho = P("0.5"); rho > P("1e-6") && !Y; rho /= 4) {
            proof::I cand = interval_of(P(-rho), rho);
            if (proof::certify_basin(K, mu, cand)) Y = cand;
          }
        }
        if (!Y) {
          v_main = verdict::undecided;
          info = m == 0 ? "no basin proved" : "frame m != 0";
        } else {
          auto imgs = proof::images_of(K, k, j, false);
          basins = detail::basins_by_lobe(K, imgs, *Y);
          auto cov = detail::run_cover(p, K, basins, interval_point(P(0)), copt, strategy, "");
          total_boxes += cov.stats.boxes;
          v_main = cov.proved ? verdict::proved : verdict::undecided;
          info = strategy + " lobes " + std::to_string(cov.stats.lobes) + " boxes " + std::to_string(cov.stats.boxes);
          if (!cov.proved) info += " " + cov.note;
        }
        c_set.add(v_main, name, v_main == verdict::proved ? "" : info);
        c_pos.add(verdict::not_applicable, name);
        c_iff.add(verdict_and(decide_bool(ints && consistent), v_main), name);
      } else {
        auto cov = detail::run_cover(p, K, basins, interval_point(P(0)), copt, strategy, "");
        total_boxes += cov.stats.boxes;
        v_main = cov.proved ? verdict::proved : verdict::undecided;
        info = strategy + " lobes " + std::to_string(cov.stats.lobes) + " boxes " + std::to_string(cov.stats.boxes);
        if (!cov.proved) info += " " + cov.note;
        c_zero.add(verdict::not_applicable, name);
        c_set.add(verdict::not_applicable, name);
        c_pos.add(v_main, name, v_main == verdict::proved ? "" : info);
        c_iff.add(v_main, name);
      }
      R.log(name + " delta_mod4=" + std::to_string(p.delta_mod4()) + " | " + info + " | " +
            (deg ? "zeros exactly {pi/2, 3pi/2}: " : "R > 0: ") + verdict_name(v_main));
    }
    R.note("cover boxes in total: " + std::to_string(total_boxes));
    return R.finish();
  });
}
