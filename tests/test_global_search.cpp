// The global search for the inscribed radius (global_search.hpp, degenerate.hpp) against the
// independent brute-force reference of src/testing/reference.hpp (naive R(theta), dense scan, refinement
// in float128 or MPFR; no lobe frames, no TOMS 748, no integer shortcut for degenerate pairs).
//
// Also: the paper's Section V numbers (docs/mathematics.md §2, P8), recomputed from the paper's own definitions.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <gyrores/core/decimal.hpp>
#include "reference/degenerate.hpp"
#include <gyrores/model/enumerate.hpp>
#include "reference/global_search.hpp"
#include <gyrores/model/pair.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/model/resonant.hpp>

#include "testing/reference.hpp"
#include "testing/test_support.hpp"

using gyrores::float128;
using gyrores::inscribed_global;
using gyrores::mpfr_real;
using gyrores::resonant_pair;
using gyrores::scoped_digits;
using gyrores::test::rel_error;
using p64 = resonant_pair<std::int64_t>;

namespace {

// Exact number of global minimisers expected (docs/mathematics.md §3; observed there, checked here):
// delta = 2 mod 4: the two zeros pi/2, 3pi/2; delta odd: 2 (a mirror pair); delta = 0 mod 4: 4.
std::size_t expected_minimisers(std::int64_t tau, std::int64_t sigma) {
  std::int64_t d = tau - sigma;
  if (d % 4 == 2) return 2;
  return d % 2 == 1 ? 2 : 4;
}

// float128 reference for every coprime pair of order <= 200, computed once (shared by the test
// cases that need it). theta to 2^-100; tie threshold 1e-25 relative.
struct ref_entry {
  std::int64_t tau, sigma;
  gyrores::ref::ref_result<float128> r;
};
const std::vector<ref_entry>& references_order_200() {
  static const std::vector<ref_entry> table = [] {
    std::vector<ref_entry> t;
    for (auto p : gyrores::coprime_pairs(3, 200))
      t.push_back({p.tau(), p.sigma(),
                   gyrores::ref::reference_inscribed<float128>(p.tau(), p.sigma(), 100, float128(1e-25),
                                                                float128(1e-50))});
    return t;
  }();
  return table;
}

}  // namespace

TEST_CASE("degeneracy (P3): r_res = 0 iff delta = 2 mod 4, every coprime pair of order <= 200",
          "[global][degenerate]") {
  const auto& refs = references_order_200();
  REQUIRE(refs.size() == 6115);  // sum_{a=3}^{200} phi(a)/2
  std::size_t degenerate = 0;
  const double pi = M_PI;
  float128 max_deg = 0, min_nondeg = 1;
  for (const auto& e : refs) {
    INFO("pair (" << e.tau << ", " << e.sigma << ")");
    p64 p(e.tau, e.sigma);
    const bool deg = (e.tau - e.sigma) % 4 == 2;
    REQUIRE(p.degenerate() == deg);
    // The reference's global minimum, found without the integer shortcut.
    if (deg) {
      ++degenerate;
      CHECK(e.r.r_res < float128(1e-25));
      if (e.r.r_res > max_deg) max_deg = e.r.r_res;
      // Zeros at pi/2 and 3 pi/2 only; pi/2 is the first zero.
      REQUIRE(e.r.minimisers.size() == 2);
      CHECK(fabs(e.r.minimisers[0] - float128(pi / 2)) < float128(1e-15));
      CHECK(fabs(e.r.minimisers[1] - float128(3 * pi / 2)) < float128(1e-15));
    } else {
      CHECK(e.r.r_res > float128(1e-6));  // smallest over these pairs: 2.2e-6 at (198, 1)
      if (e.r.r_res < min_nondeg) min_nondeg = e.r.r_res;
    }
    // The library (which does use the integer shortcut).
    auto lib = inscribed_global(p, 1.0);
    CHECK(lib.degenerate == deg);
    if (deg) {
      CHECK(lib.r_res == 0);
      CHECK(lib.h_min == 0);
      CHECK(lib.method == gyrores::inscribed_method::degenerate_exact);
      CHECK(lib.theta_first == Approx(pi / 2).epsilon(1e-15));
    } else {
      CHECK(lib.r_res > 0);
      CHECK(lib.method == gyrores::inscribed_method::global_search);
      CHECK(std::fabs(lib.r_res - double(e.r.r_res)) <= 1e-10 * double(e.r.r_res));
    }
  }
  // Sanity of the count: pairs with delta = 2 mod 4 up to order 200.
  std::size_t count = 0;
  for (auto p : gyrores::coprime_pairs(3, 200)) count += p.degenerate() ? 1 : 0;
  CHECK(degenerate == count);
  CHECK(max_deg < min_nondeg * float128(1e-15));

  // R(pi/2) = 0 and R(3 pi/2) = 0 exactly: evaluated in MPFR at 100 digits for every degenerate pair.
  scoped_digits d(100);
  double min_other = 1;
  const mpfr_real mpi = boost::math::constants::pi<mpfr_real>();
  for (const auto& e : refs) {
    if ((e.tau - e.sigma) % 4 != 2) continue;
    INFO("pair (" << e.tau << ", " << e.sigma << ")");
    gyrores::ref::naive_model<mpfr_real> m(e.tau, e.sigma);
    CHECK(m.R(mpfr_real(mpi / 2)) < mpfr_real("1e-190"));
    CHECK(m.R(mpfr_real(3 * mpi / 2)) < mpfr_real("1e-190"));
    // ... and nowhere else: every other local minimum of the scan is far from 0.
    CHECK(e.r.other_min_radius_sq > 1e-12);
    if (e.r.other_min_radius_sq < min_other) min_other = e.r.other_min_radius_sq;
  }
  WARN("order <= 200: largest reference r_res of a degenerate pair " << double(max_deg)
       << ", smallest r_res of a non-degenerate pair " << double(min_nondeg)
       << ", smallest R at another local minimum of a degenerate pair " << min_other);
}

