// The proof kernels of the lattice theorem (theorem/root.hpp), tested directly: tan_shift (the
// tangent addition formula with its remainder bound), prove_theorem_root, prove_theorem_bracket,
// prove_paper_root and theorem_radius.
//
// Containment is checked against independent values computed here in plain MPFR at many more
// bits (the kernels' precision + 160): the roots by bisection on the equations themselves,
// x u + atan(x tan u) = pi m/(2a) and u + tan u = pi m/(2b), with mpfr_tan and mpfr_atan;
// sqrt(G(u*)) from mpfr_sin and mpfr_cos; tan(c + d) by mpfr_tan. No library numerics (no
// Newton, no Arb, no addition formula). Each enclosure must also be narrow, so that containment
// says something.
//
// Negative tests, each of which the kernels must refuse: a bracket on the wrong side of the root
// (both ends below, both above), the bracket of m = 1 proved against m = 2 and back, a claim
// narrower than the enclosures at the working precision (refused there, proved with 64 more
// bits), ends farther than 2^-10 from the centre, ends outside (0, pi/2). tests/CMakeLists.txt
// also builds mutants of src/lib/theorem/root.cpp (the remainder bound, a comparison, the radius
// formula, the distance limit) against these test cases and requires each mutant to fail them.
#include <catch2/catch.hpp>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/theorem/root.hpp>

#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

using namespace gyrores;

namespace {

// ---- the independent side: plain MPFR ----

// An MPFR number owned here (the test does not use the library's fixed_mpfr for its reference).
class big_float {
 public:
  explicit big_float(mpfr_prec_t p) { mpfr_init2(v_, p); }
  ~big_float() { mpfr_clear(v_); }
  big_float(const big_float&) = delete;
  big_float& operator=(const big_float&) = delete;
  operator mpfr_ptr() { return v_; }
  operator mpfr_srcptr() const { return v_; }

