// The theorem-aware peers: the lattice theorem (proofs/lattice-theorem.md) implemented as a
// knowledgeable outsider would, from its statement alone, with none of gyrores' numerics. They
// are the limits gyrores' own paths are measured against (headlines.cpp, L1 and L2).
//
//  peer_newton    plain double (peer_newton.hpp): integers in int64/int128, Newton on H.
//  peer_arb_ball  Arb balls: Newton on midpoints with precision doubling to half the bits, then one
//                 interval Newton step at full precision, which proves the root's ball and
//                 doubles its accuracy; tan over the ball by the mean value form; r_res,
//                 theta_first, t_first as balls; the proved decimal claims (outward, D + 10
//                 digits, relative width <= 10^-(D+1), the statements of a certificate) and
//                 from them the correct roundings to D digits (precision doubled if undecided).
//  peer_arb_calc  Arb's arb_calc_refine_root_newton on the same equation, from a start ball that
//                 sign checks prove to hold the root, its convergence factor from
//                 arb_calc_newton_conv_factor; then arb_tan of the root's ball and the same
//                 balls, claims and roundings as peer_arb_ball.
// Each call of an Arb peer does all of it: integers, constants, root, proof, decimal text.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>

#include "case_support.hpp"
#include "methods.hpp"
#include "peer_newton.hpp"
#include "reference.hpp"

#ifdef GYRORES_BENCH_HAVE_ARB
#include <arb.h>
#include <arb_calc.h>
#include <flint/fmpz.h>
#include <mpfr.h>

#include <algorithm>

#include "arb_types.hpp"
#endif

