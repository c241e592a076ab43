// The horizon theorem (theorem/horizon.hpp, proofs/horizon-theorem.md) against independent
// references: the scan of every critical point of H_q in 200-bit MPFR (tests/reference/horizon_scan.hpp's
// horizon_minimum, which knows nothing of lobes) for T <= 400, the pair analysis of a resonant
// coupling, and a plain loop over lobes. Every printed digit must be the correct rounding.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "reference/horizon_scan.hpp"
#include "testing/test_support.hpp"
#include <gyrores/gyrores.hpp>

using namespace gyrores;
using ref_real = mpfr_fixed<60>;

namespace {

// q in T: numerator and denominator rounded to T, then divided (real_from_ratio: relative
// error <= 1.5 ulp; exact when both fit T's significand).
template <class T> T real_from_rational(const big_rational& q) {
  return real_from_ratio<T>(big_int(boost::multiprecision::numerator(q)), big_int(boost::multiprecision::denominator(q)));
}

struct scanned {
  ref_real h, t;
  bool at_end;
};

scanned scan(const coupling_spec& c, const big_rational& T) {
  const ref_real n = c.n ? real_from_rational<ref_real>(*c.n) : ref_real(sqrt(real_from_rational<ref_real>(c.n2)));
  const auto r = horizon_minimum<ref_real>(n, ref_real(1), real_from_rational<ref_real>(T));
  return {r.h_min, r.t_min, r.at_horizon_end};
}

// The reference rounds to the same text, unless it lies within 1e-45 (relative) of a rounding
// boundary, where a 60-digit reference cannot tell (reported, not failed).
bool same_rounding(const ref_real& ref, const std::string& proved, unsigned digits, int& undecidable) {
  const std::string a = format_scientific(real_to_mpfr(ref_real(ref * (1 - ref_real("1e-45")))), digits);
  const std::string b = format_scientific(real_to_mpfr(ref_real(ref * (1 + ref_real("1e-45")))), digits);
  if (a != b) {
    ++undecidable;
    return true;
  }
  return a == proved;
}

big_rational random_decimal(std::mt19937_64& rng, double lo, double hi, int decimals) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  const double v = std::exp(u(rng));
  const big_int scale = boost::multiprecision::pow(big_int(10), unsigned(decimals));
  return big_rational(big_int(static_cast<long long>(v * std::pow(10.0, decimals))), scale);
}

}  // namespace

TEST_CASE("horizon: minimum and first time equal the critical-point scan (T <= 400)", "[horizon]") {
  std::mt19937_64 rng(2024);
  int undecidable = 0, at_end = 0, ran = 0;
  for (int i = 0; i < 60; ++i) {
    // n from 1e-3 to 30 as a decimal, or n^2 as a fraction (resonant when D is a square); T from 0.1 to 400.
    const coupling_spec c = i % 4 == 3 ? coupling_spec::from_n2(big_rational(1 + long(rng() % 200), 1 + long(rng() % 50)))
                                       : coupling_spec::from_n(random_decimal(rng, 1e-3, 30, 6));
    const big_rational T = i % 3 == 0 ? random_decimal(rng, 0.1, 3, 3) : random_decimal(rng, 0.1, 400, 4);
    const double w1 = std::sqrt(c.n2.convert_to<double>() + 4);
    if (w1 * T.convert_to<double>() > 60000) continue;  // the scan costs O(T W1)
    ++ran;
    INFO("n^2 = " << rational_str(c.n2) << ", T = " << rational_str(T));
    const horizon_minimum_report r = report_horizon_minimum(c, T, 17);
    const scanned s = scan(c, T);
    CHECK(r.proof.at_horizon_end == s.at_end);
    at_end += r.proof.at_horizon_end;
    CHECK(same_rounding(s.h, r.h_min.value, 17, undecidable));
    CHECK(same_rounding(s.t, r.t_min.value, 17, undecidable));
    // The enclosures hold the reference.
    CHECK(parse_rational(r.h_min.enclosure.first, "lo") <= parse_rational(format_scientific(real_to_mpfr(s.h), 40), "h"));
  }
  CHECK(ran >= 50);
  CHECK(undecidable <= 2);
  CHECK(at_end >= 3);  // short horizons end while H_q still falls
}

TEST_CASE("horizon: a resonant coupling over a whole period gives the pair's H_min and t_first", "[horizon]") {
  for (auto [tau, sigma] : {std::pair{4, 3}, std::pair{6, 5}, std::pair{9, 4}, std::pair{5, 1}, std::pair{11, 9}}) {
    const resonant_pair<big_int> p{big_int(tau), big_int(sigma)};
    // n^2 = (tau - sigma)^2/(tau sigma) for the pair.
    const coupling_spec c = coupling_spec::from_n2(big_rational((tau - sigma) * (tau - sigma), tau * sigma));
    const pair_report pr = prove_pair_values(p, 25);
    const big_rational T = parse_rational(pr.t_first.value, "t") * 3 + 1;
    const horizon_minimum_report r = report_horizon_minimum(c, T, 25);
    INFO(p.str());
    CHECK(r.h_min.value == pr.h_min.value);
    CHECK(r.t_min.value == pr.t_first.value);
    CHECK_FALSE(r.proof.at_horizon_end);
  }
}

