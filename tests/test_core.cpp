// The core layer's text and precision helpers (core/real.hpp, core/decimal.hpp,
// core/rational.hpp): binary <-> decimal precision against independently computed values,
// correctly rounded scientific output in every direction, exact parsing of decimals.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/real.hpp>

using gyrores::mpfr_real;

TEST_CASE("bits <-> decimal digits: exact floors and ceilings", "[core][precision]") {
  // floor(b log10 2) and ceil(d log2 10) computed here in long double for small arguments (the
  // products are far from integers there), and at known hard points checked with 60-digit
  // logarithms: at 13301 bits log10(2) ~ 0.30103 would give the wrong floor (4004 for 4003.99997).
  for (unsigned b = 1; b <= 4000; ++b)
    CHECK(gyrores::bits_to_digits10(b) == unsigned(std::floor(b * std::log10(2.0L))));
  for (unsigned d = 1; d <= 1200; ++d)
    CHECK(gyrores::digits10_to_bits(d) == unsigned(std::ceil(d * std::log2(10.0L))));
  CHECK(gyrores::bits_to_digits10(53) == 15);
  CHECK(gyrores::bits_to_digits10(113) == 34);
  CHECK(gyrores::bits_to_digits10(13301) == 4003);  // 13301 log10 2 = 4003.99997...
  CHECK(gyrores::digits10_to_bits(97879) == 325147);  // 97879 log2 10 = 325146.9999995...
  CHECK(gyrores::digits10_for_bits(256) == 78);
  // MPFR configured through digits10_for_bits carries at least the bits asked for.
  for (unsigned bits : {64u, 100u, 256u, 1000u, 3322u, 13301u}) {
    gyrores::scoped_digits d(gyrores::digits10_for_bits(bits));
    CHECK(gyrores::real_bits<mpfr_real>() >= bits);
  }
}

TEST_CASE("format_scientific: correctly rounded in each direction", "[core][decimal]") {
  gyrores::scoped_digits d(50);
  const mpfr_real third = mpfr_real(1) / 3, two_thirds = mpfr_real(2) / 3;
  CHECK(gyrores::format_scientific(third, 5) == "3.3333e-01");
  CHECK(gyrores::format_scientific(third, 5, MPFR_RNDU) == "3.3334e-01");
  CHECK(gyrores::format_scientific(third, 5, MPFR_RNDD) == "3.3333e-01");
  CHECK(gyrores::format_scientific(two_thirds, 5) == "6.6667e-01");
  CHECK(gyrores::format_scientific(two_thirds, 5, MPFR_RNDD) == "6.6666e-01");
  CHECK(gyrores::format_scientific(mpfr_real(-two_thirds), 3, MPFR_RNDD) == "-6.67e-01");
  CHECK(gyrores::format_scientific(mpfr_real(-two_thirds), 3, MPFR_RNDU) == "-6.66e-01");
  CHECK(gyrores::format_scientific(mpfr_real(0), 4) == "0.000e+00");
  CHECK(gyrores::format_scientific(mpfr_real("12345e300"), 2) == "1.2e+304");
  CHECK(gyrores::format_scientific(mpfr_real(7), 1) == "7e+00");
  // Ziv's test: 1/3 known to 1e-40 settles 30 digits; 0.125 +- 1e-3 does not settle 4 digits.
  CHECK(gyrores::digits_settled(third, mpfr_real("1e-40"), 30));
  CHECK_FALSE(gyrores::digits_settled(mpfr_real("0.125"), mpfr_real("1e-3"), 4));
  CHECK(gyrores::digits_settled(mpfr_real(0), mpfr_real(1), 10));
}

TEST_CASE("decimal input: integers and exact rationals", "[core][decimal]") {
  using gyrores::big_rational;
  CHECK(gyrores::parse_big_int("007", "n") == 7);  // decimal, not octal
  CHECK(gyrores::parse_big_int("-0", "n") == 0);
  CHECK_THROWS_AS(gyrores::parse_big_int("0x10", "n"), gyrores::usage_error);
  CHECK(gyrores::parse_rational("1/12", "n2") == big_rational(1, 12));
  CHECK(gyrores::parse_rational("0.25", "n") == big_rational(1, 4));
  CHECK(gyrores::parse_rational("-1.5e-3", "n") == big_rational(-3, 2000));
  CHECK(gyrores::parse_rational("2E+4", "n") == big_rational(20000));
  CHECK(gyrores::parse_rational("09/012", "n") == big_rational(3, 4));
  CHECK(gyrores::rational_str(big_rational(6, 8)) == "3/4");
  CHECK(gyrores::rational_str(big_rational(5)) == "5");
  for (const char* bad : {"", "1/0", "1/-2", "1.2.3", "e5", "1e", "1e1234567", "abc", "1/2/3"})
    CHECK_THROWS_AS(gyrores::parse_rational(bad, "n"), gyrores::usage_error);
  gyrores::big_int root;
  CHECK(gyrores::int_is_square(gyrores::big_int(1600), root));
  CHECK(root == 40);
  CHECK_FALSE(gyrores::int_is_square(gyrores::big_int(32), root));
}
