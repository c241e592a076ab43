// The core layer's text and precision helpers (core/real.hpp, core/decimal.hpp,
// core/rational.hpp, core/enclosure.hpp): binary <-> decimal precision against independently
// computed values, correctly rounded scientific output in every direction, exact parsing of
// decimals, an enclosure's outward decimals.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/model/inputs.hpp>
#include "testing/test_support.hpp"

using gyrores::mpfr_real;

namespace {

// Ziv's rounding test (the product decides its roundings on enclosures instead, core/enclosure.hpp):
// true when every value within a relative `rel_err` of v rounds to the same `digits`-digit string
// as v (the ends v (1 -+ rel_err) rounded outward). Exact zero (rel_err irrelevant) is settled.
bool digits_settled(const mpfr_real& v, const mpfr_real& rel_err, unsigned digits) {
  if (mpfr_zero_p(v.backend().data())) return true;
  // |v| rel_err exactly (the product of a p-bit and a q-bit number has p + q bits), the ends outward.
  const mpfr_prec_t prec = mpfr_get_prec(v.backend().data()) + mpfr_get_prec(rel_err.backend().data());
  gyrores::fixed_mpfr d(prec), lo(prec), hi(prec);
  mpfr_mul(d, v.backend().data(), rel_err.backend().data(), MPFR_RNDN);
  mpfr_abs(d, d, MPFR_RNDN);
  mpfr_sub(lo, v.backend().data(), d, MPFR_RNDD);
  mpfr_add(hi, v.backend().data(), d, MPFR_RNDU);
  return gyrores::format_scientific(lo, digits) == gyrores::format_scientific(hi, digits);
}

}  // namespace

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
  CHECK(digits_settled(third, mpfr_real("1e-40"), 30));
  CHECK_FALSE(digits_settled(mpfr_real("0.125"), mpfr_real("1e-3"), 4));
  CHECK(digits_settled(mpfr_real(0), mpfr_real(1), 10));
}

// The directed roundings are formed by integers (core/decimal.cpp); MPFR's mpfr_get_str is the
// independent reference, over random values of every size and the hard spots: exact decimals,
// powers of ten and their binary neighbours (where the exponent estimate is off by one and a
// rounding up carries into a new digit), runs of nines.
std::string mpfr_reference_text(mpfr_srcptr v, unsigned n, mpfr_rnd_t rnd) {
  mpfr_exp_t e = 0;
  char* raw = mpfr_get_str(nullptr, &e, 10, n, v, rnd);
  std::string s(raw);
  mpfr_free_str(raw);
  const bool neg = s[0] == '-';
  if (neg) s.erase(0, 1);
  if (mpfr_zero_p(v)) return gyrores::scientific_text(false, s, 0);
  char buf[64];
  std::snprintf(buf, sizeof buf, "e%c%02ld", e - 1 < 0 ? '-' : '+', std::labs(long(e) - 1));
  return (neg ? "-" : "") + s.substr(0, 1) + (n > 1 ? "." + s.substr(1) : "") + buf;
}