TEST_CASE("brute force: inscribed_global agrees with the reference to 25 digits, all pairs of order <= 40",
          "[global][brute][mpfr]") {
  std::size_t pairs = 0;
  mpfr_real worst_r = 0, worst_t = 0;
  for (auto p : gyrores::coprime_pairs(3, 40)) {
    INFO("pair " << p.str());
    ++pairs;
    gyrores::inscribed_result<mpfr_real> lib;
    {
      scoped_digits d(40);
      lib = inscribed_global(p, mpfr_real(1));
    }
    scoped_digits d(50);
    auto ref = gyrores::ref::reference_inscribed<mpfr_real>(p.tau(), p.sigma(), 160, mpfr_real("1e-30"),
                                                            mpfr_real("1e-80"));
    const mpfr_real tol("1e-25");
    const std::size_t want = expected_minimisers(p.tau(), p.sigma());
    REQUIRE(ref.minimisers.size() == want);
    REQUIRE(lib.minimisers.size() == want);
    if (p.degenerate()) {
      CHECK(lib.r_res == 0);
      CHECK(ref.r_res < mpfr_real("1e-45"));
    } else {
      CHECK(rel_error(lib.r_res, ref.r_res) <= tol);
      if (rel_error(lib.r_res, ref.r_res) > worst_r) worst_r = rel_error(lib.r_res, ref.r_res);
    }
    CHECK(rel_error(lib.theta_first, ref.theta_first) <= tol);
    if (rel_error(lib.theta_first, ref.theta_first) > worst_t) worst_t = rel_error(lib.theta_first, ref.theta_first);
    for (std::size_t i = 0; i < want; ++i) {
      INFO("minimiser " << i);
      CHECK(rel_error(lib.minimisers[i], ref.minimisers[i]) <= tol);
    }
    // Derived fields, against the reference's own derivation.
    const mpfr_real sqrt_ts = sqrt(mpfr_real(p.tau()) * mpfr_real(p.sigma()));
    CHECK(rel_error(lib.t_first, mpfr_real(sqrt_ts * ref.theta_first)) <= tol);
    CHECK(abs(mpfr_real(lib.h_min - ref.radius_sq / 2)) <= tol * (ref.radius_sq + mpfr_real("1e-60")));
    CHECK(abs(mpfr_real(lib.h_z_max - (mpfr_real("0.5") - ref.radius_sq / 2))) <= tol);
  }
  CHECK(pairs == 244);  // sum_{a=3}^{40} phi(a)/2
  WARN("order <= 40, MPFR 40 digits: worst relative error r_res " << worst_r.str(3) << ", theta_first "
                                                                      << worst_t.str(3));
}

