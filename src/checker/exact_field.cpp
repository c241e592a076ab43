// exact_field.hpp: the checkers' exact arithmetic in Q(sqrt D) and rotation minima.
#include "exact_field.hpp"

#include <arb.h>
#include <flint/fmpz.h>

#include <algorithm>

namespace gyrores_checker::exact {

using support::fails;

// ---- Exact numbers (p + q sqrt D)/r of Q(sqrt D), r > 0 (proofs/horizon-theorem.md, "Exact
// arithmetic in Q(sqrt D)"). D is 0 when it is a perfect square: then x is rational and every
// number met has q = 0.

void normalise(QD& a) {
  if (fmpz_sgn(a.r.v) < 0) {
    fmpz_neg(a.p.v, a.p.v);
    fmpz_neg(a.q.v, a.q.v);
    fmpz_neg(a.r.v, a.r.v);
  }
  Z g;
  fmpz_gcd(g.v, a.p.v, a.q.v);
  fmpz_gcd(g.v, g.v, a.r.v);
  if (!fmpz_is_zero(g.v) && !fmpz_is_one(g.v)) {
    fmpz_divexact(a.p.v, a.p.v, g.v);
    fmpz_divexact(a.q.v, a.q.v, g.v);
    fmpz_divexact(a.r.v, a.r.v, g.v);
  }
}
QD rational(long p, long r) {
  QD a;
  fmpz_set_si(a.p.v, p);
  fmpz_set_si(a.r.v, r);
  normalise(a);
  return a;
}
QD integer(const Z& z) {
  QD a;
  a.p = z;
  return a;
}
QD add(const QD& a, const QD& b) {
  QD c;
  fmpz_mul(c.p.v, a.p.v, b.r.v);
  fmpz_addmul(c.p.v, b.p.v, a.r.v);
  fmpz_mul(c.q.v, a.q.v, b.r.v);
  fmpz_addmul(c.q.v, b.q.v, a.r.v);
  fmpz_mul(c.r.v, a.r.v, b.r.v);
  normalise(c);
  return c;
}
QD neg(const QD& a) {
  QD c = a;
  fmpz_neg(c.p.v, c.p.v);
  fmpz_neg(c.q.v, c.q.v);
  return c;
}
QD sub(const QD& a, const QD& b) { return add(a, neg(b)); }
QD mul(const field& F, const QD& a, const QD& b) {
  QD c;
  Z t;
  fmpz_mul(c.p.v, a.p.v, b.p.v);
  fmpz_mul(t.v, a.q.v, b.q.v);
  fmpz_addmul(c.p.v, t.v, F.D.v);
  fmpz_mul(c.q.v, a.p.v, b.q.v);
  fmpz_addmul(c.q.v, a.q.v, b.p.v);
  fmpz_mul(c.r.v, a.r.v, b.r.v);
  normalise(c);
  return c;
}
// 1/a = r (p - q sqrt D)/(p^2 - q^2 D); the norm is non-zero for a != 0 (sqrt D irrational).
QD inv(const field& F, const QD& a) {
  QD c;
  Z n, t;
  fmpz_mul(n.v, a.p.v, a.p.v);
  fmpz_mul(t.v, a.q.v, a.q.v);
  fmpz_submul(n.v, t.v, F.D.v);
  if (fmpz_is_zero(n.v)) throw fails("division by zero in the rotation recursion");
  fmpz_mul(c.p.v, a.r.v, a.p.v);
  fmpz_mul(c.q.v, a.r.v, a.q.v);
  fmpz_neg(c.q.v, c.q.v);
  c.r = n;
  normalise(c);
  return c;
}
QD div(const field& F, const QD& a, const QD& b) { return mul(F, a, inv(F, b)); }
int sign(const field& F, const QD& a) {
  const int sp = fmpz_sgn(a.p.v), sq = fmpz_sgn(a.q.v);
  if (sq == 0) return sp;
  if (sp == 0 || sp == sq) return sq;
  Z p2, q2d;
  fmpz_mul(p2.v, a.p.v, a.p.v);
  fmpz_mul(q2d.v, a.q.v, a.q.v);
  fmpz_mul(q2d.v, q2d.v, F.D.v);
  const int c = fmpz_cmp(p2.v, q2d.v);
  return c > 0 ? sp : (c < 0 ? sq : 0);
}
int cmp(const field& F, const QD& a, const QD& b) { return sign(F, sub(a, b)); }
// floor((p + q sqrt D)/r) = floor((p + f)/r), f = floor(q sqrt D) from an integer square root.
Z floor_of(const field& F, const QD& a) {
  Z f, m, t;
  if (!fmpz_is_zero(a.q.v)) {
    fmpz_mul(m.v, a.q.v, a.q.v);
    fmpz_mul(m.v, m.v, F.D.v);
    fmpz_sqrt(t.v, m.v);
    if (fmpz_sgn(a.q.v) > 0) f = t;
    else {
      fmpz_neg(f.v, t.v);
      fmpz_mul(t.v, t.v, t.v);
      if (!fmpz_equal(t.v, m.v)) fmpz_sub_ui(f.v, f.v, 1);
    }
  }
  fmpz_add(f.v, f.v, a.p.v);
  Z out;
  fmpz_fdiv_q(out.v, f.v, a.r.v);
  return out;
}
Z ceil_of(const field& F, const QD& a) {
  Z z = floor_of(F, neg(a));
  fmpz_neg(z.v, z.v);
  return z;
}
QD frac(const field& F, const QD& a) { return sub(a, integer(floor_of(F, a))); }

// MinFrac(alpha, beta, K) = (min over 0 <= k <= K of {k alpha + beta}, its smallest argmin), for
// alpha, beta in [0, 1): the run recursion of proofs/horizon-theorem.md ("Rotation minima"),
// K at least halves per call.
minimum min_frac(const field& F, const QD& alpha, const QD& beta, const Z& K) {
  if (fmpz_is_zero(K.v) || sign(F, alpha) == 0) return {beta, Z(0)};
  if (cmp(F, alpha, rational(1, 2)) <= 0) {
    // Wrap after: runs start at k_j = ceil((j - beta)/alpha), j = 1..J, J = floor(K alpha + beta).
    Z J = floor_of(F, add(mul(F, integer(K), alpha), beta));
    if (fmpz_is_zero(J.v)) return {beta, Z(0)};
    QD a1 = frac(F, neg(inv(F, alpha))), b1 = frac(F, div(F, beta, alpha));
    Z Jm1;
    fmpz_sub_ui(Jm1.v, J.v, 1);
    minimum sub_min = min_frac(F, a1, frac(F, add(a1, b1)), Jm1);
    Z j;
    fmpz_add_ui(j.v, sub_min.k.v, 1);
    Z kj = ceil_of(F, div(F, sub(integer(j), beta), alpha));
    QD candidate = mul(F, alpha, sub_min.value);
    if (cmp(F, beta, candidate) <= 0) return {beta, Z(0)};
    return {candidate, kj};
  }
  // Wrap before: g = 1 - alpha; complete runs j = 0..J', J' = ceil((K + 1) g - beta) - 1, each
  // with its minimum at its last element k_j = floor((beta + j)/g); the run cut by K ends at K.
  QD g = sub(rational(1, 1), alpha);
  Z K1;
  fmpz_add_ui(K1.v, K.v, 1);
  Z Jp = ceil_of(F, sub(mul(F, integer(K1), g), beta));
  fmpz_sub_ui(Jp.v, Jp.v, 1);
  minimum cut{frac(F, sub(beta, mul(F, integer(K), g))), K};
  if (fmpz_sgn(Jp.v) < 0) return cut;
  QD a1 = frac(F, inv(F, g)), b1 = frac(F, div(F, beta, g));
  minimum sub_min = min_frac(F, a1, b1, Jp);
  Z kj = floor_of(F, div(F, add(beta, integer(sub_min.k)), g));
  QD candidate = mul(F, g, sub_min.value);
  if (cmp(F, candidate, cut.value) <= 0) return {candidate, kj};
  return cut;
}

// FirstHit(alpha, beta, w, K): the smallest k in [0, K] with {k alpha + beta} <= w, or none
// (proofs/horizon-theorem.md, "Rotation minima": the first run with a hit holds the first hit).
std::optional<Z> first_hit(const field& F, const QD& alpha, const QD& beta, const QD& w, const Z& K) {
  if (cmp(F, beta, w) <= 0) return Z(0);
  if (fmpz_is_zero(K.v) || sign(F, alpha) == 0) return std::nullopt;
  if (cmp(F, alpha, rational(1, 2)) <= 0) {
    Z J = floor_of(F, add(mul(F, integer(K), alpha), beta));
    if (fmpz_is_zero(J.v)) return std::nullopt;
    const QD wa = div(F, w, alpha);
    Z j(1);
    if (cmp(F, wa, rational(1, 1)) < 0) {
      const QD a1 = frac(F, neg(inv(F, alpha))), b1 = frac(F, div(F, beta, alpha));
      Z Jm1;
      fmpz_sub_ui(Jm1.v, J.v, 1);
      auto i = first_hit(F, a1, frac(F, add(a1, b1)), wa, Jm1);
      if (!i) return std::nullopt;
      fmpz_add_ui(j.v, i->v, 1);
    }
    return ceil_of(F, div(F, sub(integer(j), beta), alpha));
  }
  const QD g = sub(rational(1, 1), alpha), wg = div(F, w, g);
  Z K1;
  fmpz_add_ui(K1.v, K.v, 1);
  Z Jp = ceil_of(F, sub(mul(F, integer(K1), g), beta));
  fmpz_sub_ui(Jp.v, Jp.v, 1);
  // The first element <= w of run j: max(start_j, ceil((beta + j - w)/g)), start_j = k_{j-1} + 1.
  auto first_in_run = [&](const Z& j) {
    Z start(0);
    if (fmpz_sgn(j.v) > 0) {
      Z jm1;
      fmpz_sub_ui(jm1.v, j.v, 1);
      start = floor_of(F, div(F, add(beta, integer(jm1)), g));
      fmpz_add_ui(start.v, start.v, 1);
    }
    Z e = ceil_of(F, div(F, sub(add(beta, integer(j)), w), g));
    return fmpz_cmp(start.v, e.v) > 0 ? start : e;
  };
  if (fmpz_sgn(Jp.v) >= 0) {
    std::optional<Z> j;
    if (cmp(F, wg, rational(1, 1)) >= 0) j = Z(0);
    else j = first_hit(F, frac(F, inv(F, g)), frac(F, div(F, beta, g)), wg, Jp);
    if (j) return first_in_run(*j);
  }
  if (cmp(F, frac(F, sub(beta, mul(F, integer(K), g))), w) <= 0) {
    Z j;
    fmpz_add_ui(j.v, Jp.v, 1);
    return first_in_run(j);
  }
  return std::nullopt;
}

// The first k in [0, K] with nu_k <= d (d in [0, 1/2)): {k x + 1/2 + d} <= 2 d (Step 9).
std::optional<Z> first_lobe_at_most(const field& F, const QD& x, const QD& d, const Z& K) {
  return first_hit(F, x, frac(F, add(rational(1, 2), d)), add(d, d), K);
}


namespace {
long bit_length(const Z& z) { return long(fmpz_bits(z.v)); }
}  // namespace

support::B ball_of(const field& F, const QD& a, long prec) {
  // |p + q sqrt D| >= 1/(|p| + |q| sqrt D) (the norm is a non-zero integer): their bit lengths
  // twice over suffice.
  const long work = prec + 2 * std::max(bit_length(a.p), bit_length(a.q) + bit_length(F.D) / 2 + 1) + 16;
  support::B out, t;
  arb_set_fmpz(out.v, a.p.v);
  if (!fmpz_is_zero(a.q.v)) {
    arb_set_fmpz(t.v, F.D.v);
    arb_sqrt(t.v, t.v, work);
    arb_mul_fmpz(t.v, t.v, a.q.v, work);
    arb_add(out.v, out.v, t.v, work);
  }
  arb_div_fmpz(out.v, out.v, a.r.v, prec);
  return out;
}

}  // namespace gyrores_checker::exact