 private:
  mpfr_t v_;
};

struct pair_case {
  const char* tau;
  const char* sigma;
};

// Pairs from x -> 0 to x -> 1, small and huge (orders up to 2 10^30).
const std::vector<pair_case> pairs{
    {"2", "1"},       {"6", "5"},   {"9", "4"},    {"5", "1"},       {"3", "1"},       {"1000", "1"},
    {"1000000000", "1"}, {"1000004", "3"}, {"30001", "10000"}, {"19999", "2"}, {"1000001", "1000000"},
    {"1000000000000000001", "1000000000000000000"}, {"18446744073709551617", "18446744073709551616"},
    {"1000000000000000000000000000001", "1000000000000000000000000000000"}};

resonant_pair<big_int> pair_of(const pair_case& c) { return {big_int(c.tau), big_int(c.sigma)}; }

// x = b/a and pi m/(2 d) at `bits`, d = a (theorem) or b (paper).
void x_of(big_float& x, const resonant_pair<big_int>& p) {
  mpfr_set_z(x, big_int(p.delta()).backend().data(), MPFR_RNDN);
  big_float a(mpfr_get_prec(x));
  mpfr_set_z(a, p.order().backend().data(), MPFR_RNDN);
  mpfr_div(x, x, a, MPFR_RNDN);
}
void pi_ratio(big_float& out, const big_int& m, const big_int& d) {
  big_float t(mpfr_get_prec(out));
  mpfr_const_pi(out, MPFR_RNDN);
  mpfr_set_z(t, m.backend().data(), MPFR_RNDN);
  mpfr_mul(out, out, t, MPFR_RNDN);
  mpfr_set_z(t, d.backend().data(), MPFR_RNDN);
  mpfr_div(out, out, t, MPFR_RNDN);
  mpfr_div_2ui(out, out, 1, MPFR_RNDN);
}

// The root of an increasing f on (lo, hi) by plain bisection at root's precision, until the
// ends agree to about the precision (relative, or absolute 2^-prec for a root at 0).
template <class F> void bisect(big_float& root, big_float& lo, big_float& hi, F&& f) {
  const mpfr_prec_t p = mpfr_get_prec(root);
  big_float mid(p), w(p), scale(p);
  for (int it = 0; it < 4 * int(p) + 4000; ++it) {
    mpfr_add(mid, lo, hi, MPFR_RNDN);
    mpfr_div_2ui(mid, mid, 1, MPFR_RNDN);
    if (f(mid) < 0) mpfr_set(lo, mid, MPFR_RNDN);
    else mpfr_set(hi, mid, MPFR_RNDN);
    mpfr_sub(w, hi, lo, MPFR_RNDN);
    if (mpfr_cmpabs(lo, hi) < 0) mpfr_abs(scale, lo, MPFR_RNDN);
    else mpfr_abs(scale, hi, MPFR_RNDN);
    if (mpfr_zero_p(scale)) mpfr_set_ui(scale, 1, MPFR_RNDN);
    mpfr_mul_2si(scale, scale, -(p - 8), MPFR_RNDN);
    if (mpfr_cmp(w, scale) <= 0) break;
  }
  mpfr_add(root, lo, hi, MPFR_RNDN);
  mpfr_div_2ui(root, root, 1, MPFR_RNDN);
}

// The root of x u + atan(x tan u) = mu on (0, pi/2), x and mu given (any coupling).
void coupling_root_reference(big_float& u, mpfr_srcptr x, mpfr_srcptr mu) {
  const mpfr_prec_t bits = mpfr_get_prec(u);
  big_float lo(bits), hi(bits), t(bits), h(bits);
  mpfr_set_ui(lo, 0, MPFR_RNDN);
  mpfr_const_pi(hi, MPFR_RNDD);
  mpfr_div_2ui(hi, hi, 1, MPFR_RNDD);
  bisect(u, lo, hi, [&](mpfr_srcptr v) {
    mpfr_tan(t, v, MPFR_RNDN);
    mpfr_mul(t, t, x, MPFR_RNDN);
    mpfr_atan(t, t, MPFR_RNDN);
    mpfr_mul(h, x, v, MPFR_RNDN);
    mpfr_add(h, h, t, MPFR_RNDN);
    return mpfr_cmp(h, mu);
  });
}

// u* of x u + atan(x tan u) = pi m/(2a) on (0, pi/2).
void theorem_root_reference(big_float& u, const resonant_pair<big_int>& p, const big_int& m) {
  const mpfr_prec_t bits = mpfr_get_prec(u);
  big_float x(bits), mu(bits);
  x_of(x, p);
  pi_ratio(mu, m, p.order());
  coupling_root_reference(u, x, mu);
}

// The root of u + tan u = pi m/(2b) on (-pi/2, pi/2).
void paper_root_reference(big_float& u, const resonant_pair<big_int>& p, const big_int& m) {
  const mpfr_prec_t bits = mpfr_get_prec(u);
  big_float s(bits), lo(bits), hi(bits), g(bits);
  pi_ratio(s, m, big_int(p.delta()));
  mpfr_const_pi(hi, MPFR_RNDD);
  mpfr_div_2ui(hi, hi, 1, MPFR_RNDD);
  mpfr_neg(lo, hi, MPFR_RNDN);
  bisect(u, lo, hi, [&](mpfr_srcptr v) {
    mpfr_tan(g, v, MPFR_RNDN);
    mpfr_add(g, g, v, MPFR_RNDN);
    return mpfr_cmp(g, s);
  });
}

// sqrt(G(u)) = x sqrt(1 - x^2) sin^2 u / sqrt(cos^2 u + x^2 sin^2 u).
void radius_reference(big_float& r, const resonant_pair<big_int>& p, mpfr_srcptr u) {
  const mpfr_prec_t bits = mpfr_get_prec(r);
  big_float x(bits), s(bits), c(bits), e(bits), t(bits);
  x_of(x, p);
  mpfr_sin_cos(s, c, u, MPFR_RNDN);
  mpfr_sqr(s, s, MPFR_RNDN);
  mpfr_sqr(c, c, MPFR_RNDN);
  mpfr_sqr(t, x, MPFR_RNDN);
  mpfr_mul(e, t, s, MPFR_RNDN);
  mpfr_add(e, e, c, MPFR_RNDN);
  mpfr_sqrt(e, e, MPFR_RNDN);
  mpfr_ui_sub(t, 1, t, MPFR_RNDN);
  mpfr_sqrt(t, t, MPFR_RNDN);
  mpfr_mul(r, x, t, MPFR_RNDN);
  mpfr_mul(r, r, s, MPFR_RNDN);
  mpfr_div(r, r, e, MPFR_RNDN);
}

// ---- comparisons of the kernels' intervals with the reference ----

// The reference v, trusted to 2^-(its precision - 24) relative, lies inside A.
bool contains(const fixed_mpfi& A, mpfr_srcptr v) {
  const mpfr_prec_t p = mpfr_get_prec(v);
  big_float slack(p), lo(p), hi(p);
  mpfr_abs(slack, v, MPFR_RNDU);
  mpfr_mul_2si(slack, slack, -(p - 24), MPFR_RNDU);
  mpfr_sub(lo, v, slack, MPFR_RNDD);
  mpfr_add(hi, v, slack, MPFR_RNDU);
  return mpfr_cmp(A.left(), lo) <= 0 && mpfr_cmp(hi, A.right()) <= 0;
}

// A's relative width is at most 2^-e.
bool narrow(const fixed_mpfi& A, int e) {
  big_float w(mpfi_get_prec(A)), m(mpfi_get_prec(A));
  mpfr_sub(w, A.right(), A.left(), MPFR_RNDU);
  if (mpfr_cmpabs(A.left(), A.right()) < 0) mpfr_abs(m, A.left(), MPFR_RNDD);
  else mpfr_abs(m, A.right(), MPFR_RNDD);
  mpfr_mul_2si(m, m, -e, MPFR_RNDD);
  return mpfr_cmp(w, m) <= 0;
}

// The point interval v (1 + f 2^-e), f = -1, 0, +1, exactly (at v's precision + e + 8 bits).
void scaled_point(fixed_mpfi& out, mpfr_srcptr v, int f, int e) {
  big_float w(mpfr_get_prec(v) + e + 8);
  mpfr_set(w, v, MPFR_RNDN);
  mpfr_mul_2si(w, w, -e, MPFR_RNDN);
  if (f < 0) mpfr_sub(w, v, w, MPFR_RNDN);
  else if (f > 0) mpfr_add(w, v, w, MPFR_RNDN);
  else mpfr_set(w, v, MPFR_RNDN);
  mpfi_set_fr(out, w);
}

std::string text(mpfr_srcptr v) {
  char buf[64];
  mpfr_snprintf(buf, sizeof buf, "%.20Rg", v);
  return buf;
}

// v as a decimal of 91 significant digits (rounded).
std::string text_of_decimal(mpfr_srcptr v) {
  char buf[160];
  mpfr_snprintf(buf, sizeof buf, "%.90Re", v);
  return buf;
}

constexpr mpfr_prec_t extra_bits = 160;

}  // namespace