TEST_CASE("brute force in double: all pairs of order <= 200 agree with the reference to 10 digits",
          "[global][brute]") {
  const auto& refs = references_order_200();
  double worst_r = 0, worst_t = 0;
  for (const auto& e : refs) {
    INFO("pair (" << e.tau << ", " << e.sigma << ")");
    p64 p(e.tau, e.sigma);
    auto lib = inscribed_global(p, 1.0);
    const std::size_t want = expected_minimisers(e.tau, e.sigma);
    REQUIRE(e.r.minimisers.size() == want);
    REQUIRE(lib.minimisers.size() == want);
    if (!p.degenerate()) {
      double er = std::fabs(lib.r_res - double(e.r.r_res)) / double(e.r.r_res);
      CHECK(er <= 1e-10);
      worst_r = std::max(worst_r, er);
    }
    double et = std::fabs(lib.theta_first - double(e.r.theta_first)) / double(e.r.theta_first);
    CHECK(et <= 1e-10);
    worst_t = std::max(worst_t, et);
    for (std::size_t i = 0; i < want; ++i) {
      INFO("minimiser " << i);
      CHECK(std::fabs(lib.minimisers[i] - double(e.r.minimisers[i])) <= 1e-10 * double(e.r.minimisers[i]));
    }
    CHECK(lib.t_first == Approx(std::sqrt(double(e.tau) * double(e.sigma)) * double(e.r.theta_first)).epsilon(1e-10));
  }
  WARN("order <= 200, double: worst relative error r_res " << worst_r << ", theta_first " << worst_t);
}

namespace {
struct ladder_value {
  mpfr_real r_res, theta_first;
  std::vector<mpfr_real> minimisers;
};
template <class T> ladder_value ladder_run(const p64& p) {
  auto r = inscribed_global(p, T(1));
  ladder_value out{gyrores::real_to_mpfr(r.r_res), gyrores::real_to_mpfr(r.theta_first), {}};
  for (const auto& m : r.minimisers) out.minimisers.push_back(gyrores::real_to_mpfr(m));
  return out;
}
}  // namespace

TEST_CASE("precision ladder: double, long double, float128, MPFR 50 and 200 digits agree to the lower precision",
          "[global][ladder]") {
  const std::pair<std::int64_t, std::int64_t> pairs[] = {{6, 5}, {9, 4}, {5, 1}, {2, 1}, {101, 100}, {1000, 1}};
  for (auto [tau, sigma] : pairs) {
    p64 p(tau, sigma);
    INFO("pair " << p.str());
    scoped_digits top(200);
    ladder_value v200 = ladder_run<mpfr_real>(p);
    // The top rung against the independent reference at 230 digits.
    {
      scoped_digits d(230);
      auto ref = gyrores::ref::reference_inscribed<mpfr_real>(tau, sigma, 700, mpfr_real("1e-100"),
                                                              mpfr_real("1e-300"));
      REQUIRE(ref.minimisers.size() == v200.minimisers.size());
      CHECK(rel_error(v200.r_res, ref.r_res) <= mpfr_real("1e-195"));
      CHECK(rel_error(v200.theta_first, ref.theta_first) <= mpfr_real("1e-195"));
    }
    ladder_value v50;
    {
      scoped_digits d(50);
      v50 = ladder_run<mpfr_real>(p);
    }
    struct rung {
      const char* name;
      ladder_value v;
      mpfr_real eps;
    };
    const rung rungs[] = {
        {"double", ladder_run<double>(p), mpfr_real(std::numeric_limits<double>::epsilon())},
        {"long double", ladder_run<long double>(p), mpfr_real(std::numeric_limits<long double>::epsilon())},
        {"float128", ladder_run<float128>(p), gyrores::real_to_mpfr(std::numeric_limits<float128>::epsilon())},
        {"mpfr 50", v50, mpfr_real("1e-49")},
    };
    for (const auto& g : rungs) {
      INFO("type " << g.name);
      // 16 ulp of the lower type (observed: at most 2.3 ulp).
      CHECK(rel_error(g.v.r_res, v200.r_res) <= 16 * g.eps);
      CHECK(rel_error(g.v.theta_first, v200.theta_first) <= 16 * g.eps);
      REQUIRE(g.v.minimisers.size() == v200.minimisers.size());
      for (std::size_t i = 0; i < v200.minimisers.size(); ++i) CHECK(rel_error(g.v.minimisers[i], v200.minimisers[i]) <= 16 * g.eps);
    }
  }
}