TEST_CASE("horizon: a plain loop over every lobe agrees up to T = 10^6", "[horizon]") {
  // The lobe with the smallest ||k x - 1/2|| over k < k_c, found by a loop in long double over
  // every lobe, for n = 2 (the paper's Fig. 1a), 0.1832, 7.25 and random couplings from 10^-3 to
  // 30: decimals, and n^2 as a fraction (resonant pairs and not); T = 10^6 and random T.
  std::mt19937_64 rng(1906);
  std::vector<std::pair<coupling_spec, big_rational>> cases;
  for (const char* n_text : {"2", "0.1832", "7.25"})
    cases.push_back({coupling_spec::from_n(parse_rational(n_text, "n")), big_rational(1000000)});
  for (int i = 0; i < 6; ++i)
    cases.push_back({coupling_spec::from_n(random_decimal(rng, 1e-3, 30, 6)), i % 2 ? big_rational(1000000) : random_decimal(rng, 1e3, 1e6, 2)});
  for (auto [tau, sigma] : {std::pair{7, 3}, std::pair{101, 100}, std::pair{40, 1}})  // resonant: n^2 = (tau - sigma)^2/(tau sigma)
    cases.push_back({coupling_spec::from_n2(big_rational((tau - sigma) * (tau - sigma), tau * sigma)), big_rational(1000000)});
  cases.push_back({coupling_spec::from_n2(big_rational(7, 3)), big_rational(654321)});  // not resonant
  for (const auto& [c, T] : cases) {
    const horizon_minimum_report r = report_horizon_minimum(c, T, 20);
    const long double n = std::sqrt(c.n2.convert_to<long double>()), x = n / std::sqrt(n * n + 4);
    const long kc = r.proof.cut_lobe.convert_to<long>();
    long best = 0;
    long double best_nu = 0.5L;
    for (long k = 1; k < kc; ++k) {
      long double f = k * x - 0.5L;
      long double nu = std::fabs(f - std::nearbyint(f));
      if (nu < best_nu) best_nu = nu, best = k;
    }
    INFO("n^2 = " << rational_str(c.n2) << ", T = " << rational_str(T) << ", k_c = " << kc);
    CHECK(std::fabs(double(kc - std::floor(std::sqrt(n * n + 4) * T.convert_to<long double>() / (2 * M_PIl) + 0.5L))) < 1);
    REQUIRE(r.lobe.has_value());
    // A resonant coupling repeats its lobes (nu_{k+a} = nu_k): the loop's first may be a later
    // copy after rounding, so there only the value is compared.
    if (r.lobe->k != r.proof.cut_lobe && !r.proof.x.is_rational()) CHECK(r.lobe->k == best);
    CHECK(std::fabs(r.lobe->nu.approx() - double(best_nu)) < 1e-12);
  }
}

TEST_CASE("horizon: tiny couplings answer (x below the working precision's spacing)", "[horizon_precision]") {
  // x ~ n/2: H(pi/2) = (1 + x) pi/2 exceeds pi/2 by less than the first precision can see, so
  // the first brackets are refused and the precision rises (a refusal must not be an error).
  // (Not tagged [horizon]: the mutants, whose brackets fail at every precision, would spend
  // minutes here on G's steep root before giving up.)
  for (const char* n : {"1e-40", "1e-50", "3e-200"}) {
    for (const char* T : {"10", "100", "1e6"}) {
      INFO("n = " << n << ", T = " << T);
      const horizon_minimum_report r =
          report_horizon_minimum(coupling_spec::from_n(parse_rational(n, "n")), horizon_time(parse_rational(T, "T")), 12);
      // For n T << 1, R = q^2 + q'^2 = 1 - x^2 sin^2(t) + O(n T): H_q stays within 1e-30 of 1/2.
      const double h = std::stod(r.h_min.value);
      CHECK(h <= 0.5);
      CHECK(h > 0.5 - 1e-12);
    }
    CHECK_FALSE(report_first_below(coupling_spec::from_n(parse_rational(n, "n")), big_rational(1, 4), 12).never);
  }
}

TEST_CASE("horizon: T up to 10^100 answers, and the lobe is exact", "[horizon]") {
  const coupling_spec c = coupling_spec::from_n(big_rational(2));
  const big_rational T(boost::multiprecision::pow(big_int(10), 100));
  const horizon_minimum_report r = report_horizon_minimum(c, T, 30);
  REQUIRE(r.lobe.has_value());
  // nu ~ 1/k_c: the minimum is of order (pi nu)^4; the time has 100 digits before the point.
  CHECK(r.lobe->nu.approx() < 1e-98);
  CHECK(r.t_min.value.find("e+") != std::string::npos);
  CHECK(r.h_min.value.find("e-") != std::string::npos);
  CHECK(r.lobe->k <= r.proof.cut_lobe);
}

