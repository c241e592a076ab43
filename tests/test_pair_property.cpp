// Property test of prove_pair (report/pair_report.hpp) over random pairs of every size:
// tau with 2 to 500 decimal digits, x = (tau - sigma)/(tau + sigma) near 0, near 1/2 and near 1
// (and tau = 3 sigma + 1, a minimiser just past 0 and its mirror just below 2 pi),
// D in 1..200. For each case:
//   * it answers (no compute_error: `gyrores pair` would exit 3);
//   * every field at D digits (the minimiser list and the asymptotics included) is the
//     (D + 10)-digit answer rounded to D digits (a hand rounding of the decimal string, exact; a
//     tail of exactly 5000000000 accepts either neighbour), and the same for a third run at D_hi
//     digits (enough to place the fast phase tau theta well inside r_res 10^-D);
//   * every D-digit value lies inside the enclosure of the D_hi run widened to D digits;
//   * the minimisers are ascending in [0, 2 pi), 2 of them (4 when delta = 0 mod 4), the mirror
//     of each is another (theta -> 2 pi - theta, checked on the D_hi strings);
//   * the independent naive forms (src/testing/naive_forms.hpp, tau theta formed directly at
//     brute precision) evaluated at the D_hi minimisers give R = r_res^2 to D digits.
// The default ctest run is short (a fixed seed, 3 cases per size and pair class, D <= 60); set
// GYRORES_TEST_MULTIPLIER=N for N times more cases with D up to 200 (the long run; its count and
// result are printed).
#include <catch2/catch.hpp>

#include <algorithm>
#include <iostream>
#include <random>
#include <string>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/report/pair_report.hpp>

#include "testing/naive_forms.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;