TEST_CASE("result fields, amplitude scaling, integer types and errors", "[global]") {
  for (auto [tau, sigma] : std::vector<std::pair<std::int64_t, std::int64_t>>{{2, 1}, {6, 5}, {9, 4}, {5, 1}, {13, 5}, {120, 7}}) {
    p64 p(tau, sigma);
    INFO("pair " << p.str());
    auto r = inscribed_global(p, 1.0);
    CHECK(r.critical_points == std::size_t(4 * tau));  // every root of q' and z'
    CHECK(r.evaluations > 0);
    CHECK(r.h_min == Approx(r.r_res * r.r_res / 2).epsilon(1e-15));
    CHECK(r.h_z_max == Approx(0.5 - r.h_min).epsilon(1e-15));
    CHECK(r.theta_first == r.minimisers.front());
    for (std::size_t i = 0; i < r.minimisers.size(); ++i) {
      CHECK(r.minimisers[i] >= 0);
      CHECK(r.minimisers[i] < 2 * M_PI);
      if (i > 0) CHECK(r.minimisers[i - 1] < r.minimisers[i]);
    }
    // Mirror pairs: theta and 2 pi - theta are both minimisers.
    for (double m : r.minimisers) {
      bool found = false;
      for (double m2 : r.minimisers) found = found || std::fabs(m + m2 - 2 * M_PI) < 1e-12;
      CHECK(found);
    }
    // The first minimiser in lobe coordinates: theta = 2 (k pi + u)/a (mod 2 pi), m = (2j+1) a - 2 k b.
    const std::int64_t a = tau + sigma, b = tau - sigma;
    gyrores::big_int k = r.first.k, j = r.first.j;
    CHECK(r.first.m == (2 * j + 1) * a - 2 * k * b);
    gyrores::big_int k_mod = k % a;
    double th = 2 * (k_mod.convert_to<double>() * M_PI + r.first.u) / double(a);
    th = std::fmod(th + 4 * M_PI, 2 * M_PI);
    CHECK(th == Approx(r.theta_first).epsilon(1e-14));
    // Linearity in the amplitude: r_res(v) = v r_res(1).
    auto r2 = inscribed_global(p, 2.5);
    CHECK(r2.r_res == Approx(2.5 * r.r_res).epsilon(1e-14));
    CHECK(r2.theta_first == Approx(r.theta_first).epsilon(1e-14));
    CHECK(r2.h_z_max == Approx(2.5 * 2.5 / 2 - r2.h_min).epsilon(1e-14));
    // big_int pairs give the same answer.
    auto rb = inscribed_global(resonant_pair<gyrores::big_int>(tau, sigma), 1.0);
    CHECK(rb.r_res == Approx(r.r_res).epsilon(1e-15));
    CHECK(rb.theta_first == Approx(r.theta_first).epsilon(1e-15));
  }
  CHECK_THROWS_AS(inscribed_global(p64(6, 5), 0.0), gyrores::usage_error);
  CHECK_THROWS_AS(inscribed_global(p64(6, 5), -1.0), gyrores::usage_error);
  CHECK_THROWS_AS(inscribed_global(p64(6, 5), std::nan("")), gyrores::usage_error);
  gyrores::global_search_options small;
  small.max_order = 10;
  CHECK_THROWS_AS(inscribed_global(p64(9, 4), 1.0, small), gyrores::compute_error);
  CHECK_THROWS_WITH(inscribed_global(p64(9, 4), 1.0, small), Catch::Contains("(9, 4)"));
  CHECK_NOTHROW(inscribed_global(p64(4, 3), 1.0, small));   // order 7 <= 10
  CHECK_NOTHROW(inscribed_global(p64(11, 9), 1.0, small));  // degenerate: decided exactly, no search
}