TEST_CASE("tan_shift encloses tan(c + d) for |d| up to 1/4, narrowly for small d", "[theorem][tan_shift]") {
  // c across (-pi/2, pi/2); d at the remainder bound's limit 1/4, the brackets' 2^-10, and small.
  const std::vector<double> cs{-1.4, -0.9, -0.3, 0.0, 1e-9, 0.2, 0.7110285065772783, 1.1, 1.45};
  const std::vector<double> ds{0.25, -0.25, 0.2, -0.13, 0x1p-10, -0x1p-10, 1e-6, -3e-12, 0x1p-300, -0x1p-300, 0.0};
  for (mpfr_prec_t prec : {64, 200, 1000}) {
    const mpfr_prec_t bits = prec + extra_bits;
    for (double c : cs)
      for (double d : ds) {
        INFO("prec " << prec << ", c = " << c << ", d = " << d);
        big_float cd(bits), exact(bits), lo(prec), hi(prec);
        // TC: tan c rounded down and up (MPFR rounds correctly, so this encloses tan c).
        fixed_mpfi TC(prec), D(prec), out(prec);
        mpfr_set_d(cd, c, MPFR_RNDN);
        mpfr_tan(lo, cd, MPFR_RNDD);
        mpfr_tan(hi, cd, MPFR_RNDU);
        mpfi_interv_fr(TC, lo, hi);
        mpfi_set_d(D, d);
        tan_shift(out, TC, D);
        mpfr_set_d(exact, d, MPFR_RNDN);
        mpfr_add(exact, exact, cd, MPFR_RNDN);
        mpfr_tan(exact, exact, MPFR_RNDN);
        CHECK(contains(out, exact));
        // Width: a few roundings at the working precision (where the remainder |d|^5/7 is below it).
        if (std::fabs(d) < 0x1p-290 && std::fabs(c) <= 1.1) CHECK(narrow(out, int(prec) - 12));
      }
    // An interval D = [d1, d2]: every d inside, the ends and the middle checked.
    for (double c : cs) {
      INFO("prec " << prec << ", c = " << c << ", D = [-2^-10, 0.25]");
      fixed_mpfi TC(prec), D(prec), out(prec);
      big_float cd(bits), exact(bits), lo(prec), hi(prec);
      mpfr_set_d(cd, c, MPFR_RNDN);
      mpfr_tan(lo, cd, MPFR_RNDD);
      mpfr_tan(hi, cd, MPFR_RNDU);
      mpfi_interv_fr(TC, lo, hi);
      mpfi_interv_d(D, -0x1p-10, 0.25);
      tan_shift(out, TC, D);
      for (double d : {-0x1p-10, 0.0, 0.1, 0.25}) {
        mpfr_set_d(exact, d, MPFR_RNDN);
        mpfr_add(exact, exact, cd, MPFR_RNDN);
        mpfr_tan(exact, exact, MPFR_RNDN);
        CHECK(contains(out, exact));
      }
    }
  }
}

