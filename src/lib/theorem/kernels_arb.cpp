// src/lib/theorem/kernels_arb.hpp: the equations in balls.
#include "kernels_arb.hpp"

#include "../core/ball.hpp"

namespace gyrores::kernels_arb {

using arb_support::ball;

void H(arb_t out, const arb_t x, const arb_t u, slong p) {
  ball sn, cs, t;
  arb_sin_cos(sn, cs, u, p);
  arb_mul(sn, sn, x, p);
  arb_atan2(t, sn, cs, p);
  arb_mul(out, x, u, p);
  arb_add(out, out, t, p);
}

namespace {

// out = v^2 from the ends of v (a plain product v v of a wide ball can reach below 0).
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

// The terms G and dG share: sin u, cos u, E(u) = cos^2 u + x^2 sin^2 u, x^2 sin^2 u, sin^2 u,
// x^2 and 1 - x^2 (squares from their ends).
struct lobe_terms {
  ball sn, cs, e, xs2, s2, x2, w;
  lobe_terms(const arb_t x, const arb_t u, slong p) {
    ball c2;
    arb_sin_cos(sn, cs, u, p);
    arb_mul(xs2, x, sn, p);
    square(xs2, xs2, p);
    square(c2, cs, p);
    arb_add(e, c2, xs2, p);
    square(s2, sn, p);
    square(x2, x, p);
    arb_sub_si(w, x2, 1, p);
    arb_neg(w, w);              // 1 - x^2
  }
};

}  // namespace

void G(arb_t out, const arb_t x, const arb_t u, slong p) {
  const lobe_terms L(x, u, p);
  ball t;
  arb_mul(t, L.s2, L.xs2, p);  // x^2 sin^4
  arb_mul(out, L.w, t, p);
  arb_div(out, out, L.e, p);
}

void dG(arb_t out, const arb_t x, const arb_t u, slong p) {
  const lobe_terms L(x, u, p);
  ball e2;
  arb_mul(out, L.w, L.s2, p);
  arb_mul_2exp_si(out, out, 1);     // 2 (1 - x^2) sin^2
  arb_addmul_si(out, L.e, 4, p);    // 4E + 2 (1 - x^2) sin^2
  arb_mul(out, out, L.w, p);
  arb_mul(out, out, L.x2, p);
  arb_mul(out, out, L.s2, p);
  arb_mul(out, out, L.sn, p);
  arb_mul(out, out, L.cs, p);
  arb_mul(e2, L.e, L.e, p);
  arb_div(out, out, e2, p);
}

namespace {

// sin and cos of alpha and of beta = x alpha.
struct phases {
  ball sa, ca, sb, cb;
  phases(const arb_t x, const arb_t alpha, slong p) {
    ball b;
    arb_mul(b, x, alpha, p);
    arb_sin_cos(sa, ca, alpha, p);
    arb_sin_cos(sb, cb, b, p);
  }
  // q' = cos alpha cos beta - x sin alpha sin beta
  void qdot(arb_t out, const arb_t x, slong p) const {
    ball t;
    arb_mul(out, ca, cb, p);
    arb_mul(t, sa, sb, p);
    arb_mul(t, t, x, p);
    arb_sub(out, out, t, p);
  }
};

}  // namespace

void R(arb_t out, const arb_t x, const arb_t c, const arb_t alpha, slong p) {
  const phases f(x, alpha, p);
  ball q, qd;
  arb_mul(q, f.sa, f.cb, p);
  arb_mul(q, q, c, p);
  f.qdot(qd, x, p);
  arb_mul(q, q, q, p);
  arb_mul(qd, qd, qd, p);
  arb_add(out, q, qd, p);
}

void alpha_T(arb_t out, const arb_t S, const horizon_time& T, const arb_t pi, slong p) {
  arb_support::set_rational(out, T.value, p);
  arb_mul(out, out, S, p);
  arb_mul_2exp_si(out, out, -1);
  if (T.times_pi) arb_mul(out, out, pi, p);
}

std::optional<big_int> cut_lobe(const coupling_spec& spec, const horizon_time& T, slong p) {
  if (T.value == 0) return big_int(0);
  if (T.times_pi) {
    const big_int P = spec.P(), Q = spec.Q(), d = Q * (P + 4 * Q);
    big_int root;
    const quadratic_number s = int_is_square(d, root) ? quadratic_number(root, Q) : quadratic_number(0, 1, Q, d);
    return (s * quadratic_number(T.value / 2) + quadratic_number(1, 2)).floor();
  }
  ball S, pi, a, f, half;
  arb_support::set_rational(S, spec.n2 + 4, p);
  arb_sqrt(S, S, p);
  arb_const_pi(pi, p);
  alpha_T(a, S, T, pi, p);
  arb_div(a, a, pi, p);
  arb_set_d(half, 0.5);
  arb_add(a, a, half, p);
  arb_floor(f, a, p);
  arb_support::fmpz_holder z;
  if (arb_get_unique_fmpz(z, f)) return z.value();
  return std::nullopt;
}

void dR(arb_t out, const arb_t x, const arb_t alpha, slong p) {
  const phases f(x, alpha, p);
  ball qd, zd, t;
  f.qdot(qd, x, p);
  arb_mul(zd, f.sa, f.cb, p);  // z' = x sin alpha cos beta + cos alpha sin beta
  arb_mul(zd, zd, x, p);
  arb_mul(t, f.ca, f.sb, p);
  arb_add(zd, zd, t, p);
  arb_mul(out, qd, zd, p);
  arb_mul(out, out, x, p);
  arb_mul_2exp_si(out, out, 2);
  arb_neg(out, out);
}

}  // namespace gyrores::kernels_arb