// The paper's Section V numbers (docs/mathematics.md §2, P8), recomputed from the paper's
// definitions, at 50 digits: the resonant coupling n = delta/sqrt(tau sigma), its proxy
// T_min ~ pi/n, and the paper's beat condition (tau + sigma >= 10 delta).
namespace {

mpfr_real n_of(std::int64_t tau, std::int64_t sigma) {
  return mpfr_real(tau - sigma) / sqrt(mpfr_real(tau) * mpfr_real(sigma));
}
bool beat_ok(std::int64_t tau, std::int64_t sigma) { return (tau + sigma) >= 10 * (tau - sigma); }

// Every Section V case runs at 50 digits (d first: pi is then a 50-digit pi).
struct section_v {
  scoped_digits d{50};
  const mpfr_real pi = boost::math::constants::pi<mpfr_real>();
};

}  // namespace

TEST_CASE_METHOD(section_v,
                 "paper Section V, case A, delta = 2: (11, 9), n = 0.201, T_min ~ pi/n = 15.6 s; the true first "
                 "zero is at pi/n too",
                 "[global][paper]") {
  // Smallest pair with delta = 2 and beat ratio >= 10 (tau >= 11, sigma >= 9): (11, 9).
  std::int64_t s = 1;
  while (!(std::gcd(s + 2, s) == 1 && beat_ok(s + 2, s))) ++s;
  CHECK(s + 2 == 11);
  CHECK(s == 9);
  mpfr_real n = n_of(11, 9);
  CHECK(abs(mpfr_real(n - 2 / sqrt(mpfr_real(99)))) < mpfr_real("1e-48"));
  CHECK(abs(mpfr_real(n - mpfr_real("0.201"))) < mpfr_real("0.0005"));  // printed "n = 0.201"
  mpfr_real tmin = pi / n;                                                // 15.6292...
  CHECK(abs(mpfr_real(tmin - mpfr_real("15.6"))) < mpfr_real("0.05"));  // printed "T_min = 15.6 s"
  // True first zero: theta = pi/2, t = sqrt(tau sigma) pi/2 = (delta/2) pi/n = pi/n for delta = 2.
  auto r = inscribed_global(p64(11, 9), mpfr_real(1));
  CHECK(r.r_res == 0);
  CHECK(rel_error(r.t_first, mpfr_real(sqrt(mpfr_real(99)) * pi / 2)) < mpfr_real("1e-45"));
  CHECK(rel_error(r.t_first, tmin) < mpfr_real("1e-45"));
  gyrores::ref::naive_model<mpfr_real> m(11, 9);
  CHECK(m.R(mpfr_real(pi / 2)) < mpfr_real("1e-90"));
}