TEST_CASE("tan_shift: the remainder bound is needed at |d| = 1/4 (the Taylor part alone misses)",
          "[theorem][tan_shift]") {
  // tan d - d - d^3/3 = 2 d^5/15 + ... = 1.3359e-4 at d = 1/4: without the remainder interval
  // (or with a bound below 2/15 |d|^5) the enclosure would miss. Shown here on the formula's
  // Taylor part, computed as the kernel does but without [-1, 1] |d|^5/7.
  const mpfr_prec_t prec = 128;
  big_float d(prec), taylor(prec), exact(prec + extra_bits), r(prec + extra_bits);
  mpfr_set_d(d, 0.25, MPFR_RNDN);
  mpfr_pow_ui(taylor, d, 3, MPFR_RNDN);
  mpfr_div_ui(taylor, taylor, 3, MPFR_RNDN);
  mpfr_add(taylor, taylor, d, MPFR_RNDN);
  mpfr_tan(exact, d, MPFR_RNDN);
  mpfr_sub(r, exact, taylor, MPFR_RNDN);  // the true remainder
  big_float bound7(prec), bound8(prec);
  mpfr_pow_ui(bound7, d, 5, MPFR_RNDU);
  mpfr_set(bound8, bound7, MPFR_RNDN);
  mpfr_div_ui(bound7, bound7, 7, MPFR_RNDU);
  mpfr_div_ui(bound8, bound8, 8, MPFR_RNDU);
  CHECK(mpfr_cmp(r, bound7) < 0);  // the kernel's bound holds
  CHECK(mpfr_cmp(r, bound8) > 0);  // a bound of |d|^5/8 would not
  // And the kernel's enclosure of tan(0 + 1/4) holds it.
  fixed_mpfi TC(prec), D(prec), out(prec);
  mpfi_set_ui(TC, 0);
  mpfi_set_d(D, 0.25);
  tan_shift(out, TC, D);
  CHECK(contains(out, exact));
}

TEST_CASE("prove_theorem_root and theorem_radius contain the independent u* and r_res", "[theorem][root]") {
  for (const auto& c : pairs) {
    const auto p = pair_of(c);
    const big_int m(p.strand_offset_min());
    if (m == 0) continue;
    for (mpfr_prec_t prec : {64, 128, 333, 1000}) {
      INFO(p.str() << " at " << prec << " bits");
      theorem_constants K(prec, p);
      root_enclosure r(prec);
      REQUIRE(prove_theorem_root(r, K, m));
      big_float u(prec + extra_bits), rr(prec + extra_bits);
      theorem_root_reference(u, p, m);
      INFO("u* = " << text(u));
      CHECK(contains(r.U, u));
      CHECK(narrow(r.U, int(prec) - 18));  // relative half-width 2^-(prec - 16)
      fixed_mpfi radius(prec);
      theorem_radius(radius, K, r.T);
      radius_reference(rr, p, u);
      INFO("r_res = " << text(rr));
      CHECK(contains(radius, rr));
      CHECK(narrow(radius, int(prec) - 24));
    }
  }
}

TEST_CASE("prove_theorem_root for larger offsets m (the paper's lobe roots)", "[theorem][root]") {
  // mu = pi m/(2a) < pi/2 for every 0 < m < a. The contract allows a failed proof at a precision
  // (the caller doubles it): roots near pi/2 ((6, 5), m = 5, 6: u* = 1.43, 1.46) fail at about a
  // third of the precisions, so each case starts at 200 bits and may double 3 times.
  for (auto [tau, sigma, m] : {std::tuple{"6", "5", 5}, {"6", "5", 6}, {"6", "5", 10}, {"9", "4", 3},
                               {"1000", "1", 999}, {"1000", "1", 500}, {"30001", "10000", 9999}}) {
    const resonant_pair<big_int> p{big_int(tau), big_int(sigma)};
    bool proved = false;
    for (mpfr_prec_t prec = 200; prec <= 1600 && !proved; prec *= 2) {
      INFO(p.str() << ", m = " << m << " at " << prec << " bits");
      theorem_constants K(prec, p);
      root_enclosure r(prec);
      if (!(proved = bool(prove_theorem_root(r, K, big_int(m))))) continue;
      big_float u(prec + extra_bits);
      theorem_root_reference(u, p, big_int(m));
      CHECK(contains(r.U, u));
      CHECK(narrow(r.U, int(prec) - 18));
    }
    INFO(p.str() << ", m = " << m);
    CHECK(proved);
  }
}