TEST_CASE("format_scientific: directed roundings equal MPFR's", "[core][decimal]") {
  gmp_randstate_t rs;
  gmp_randinit_default(rs);
  gmp_randseed_ui(rs, 20261127);
  std::mt19937_64 gen(7);
  long checks = 0;
  auto check_all = [&](mpfr_srcptr v, unsigned n) {
    for (mpfr_rnd_t r : {MPFR_RNDD, MPFR_RNDU, MPFR_RNDZ, MPFR_RNDA}) {
      const std::string got = gyrores::format_scientific(v, n, r), want = mpfr_reference_text(v, n, r);
      if (got != want) FAIL_CHECK(got << " != " << want << " (" << n << " digits, rounding " << int(r) << ")");
      ++checks;
    }
  };
  for (int i = 0; i < 3000; ++i) {
    const mpfr_prec_t prec = 2 + mpfr_prec_t(gen() % (i % 10 == 0 ? 4000 : 300));
    mpfr_t v;
    mpfr_init2(v, prec);
    mpfr_urandomb(v, rs);
    if (mpfr_zero_p(v)) mpfr_set_ui(v, 1, MPFR_RNDN);
    mpfr_mul_2si(v, v, long(gen() % 4001) - 2000, MPFR_RNDN);
    if (gen() % 2) mpfr_neg(v, v, MPFR_RNDN);
    check_all(v, 1 + unsigned(gen() % (i % 10 == 0 ? 1300 : 60)));
    mpfr_clear(v);
  }
  for (long j = -40; j <= 40; ++j) {
    for (mpfr_prec_t prec : {24, 53, 200}) {
      mpfr_t p, w;
      mpfr_inits2(prec, p, w, (mpfr_ptr)nullptr);
      mpfr_set_si(p, j, MPFR_RNDN);
      mpfr_exp10(p, p, MPFR_RNDN);  // 10^j rounded: exact for 0 <= j <= 10 at 24 bits
      for (int s = -3; s <= 3; ++s) {
        mpfr_set(w, p, MPFR_RNDN);
        for (int t = 0; t < std::abs(s); ++t) s < 0 ? mpfr_nextbelow(w) : mpfr_nextabove(w);
        for (unsigned n : {1u, 2u, 7u, 30u}) check_all(w, n);
      }
      mpfr_clears(p, w, (mpfr_ptr)nullptr);
    }
  }
  for (const char* text : {"9.99999", "0.125", "999", "1e-5", "0.0999999999", "12345e300", "-7.5e-300"}) {
    mpfr_t v;
    mpfr_init2(v, 120);
    mpfr_set_str(v, text, 10, MPFR_RNDN);
    for (unsigned n = 1; n <= 8; ++n) check_all(v, n);
    mpfr_clear(v);
  }
  gmp_randclear(rs);
  CHECK(checks > 10000);
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

TEST_CASE("enclosure: outward decimals bracket the exact ends", "[core][enclosure]") {
  // outward() formats the binary ends by directed digits; their exact rationals must bracket the
  // ends' exact rationals (decimal_rounded, core/rational.hpp, rounds the same way in integers).
  using namespace gyrores;
  std::mt19937_64 rng(33);
  for (int i = 0; i < 400; ++i) {
    const mpfr_prec_t prec = 53 + mpfr_prec_t(rng() % 300);
    exact_binary lo(prec), hi(prec);
    std::uniform_real_distribution<double> mant(0.5, 1.0);
    const long e2 = long(rng() % 400) - 200;
    mpfr_set_d(lo.get(), mant(rng), MPFR_RNDN);
    mpfr_mul_2si(lo.get(), lo, e2, MPFR_RNDN);
    if (i % 7 == 0) mpfr_neg(lo.get(), lo, MPFR_RNDN);
    mpfr_set(hi.get(), lo, MPFR_RNDN);
    mpfr_mul_d(hi.get(), hi, i % 7 == 0 ? 0.9999 : 1.0001, MPFR_RNDU);
    const enclosure e(lo, hi);
    const unsigned digits = 1 + unsigned(rng() % 40);
    const auto text = e.outward(digits);
    const big_rational qlo = parse_rational(text.first, "lo"), qhi = parse_rational(text.second, "hi");
    INFO(text.first << " " << text.second << " at " << digits);
    CHECK(qlo == decimal_rounded(e.lo_rational(), digits, -1));
    CHECK(qhi == decimal_rounded(e.hi_rational(), digits, +1));
    CHECK(qlo <= e.lo_rational());
    CHECK(e.hi_rational() <= qhi);
  }
  // Exact rationals: their own decimal when it has at most D digits, else outward.
  CHECK(enclosure::exact(big_rational(3, 10)).outward(5) == std::pair<std::string, std::string>{"3.0000e-01", "3.0000e-01"});
  CHECK(enclosure::exact(big_rational(1, 3)).outward(5) == std::pair<std::string, std::string>{"3.3333e-01", "3.3334e-01"});
  CHECK(enclosure::exact(big_rational(-1, 3)).outward(2) == std::pair<std::string, std::string>{"-3.4e-01", "-3.3e-01"});
  CHECK(enclosure::exact(big_rational(1, 3)).report(3)->value == "3.33e-01");
  CHECK(enclosure().report(4)->enclosure == std::pair<std::string, std::string>{"0.000000e+00", "0.000000e+00"});
}

TEST_CASE("an input quoted in a usage_error is shown on one line", "[core]") {
  // Found by the fuzz target coupling_inputs (tests/fuzz/corpus/coupling_inputs/regression-newline-in-n):
  // a newline inside an argument made the refusal two lines.
  const auto message = [](auto f) {
    try {
      f();
    } catch (const gyrores::usage_error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  for (const std::string m : {message([] { gyrores::parse_rational(".2\n4", "N"); }),
                              message([] { gyrores::parse_rational("1/2\n", "--n2"); }),
                              message([] { gyrores::parse_big_int("12\x01", "tau"); }),
                              message([] { gyrores::parse_band("1\n2", "--band"); }),
                              message([] { gyrores::parse_tolerance_band(2, "5\n", "--tolerance"); })}) {
    INFO(m);
    CHECK(m != "accepted");
    CHECK(m.find('\n') == std::string::npos);
    CHECK((m.find("\\n") != std::string::npos || m.find("\\x01") != std::string::npos));
  }
}