namespace gyrores::bench {

namespace {

// ---- peer_newton ----------------------------------------------------------------------------

bool fits_int128(const bench_pair& bp) {
  // a < 2^120: the peer forms a, 2b and the cofactors of Euclid, all below 2a.
  return boost::multiprecision::msb(bp.order()) < 120;
}

bench_case peer_newton_case(const bench_pair& bp, const precision& pr, const reference&) {
  auto convert = [](const peer_point& m) {
    outcome o;
    o.theta = real_text(m.theta_first);
    o.r_res = real_text(m.r_res);
    o.evaluations = std::uint64_t(m.iterations);
    return o;
  };
  if (bp.fits64()) {
    const auto p = bp.p64();
    const std::int64_t tau = p.tau(), sigma = p.sigma();
    return make_case("peer_newton", pr, bp, [=] { return peer_newton_minimum(tau, sigma); }, convert);
  }
  const int128 tau = to_int128(bp.p.tau()), sigma = to_int128(bp.p.sigma());
  return make_case("peer_newton", pr, bp, [=] { return peer_newton_minimum(tau, sigma); }, convert);
}

std::string skip_peer_newton(const bench_pair& bp, const precision& pr) {
  if (pr.kind != real_kind::dbl) return "the plain peer is double only; the Arb peers cover the other precisions";
  if (!fits_int128(bp)) return "order beyond 2^120: the plain peer's integers are __int128";
  return "";
}

#ifdef GYRORES_BENCH_HAVE_ARB

// ---- the Arb peers: shared parts --------------------------------------------------------------

using ball = arb_ball;
using integer = fmpz_int;

// The pair's integers and constants: x = b/a, mu = pi m_min/(2a), 1 - x^2 = 4 tau sigma/a^2,
// sqrt(tau sigma), pi; the first minimiser's lobe: theta_first = 2 (key pi + sign u*)/a.
struct problem {
  integer a, b, ts, key;
  int m_min = 0, sign = 1;
  ball x, mu, omx2, sqrt_ts, pi;
  std::uint64_t evaluations = 0;
  problem(const big_int& tau, const big_int& sigma)
      : a(big_int(tau + sigma)), b(big_int(tau - sigma)), ts(big_int(tau * sigma)) {
    m_min = int(fmpz_fdiv_ui(a, 4));
    m_min = m_min == 0 ? 0 : (m_min == 2 ? 2 : 1);
    if (m_min == 0) {  // r_res = 0 at theta = pi/2: key a/4, u = 0
      fmpz_fdiv_q_2exp(key, a, 2);
      return;
    }
    integer P, B, inv;  // the + lobes: k = -B^{-1} mod P (peer_newton.hpp)
    if (m_min == 1) fmpz_set(P, a), fmpz_mul_2exp(B, b, 1);
    else fmpz_fdiv_q_2exp(P, a, 1), fmpz_set(B, b);
    fmpz_mod(B, B, P);
    fmpz_invmod(inv, B, P);
    if (!fmpz_is_zero(inv)) fmpz_sub(key, P, inv);
    fmpz_mul_2exp(inv, key, 1);  // 2k < P: the + lobe comes first, else the mirror P - k
    if (!fmpz_is_zero(key) && fmpz_cmp(inv, P) > 0) fmpz_sub(key, P, key), sign = -1;
  }
  void set_constants(slong prec) {
    arb_const_pi(pi, prec);
    arb_set_fmpz(x, b);
    arb_div_fmpz(x, x, a, prec);
    arb_mul_si(mu, pi, m_min, prec);
    arb_div_fmpz(mu, mu, a, prec);
    arb_mul_2exp_si(mu, mu, -1);
    arb_set_fmpz(sqrt_ts, ts);
    arb_sqrt(sqrt_ts, sqrt_ts, prec);
    arb_set_fmpz(omx2, ts);
    arb_mul_2exp_si(omx2, omx2, 2);
    arb_div_fmpz(omx2, omx2, a, prec);
    arb_div_fmpz(omx2, omx2, a, prec);
  }
  // The double start: u* by peer_newton's Newton.
  double start() const {
    const double ad = fmpz_get_d(a), x0 = fmpz_get_d(b) / ad;
    int steps = 0;
    return peer_root(x0, std::numbers::pi * m_min / (2 * ad), steps);
  }
};

// f = H(u) - mu = x u + atan(x t) - mu with t = tan u (also returned).
void h_at(arb_t f, arb_t t, const arb_t u, problem& P, slong prec) {
  ++P.evaluations;
  arb_tan(t, u, prec);
  arb_mul(f, P.x, t, prec);
  arb_atan(f, f, prec);
  arb_addmul(f, P.x, u, prec);
  arb_sub(f, f, P.mu, prec);
}

// f' = x + x tan'(u)/(1 + x^2 t^2) from t = tan u and tan'(u) = 1 + t^2 (given, or formed when null).
void h_derivative(arb_t df, const arb_t t, const arb_t dtan, const problem& P, slong prec) {
  ball d, g;
  if (!dtan) {
    arb_sqr(g, t, prec);
    arb_add_ui(g, g, 1, prec);
  }
  arb_mul(d, P.x, t, prec);
  arb_sqr(d, d, prec);
  arb_add_ui(d, d, 1, prec);
  arb_div(df, dtan ? dtan : g.v, d, prec);
  arb_add_ui(df, df, 1, prec);
  arb_mul(df, df, P.x, prec);
}

// arb_calc's function: out[0] = f, out[1] = f', out[2] = f''/2 = x (1 - x^2) t (1 + t^2)/(1 + x^2 t^2)^2.
int h_minus_mu(arb_ptr out, const arb_t u, void* param, slong order, slong prec) {
  auto& P = *static_cast<problem*>(param);
  ball t, d;
  h_at(out, t, u, P, prec);
  if (order > 1) h_derivative(out + 1, t, nullptr, P, prec);
  if (order > 2) {
    arb_sqr(d, t, prec);
    arb_add_ui(d, d, 1, prec);
    arb_mul(out + 2, d, t, prec);
    arb_mul(out + 2, out + 2, P.x, prec);
    arb_mul(out + 2, out + 2, P.omx2, prec);
    arb_mul(d, P.x, t, prec);
    arb_sqr(d, d, prec);
    arb_add_ui(d, d, 1, prec);
    arb_sqr(d, d, prec);
    arb_div(out + 2, out + 2, d, prec);
  }
  return 0;
}

// Outward decimal text of a positive ball with n digits, and its rounding to D digits (half up:
// monotone, so equal roundings of both ends are the rounding of every point between).
struct decimal {
  std::string digits;  // n significant digits
  long exp = 0;        // value = 0.digits x 10^exp
};
decimal decimal_of(const arf_t v, unsigned n, mpfr_rnd_t rnd) {
  mpfr_t m;
  mpfr_init2(m, std::max<slong>(arf_bits(v), 2));
  arf_get_mpfr(m, v, MPFR_RNDN);  // exact: enough bits
  mpfr_exp_t e = 0;
  char* s = mpfr_get_str(nullptr, &e, 10, n, m, rnd);
  decimal out{s, long(e)};
  mpfr_free_str(s);
  mpfr_clear(m);
  return out;
}
decimal rounded(decimal d, unsigned D) {
  const bool up = d.digits[D] >= '5';
  d.digits.resize(D);
  int i = int(D) - 1;
  for (; up && i >= 0 && d.digits[std::size_t(i)] == '9'; --i) d.digits[std::size_t(i)] = '0';
  if (up && i < 0) d.digits.insert(0, "1"), d.digits.pop_back(), ++d.exp;
  else if (up) ++d.digits[std::size_t(i)];
  return d;
}
std::string text(const decimal& d) {
  return d.digits.substr(0, 1) + "." + d.digits.substr(1) + "e" + std::to_string(d.exp - 1);
}

// What an Arb peer produces: the decimal claims [lo, hi] and the D-digit values.
struct claims {
  std::pair<std::string, std::string> u_star, r_res, theta_first, t_first;
  std::string r_value, theta_value, t_value;
  slong bits = 0;
};

// The claims of X (n = D + 10 digits outward) and its D-digit value; false when X is wider than
// 10^-(D+1) relative or its rounding is undecided.
bool claim(std::pair<std::string, std::string>& ends, std::string* value, const arb_t X, unsigned D) {
  if (arb_is_zero(X)) {
    ends = {"0", "0"};
    if (value) *value = "0";
    return true;
  }
  if (!arb_is_positive(X) || arb_rel_accuracy_bits(X) < slong(std::ceil((D + 1) * 3.3219280948873623)) + 2)
    return false;
  arf_t lo, hi;
  arf_init(lo);
  arf_init(hi);
  arb_get_lbound_arf(lo, X, arb_bits(X) + 8);
  arb_get_ubound_arf(hi, X, arb_bits(X) + 8);
  const decimal l = decimal_of(lo, D + 10, MPFR_RNDD), h = decimal_of(hi, D + 10, MPFR_RNDU);
  arf_clear(lo);
  arf_clear(hi);
  ends = {text(l), text(h)};
  if (!value) return true;
  const decimal rl = rounded(l, D), rh = rounded(h, D);
  if (rl.digits != rh.digits || rl.exp != rh.exp) return false;
  *value = text(rl);
  return true;
}

// From the root's ball U and T = tan(U): r_res, theta_first, t_first and the claims.
bool write_claims(claims& c, problem& P, const arb_t U, const arb_t T, unsigned D, slong prec) {
  ball r, d, th, t;
  if (P.m_min > 0) {  // r_res = x sqrt(1-x^2) t^2/sqrt((1+t^2)(1+x^2 t^2))
    arb_sqr(r, T, prec);
    arb_mul(d, r, P.x, prec);
    arb_mul(d, d, P.x, prec);
    arb_add_ui(d, d, 1, prec);
    arb_add_ui(th, r, 1, prec);
    arb_mul(d, d, th, prec);
    arb_rsqrt(d, d, prec);
    arb_mul(r, r, d, prec);
    arb_sqrt(d, P.omx2, prec);
    arb_mul(r, r, d, prec);
    arb_mul(r, r, P.x, prec);
  }
  arb_mul_fmpz(th, P.pi, P.key, prec);  // theta_first = 2 (key pi + sign u*)/a
  if (P.sign > 0) arb_add(th, th, U, prec);
  else arb_sub(th, th, U, prec);
  arb_mul_2exp_si(th, th, 1);
  arb_div_fmpz(th, th, P.a, prec);
  arb_mul(t, th, P.sqrt_ts, prec);
  c.bits = prec;
  return claim(c.u_star, nullptr, U, D) && claim(c.r_res, &c.r_value, r, D) &&
         claim(c.theta_first, &c.theta_value, th, D) && claim(c.t_first, &c.t_value, t, D);
}

// The first precision: the digits' bits and 32 guard bits, as gyrores' proved paths start.
slong start_bits(unsigned D) { return slong(std::ceil(D * 3.3219280948873623)) + 32; }

// ---- peer_arb_ball --------------------------------------------------------------------------

// u* proved at `prec` bits: U its ball, T = tan(U). False if the proof fails (then double prec).
bool ball_root(arb_t U, arb_t T, problem& P, slong prec) {
  slong level[64];  // Newton on midpoints, each level doubling the bits, up to prec/2 + 16
  int n = 0;
  for (slong p = prec / 2 + 16; p > 60 && n < 64; p = p / 2 + 8) level[n++] = p;
  ball u, f, t, df, Ur, TU, dtan, dfU;
  arb_set_d(u, P.start());
  for (int i = n - 1; i >= 0; --i) {
    const slong w = level[i] + 16;
    h_at(f, t, u, P, w);
    h_derivative(df, t, nullptr, P, w);
    arb_div(f, f, df, w);
    arb_sub(u, u, f, w);
    mag_zero(arb_radref(u.v));
  }
  // Interval Newton on Ur = u +- 2^-(level - 8) |u|: N = u - f(u)/f'(Ur) inside Ur proves that
  // the root is in N (f' > 0). f' over Ur needs only half the bits.
  const slong good = n ? level[0] : 48, half = good + 32;
  arb_set(Ur, u);
  arb_add_error_2exp_si(Ur, arf_abs_bound_lt_2exp_si(arb_midref(u.v)) - good + 8);
  arb_tan(TU, Ur, half);
  arb_sqr(dtan, TU, half);
  arb_add_ui(dtan, dtan, 1, half);  // tan' = 1 + tan^2 over Ur
  h_derivative(dfU, TU, dtan, P, half);
  h_at(f, T, u, P, prec + 16);
  arb_div(f, f, dfU, prec + 16);
  arb_sub(U, u, f, prec + 16);
  if (!arb_is_positive(dfU) || !arb_contains(Ur, U)) return false;
  arb_sub(f, U, u, prec + 16);  // tan(U) in tan(u) + tan'(Ur) (U - u)
  arb_addmul(T, dtan, f, prec + 16);
  return true;
}

// The Arb peers' common loop: root(U, T, P, prec) proves u*; the claims at the first precision
// that decides them.
template <class Root> claims arb_peer(const big_int& tau, const big_int& sigma, unsigned D, Root root,
                                      std::uint64_t& evaluations) {
  problem P(tau, sigma);
  for (slong prec = start_bits(D); prec <= (slong(1) << 20); prec *= 2) {
    P.set_constants(prec + 16);
    ball U, T;
    claims c;
    if (P.m_min > 0 && !root(U.v, T.v, P, prec)) continue;
    if (write_claims(c, P, U, T, D, prec + 16)) {
      evaluations = P.evaluations;
      return c;
    }
  }
  throw std::runtime_error("Arb peer: not decided within 2^20 bits");
}

// ---- peer_arb_calc --------------------------------------------------------------------------

// u* by arb_calc_refine_root_newton from u0 +- 2^-40 |u0| (proved to hold the root by the signs
// of f at its ends), convergence region u0 +- 2^-20 |u0|; T = tan(U) by arb_tan.
bool calc_root(arb_t U, arb_t T, problem& P, slong prec) {
  const double u0 = P.start();
  const slong e = slong(std::ilogb(u0)) + 1;  // |u0| < 2^e
  ball start, region, end, f, t;
  arb_set_d(start, u0);
  arb_add_error_2exp_si(start, e - 40);
  arb_set_d(region, u0);
  arb_add_error_2exp_si(region, e - 20);
  arb_set_d(end, std::ldexp(1.0, int(e - 40)));
  arb_sub(end, start, end, 128);  // the lower end, exact
  mag_zero(arb_radref(end.v));
  h_at(f, t, end, P, 128);
  if (!arb_is_negative(f)) return false;
  arb_set_d(end, std::ldexp(1.0, int(e - 40)));
  arb_add(end, start, end, 128);
  mag_zero(arb_radref(end.v));
  h_at(f, t, end, P, 128);
  if (!arb_is_positive(f)) return false;
  arf_t conv;
  arf_init(conv);
  arb_calc_newton_conv_factor(conv, h_minus_mu, &P, region, 64);
  const int status = arb_calc_refine_root_newton(U, h_minus_mu, &P, start, region, conv, 16, prec);
  arf_clear(conv);
  if (status != ARB_CALC_SUCCESS) return false;
  arb_tan(T, U, prec + 16);
  return true;
}

// ---- the cases ------------------------------------------------------------------------------

// The reference rounded to D digits, as text() writes it.
std::string reference_rounding(const std::string& ref, unsigned ref_digits, unsigned D) {
  mpfr_t m;
  mpfr_init2(m, mpfr_prec_t(ref_digits * 3.33) + 64);
  mpfr_set_str(m, ref.c_str(), 10, MPFR_RNDN);
  mpfr_exp_t e = 0;
  char* s = mpfr_get_str(nullptr, &e, 10, D, m, MPFR_RNDN);
  const std::string out = text({s, long(e)});
  mpfr_free_str(s);
  mpfr_clear(m);
  return out;
}

template <class Root>
bench_case arb_peer_case(const std::string& name, const bench_pair& bp, const precision& pr, const reference& ref,
                         Root root) {
  const big_int tau = bp.p.tau(), sigma = bp.p.sigma();
  const unsigned D = pr.digits;
  bench_case c = new_case(name, pr, bp);
  c.timed = [=] {
    std::uint64_t ev = 0;
    benchmark::DoNotOptimize(arb_peer(tau, sigma, D, root, ev));
  };
  const std::string ref_r = reference_rounding(ref.r_res, ref.digits, D),
                    ref_theta = reference_rounding(ref.theta_first, ref.digits, D);
  c.pilot = [=] {
    std::uint64_t ev = 0;
    const claims cl = arb_peer(tau, sigma, D, root, ev);
    outcome o;
    o.theta = cl.theta_value;
    o.r_res = cl.r_value;
    o.r_enclosure = cl.r_res;
    o.evaluations = ev;
    if (cl.r_value != ref_r || cl.theta_value != ref_theta)
      o.note = "ROUNDING TO " + std::to_string(D) + " DIGITS DIFFERS FROM THE REFERENCE'S";
    if (cl.bits != start_bits(D) + 16)
      o.note += std::string(o.note.empty() ? "" : "; ") + "decided at " + std::to_string(cl.bits) + " bits";
    return o;
  };
  return c;
}

bench_case peer_arb_ball_case(const bench_pair& bp, const precision& pr, const reference& ref) {
  return arb_peer_case("peer_arb_ball", bp, pr, ref, ball_root);
}

bench_case peer_arb_calc_case(const bench_pair& bp, const precision& pr, const reference& ref) {
  return arb_peer_case("peer_arb_calc", bp, pr, ref, calc_root);
}

std::string skip_arb_peer(const bench_pair&, const precision& pr) {
  if (!pr.is_mp())
    return "the Arb peers take a number of decimal digits (mp30 to mp10000); in double the plain peer is peer_newton";
  return "";
}

#endif

}  // namespace

std::vector<method_def> theorem_peer_methods(const run_config&) {
  std::vector<method_def> out{
      {"peer_newton", "peer_newton",
       "**theorem-aware peer, plain double** (bench/speed_error/peer_newton.hpp, written from "
       "proofs/lattice-theorem.md alone): m_min from a mod 4, the first minimiser's lobe by one modular inverse "
       "(extended Euclid in int64, __int128 beyond order 2^62), u* by Newton on H(u) = x u + atan(x tan u) from "
       "the upper bound pi m_min/(4b) (H convex: monotone descent, guarded by the lower bound mu/(1+x)), r_res, "
       "theta_first and t_first; no heap; evaluations: Newton steps",
       skip_peer_newton, peer_newton_case},
  };
#ifdef GYRORES_BENCH_HAVE_ARB
  out.push_back(
      {"peer_arb_ball", "peer_arb_ball",
       "**theorem-aware peer, Arb balls** (bench/speed_error/peer_theorem.cpp): the integers by FLINT (one "
       "fmpz_invmod), u* by Newton on midpoints with precision doubling to half the bits, then one interval Newton "
       "step at full precision that proves the root's ball (f' over the ball at half precision) and tan over it by "
       "the mean value form; r_res, theta_first, t_first as balls; writes the certificate's claims (decimal "
       "brackets of u*, r_res, theta_first, t_first, outward, digits + 10 digits, relative width <= "
       "10^-(digits+1)) and from them the correct roundings of r_res, theta_first, t_first to the digits "
       "(precision doubled until decided); scored on those roundings, which are also compared with the "
       "reference's",
       skip_arb_peer, peer_arb_ball_case});
  out.push_back(
      {"peer_arb_calc", "peer_arb_calc",
       "**theorem-aware peer, Arb's root refinement** (bench/speed_error/peer_theorem.cpp): "
       "arb_calc_refine_root_newton on H(u) - mu with arb_calc_newton_conv_factor over u0 +- 2^-20 u0, from "
       "u0 +- 2^-40 u0 (u0: peer_newton's double root; signs at its ends prove it holds u*), then arb_tan over the "
       "root's ball and the same balls, claims and roundings as peer_arb_ball",
       skip_arb_peer, peer_arb_calc_case});
#endif
  return out;
}

}  // namespace gyrores::bench