namespace {

// A coupling's equation as the horizon theorem poses it: x = n/sqrt(n^2 + 4) (a point, the exact
// x of the problem) and mu = pi nu (an interval holding it), at `prec` bits.
struct coupling_case {
  const char* n;
  const char* nu;
};

void coupling_x(big_float& x, const char* n) {
  big_float t(mpfr_get_prec(x));
  mpfr_set_str(x, n, 10, MPFR_RNDN);
  mpfr_sqr(t, x, MPFR_RNDN);
  mpfr_add_ui(t, t, 4, MPFR_RNDN);
  mpfr_sqrt(t, t, MPFR_RNDN);
  mpfr_div(x, x, t, MPFR_RNDN);
}

// mu = pi nu for nu = "p/q": the interval (pi as an interval), and a point at v's precision.
void coupling_mu(fixed_mpfi& mu, big_float& v, const char* nu) {
  const big_rational q = parse_rational(nu, "nu");
  mpfi_const_pi(mu);
  mpfi_mul_q(mu, mu, q.backend().data());
  big_float pi(mpfr_get_prec(v)), qq(mpfr_get_prec(v));
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_set_q(qq, q.backend().data(), MPFR_RNDN);
  mpfr_mul(v, pi, qq, MPFR_RNDN);
}

}  // namespace

TEST_CASE("prove_theorem_root for any coupling: x from 1e-300 to 1 - 1e-30, mu up to pi/2", "[theorem][root][coupling]") {
  // x and mu intervals (no integers): the lobe roots H^{-1}(pi nu) of the horizon theorem, near
  // 0 (nu small), near pi/2 (x small and nu not: tan u* up to 2^1000, the pole bits), at
  // mu = pi/2 exactly (lobe 0) and for x next to 1. Each case starts where the horizon theorem
  // starts (64 bits and twice log2(1/x)) and may double 3 times; the bracket must hold the
  // bisection's root and be narrow.
  for (const auto& c : std::vector<coupling_case>{{"2", "1/2"},          {"2", "1/3"},       {"2", "1/100000"},
                                                  {"0.5", "1/2"},        {"0.01", "1/2"},    {"0.01", "49/100"},
                                                  {"1e-40", "1/2"},      {"1e-40", "1/7"},   {"1e-150", "1/2"},
                                                  {"1e-300", "1/1000"},  {"1e15", "1/2"},    {"1e15", "1/3"},
                                                  {"30", "1/1000000000000000000000000000000"}}) {
    // (and 192 bits at least: x = 1 - 2 10^-30 for n = 10^15 must show)
    const mpfr_prec_t start = std::max<mpfr_prec_t>(192, 64 + 2 * mpfr_prec_t(std::max(0.0, -std::log2(std::stod(c.n) / 2))));
    bool proved = false;
    for (mpfr_prec_t prec = start; prec <= 8 * start && !proved; prec *= 2) {
      INFO("n = " << c.n << ", nu = " << c.nu << " at " << prec << " bits");
      big_float x(prec), xr(prec + extra_bits), mu_r(prec + extra_bits), u(prec + extra_bits);
      coupling_x(x, c.n);
      fixed_mpfi X(prec);
      mpfi_set_fr(X, x);
      theorem_constants K(prec);
      set_theorem_constants(K, X);
      root_enclosure r(prec);
      coupling_mu(r.mu, mu_r, c.nu);
      if (!(proved = bool(prove_theorem_root(r, K)))) continue;
      mpfr_set(xr, x, MPFR_RNDN);
      coupling_root_reference(u, xr, mu_r);
      INFO("u* = " << text(u));
      CHECK(contains(r.U, u));
      CHECK(narrow(r.U, int(prec) - 18));
      CHECK(r.decimals == 0);
    }
    INFO("n = " << c.n << ", nu = " << c.nu);
    CHECK(proved);
  }
}