TEST_CASE_METHOD(section_v,
                 "paper Section V, case A, delta = 6: the smallest valid pair is (35, 29), not (41, 35); T_min ~ "
                 "19.8 s is only the proxy",
                 "[global][paper]") {
  // The paper: "With delta = 6, (beat) gives tau >= 33, so the smallest coprime that agrees to these
  // conditions is (41, 35), but T_min = 19.8 s". tau >= 33 is right, but (33, 27) has gcd 3 and
  // (35, 29) is coprime: (35, 29) is the smallest. The paper's (41, 35) is wrong.
  std::int64_t s = 1;
  while (!beat_ok(s + 6, s)) ++s;
  CHECK(s + 6 == 33);  // the paper's bound tau >= 33 is correct
  CHECK(std::gcd(33, 27) == 3);
  while (std::gcd(s + 6, s) != 1) ++s;
  CHECK(s + 6 == 35);
  CHECK(s == 29);
  CHECK(p64(35, 29).degenerate());
  CHECK(p64(41, 35).degenerate());
  // For (41, 35): n = 6/sqrt(1435) and pi/n = 19.83 s: the printed 19.8 is the proxy pi/n.
  mpfr_real n41 = n_of(41, 35);
  CHECK(abs(mpfr_real(n41 - 6 / sqrt(mpfr_real(1435)))) < mpfr_real("1e-48"));
  CHECK(abs(mpfr_real(pi / n41 - mpfr_real("19.8"))) < mpfr_real("0.05"));
  // But the TRUE first zero time is (delta/2) pi/n = 3 pi/n = 59.50 s (theta = pi/2 is the first
  // zero: P3 above), three times the printed T_min.
  auto r41 = inscribed_global(p64(41, 35), mpfr_real(1));
  CHECK(rel_error(r41.t_first, mpfr_real(3 * pi / n41)) < mpfr_real("1e-45"));
  CHECK(abs(mpfr_real(r41.t_first - mpfr_real("59.504"))) < mpfr_real("0.001"));
  // And for the true smallest pair (35, 29): proxy pi/n = 16.68 s, true first zero 3 pi/n = 50.04 s.
  mpfr_real n35 = n_of(35, 29);
  auto r35 = inscribed_global(p64(35, 29), mpfr_real(1));
  CHECK(abs(mpfr_real(pi / n35 - mpfr_real("16.681"))) < mpfr_real("0.001"));
  CHECK(rel_error(r35.t_first, mpfr_real(3 * pi / n35)) < mpfr_real("1e-45"));
  CHECK(abs(mpfr_real(r35.t_first - mpfr_real("50.044"))) < mpfr_real("0.001"));
  // The paper's conclusion ("delta = 6 is worse than (11, 9)") still holds, more strongly.
  CHECK(r35.t_first > pi / n_of(11, 9));
}