namespace {

constexpr std::uint64_t kSeed = 20261123u;

big_int random_digits(std::mt19937_64& rng, unsigned digits) {
  std::string s(1, char('1' + rng() % 9));
  for (unsigned i = 1; i < digits; ++i) s += char('0' + rng() % 10);
  return big_int(s);
}

// A coprime pair with tau of `digits` digits and x near 0 (class 0), 1/2 (1) or 1 (2), or
// tau = 3 sigma + 1 (class 3: x ~ 1/2 with a minimiser ~ pi/(2 sigma) just past 0 and its mirror
// just below 2 pi, the shape of issue 12's wrong number).
resonant_pair<big_int> random_pair(std::mt19937_64& rng, unsigned digits, int cls) {
  for (;;) {
    big_int tau = random_digits(rng, digits), sigma;
    const big_int wiggle = big_int(rng() % 1000);
    if (cls == 0) sigma = tau - 1 - wiggle;                 // b small: x ~ (1 + wiggle)/(2 tau)
    else if (cls == 1) sigma = tau / 3 + wiggle;           // x = (tau - sigma)/(tau + sigma) ~ 1/2
    else if (cls == 2) sigma = 1 + wiggle;                 // x ~ 1 - 2 sigma/tau
    else {
      sigma = tau / 3;
      tau = 3 * sigma + 1;
    }
    if (sigma < 1 || sigma >= tau) continue;
    if (boost::multiprecision::gcd(tau, sigma) != 1) continue;
    return resonant_pair<big_int>(tau, sigma);
  }
}

// The decimal string s ("d.ddd...e+XX") rounded to d digits, exactly (ties to even); `tie` is set
// when the digits dropped are exactly 5000...0 (the rounding of s is then not the rounding of the
// value s came from).
std::string rounded(const std::string& s, unsigned d, bool& tie) {
  const big_rational q = parse_rational(s, "value");
  const std::size_t e = s.find('e');
  std::string mant = s.substr(0, e);
  mant.erase(std::remove(mant.begin(), mant.end(), '.'), mant.end());
  if (!mant.empty() && mant[0] == '-') mant.erase(0, 1);
  const std::string dropped = mant.size() > d ? mant.substr(d) : "";
  tie = !dropped.empty() && dropped[0] == '5' && dropped.find_first_not_of('0', 1) == std::string::npos;
  return format_rational_scientific(q, d);
}

// a (D digits) agrees with b (more digits) rounded to D digits.
bool agrees(const std::string& a, const std::string& b, unsigned d) {
  bool tie = false;
  const std::string r = rounded(b, d, tie);
  if (r == a) return true;
  if (!tie) return false;
  // A tie in b: a may be either neighbour of b's D-digit truncation.
  const big_rational qa = parse_rational(a, "a"), qb = parse_rational(b, "b");
  const big_rational diff = qa > qb ? big_rational(qa - qb) : big_rational(qb - qa);
  const big_rational ra = parse_rational(r, "r");
  const big_rational half_ulp = ra > qb ? big_rational(ra - qb) : big_rational(qb - ra);
  return diff == half_ulp;
}

pair_report report_at(const resonant_pair<big_int>& p, unsigned digits) {
  pair_report_options opt;
  opt.digits = digits;
  opt.enclosures = true;
  return prove_pair(p, opt);
}

// Every field of lo (D digits) agrees with hi (more digits), and lies in hi's enclosure.
void check_agree(const pair_report& lo, const pair_report& hi, unsigned d) {
  auto same = [&](const std::string& name, const proved_real& a, const proved_real& b) {
    INFO(name << ": " << a.value << " vs " << b.value);
    CHECK(agrees(a.value, b.value, d));
    // The exact value is in b's enclosure, and a is its rounding: a is within half a unit of
    // its last digit of that enclosure.
    const big_rational qa = parse_rational(a.value, "a"), lo_b = parse_rational(b.enclosure.first, "lo"),
                       hi_b = parse_rational(b.enclosure.second, "hi");
    const big_rational ulp = parse_rational("1e" + std::to_string(std::stol(a.value.substr(a.value.find('e') + 1)) -
                                                                   long(d) + 1), "ulp");
    CHECK(qa >= lo_b - ulp);
    CHECK(qa <= hi_b + ulp);
  };
  for (auto [name, a, b] : {std::tuple{"beat_ratio", &lo.beat_ratio, &hi.beat_ratio}, {"n", &lo.n, &hi.n},
                            {"omega1", &lo.omega1, &hi.omega1}, {"omega2", &lo.omega2, &hi.omega2},
                            {"rho0", &lo.rho0, &hi.rho0}, {"qdot0", &lo.qdot0, &hi.qdot0},
                            {"r_res", &lo.r_res, &hi.r_res},
                            {"h_min", &lo.h_min, &hi.h_min}, {"h_z_max", &lo.h_z_max, &hi.h_z_max},
                            {"theta_first", &lo.theta_first, &hi.theta_first}, {"t_first", &lo.t_first, &hi.t_first},
                            {"t_min_paper", &lo.t_min_paper, &hi.t_min_paper}})
    same(name, *a, *b);
  REQUIRE(lo.minimisers.size() == hi.minimisers.size());
  for (std::size_t i = 0; i < lo.minimisers.size(); ++i) same("minimisers", lo.minimisers[i], hi.minimisers[i]);
  REQUIRE(bool(lo.r_res_asy) == bool(hi.r_res_asy));
  if (lo.r_res_asy) {
    same("r_res_asy", *lo.r_res_asy, *hi.r_res_asy);
    same("r_res_asy_rel_error", *lo.r_res_asy_rel_error, *hi.r_res_asy_rel_error);
  }
  REQUIRE(lo.lobes.size() == hi.lobes.size());
  for (std::size_t i = 0; i < lo.lobes.size(); ++i) {
    const std::string pre = "asymptotic.lobes." + std::to_string(i) + ".";
    CHECK(lo.lobes[i].k == hi.lobes[i].k);
    CHECK(lo.lobes[i].m == hi.lobes[i].m);
    for (auto [name, a, b] : {std::tuple{"s", &lo.lobes[i].s, &hi.lobes[i].s},
                              {"u_asy", &lo.lobes[i].u_asy, &hi.lobes[i].u_asy},
                              {"theta_asy", &lo.lobes[i].theta_asy, &hi.lobes[i].theta_asy},
                              {"theta_c", &lo.lobes[i].theta_c, &hi.lobes[i].theta_c},
                              {"error", &lo.lobes[i].error, &hi.lobes[i].error},
                              {"bound", &lo.lobes[i].bound, &hi.lobes[i].bound},
                              {"ratio", &lo.lobes[i].ratio, &hi.lobes[i].ratio}})
      same(pre + name, *a, *b);
  }
}

// Structure of the minimiser list and R at the minimisers by the naive forms, from the D_hi run.
void check_minimisers(const resonant_pair<big_int>& p, const pair_report& hi, unsigned d) {
  const unsigned tau_digits = unsigned(p.tau().str().size());
  scoped_digits sd(hi.digits + tau_digits + 30);  // tau theta and the cancellation in q
  const mpfr_real two_pi = 2 * real_pi<mpfr_real>();
  const std::size_t expected = p.degenerate() ? 2 : (p.delta_mod4() == 0 ? 4 : 2);
  REQUIRE(hi.minimisers.size() == expected);
  std::vector<mpfr_real> th;
  for (const auto& s : hi.minimisers) th.push_back(mpfr_real(s.value));
  for (std::size_t i = 0; i < th.size(); ++i) {
    CHECK(th[i] > 0);
    CHECK(th[i] < two_pi);
    if (i) CHECK(th[i - 1] < th[i]);
    // The mirror 2 pi - theta is in the list (to the D_hi strings' rounding).
    const mpfr_real tol = two_pi * pow(mpfr_real(10), -int(hi.digits) + 1);
    bool found = false;
    for (const auto& t : th) found = found || abs(mpfr_real(two_pi - th[i] - t)) <= tol;
    CHECK(found);
  }
  const mpfr_real r = mpfr_real(hi.r_res.value), v = mpfr_real(hi.qdot0.value);
  const test::naive_forms<mpfr_real> f(real_from_int<mpfr_real>(p.tau()), real_from_int<mpfr_real>(p.sigma()), v);
  for (const auto& t : th) {
    const mpfr_real R = f.R(t);
    INFO("R at " << format_scientific(t, 20) << " = " << format_scientific(R, 20) << ", r_res^2 = "
                 << format_scientific(mpfr_real(r * r), 20));
    if (p.degenerate()) CHECK(abs(R) < pow(mpfr_real(10), -int(d)));
    else CHECK(format_scientific(sqrt(R), d) == format_scientific(r, d));
  }
}

// Digits of the third run: its minimisers must place R within r_res^2 10^-(D+10) of the
// minimum. R - r_res^2 ~ (tau W1 dtheta)^2 (q' has slope ~ tau W1 through its root), so dtheta
// ~ 10^-D_hi must be below r_res 10^-(D/2+5)/(tau W1), with W1 = sqrt(tau/sigma).
unsigned d_hi_for(const resonant_pair<big_int>& p, const pair_report& lo, unsigned d) {
  const unsigned tau_digits = unsigned(p.tau().str().size()), sigma_digits = unsigned(p.sigma().str().size());
  const unsigned w1_digits = (tau_digits + 1 - std::min(tau_digits, sigma_digits)) / 2 + 1;
  unsigned r_digits = tau_digits;  // degenerate pairs: the zero's neighbourhood, as for r_res ~ 1/tau
  if (!p.degenerate()) {
    const long e = std::stol(lo.r_res.value.substr(lo.r_res.value.find('e') + 1));
    r_digits = e < 0 ? unsigned(-e) : 0u;
  }
  return d + 20 + tau_digits + w1_digits + r_digits;
}

}  // namespace

