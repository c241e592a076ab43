// The interval Newton of tests/reference/interval_newton.hpp: it encloses simple roots (also tiny ones and
// from a poor guess), returns nothing for a double root, for no root and for a spent budget, and
// its enclosures contain the root computed independently in MPFR. (Comparisons of MPFR values
// are checked as bool: Catch would print the operands through Boost's str(), which GCC 12 warns
// about with -Wrestrict.)
#include <catch2/catch.hpp>

#include "reference/interval.hpp"
#include "reference/interval_newton.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;

namespace {

mpfr_real width(const mpfi_real& x) { return interval_upper(x) - interval_lower(x); }

bool contains(const mpfi_real& x, const mpfr_real& v) { return certainly_subset(interval_point(v), x); }

}  // namespace

TEST_CASE("interval Newton encloses simple roots tightly", "[interval_newton]") {
  scoped_digits sd(digits10_for_bits(200));
  auto f = [](const mpfi_real& x) { return mpfi_real(x * x - 2); };
  auto df = [](const mpfi_real& x) { return mpfi_real(2 * x); };
  // Guesses at the working precision, 2^-160 off, and a double (53 bits: it needs about 70
  // widenings from the first radius 2^-188, so a larger budget).
  const mpfr_real r2 = sqrt(mpfr_real(2));
  for (auto [guess, steps] :
       {std::pair{r2, 40}, {r2 + ldexp(mpfr_real(1), -160), 40}, {mpfr_real(1.4142135623730951), 80}}) {
    INFO(format_scientific(guess, 20) << " " << steps);
    auto X = interval_newton(f, df, guess, guess, steps);
    REQUIRE(X);
    CHECK(contains(*X, sqrt(mpfr_real(2))));
    CHECK(bool(width(*X) <= ldexp(mpfr_real(1), -190)));  // to about the working precision
  }
  // A root of size 1e-30, found relative to its size.
  auto g = [](const mpfi_real& x) { return mpfi_real(x - mpfi_real("1e-30")); };
  auto dg = [](const mpfi_real&) { return mpfi_real(1); };
  auto Y = interval_newton(g, dg, mpfr_real("1.00000000000000000000000000000000000000000000000001e-30"),
                           mpfr_real("1e-30"), 40);
  REQUIRE(Y);
  CHECK(contains(*Y, mpfr_real("1e-30")));
  CHECK(bool(interval_rel_width(*Y) < mpfr_real("1e-50")));
}

TEST_CASE("interval Newton proves nothing it cannot", "[interval_newton]") {
  scoped_digits sd(digits10_for_bits(128));
  auto df2 = [](const mpfi_real& x) { return mpfi_real(2 * x); };
  // Double root at 0: f' vanishes at the root, so no step is ever accepted.
  auto sq = [](const mpfi_real& x) { return interval_sqr(x); };
  CHECK_FALSE(interval_newton(sq, df2, mpfr_real("0.1"), mpfr_real("0.1"), 60));
  // No real root.
  auto none = [](const mpfi_real& x) { return mpfi_real(interval_sqr(x) + 1); };
  CHECK_FALSE(interval_newton(none, df2, mpfr_real("0.5"), mpfr_real("0.5"), 60));
  // No budget.
  auto f = [](const mpfi_real& x) { return mpfi_real(x * x - 2); };
  CHECK_FALSE(interval_newton(f, df2, mpfr_real("1.4"), mpfr_real("1.4"), 0));
  // A guess too far for the widening budget (radius 2^-116 times 4 per step).
  CHECK_FALSE(interval_newton(f, df2, mpfr_real("1.5"), mpfr_real("1.5"), 40));
  // The same guess with enough budget.
  CHECK(interval_newton(f, df2, mpfr_real("1.5"), mpfr_real("1.5"), 80));
}

TEST_CASE("interval Newton on u + tan u = s agrees with an independent MPFR root", "[interval_newton]") {
  scoped_digits sd(digits10_for_bits(256));
  for (const char* s_text : {"-1.5707963267948966", "0.001", "3", "-40"}) {
    INFO(s_text);
    mpfi_real s(s_text);
    auto h = [&](const mpfi_real& u) { return mpfi_real(u + tan(u) - s); };
    auto dh = [](const mpfi_real& u) { return mpfi_real(2 + interval_sqr(tan(u))); };
    // Independent root: bisection in MPFR on u + tan u - s over (-pi/2, pi/2).
    mpfr_real sp(s_text), lo = -boost::math::constants::half_pi<mpfr_real>() + mpfr_real("1e-70"),
                          hi = boost::math::constants::half_pi<mpfr_real>() - mpfr_real("1e-70");
    for (int i = 0; i < 300; ++i) {
      mpfr_real mid = (lo + hi) / 2;
      if (mid + tan(mid) - sp < 0) lo = mid;
      else hi = mid;
    }
    mpfr_real guess = lo + ldexp(abs(lo), -200);  // 2^-200 relative off the root
    auto U = interval_newton(h, dh, guess, abs(guess), 60);
    REQUIRE(U);
    mpfi_real bracket = interval_of(lo, hi);
    CHECK_FALSE(certainly_less(*U, bracket));
    CHECK_FALSE(certainly_less(bracket, *U));
    CHECK(bool(interval_rel_width(*U) <= ldexp(mpfr_real(1), -240)));
  }
}