TEST_CASE_METHOD(section_v,
                 "paper Section V, case B: (6, 5), n = 0.183, T_min ~ 17.2 s, r_min = 5.075e-2 and the asymptotic "
                 "numbers",
                 "[global][paper]") {
  mpfr_real n = n_of(6, 5);
  CHECK(abs(mpfr_real(n - 1 / sqrt(mpfr_real(30)))) < mpfr_real("1e-48"));
  CHECK(abs(mpfr_real(n - mpfr_real("0.183"))) < mpfr_real("0.0005"));  // 0.18257...
  CHECK(abs(mpfr_real(pi / n - mpfr_real("17.2"))) < mpfr_real("0.05"));  // 17.2072...
  // delta = 1 and beat ratio 11 >= 10; tau >= 5.5, so (6, 5) is the smallest such pair.
  CHECK(beat_ok(6, 5));
  CHECK_FALSE(beat_ok(5, 4));

  auto r = inscribed_global(p64(6, 5), mpfr_real(1));
  auto ref = gyrores::ref::reference_inscribed<mpfr_real>(6, 5, 160, mpfr_real("1e-30"), mpfr_real("1e-80"));
  CHECK(rel_error(r.r_res, ref.r_res) < mpfr_real("1e-45"));
  // r_res = 0.050745805791033372463715651186..., printed r_min = 5.075e-2 (4 significant digits: right).
  CHECK(rel_error(r.r_res, mpfr_real("0.0507458057910333724637156511865")) < mpfr_real("1e-30"));
  CHECK(abs(mpfr_real(r.r_res - mpfr_real("0.05075"))) < mpfr_real("0.000005"));

  // Asymptotics (Thm. theta_asy): 1/(2x) = 5.5, so k = 5 and k = 6 are both valid (a tie).
  // The paper uses k = 6: mu = pi/2 - 6 pi/11 = -pi/22, s = mu/x = -pi/2, u + tan u = s.
  const mpfr_real x = mpfr_real(1) / 11;
  const mpfr_real mu = pi * mpfr_real(11 - 2 * 6) / 22;
  const mpfr_real s = mu / x;
  CHECK(abs(mpfr_real(s + pi / 2)) < mpfr_real("1e-45"));
  auto g = [&](const mpfr_real& u) { return mpfr_real(u + tan(u) - s); };
  mpfr_real u_asy = gyrores::ref::bisect_root(g, mpfr_real("-1.5"), mpfr_real("1.5"), 160);
  // The paper prints u_asy = -0.17 rad; the paper's own equation gives u_asy = -0.7105 rad.
  CHECK(abs(mpfr_real(u_asy - mpfr_real("-0.71046"))) < mpfr_real("0.00001"));
  CHECK(abs(mpfr_real(u_asy - mpfr_real("-0.17"))) > mpfr_real("0.5"));
  // theta_asy = pi/b + (2/a)(u_asy - s) = 3.2980 (printed 3.30: right).
  mpfr_real theta_asy = pi + 2 * (u_asy - s) / 11;
  CHECK(abs(mpfr_real(theta_asy - mpfr_real("3.30"))) < mpfr_real("0.005"));
  // q'(theta_asy) for v = 1 is -1.2082e-4. The printed 2.43e-4 is |q'|/rho0 (rho0 = sqrt(30)/11 =
  // 0.498): the paper drops rho0 (and the sign); q' itself is half the printed number.
  gyrores::ref::naive_model<mpfr_real> m(6, 5);
  mpfr_real qd = m.qdot(theta_asy);
  CHECK(abs(mpfr_real(qd - mpfr_real("-1.2082e-4"))) < mpfr_real("1e-8"));
  CHECK(abs(mpfr_real(abs(qd) / m.rho0 - mpfr_real("2.43e-4"))) < mpfr_real("0.005e-4"));
  // theta_c: the root of q' near theta_asy = the library's second global minimiser.
  auto qdf = [&](const mpfr_real& th) { return m.qdot(th); };
  mpfr_real theta_c = gyrores::ref::bisect_root(qdf, mpfr_real(theta_asy - mpfr_real("0.01")),
                                                mpfr_real(theta_asy + mpfr_real("0.01")), 160);
  REQUIRE(r.minimisers.size() == 2);
  CHECK(rel_error(r.minimisers[1], theta_c) < mpfr_real("1e-45"));
  // |theta_c - theta_asy| = 1.1638e-4 (printed 1.16e-4: right) <= pi^3 x^2/a = 2.3295e-2 (printed 2.33e-2).
  mpfr_real err = abs(mpfr_real(theta_c - theta_asy));
  CHECK(abs(mpfr_real(err - mpfr_real("1.16e-4"))) < mpfr_real("0.005e-4"));
  mpfr_real bound = pi * pi * pi * x * x / 11;
  CHECK(abs(mpfr_real(bound - mpfr_real("2.33e-2"))) < mpfr_real("0.005e-2"));
  CHECK(err <= bound);
  // The paper's T_min = 17.2 s is the proxy pi/n. The TRUE first minimum is in the mirror lobe
  // (k = 5): theta_first = 2 pi - theta_c = 2.98528..., t_first = sqrt(30) theta_first = 16.351 s,
  // earlier than the proxy; the k = 6 minimum the paper computes comes at sqrt(30) theta_c = 18.064 s.
  CHECK(rel_error(r.theta_first, mpfr_real(2 * pi - theta_c)) < mpfr_real("1e-45"));
  CHECK(abs(mpfr_real(r.t_first - mpfr_real("16.351"))) < mpfr_real("0.001"));
  CHECK(abs(mpfr_real(sqrt(mpfr_real(30)) * theta_c - mpfr_real("18.064"))) < mpfr_real("0.001"));
  CHECK(r.t_first < pi / n);
}

TEST_CASE_METHOD(section_v,
                 "paper Section V (docs/mathematics.md §2, P5): for (9, 4) the global minimum is near 3 pi/5, not "
                 "near the first slow node pi/5",
                 "[global][paper]") {
  auto r = inscribed_global(p64(9, 4), mpfr_real(1));
  auto ref = gyrores::ref::reference_inscribed<mpfr_real>(9, 4, 160, mpfr_real("1e-30"), mpfr_real("1e-80"));
  CHECK(rel_error(r.theta_first, ref.theta_first) < mpfr_real("1e-45"));
  CHECK(abs(mpfr_real(r.theta_first - 3 * pi / 5)) < pi / 13);  // within one fast lobe (2 pi/a)
  CHECK(abs(mpfr_real(r.theta_first - pi / 5)) > mpfr_real(1));
  // So the proxy T_min = pi/n = 3.77 s misses the true first-hit time 11.455 s.
  CHECK(abs(mpfr_real(r.t_first - mpfr_real("11.455"))) < mpfr_real("0.001"));
}