TEST_CASE("prove_theorem_root for a coupling: another mu's bracket is refused; decimals only inside (0, pi/2)",
          "[theorem][root][coupling]") {
  const mpfr_prec_t prec = 256;
  big_float x(prec), mu_r(prec + extra_bits), u(prec + extra_bits);
  coupling_x(x, "0.7");
  fixed_mpfi X(prec);
  mpfi_set_fr(X, x);
  theorem_constants K(prec);
  set_theorem_constants(K, X);
  // The bracket of nu = 1/5 with its decimals to 40 digits: the decimals hold the root, and the
  // bracket is refused against nu (1 + 2^-100), whose root lies outside it.
  root_enclosure own(prec), other(prec);
  coupling_mu(own.mu, mu_r, "1/5");
  REQUIRE(prove_theorem_root(own, K, 40));
  CHECK(own.decimals == 40);
  big_float xr(prec + extra_bits);
  mpfr_set(xr, x, MPFR_RNDN);
  coupling_root_reference(u, xr, mu_r);
  const big_rational ur = parse_rational(text_of_decimal(u), "u");
  CHECK(parse_rational(format_scientific(static_cast<mpfr_srcptr>(own.lo), 40, MPFR_RNDD), "lo") < ur);
  CHECK(parse_rational(format_scientific(static_cast<mpfr_srcptr>(own.hi), 40, MPFR_RNDU), "hi") > ur);
  CHECK(contains(own.U, u));
  fixed_mpfi shift(prec);
  coupling_mu(other.mu, mu_r, "1/5");
  mpfi_mul_2si(shift, other.mu, -100);
  mpfi_add(other.mu, other.mu, shift);
  REQUIRE(theorem_centre(other, K));
  fixed_mpfi LO(prec), HI(prec), T(prec);
  mpfi_set_fr(LO, own.lo);
  mpfi_set_fr(HI, own.hi);
  CHECK_FALSE(prove_theorem_bracket(K, other, LO, HI, T));
  // A root within 10^-80 of pi/2 (x ~ 5e-41, nu = 1/2): proved, but its 30-digit decimals would
  // pass pi/2, so they are not claimed.
  const mpfr_prec_t p2 = 1024;
  big_float x2(p2);
  coupling_x(x2, "1e-40");
  fixed_mpfi X2(p2);
  mpfi_set_fr(X2, x2);
  theorem_constants K2(p2);
  set_theorem_constants(K2, X2);
  root_enclosure near(p2);
  big_float mu2(p2);
  coupling_mu(near.mu, mu2, "1/2");
  REQUIRE(prove_theorem_root(near, K2, 30));
  CHECK(near.decimals == 0);
}

TEST_CASE("prove_paper_root contains the independent root of u + tan u = s", "[theorem][paper]") {
  for (const auto& c : pairs) {
    const auto p = pair_of(c);
    const big_int b(p.delta());
    for (const big_int& m : {big_int(1), big_int(-1), b, big_int(-b), big_int(b / 2 + 1)}) {
      if (m > b || -m > b) continue;
      for (mpfr_prec_t prec : {64, 256, 1000}) {
        INFO(p.str() << ", m = " << m << " at " << prec << " bits");
        theorem_constants K(prec, p);
        root_enclosure r(prec);
        REQUIRE(prove_paper_root(r, K, m));
        big_float u(prec + extra_bits);
        paper_root_reference(u, p, m);
        INFO("u = " << text(u));
        CHECK(contains(r.U, u));
        CHECK(narrow(r.U, int(prec) - 18));
        // T = tan(U) holds tan u.
        big_float t(prec + extra_bits);
        mpfr_tan(t, u, MPFR_RNDN);
        CHECK(contains(r.T, t));
      }
    }
  }
  // m = 0: the exact root 0.
  theorem_constants K(64);
  set_theorem_constants(K, resonant_pair<big_int>(6, 5));
  root_enclosure r(64);
  REQUIRE(prove_paper_root(r, K, big_int(0)));
  CHECK(mpfr_zero_p(r.U.left()));
  CHECK(mpfr_zero_p(r.U.right()));
}

