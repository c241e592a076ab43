// src/lib/theorem/lobe_balls.hpp
#include "lobe_balls.hpp"

#include "../core/ball.hpp"

namespace gyrores::lobe_balls {

using arb_support::ball;

void square(arb_t out, const arb_t v, slong p) {
  arf_t l, h;
  arf_init(l);
  arf_init(h);
  arb_get_lbound_arf(l, v, p);
  arb_get_ubound_arf(h, v, p);
  ball a, b;
  arb_set_arf(a, l);
  arb_set_arf(b, h);
  arb_mul(a, a, a, p);
  arb_mul(b, b, b, p);
  arb_union(out, a, b, p);
  if (arf_sgn(l) < 0 && arf_sgn(h) > 0) {  // 0 inside
    ball z;
    arb_zero(z);
    arb_union(out, out, z, p);
  }
  arf_clear(l);
  arf_clear(h);
}

void H_of(arb_t out, const arb_t x, const arb_t u, slong p) {
  ball sn, cs, t;
  arb_sin_cos(sn, cs, u, p);
  arb_mul(sn, sn, x, p);
  arb_atan2(t, sn, cs, p);
  arb_mul(out, x, u, p);
  arb_add(out, out, t, p);
}

void dH_of(arb_t out, const arb_t x, const arb_t u, slong p) {
  ball sn, cs, e;
  arb_sin_cos(sn, cs, u, p);
  arb_mul(sn, sn, x, p);
  arb_mul(sn, sn, sn, p);
  arb_mul(cs, cs, cs, p);
  arb_add(e, sn, cs, p);
  arb_div(out, x, e, p);
  arb_add(out, out, x, p);
}

void G_of(arb_t out, const arb_t x, const arb_t u, slong p) {
  ball sn, cs, xs, e, t, w;
  arb_sin_cos(sn, cs, u, p);
  arb_mul(xs, x, sn, p);
  square(xs, xs, p);       // x^2 sin^2
  square(cs, cs, p);
  arb_add(e, cs, xs, p);
  square(t, sn, p);
  arb_mul(t, t, xs, p);    // x^2 sin^4
  square(w, x, p);
  arb_sub_si(w, w, 1, p);
  arb_neg(w, w);           // 1 - x^2
  arb_mul(out, w, t, p);
  arb_div(out, out, e, p);
}

}  // namespace gyrores::lobe_balls
