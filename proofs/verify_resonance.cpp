// verify_resonance: paper Prop. resonance (docs/mathematics.md §2, P1), for every pair up to --max-order.
//
// The proof is exact algebra (proofs/README.md, P1): with a = tau + sigma, b = tau - sigma,
//   a^2 - b^2 = 4 tau sigma                                            (integer identity)
// gives, for n = b/sqrt(tau sigma), n^2 + 4 = a^2/(tau sigma), so sqrt(n^2 + 4) = a/sqrt(tau sigma),
// Omega_1 = (a + b)/(2 sqrt(tau sigma)) = sqrt(tau/sigma), Omega_2 = sqrt(sigma/tau), and
// Omega_1/Omega_2 = tau/sigma. The period of (q, q') is T = 2 pi sqrt(tau sigma)
// (Omega_1 T = 2 pi tau, Omega_2 T = 2 pi sigma).
//
// Per pair the program decides, exactly in integers (__int128):
//   P1.identity   a^2 - b^2 = 4 tau sigma, a + b = 2 tau, a - b = 2 sigma, gcd(b^2, tau sigma) = 1
//                 (so n^2 = b^2/(tau sigma) is in lowest terms);
// and cross-checks in MPFI at 128 bits, from the paper's own formulas (eq. Omegas, not the
// simplified ones):
//   P1.intervals  tau lies in the enclosure of sigma Omega_1/Omega_2, 1 in that of
//                 Omega_1 Omega_2, and tau, sigma in those of Omega_1 T/(2 pi), Omega_2 T/(2 pi).
// Over the whole run it decides
//   P1.injective  distinct pairs give distinct n^2 (n^2 = b^2/(tau sigma) reduced; the pairs
//                 (b, tau sigma) are all distinct), so each resonant coupling n > 0 has one pair.
// Intervals can only show consistency (containment), never equality: the identity is the proof.
#include <algorithm>
#include <numeric>

#include "verify_common.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using namespace gyrores::proofs;

namespace {

int verify(const options& opt) {
  run R("verify_resonance", "paper Prop. resonance (P1): n^2 = (tau-sigma)^2/(tau sigma) <=> Omega_1/Omega_2 = tau/sigma",
        opt);
  auto& c_id = R.add_claim("P1.identity",
                           "a^2 - b^2 = 4 tau sigma, a +- b = 2 tau, 2 sigma and gcd(b^2, tau sigma) = 1 (exact integers)",
                           true);
  auto& c_iv = R.add_claim("P1.intervals",
                           "tau in sigma Omega_1/Omega_2, 1 in Omega_1 Omega_2, Omega_1 T/(2 pi) contains tau, Omega_2 T/(2 pi) contains "
                           "sigma with T = 2 pi sqrt(tau sigma) (paper eq. Omegas, MPFI 128 bits)",
                           true);
  auto& c_inj = R.add_claim("P1.injective", "distinct pairs have distinct n^2 = b^2/(tau sigma)", true);
  R.log("# per pair: (tau,sigma) a b n^2=b^2/(tau sigma) Omega_1/Omega_2 enclosure | identity intervals");

  scoped_digits sd(digits10_for_bits(128));
  const mpfi_real pi = real_pi<mpfi_real>();
  std::vector<std::vector<std::int64_t>> products(std::size_t(opt.max_order) + 1);  // by b: tau sigma
  for_each_pair(R, opt, [&](const resonant_pair<std::int64_t>& p) {
    const __int128 t = p.tau(), s = p.sigma(), a = t + s, b = t - s;
    const std::string name = p.str();
    bool ok = a * a - b * b == 4 * t * s && a + b == 2 * t && a - b == 2 * s;
    std::int64_t ts = std::int64_t(t * s);
    ok = ok && std::gcd(std::int64_t(b * b), ts) == 1;
    c_id.add(decide_bool(ok), name);
    products[std::size_t(b)].push_back(ts);

    // The paper's formulas, literally: n, then Omega_{1,2} = (sqrt(n^2 + 4) +- n)/2.
    mpfi_real T = mpfi_real(std::int64_t(t)), S = mpfi_real(std::int64_t(s));
    mpfi_real n = mpfi_real(std::int64_t(b)) / sqrt(T * S);
    mpfi_real root = sqrt(n * n + 4);
    mpfi_real w1 = (root + n) / 2, w2 = (root - n) / 2;
    mpfi_real ratio = w1 / w2, prod = w1 * w2;
    mpfi_real period = 2 * pi * sqrt(T * S);
    mpfi_real c1 = w1 * period / (2 * pi), c2 = w2 * period / (2 * pi);
    auto holds = [](const mpfi_real& v, const mpfi_real& in) { return certainly_subset(v, in); };
    // tau/sigma is not a binary point: require the integer tau inside sigma (Omega_1/Omega_2).
    bool consistent = holds(T, S * ratio) && holds(mpfi_real(1), prod) && holds(T, c1) && holds(S, c2);
    c_iv.add(decide_bool(consistent), name);
    if (R.logging())
      R.log(name + " a=" + to_decimal(std::int64_t(a)) + " b=" + to_decimal(std::int64_t(b)) + " n^2=" +
            to_decimal(std::int64_t(b * b)) + "/" + to_decimal(ts) + " W1/W2=" + enc(ratio, 20) + " | " +
            verdict_name(decide_bool(ok)) + " " + verdict_name(decide_bool(consistent)));
  });
  // Injectivity: for each b, the products tau sigma are distinct (b and tau sigma fix the pair:
  // tau and -sigma are the roots of X^2 - b X - tau sigma).
  bool inj = true;
  std::string dup;
  for (std::size_t b = 1; b < products.size(); ++b) {
    auto& v = products[b];
    std::sort(v.begin(), v.end());
    auto it = std::adjacent_find(v.begin(), v.end());
    if (it != v.end()) {
      inj = false;
      dup = "b = " + std::to_string(b) + ", tau sigma = " + std::to_string(*it);
      break;
    }
  }
  c_inj.add(decide_bool(inj), "all pairs", dup);
  R.log(std::string("# P1.injective over the run: ") + verdict_name(decide_bool(inj)));
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  return run_program("verify_resonance", "verify_resonance: paper Prop. resonance (P1)", {}, argc, argv, verify);
}