TEST_CASE("prove_theorem_bracket refuses brackets on the wrong side of the root", "[theorem][bracket]") {
  for (const auto& c : pairs) {
    const auto p = pair_of(c);
    const big_int m(p.strand_offset_min());
    if (m == 0) continue;
    const mpfr_prec_t prec = 128;
    INFO(p.str());
    theorem_constants K(prec, p);
    root_enclosure r(prec);
    REQUIRE(theorem_centre_of(r, K, m));
    big_float u(prec + extra_bits);
    theorem_root_reference(u, p, m);
    fixed_mpfi LO(prec + 64), HI(prec + 64), T(prec);
    // An honest bracket, u* (1 -+ 2^-40): proved.
    scaled_point(LO, u, -1, 40);
    scaled_point(HI, u, +1, 40);
    CHECK(prove_theorem_bracket(K, r, LO, HI, T));
    // Both ends below u*, both above, and the two ends swapped: refused.
    scaled_point(LO, u, -1, 30);
    scaled_point(HI, u, -1, 40);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
    scaled_point(LO, u, +1, 40);
    scaled_point(HI, u, +1, 30);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
    scaled_point(LO, u, +1, 40);
    scaled_point(HI, u, -1, 40);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
  }
}

TEST_CASE("prove_theorem_bracket: the bracket of one offset m is refused for another", "[theorem][bracket]") {
  // x -> 1: the roots of m = 1 and m = 2 lie within 2^-10 of each other, so only the inequality
  // H(lo) < mu < H(hi) can refuse (checked: the ends are near the other centre).
  for (const auto& [tau, sigma] : {std::pair{"1000", "1"}, {"1000000000", "1"}, {"1000004", "3"}, {"19999", "2"}}) {
    const resonant_pair<big_int> p{big_int(tau), big_int(sigma)};
    const mpfr_prec_t prec = 128;
    theorem_constants K(prec, p);
    for (auto [proved, against] : {std::pair{1, 2}, {2, 1}}) {
      INFO(p.str() << ": the bracket of m = " << proved << " against m = " << against);
      root_enclosure own(prec), other(prec);
      REQUIRE(prove_theorem_root(own, K, big_int(proved)));
      REQUIRE(theorem_centre_of(other, K, big_int(against)));
      fixed_mpfi LO(prec), HI(prec), T(prec), d(prec);
      mpfi_set_fr(LO, own.U.left());
      mpfi_set_fr(HI, own.U.right());
      REQUIRE(prove_theorem_bracket(K, own, LO, HI, T));  // its own centre: proved
      big_float dmax(prec);
      mpfi_sub_fr(d, own.U, other.centre);
      mpfi_mag(dmax, d);
      REQUIRE(mpfr_cmp_d(dmax, 0x1p-10) <= 0);  // near the other centre: the inequality decides
      CHECK_FALSE(prove_theorem_bracket(K, other, LO, HI, T));
    }
  }
}

TEST_CASE("prove_theorem_bracket refuses a claim narrower than its enclosures at the working precision",
          "[theorem][bracket][precision]") {
  // Ends u* (1 -+ 2^-(P+4)), exact at P + 64 bits: below one unit of the working precision P, so
  // no P-bit enclosure of H can separate them from u*. Refused at P bits; the same ends are
  // proved at P + 64 bits. One end at a time (the other at a safe distance), so that a kernel
  // which let an undecided comparison pass for either end would be caught.
  for (const auto& c : {pairs[1], pairs[2], pairs[5], pairs[12], pairs[13]}) {
    const auto p = pair_of(c);
    const big_int m(p.strand_offset_min());
    for (mpfr_prec_t P : {64, 128, 500}) {
      big_float u(P + 64 + extra_bits);
      theorem_root_reference(u, p, m);
      for (int which : {0, 1}) {
        INFO(p.str() << " at " << P << " bits, the " << (which == 0 ? "lower" : "upper") << " end close");
        fixed_mpfi LO(P + 64), HI(P + 64);
        scaled_point(LO, u, -1, which == 0 ? int(P) + 4 : int(P) - 24);
        scaled_point(HI, u, +1, which == 1 ? int(P) + 4 : int(P) - 24);
        {
          theorem_constants K(P, p);
          root_enclosure r(P);
          REQUIRE(theorem_centre_of(r, K, m));
          fixed_mpfi T(P);
          CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
        }
        {
          theorem_constants K(P + 64);
          set_theorem_constants(K, p);
          root_enclosure r(P + 64);
          REQUIRE(theorem_centre_of(r, K, m));
          fixed_mpfi T(P + 64);
          CHECK(prove_theorem_bracket(K, r, LO, HI, T));
        }
      }
    }
  }
}

