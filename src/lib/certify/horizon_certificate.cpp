// The producer of coupling certificates (certify/horizon_certificate.hpp). The decisions (the cut
// lobe, whether its minimiser is reached, the end point against the best lobe) and the claims
// come from theorem/horizon.hpp; this file adds what the checker needs to re-prove them: the lobe
// integers (model/rotation.hpp) and decimal brackets of the lobe roots H^{-1}(pi nu), found by
// bisection in Arb and proved after rounding to decimals (H(lo) < pi nu < H(hi), strict).
#include <gyrores/certify/horizon_certificate.hpp>

#include <arb.h>

#include <algorithm>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/model/rotation.hpp>
#include <gyrores/theorem/horizon.hpp>

namespace gyrores {
namespace {

struct ball {
  arb_t v;
  ball() { arb_init(v); }
  ~ball() { arb_clear(v); }
  ball(const ball&) = delete;
  ball& operator=(const ball&) = delete;
};

void set_int(arb_t out, const big_int& z) {
  fmpz_t f;
  fmpz_init(f);
  fmpz_set_mpz(f, z.backend().data());
  arb_set_fmpz(out, f);
  fmpz_clear(f);
}

slong bits_of(const big_int& z) { return z == 0 ? 0 : slong(boost::multiprecision::msb(z < 0 ? big_int(-z) : z)) + 1; }

// (p + q sqrt d)/r to `prec` bits: the norm p^2 - q^2 d is a non-zero integer, so the sum is never
// smaller than 1/(|p| + |q| sqrt d) and twice their bit length more suffices against cancellation.
void set_quadratic(arb_t out, const quadratic_number& v, slong prec) {
  const slong work = prec + 2 * std::max(bits_of(v.p()), bits_of(v.q()) + bits_of(v.d()) / 2 + 1) + 16;
  ball t, q;
  set_int(out, v.p());
  if (!v.is_rational()) {
    set_int(t.v, v.d());
    arb_sqrt(t.v, t.v, work);
    set_int(q.v, v.q());
    arb_mul(t.v, t.v, q.v, work);
    arb_add(out, out, t.v, work);
  }
  set_int(t.v, v.r());
  arb_div(out, out, t.v, prec);
}

// H(u) = x u + atan2(x sin u, cos u) (lattice-theorem.md Step A), |u| < pi/2.
void H(arb_t out, const arb_t x, const arb_t u, slong prec) {
  ball s, c;
  arb_sin_cos(s.v, c.v, u, prec);
  arb_mul(s.v, s.v, x, prec);
  arb_atan2(out, s.v, c.v, prec);
  arb_addmul(out, x, u, prec);
}

// The decimal text of an arf, rounded outward (down for a lower end, up for an upper end).
std::string decimal_of(const arf_t v, unsigned digits, bool up, slong prec) {
  if (arf_is_zero(v)) return "0";
  fixed_mpfr m(prec + 16);
  arf_get_mpfr(m, v, MPFR_RNDN);  // exact: the arf has at most prec bits
  return format_scientific(static_cast<mpfr_srcptr>(m), digits, up ? MPFR_RNDU : MPFR_RNDD);
}

// A decimal bracket of u0 = H^{-1}(pi nu) in [0, pi/2), relative width about 10^-(digits + 12).
decimal_bracket root_bracket(const quadratic_number& x, const quadratic_number& nu, unsigned digits) {
  if (nu.sign() == 0) return {"0", "0"};
  const unsigned text_digits = digits + 15;
  const slong target_bits = slong(3.33 * (digits + 12));
  for (slong prec = slong(3.33 * text_digits) + 64; prec <= (slong(1) << 17); prec *= 2) {
    ball xb, pi, target, half_pi, lo, hi, mid, h, w;
    set_quadratic(xb.v, x, prec);
    arb_const_pi(pi.v, prec);
    set_quadratic(target.v, nu, prec);
    arb_mul(target.v, target.v, pi.v, prec);
    arb_mul_2exp_si(half_pi.v, pi.v, -1);
    arb_zero(lo.v);
    arf_t top;
    arf_init(top);
    arb_get_lbound_arf(top, half_pi.v, prec);
    arb_set_arf(hi.v, top);
    arf_clear(top);
    // Bisection on exact midpoints: H(lo) < pi nu < H(hi) throughout (H increases, Step A).
    for (slong step = 0; step < 4 * prec; ++step) {
      arb_sub(w.v, hi.v, lo.v, prec);
      arb_mul_2exp_si(w.v, w.v, target_bits);
      if (!arb_is_zero(lo.v) && arb_lt(w.v, lo.v)) break;
      arb_add(mid.v, lo.v, hi.v, prec + 8);
      arb_mul_2exp_si(mid.v, mid.v, -1);
      H(h.v, xb.v, mid.v, prec);
      if (arb_lt(h.v, target.v)) arb_swap(lo.v, mid.v);
      else if (arb_gt(h.v, target.v)) arb_swap(hi.v, mid.v);
      else break;
    }
    const decimal_bracket out{decimal_of(arb_midref(lo.v), text_digits, false, prec),
                              decimal_of(arb_midref(hi.v), text_digits, true, prec)};
    // The proof, on the decimals as written (what the checker reads).
    ball dlo, dhi, hlo, hhi;
    if (arb_set_str(dlo.v, out.first.c_str(), prec) || arb_set_str(dhi.v, out.second.c_str(), prec)) continue;
    H(hlo.v, xb.v, dlo.v, prec);
    H(hhi.v, xb.v, dhi.v, prec);
    if (arb_is_nonnegative(dlo.v) && arb_lt(dlo.v, dhi.v) && arb_lt(dhi.v, half_pi.v) && arb_lt(hlo.v, target.v) &&
        arb_lt(target.v, hhi.v))
      return out;
  }
  throw compute_error("coupling certificate: the lobe root was not bracketed within 2^17 bits");
}

}  // namespace

certificate_lobe certificate_lobe_of(const coupling_spec& c, const big_int& k, unsigned digits) {
  if (k < 0) throw usage_error("a lobe index must be >= 0, got " + k.str());
  const quadratic_number x = coupling_rotation_number(c);
  certificate_lobe l;
  l.k = k;
  l.j = (x * quadratic_number(k)).floor();
  const quadratic_number nu = distance_to_half(x, k);
  l.side = k == 0 ? 1 : lobe_offset_sign(x, k);
  // nu = 1/2 in a lobe k >= 1: the first of the two minimisers is -H^{-1}(pi/2) (horizon-theorem.md Step 3).
  if (k >= 1 && nu == quadratic_number(1, 2)) l.side = -1;
  l.root = root_bracket(x, nu, digits);
  return l;
}

horizon_certificate certify_horizon_minimum(const coupling_spec& c, const big_rational& T, unsigned digits) {
  if (T <= 0) throw usage_error("a coupling certificate needs a horizon T > 0, got " + rational_str(T));
  const horizon_minimum_report r = prove_horizon_minimum(c, T, digits);
  const quadratic_number x = coupling_rotation_number(c);
  horizon_certificate out;
  out.theorem = horizon_theorem_id;
  out.n2 = c.n2;
  out.horizon = T;
  out.digits = digits;
  out.cut_lobe = r.cut_lobe;
  out.cut_lobe_reached = r.cut_lobe_reached;
  out.at_horizon_end = r.at_horizon_end;
  out.cut_root = root_bracket(x, distance_to_half(x, r.cut_lobe), digits);
  // The admissible lobes are 0..K_T; at the horizon's end the best of them is still stated, as
  // the checker needs its value to prove R(T) below it.
  const big_int K_T = r.cut_lobe_reached ? r.cut_lobe : big_int(r.cut_lobe - 1);
  if (K_T >= 0) {
    const big_int k = r.lobe ? r.lobe->k : min_distance_to_half(x, K_T).k;
    out.lobe = certificate_lobe_of(c, k, digits);
  }
  out.h_min = r.h_min.enclosure;
  out.t_min = r.t_min.enclosure;
  if (!r.at_horizon_end && r.lobe && r.lobe->nu.sign() == 0) out.h_min = {"0", "0"};
  return out;
}

}  // namespace gyrores