TEST_CASE("prove_pair property: random pairs of every size agree across precisions and with R", "[truth][property]") {
  const int mult = test::multiplier();
  std::mt19937_64 rng(kSeed + std::uint64_t(mult));
  const unsigned max_digits = mult > 1 ? 200u : 60u;
  // Size classes of tau: 2-3, 4-20, 21-100, 101-500 digits.
  const unsigned lo_sizes[] = {2, 4, 21, 101}, hi_sizes[] = {3, 20, 100, 500};
  const int per_class = mult > 1 ? 4 * mult : 3;
  int cases = 0;
  for (int size_class = 0; size_class < 4; ++size_class)
    for (int cls = 0; cls < 4; ++cls)
      for (int i = 0; i < per_class; ++i) {
        const unsigned span = hi_sizes[size_class] - lo_sizes[size_class] + 1;
        const unsigned digits_tau = lo_sizes[size_class] + unsigned(rng() % span);
        const auto p = random_pair(rng, digits_tau, cls);
        const unsigned d = 1 + unsigned(rng() % max_digits);
        pair_report lo, mid, hi;
        REQUIRE_NOTHROW(lo = report_at(p, d));
        REQUIRE_NOTHROW(mid = report_at(p, d + 10));
        REQUIRE_NOTHROW(hi = report_at(p, d_hi_for(p, lo, d)));
        check_agree(lo, mid, d);
        check_agree(lo, hi, d);
        check_minimisers(p, hi, d);
        ++cases;
      }
  std::cout << "prove_pair property: " << cases << " random pairs (tau 2..500 digits, D 1.." << max_digits
            << "), multiplier " << mult << "\n";
}