TEST_CASE("prove_theorem_bracket refuses ends farther than 2^-10 from the centre or outside (0, pi/2)",
          "[theorem][bracket][distance]") {
  // Pairs with u* well inside (2^-9, pi/2 - 2^-9): the brackets below are true, so only the
  // distance (or the range) can refuse them.
  for (const auto& c : {pairs[0], pairs[1], pairs[2], pairs[3]}) {
    const auto p = pair_of(c);
    const big_int m(p.strand_offset_min());
    REQUIRE(m != 0);
    const mpfr_prec_t prec = 128;
    INFO(p.str());
    theorem_constants K(prec, p);
    root_enclosure r(prec);
    REQUIRE(theorem_centre_of(r, K, m));
    fixed_mpfi LO(prec), HI(prec), T(prec);
    big_float end(prec);
    auto ends = [&](double below, double above) {
      mpfr_set_d(end, below, MPFR_RNDN);
      mpfr_sub(end, r.centre, end, MPFR_RNDN);
      mpfi_set_fr(LO, end);
      mpfr_set_d(end, above, MPFR_RNDN);
      mpfr_add(end, r.centre, end, MPFR_RNDN);
      mpfi_set_fr(HI, end);
    };
    ends(0x1p-11, 0x1p-11);
    CHECK(prove_theorem_bracket(K, r, LO, HI, T));  // within 2^-10: proved
    ends(0x1p-9, 0x1p-11);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
    ends(0x1p-11, 0x1p-9);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
    ends(0x1.2p-10, 0x1.2p-10);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
  }
  // u* < 2^-10 (x -> 1): the bracket [0, hi] is true (H(0) = 0 < mu) and within 2^-10 of the
  // centre, but lo must be > 0.
  for (const auto& c : {pairs[5], pairs[6], pairs[7]}) {
    const auto p = pair_of(c);
    const mpfr_prec_t prec = 128;
    INFO(p.str());
    theorem_constants K(prec, p);
    root_enclosure r(prec);
    REQUIRE(prove_theorem_root(r, K, big_int(p.strand_offset_min())));
    REQUIRE(mpfr_cmp_d(r.U.right(), 0x1.cp-11) < 0);
    fixed_mpfi LO(prec), HI(prec), T(prec);
    mpfi_set_fr(LO, r.U.left());
    mpfi_set_fr(HI, r.U.right());
    CHECK(prove_theorem_bracket(K, r, LO, HI, T));
    mpfi_set_ui(LO, 0);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
    mpfi_interv_d(LO, -0x1p-40, 0x1p-40);
    CHECK_FALSE(prove_theorem_bracket(K, r, LO, HI, T));
  }
}

TEST_CASE("theorem_radius encloses sqrt(G) over an interval T and only there", "[theorem][radius]") {
  // T = [tan(u* (1 - 2^-30)), tan(u* (1 + 2^-30))]: the enclosure holds sqrt(G) at both ends and
  // at u*, and it is narrow; sqrt(G) at u* (1 + 2^-20) lies outside.
  for (const auto& c : pairs) {
    const auto p = pair_of(c);
    const big_int m(p.strand_offset_min());
    if (m == 0) continue;
    INFO(p.str());
    const mpfr_prec_t prec = 200, bits = prec + extra_bits;
    theorem_constants K(prec, p);
    big_float u(bits), v(bits), t(bits), g(bits);
    theorem_root_reference(u, p, m);
    fixed_mpfi T(prec), R(prec);
    big_float lo(prec), hi(prec);
    mpfr_mul_2si(v, u, -30, MPFR_RNDN);
    mpfr_sub(v, u, v, MPFR_RNDN);
    mpfr_tan(lo, v, MPFR_RNDD);
    mpfr_mul_2si(v, u, -30, MPFR_RNDN);
    mpfr_add(v, u, v, MPFR_RNDN);
    mpfr_tan(hi, v, MPFR_RNDU);
    mpfi_interv_fr(T, lo, hi);
    theorem_radius(R, K, T);
    for (int f : {-1, 0, 1}) {
      mpfr_mul_2si(v, u, -30, MPFR_RNDN);
      mpfr_mul_si(v, v, f, MPFR_RNDN);
      mpfr_add(v, u, v, MPFR_RNDN);
      radius_reference(g, p, v);
      CHECK(contains(R, g));
    }
    CHECK(narrow(R, 26));
    mpfr_mul_2si(v, u, -20, MPFR_RNDN);
    mpfr_add(v, u, v, MPFR_RNDN);
    radius_reference(g, p, v);
    CHECK_FALSE(contains(R, g));
  }
}
