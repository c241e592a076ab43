// The producer of coupling certificates (certify/horizon_certificate.hpp). The decisions (the cut
// lobe, whether its minimiser is reached, the end point against the best lobe) and the claims
// come from theorem/horizon.hpp; this file adds what the checker needs to re-prove them: the lobe
// integers (model/rotation.hpp) and decimal brackets of the lobe roots H^{-1}(pi nu), found by
// bisection in Arb and proved after rounding to decimals (H(lo) < pi nu < H(hi), strict).
#include <gyrores/certify/horizon_certificate.hpp>

#include <arb.h>

#include <algorithm>
#include <functional>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/model/rotation.hpp>
#include <gyrores/theorem/horizon.hpp>

#include "../core/ball.hpp"

namespace gyrores {
namespace {

using namespace arb_support;

slong bits_of(const big_int& z) { return z == 0 ? 0 : slong(boost::multiprecision::msb(z < 0 ? big_int(-z) : z)) + 1; }

// H(u) = x u + atan2(x sin u, cos u) (lattice-theorem.md Step A), |u| < pi/2.
void H(arb_t out, const arb_t x, const arb_t u, slong prec) {
  ball s, c;
  arb_sin_cos(s.get(), c.get(), u, prec);
  arb_mul(s.get(), s.get(), x, prec);
  arb_atan2(out, s.get(), c.get(), prec);
  arb_addmul(out, x, u, prec);
}

// The decimal text of an arf, rounded outward (down for a lower end, up for an upper end).
std::string decimal_of(const arf_t v, unsigned digits, bool up, slong prec) {
  if (arf_is_zero(v)) return "0";
  fixed_mpfr m(prec + 16);
  arf_get_mpfr(m, v, MPFR_RNDN);  // exact: the arf has at most prec bits
  return format_scientific(static_cast<mpfr_srcptr>(m), digits, up ? MPFR_RNDU : MPFR_RNDD);
}

// f(u), negative before the root and positive after it (on the interval searched), at `prec` bits.
using root_fn = std::function<void(arb_t, const arb_t, slong)>;
// The two exact start points lo < hi of a search, at `prec` bits.
using ends_fn = std::function<void(arb_t, arb_t, slong)>;

// A decimal bracket of the root of f, relative width about 10^-(digits + 12): bisection on exact
// midpoints, then the proof f(lo) < 0 < f(hi) on the decimals as written (what the checker reads).
decimal_bracket bracket_root(const root_fn& f, const ends_fn& ends, unsigned digits, slong extra_bits) {
  const unsigned text_digits = digits + 15;
  const slong target_bits = slong(3.33 * (digits + 12));
  for (slong prec = slong(3.33 * text_digits) + 64 + extra_bits; prec <= (slong(1) << 17); prec *= 2) {
    ball lo, hi, mid, v, w, scale;
    ends(lo.get(), hi.get(), prec);
    f(v.get(), lo.get(), prec);
    if (!arb_is_negative(v.get())) continue;
    f(v.get(), hi.get(), prec);
    if (!arb_is_positive(v.get())) continue;
    for (slong step = 0; step < 4 * prec; ++step) {
      arb_sub(w.get(), hi.get(), lo.get(), prec);
      arb_mul_2exp_si(w.get(), w.get(), target_bits);
      arb_abs(scale.get(), lo.get());
      arb_abs(mid.get(), hi.get());
      arb_max(scale.get(), scale.get(), mid.get(), prec);
      if (arb_lt(w.get(), scale.get())) break;
      arb_add(mid.get(), lo.get(), hi.get(), 2 * prec);
      arb_mul_2exp_si(mid.get(), mid.get(), -1);
      f(v.get(), mid.get(), prec);
      if (arb_is_negative(v.get())) arb_swap(lo.get(), mid.get());
      else if (arb_is_positive(v.get())) arb_swap(hi.get(), mid.get());
      else break;
    }
    const decimal_bracket out{decimal_of(arb_midref(lo.get()), text_digits, false, 2 * prec),
                              decimal_of(arb_midref(hi.get()), text_digits, true, 2 * prec)};
    ball dlo, dhi, flo, fhi;
    if (arb_set_str(dlo.get(), out.first.c_str(), prec) || arb_set_str(dhi.get(), out.second.c_str(), prec)) continue;
    f(flo.get(), dlo.get(), prec);
    f(fhi.get(), dhi.get(), prec);
    if (arb_is_negative(flo.get()) && arb_is_positive(fhi.get()) && arb_lt(dlo.get(), dhi.get())) return out;
  }
  throw compute_error("coupling certificate: a root was not bracketed within 2^17 bits");
}

// The coupling's x, x^2 = P/(P + 4Q) and S = sqrt(n^2 + 4) as balls.
struct coupling_balls {
  ball x, x2, s;
  coupling_balls(const coupling_spec& c, const quadratic_number& xq, slong prec) {
    set_quadratic(x.get(), xq, prec);
    arb_mul(x2.get(), x.get(), x.get(), prec);
    ball n2, d;
    set_int(n2.get(), c.P());
    set_int(d.get(), c.Q());
    arb_div(n2.get(), n2.get(), d.get(), prec);
    arb_add_ui(s.get(), n2.get(), 4, prec);
    arb_sqrt(s.get(), s.get(), prec);
  }
};

// G(u) = (1 - x^2) x^2 sin^4 u/(cos^2 u + x^2 sin^2 u) (lattice-theorem.md Step C).
void G(arb_t out, const coupling_balls& cb, const arb_t u, slong prec) {
  ball s, c, e, t;
  arb_sin_cos(s.get(), c.get(), u, prec);
  arb_sqr(s.get(), s.get(), prec);
  arb_sqr(c.get(), c.get(), prec);
  arb_mul(e.get(), cb.x2.get(), s.get(), prec);
  arb_add(e.get(), e.get(), c.get(), prec);
  arb_sqr(t.get(), s.get(), prec);
  arb_mul(t.get(), t.get(), cb.x2.get(), prec);
  arb_sub_ui(out, cb.x2.get(), 1, prec);
  arb_neg(out, out);
  arb_mul(out, out, t.get(), prec);
  arb_div(out, out, e.get(), prec);
}

// R at alpha (qdot0 = 1): (1 - x^2) sin^2 alpha cos^2 beta + (cos alpha cos beta - x sin alpha sin beta)^2.
void R_at(arb_t out, const coupling_balls& cb, const arb_t alpha, slong prec) {
  ball b, sa, ca, sb, cbeta, q, qd, t;
  arb_mul(b.get(), cb.x.get(), alpha, prec);
  arb_sin_cos(sa.get(), ca.get(), alpha, prec);
  arb_sin_cos(sb.get(), cbeta.get(), b.get(), prec);
  arb_mul(q.get(), sa.get(), cbeta.get(), prec);
  arb_sqr(q.get(), q.get(), prec);
  arb_sub_ui(t.get(), cb.x2.get(), 1, prec);
  arb_neg(t.get(), t.get());
  arb_mul(q.get(), q.get(), t.get(), prec);
  arb_mul(qd.get(), ca.get(), cbeta.get(), prec);
  arb_mul(t.get(), sa.get(), sb.get(), prec);
  arb_mul(t.get(), t.get(), cb.x.get(), prec);
  arb_sub(qd.get(), qd.get(), t.get(), prec);
  arb_sqr(qd.get(), qd.get(), prec);
  arb_add(out, q.get(), qd.get(), prec);
}

// [0, a point just below pi/2].
void quarter_turn(arb_t lo, arb_t hi, slong prec) {
  arb_zero(lo);
  ball p;
  arb_const_pi(p.get(), prec);
  arb_mul_2exp_si(p.get(), p.get(), -1);
  arf_t top;
  arf_init(top);
  arb_get_lbound_arf(top, p.get(), prec);
  arb_set_arf(hi, top);
  arf_clear(top);
}

// A decimal bracket of u0 = H^{-1}(pi nu) in [0, pi/2) (H increases, lattice-theorem.md Step A).
decimal_bracket root_bracket(const quadratic_number& x, const quadratic_number& nu, unsigned digits) {
  if (nu.sign() == 0) return {"0", "0"};
  auto f = [&](arb_t out, const arb_t u, slong prec) {
    ball xb, t;
    set_quadratic(xb.get(), x, prec);
    set_quadratic(t.get(), nu, prec);
    ball pi;
    arb_const_pi(pi.get(), prec);
    arb_mul(t.get(), t.get(), pi.get(), prec);
    H(out, xb.get(), u, prec);
    arb_sub(out, out, t.get(), prec);
  };
  return bracket_root(f, quarter_turn, digits, 0);
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


namespace {

// The lower (upper) end of the decimal `text` as an exact point: <= (>=) the decimal.
void decimal_point(arb_t out, const std::string& text, bool upper, slong prec) {
  ball b;
  arb_set_str(b.get(), text.c_str(), prec);
  arf_t e;
  arf_init(e);
  if (upper) arb_get_ubound_arf(e, b.get(), prec);
  else arb_get_lbound_arf(e, b.get(), prec);
  arb_set_arf(out, e);
  arf_clear(e);
}

// level_root (G^{-1}(2E)) and delta (H(G^{-1}(2E))/pi), both decimal brackets.
void level_brackets(const coupling_spec& c, const quadratic_number& x, const big_rational& E, unsigned digits,
                    below_certificate& out) {
  auto f = [&](arb_t o, const arb_t u, slong prec) {
    coupling_balls cb(c, x, prec);
    G(o, cb, u, prec);
    ball level;
    set_int(level.get(), big_int(2 * boost::multiprecision::numerator(E)));
    ball d;
    set_int(d.get(), big_int(boost::multiprecision::denominator(E)));
    arb_div(level.get(), level.get(), d.get(), prec);
    arb_sub(o, o, level.get(), prec);
  };
  out.level_root = bracket_root(f, quarter_turn, digits, 0);
  const slong prec = slong(3.33 * (digits + 20)) + 64;
  ball xb, pi, u, h;
  set_quadratic(xb.get(), x, prec);
  arb_const_pi(pi.get(), prec);
  decimal_bracket d;
  arf_t e;
  arf_init(e);
  arb_set_str(u.get(), out.level_root->first.c_str(), prec);
  H(h.get(), xb.get(), u.get(), prec);
  arb_div(h.get(), h.get(), pi.get(), prec);
  arb_get_lbound_arf(e, h.get(), prec);
  d.first = decimal_of(e, digits + 15, false, prec);
  arb_set_str(u.get(), out.level_root->second.c_str(), prec);
  H(h.get(), xb.get(), u.get(), prec);
  arb_div(h.get(), h.get(), pi.get(), prec);
  arb_get_ubound_arf(e, h.get(), prec);
  d.second = decimal_of(e, digits + 15, true, prec);
  arf_clear(e);
  out.delta = d;
}

// The crossing R = 2E on lobe k's descending branch [max(u_g, -pi/2), u*], u_g = -H^{-1}(pi/2 - mu).
decimal_bracket crossing_bracket(const coupling_spec& c, const quadratic_number& x, const big_rational& E,
                                 const certificate_lobe& lobe, const quadratic_number& nu, unsigned digits) {
  const slong kbits = bits_of(lobe.k) + 8;
  // The branch start: 0 in lobe 0; else just after u_g, or just after -pi/2 when u_g < -pi/2.
  std::string start_text;
  if (lobe.k > 0) {
    const quadratic_number mu = nu * quadratic_number(lobe.side);  // mu_k/pi
    if (mu + x / quadratic_number(2) > quadratic_number(0)) {  // mu > -x pi/2 (exact): u_g >= -pi/2
      auto fg = [&](arb_t o, const arb_t u, slong prec) {
        ball xb, t, pi;
        set_quadratic(xb.get(), x, prec);
        set_quadratic(t.get(), quadratic_number(1, 2) - mu, prec);
        arb_const_pi(pi.get(), prec);
        arb_mul(t.get(), t.get(), pi.get(), prec);
        H(o, xb.get(), u, prec);
        arb_sub(o, o, t.get(), prec);
      };
      start_text = "-" + bracket_root(fg, quarter_turn, digits, 0).first;  // -v_lo >= u_g
    }
  }
  auto ends = [&](arb_t lo, arb_t hi, slong prec) {
    if (lobe.k == 0) arb_zero(lo);
    else if (!start_text.empty()) decimal_point(lo, start_text, true, prec);
    else {
      ball p;
      arb_const_pi(p.get(), prec);
      arb_mul_2exp_si(p.get(), p.get(), -1);
      arb_neg(p.get(), p.get());
      arf_t e;
      arf_init(e);
      arb_get_ubound_arf(e, p.get(), prec);
      arb_set_arf(lo, e);
      arf_clear(e);
    }
    if (lobe.side > 0) decimal_point(hi, lobe.root.first, false, prec);
    else if (lobe.side < 0) {
      decimal_point(hi, lobe.root.second, true, prec);
      arb_neg(hi, hi);
    } else arb_zero(hi);
  };
  auto f = [&](arb_t o, const arb_t u, slong prec) {
    coupling_balls cb(c, x, prec + kbits);
    ball alpha, pi, level, d;
    arb_const_pi(pi.get(), prec + kbits);
    set_int(alpha.get(), lobe.k);
    arb_mul(alpha.get(), alpha.get(), pi.get(), prec + kbits);
    arb_add(alpha.get(), alpha.get(), u, prec + kbits);
    R_at(o, cb, alpha.get(), prec + kbits);
    set_int(level.get(), big_int(2 * boost::multiprecision::numerator(E)));
    set_int(d.get(), big_int(boost::multiprecision::denominator(E)));
    arb_div(level.get(), level.get(), d.get(), prec);
    arb_sub(o, level.get(), o, prec);  // 2E - R: negative before the crossing, positive after
  };
  return bracket_root(f, ends, digits, kbits);
}

}  // namespace

below_certificate certify_first_below(const coupling_spec& c, const big_rational& E, unsigned digits) {
  const first_below_report r = prove_first_below(c, E, digits);
  const quadratic_number x = coupling_rotation_number(c);
  below_certificate out;
  out.level = E;
  if (2 * E >= 1) {
    out.kase = "start";
    out.t_below = decimal_bracket{"0", "0"};
    return out;
  }
  if (E == 0) {
    out.kase = r.never ? "never" : "zero";
    if (!r.never) {
      out.lobe = certificate_lobe_of(c, r.lobe->k, digits);
      out.t_below = r.t_below.enclosure;
    }
    return out;
  }
  if (r.never || r.lobe->k > 0) level_brackets(c, x, E, digits, out);
  if (r.never) {
    out.kase = "never";
    return out;
  }
  out.kase = "lobe";
  out.lobe = certificate_lobe_of(c, r.lobe->k, digits);
  out.crossing = crossing_bracket(c, x, E, *out.lobe, distance_to_half(x, r.lobe->k), digits);
  out.t_below = r.t_below.enclosure;
  return out;
}

}  // namespace gyrores