TEST_CASE("horizon: first time below a level equals a fine scan", "[horizon]") {
  std::mt19937_64 rng(99);
  for (int i = 0; i < 25; ++i) {
    const coupling_spec c = coupling_spec::from_n(random_decimal(rng, 0.05, 10, 5));
    // A level between the minimum over [0, 60] and 1/2.
    const horizon_minimum_report m = report_horizon_minimum(c, big_rational(60), 17);
    const double hmin = std::stod(m.h_min.value);
    const double level = hmin + (0.5 - hmin) * std::uniform_real_distribution<double>(0.02, 0.9)(rng);
    const big_rational E = parse_rational(format_scientific(real_to_mpfr(level), 12), "E");
    const first_below_report b = report_first_below(c, E, 17);
    INFO("n^2 = " << rational_str(c.n2) << " E = " << rational_str(E));
    REQUIRE_FALSE(b.never);
    // Reference: the first critical-point scan minimum below E over growing horizons brackets the
    // crossing; check H_q at the proved time equals E and H_q > E a little before.
    const double t = std::stod(b.t_below.value);
    const ref_real n = real_from_rational<ref_real>(*c.n);
    const auto before = horizon_minimum<ref_real>(n, ref_real(1), ref_real(t * (1 - 1e-9)));
    const auto st = impulse_response<ref_real>(n, ref_real(1), real_from_rational<ref_real>(parse_rational(b.t_below.value, "t")));
    CHECK(before.h_min > real_from_rational<ref_real>(E));
    CHECK(abs(energy_q(st) - real_from_rational<ref_real>(E)) < ref_real("1e-12"));
  }
}

TEST_CASE("horizon: levels that are never reached, and E >= 1/2", "[horizon]") {
  // (6, 5) is resonant with H_min ~ 1.29e-3: E = 1e-3 is never reached; E = 2e-3 is.
  const coupling_spec c = coupling_spec::from_n2(big_rational(1, 30));
  CHECK(report_first_below(c, big_rational(1, 1000), 12).never);
  CHECK_FALSE(report_first_below(c, big_rational(2, 1000), 12).never);
  CHECK(report_first_below(c, big_rational(0), 12).never);
  // Irrational: 0 is never reached, any E > 0 is.
  const coupling_spec two = coupling_spec::from_n(big_rational(2));
  CHECK(report_first_below(two, big_rational(0), 12).never);
  CHECK_FALSE(report_first_below(two, big_rational(1, 1000000), 12).never);
  const first_below_report z = report_first_below(two, big_rational(1, 2), 12);
  CHECK(z.t_below.value == "0.00000000000e+00");
  // Degenerate (11, 9): H_q = 0 first at t_first = sqrt(99) pi/2.
  const coupling_spec d = coupling_spec::from_n2(big_rational(4, 99));
  const first_below_report zero = report_first_below(d, big_rational(0), 15);
  REQUIRE_FALSE(zero.never);
  CHECK(zero.t_below.value == prove_pair_values(resonant_pair<big_int>(11, 9), 15).t_first.value);
  CHECK_THROWS_AS(report_first_below(two, big_rational(-1), 12), usage_error);
  CHECK_THROWS_AS(report_horizon_minimum(two, big_rational(-1), 12), usage_error);
}

TEST_CASE("horizon: levels at the supremum 1 - x^2 of the lobe values are decided exactly", "[horizon]") {
  // n = 2: x^2 = 1/2, so 2E = 1 - x^2 at E = 1/4 (the level "50%"). The comparison with the
  // supremum is exact (a rational), so the level itself, and levels 10^-30 above and below it,
  // answer: lobe 0 reaches each of them, at a time that does not decrease as the level falls
  // (H_q decreases on lobe 0's descending branch).
  const coupling_spec two = coupling_spec::from_n(big_rational(2));
  const big_rational sup(1, 4), eps(1, boost::multiprecision::pow(big_int(10), 30));
  const first_below_report at = report_first_below(two, sup, 20);
  const first_below_report above = report_first_below(two, sup + eps, 20);
  const first_below_report below = report_first_below(two, sup - eps, 20);
  for (const first_below_report* r : {&at, &above, &below}) {
    REQUIRE_FALSE(r->never);
    REQUIRE(r->proof.lobe);
    CHECK(r->proof.lobe->lobe.k == 0);
    CHECK(r->proof.kase == below_case::lobe);
  }
  // The crossing times are ordered (the times differ by about 10^-30 relative: equal to 20 digits
  // is allowed, the order of the enclosures' ends is not).
  CHECK(above.proof.t_below.lo_rational() <= at.proof.t_below.hi_rational());
  CHECK(at.proof.t_below.lo_rational() <= below.proof.t_below.hi_rational());
  CHECK(at.proof.t_below.lo_rational() > 0);
  // An independent value: the model's impulse response (model.hpp, 60 digits) has H_q = 1/4 at
  // the printed time (to its 20 digits) and H_q > 1/4 a little before it.
  const ref_real t = ref_real(at.t_below.value);
  const auto hq = [](const ref_real& s) { return energy_q(impulse_response(ref_real(2), ref_real(1), s)); };
  CHECK(abs(hq(t) - ref_real("0.25")) < ref_real("1e-17"));
  CHECK(hq(t * ref_real("0.999")) > ref_real("0.25"));
}
