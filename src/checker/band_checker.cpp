// The independent checker of band certificates (band_checker.hpp). What it proves, for each of
// the two claims (proofs/band-theorem.md, items 4 and 5, "What a certificate needs"):
//   1. the cover: intervals [a, b] of n^2 (exact rationals), a < b, the first a = n1^2, the last
//      b = n2^2, each b the next a (no gap, no overlap, in order);
//   2. for each interval, its integers: K = k_c(a) - 1, or k_c(a) with `reached` proved
//      (absorption); K = k_c(b), or k_c(b) - 1 with `unreached` proved (containment); k_c by Arb;
//   3. for each interval, the bound of its kind (item 4), recomputed: fractions by this file's
//      Stern-Brocot search, F_K by MinFrac (exact_field.hpp), V_x(nu) by bisection of H(u) = pi nu,
//      g by its interval bounds (item 4, Step 4), the end point R(T) by a mean-value form on pieces
//      of the interval (halved until decided, at most 1024); the
//      printed bound must be on the safe side of the recomputed one (absorption: printed >= the
//      checker's upper bound; containment: printed <= the checker's lower bound, 0 always allowed);
//   4. the claim [lo, hi] (H_q units): every interval's bound on its side (absorption: bound <=
//      2 hi; containment: bound >= 2 lo), and the attaining coupling, in the band, with its own
//      coupling certificate (check_coupling_certificate) whose h_min gives the other side
//      (absorption: lo <= h_min lo; containment: h_min hi <= hi).
// A kind this checker does not know for a claim (a line kind in a containment cover) is refused.
#include "band_checker.hpp"

#include <arb.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "checker_support.hpp"
#include "exact_field.hpp"
#include "horizon_checker.hpp"

namespace gyrores_checker {

namespace {

using namespace support;
using namespace exact;

using Qr = Q;

// ---- Reading.
void check_len(const std::string& s, const std::string& name) {
  if (s.size() > band_max_field_chars)
    throw fails("work bound: " + name + " has more than " + std::to_string(band_max_field_chars) + " characters");
}
Qr rational_of(const json& j, const std::string& name) {
  if (!j.is_string()) throw malformed(name + " must be a string \"p/q\"");
  const std::string s = j.get<std::string>();
  check_len(s, name);
  const auto slash = s.find('/');
  const std::string a = s.substr(0, slash), b = slash == std::string::npos ? "1" : s.substr(slash + 1);
  if (!all_digits(a, 0) || !all_digits(b, 0) || (a[0] == '0' && a.size() > 1) || b[0] == '0')
    throw malformed(name + " is not a rational p/q: '" + s.substr(0, 40) + "'");
  Z n, d;
  fmpz_set_str(n.v, a.c_str(), 10);
  fmpz_set_str(d.v, b.c_str(), 10);
  if (fmpz_is_zero(n.v)) throw fails(name + " must be > 0");
  Qr q;
  fmpq_set_fmpz_frac(q.v, n.v, d.v);
  return q;
}
Z signed_integer(const json& j, const std::string& name) {
  if (!j.is_string()) throw malformed(name + " must be a decimal string");
  const std::string s = j.get<std::string>();
  check_len(s, name);
  const std::size_t from = !s.empty() && s[0] == '-' ? 1 : 0;
  if (!all_digits(s, from) || (s[from] == '0' && s.size() > from + 1) || s == "-0")
    throw malformed(name + " is not an integer: '" + s.substr(0, 40) + "'");
  Z z;
  fmpz_set_str(z.v, s.c_str(), 10);
  return z;
}
Qr decimal_value(const std::string& s, const std::string& name) {
  Qr q;
  if (!decimal_exact(s, 4000, q.v)) throw fails("work bound: " + name + " has an exponent beyond 4000");
  return q;
}

// ---- A coupling n^2 = P/Q: x = sqrt(P/(P + 4Q)) exactly in Q(sqrt D), D = P (P + 4Q).
struct coupling {
  Z P, Q, S;  // S = P + 4Q
  field F;
  QD x;
};
coupling coupling_of(const Qr& n2) {
  coupling c;
  fmpz_set(c.P.v, fmpq_numref(n2.v));
  fmpz_set(c.Q.v, fmpq_denref(n2.v));
  fmpz_mul_ui(c.S.v, c.Q.v, 4);
  fmpz_add(c.S.v, c.S.v, c.P.v);
  Z D, s, s2;
  fmpz_mul(D.v, c.P.v, c.S.v);
  fmpz_sqrt(s.v, D.v);
  fmpz_mul(s2.v, s.v, s.v);
  if (fmpz_equal(s2.v, D.v)) c.x.p = s;
  else {
    c.F.D = D;
    fmpz_one(c.x.q.v);
  }
  c.x.r = c.S;
  normalise(c.x);
  return c;
}

// A point of (0, 1) for the fraction search: a coupling's x, or a fraction p/q.
struct point {
  const coupling* c = nullptr;
  Z p, q;
};
// sign(p/q - point), p, q >= 0, q > 0.
int cmp_frac(const Z& p, const Z& q, const point& y) {
  Z l, r;
  if (y.c) {  // p/q vs sqrt(P/S): p^2 S vs q^2 P
    fmpz_mul(l.v, p.v, p.v);
    fmpz_mul(l.v, l.v, y.c->S.v);
    fmpz_mul(r.v, q.v, q.v);
    fmpz_mul(r.v, r.v, y.c->P.v);
  } else {
    fmpz_mul(l.v, p.v, y.q.v);
    fmpz_mul(r.v, y.p.v, q.v);
  }
  return fmpz_cmp(l.v, r.v);
}
struct frac {
  Z p, q;
};
// The largest k >= 0 with pred(k) true (pred(0) true, pred false for large k), by doubling and
// bisection; bounded by the caller's work count.
template <class F> Z largest(F pred, long& work) {
  Z lo(0), hi(1);
  while (pred(hi)) {
    fmpz_set(lo.v, hi.v);
    fmpz_mul_2exp(hi.v, hi.v, 1);
    if (++work > 200000) throw fails("work bound: the fraction search did not end");
  }
  for (;;) {  // pred(lo), !pred(hi)
    Z mid;
    fmpz_add(mid.v, lo.v, hi.v);
    fmpz_fdiv_q_2exp(mid.v, mid.v, 1);
    if (fmpz_equal(mid.v, lo.v)) return lo;
    if (pred(mid)) lo = mid;
    else hi = mid;
    if (++work > 200000) throw fails("work bound: the fraction search did not end");
  }
}
// The largest m >= 0 with (p + m dp)/(q + m dq) <= y (side -1) or >= y (side +1).
Z largest_step(const Z& p, const Z& q, const Z& dp, const Z& dq, const point& y, int side, long& work) {
  return largest(
      [&](const Z& m) {
        Z a, b;
        fmpz_set(a.v, p.v);
        fmpz_addmul(a.v, m.v, dp.v);
        fmpz_set(b.v, q.v);
        fmpz_addmul(b.v, m.v, dq.v);
        const int c = cmp_frac(a, b, y);
        return side < 0 ? c <= 0 : c >= 0;
      },
      work);
}
// The fraction of least denominator strictly between y1 < y2 in (0, 1]: the Stern-Brocot
// descent, each run of one direction taken at once.
frac simplest(const point& y1, const point& y2, long& work) {
  Z pl(0), ql(1), pr(1), qr(0);  // 0/1 and 1/0
  for (;;) {
    Z pm, qm;
    fmpz_add(pm.v, pl.v, pr.v);
    fmpz_add(qm.v, ql.v, qr.v);
    if (cmp_frac(pm, qm, y1) <= 0) {  // L + k R <= y1: advance L
      const Z k = largest_step(pl, ql, pr, qr, y1, -1, work);
      fmpz_addmul(pl.v, k.v, pr.v);
      fmpz_addmul(ql.v, k.v, qr.v);
    } else if (cmp_frac(pm, qm, y2) >= 0) {  // k L + R >= y2: advance R
      const Z k = largest_step(pr, qr, pl, ql, y2, +1, work);
      fmpz_addmul(pr.v, k.v, pl.v);
      fmpz_addmul(qr.v, k.v, ql.v);
    } else
      return {pm, qm};
    if (++work > 200000) throw fails("work bound: the fraction search did not end");
  }
}
// The least denominator of a fraction of parity `odd` strictly between y1 and y2, if it is
// <= cap: the simplest fraction if its parity fits, else the better of the two sides around it.
std::optional<frac> least_of_parity(const point& y1, const point& y2, bool odd, const Z& cap, long& work) {
  if (fmpz_sgn(cap.v) <= 0) return std::nullopt;
  const frac s = simplest(y1, y2, work);
  if (fmpz_cmp(s.q.v, cap.v) > 0) return std::nullopt;
  if (bool(fmpz_is_odd(s.q.v)) == odd) return s;
  point m;
  m.p = s.p;
  m.q = s.q;
  auto left = least_of_parity(y1, m, odd, cap, work);
  Z cap2 = cap;
  if (left) fmpz_sub_ui(cap2.v, left->q.v, 1);
  auto right = least_of_parity(m, y2, odd, cap2, work);
  return right ? right : left;
}

// ---- Balls.
B ball_qd(const field& F, const QD& a, long prec) { return exact::ball_of(F, a, prec); }
B ball_q(const Qr& q, long prec) {
  B b;
  arb_set_fmpq(b.v, q.v, prec);
  return b;
}

struct ctx {
  long prec;
  Qr T;
  B pi, half;
  long* pieces;  // the end point's pieces over the whole certificate (band_max_pieces)
};
struct at_x {  // the coupling's balls
  B x, x2, one_m_x2, alpha_T;
};
at_x balls_of(const ctx& C, const coupling& c) {
  at_x b;
  arb_set_fmpz(b.x2.v, c.P.v);
  arb_div_fmpz(b.x2.v, b.x2.v, c.S.v, C.prec);
  arb_sqrt(b.x.v, b.x2.v, C.prec);
  arb_set_fmpz(b.one_m_x2.v, c.Q.v);
  arb_mul_ui(b.one_m_x2.v, b.one_m_x2.v, 4, C.prec);
  arb_div_fmpz(b.one_m_x2.v, b.one_m_x2.v, c.S.v, C.prec);
  B s;  // sqrt(n^2 + 4) = sqrt(S/Q)
  arb_set_fmpz(s.v, c.S.v);
  arb_div_fmpz(s.v, s.v, c.Q.v, C.prec);
  arb_sqrt(s.v, s.v, C.prec);
  b.alpha_T = ball_q(C.T, C.prec);
  arb_mul(b.alpha_T.v, b.alpha_T.v, s.v, C.prec);
  arb_mul_2exp_si(b.alpha_T.v, b.alpha_T.v, -1);
  return b;
}
// An inequality Arb did not decide at this precision: the interval is retried at twice it.
struct undecided {};

B H(const ctx& C, const at_x& X, const B& u) { return lobe_H(X.x, u, C.prec); }
B G(const ctx& C, const at_x& X, const B& u) { return lobe_G(X.x2, X.one_m_x2, u, C.prec); }
// H^{-1}(pi nu) for a ball nu in (0, 1/2]: lo, hi exact with H(lo) < pi nu < H(hi) for every nu
// of the ball (hi may be the ball of pi/2, where H = (1 + x) pi/2 > pi nu). Bisection to about
// prec relative bits.
void root(const ctx& C, const at_x& X, const B& nu, B& lo, B& hi) {
  B t;
  arb_mul(t.v, nu.v, C.pi.v, C.prec);
  if (!arb_is_positive(t.v)) throw undecided{};
  arb_mul_2exp_si(hi.v, C.pi.v, -1);
  B m;
  arf_t e;
  arf_init(e);
  arb_get_lbound_arf(e, hi.v, C.prec);
  arb_set_arf(m.v, e);
  arf_clear(e);
  if (arb_gt(H(C, X, m).v, t.v)) hi = m;
  arb_zero(lo.v);
  for (long i = 0; i < 100000; ++i) {  // halve while still above: the root's scale
    B h;
    arb_get_mid_arb(h.v, hi.v);
    arb_mul_2exp_si(h.v, h.v, -1);
    if (!arb_gt(H(C, X, h).v, t.v)) break;
    hi = h;
  }
  {
    B h;
    arb_get_mid_arb(h.v, hi.v);
    arb_mul_2exp_si(h.v, h.v, -1);
    if (arb_lt(H(C, X, h).v, t.v)) lo = h;
  }
  for (long i = 0; i < C.prec + 8; ++i) {
    B mid, a;
    arb_get_mid_arb(a.v, hi.v);
    arb_add(mid.v, lo.v, a.v, ARF_PREC_EXACT);
    arb_mul_2exp_si(mid.v, mid.v, -1);
    const B h = H(C, X, mid);
    if (arb_gt(h.v, t.v)) hi = mid;
    else if (arb_lt(h.v, t.v)) lo = mid;
    else break;
  }
}
// V_x(nu) bounds: upper (dir > 0) or lower (dir < 0), as a ball whose upper (lower) end is one.
B V(const ctx& C, const at_x& X, const B& nu, int dir) {
  if (arb_is_zero(nu.v)) return B();
  B lo, hi;
  root(C, X, nu, lo, hi);
  return G(C, X, dir > 0 ? hi : lo);
}
// The unsigned u*(x) bounds for a ball nu: upper end of H^{-1} (dir > 0) or lower end (dir < 0).
B root_end(const ctx& C, const at_x& X, const B& nu, int dir) {
  if (arb_is_zero(nu.v)) return B();
  B lo, hi;
  root(C, X, nu, lo, hi);
  return dir > 0 ? hi : lo;
}

// k_c = floor(alpha_T/pi + 1/2) at c (never a tie: transcendental).
Z cut_lobe(const ctx& C, const at_x& X) {
  B v, f;
  arb_div(v.v, X.alpha_T.v, C.pi.v, C.prec);
  arb_add(v.v, v.v, C.half.v, C.prec);
  arb_floor(f.v, v.v, C.prec);
  Z z;
  if (!arb_get_unique_fmpz(z.v, f.v)) throw undecided{};
  return z;
}
// nu_k(x) = |1/2 + floor(k x) - k x| and the sign of mu = 1/2 + floor(k x) - k x (exact).
QD mu_of(const coupling& c, const Z& k) {
  const QD kx = mul(c.F, integer(k), c.x);
  return sub(add(integer(floor_of(c.F, kx)), rational(1, 2)), kx);
}
QD nu_of(const coupling& c, const Z& k) {
  const QD mu = mu_of(c, k);
  return sign(c.F, mu) < 0 ? neg(mu) : mu;
}
// F_K(x) = min over 0 <= k <= K of nu_k(x) (K >= 0): MinFrac on both sides.
QD F_of(const coupling& c, const Z& K) {
  const minimum a = min_frac(c.F, c.x, rational(1, 2), K);
  const minimum b = min_frac(c.F, sub(rational(1, 1), c.x), rational(1, 2), K);
  return cmp(c.F, a.value, b.value) <= 0 ? a.value : b.value;
}
Z floor_kx(const coupling& c, const Z& k) { return floor_of(c.F, mul(c.F, integer(k), c.x)); }

// k pi + u* of lobe k's first minimiser (k >= 0) at its extreme over [a, b] against alpha_T there
// (horizon Step 12 (a)): side +1 its largest, at X = a (u* largest at a for mu(a) >= 0, else
// -H_b^{-1}(|mu(a)|)), side -1 its least, at X = b (Y the other end). True when it is <= alpha_T
// at X, false when it is above; undecided when the balls overlap.
bool first_minimiser_before(const ctx& C, const Z& k, const coupling& c, const at_x& X, const at_x& Y, int side) {
  B u;
  if (fmpz_is_zero(k.v)) u = root_end(C, X, C.half, side);
  else {
    const QD mu = mu_of(c, k);
    const bool pos = sign(c.F, mu) >= 0;
    const B nu = ball_qd(c.F, pos ? mu : neg(mu), C.prec);
    if (pos) u = root_end(C, X, nu, side);
    else {
      u = root_end(C, Y, nu, -side);
      arb_neg(u.v, u.v);
    }
    B top;
    arb_mul_fmpz(top.v, C.pi.v, k.v, C.prec);
    arb_add(u.v, top.v, u.v, C.prec);
  }
  if (arb_le(u.v, X.alpha_T.v)) return true;
  if (arb_gt(u.v, X.alpha_T.v)) return false;
  throw undecided{};
}
// Lobe k's first minimiser after its start is reached on all of [a, b] (k pi + u* <= alpha_T(a)),
// or lies after T on all of it (k pi + u* > alpha_T(b)); false for k < 0 or where floor(k x)
// changes on [a, b].
bool reached_on(const ctx& C, const Z& k, const coupling& a, const coupling& b, const at_x& A, const at_x& Bb) {
  if (fmpz_sgn(k.v) < 0) return false;
  if (!fmpz_is_zero(k.v) && !fmpz_equal(floor_kx(a, k).v, floor_kx(b, k).v)) return false;
  return first_minimiser_before(C, k, a, A, Bb, +1);
}
bool unreached_on(const ctx& C, const Z& k, const coupling& a, const coupling& b, const at_x& A, const at_x& Bb) {
  if (fmpz_sgn(k.v) < 0) return false;
  if (!fmpz_is_zero(k.v) && !fmpz_equal(floor_kx(a, k).v, floor_kx(b, k).v)) return false;
  return !first_minimiser_before(C, k, b, Bb, A, -1);
}

// g = (pi k - u)(1 - x^2) - x^2 tan u at (x, u) = (c, u) with u an exact end (Step 4).
B g_at(const ctx& C, const Z& k, const at_x& X, const B& u) {
  B g, t;
  arb_mul_fmpz(g.v, C.pi.v, k.v, C.prec);
  arb_sub(g.v, g.v, u.v, C.prec);
  arb_mul(g.v, g.v, X.one_m_x2.v, C.prec);
  arb_tan(t.v, u.v, C.prec);
  arb_mul(t.v, t.v, X.x2.v, C.prec);
  arb_sub(g.v, g.v, t.v, C.prec);
  return g;
}

// ---- The end point R(T) over n in [na, nb] (horizon-theorem.md Step 12 (d)): a direct
// enclosure and the mean-value form about the middle, intersected.
void coefficients_at(const ctx& C, B& s, B& x, B& c, B& dx, B& dc, const B& n) {
  const long p = C.prec;
  B s3;
  arb_mul(s.v, n.v, n.v, p);
  arb_add_si(s.v, s.v, 4, p);
  arb_sqrt(s.v, s.v, p);
  arb_div(x.v, n.v, s.v, p);
  arb_set_si(c.v, 2);
  arb_div(c.v, c.v, s.v, p);
  arb_mul(s3.v, s.v, s.v, p);
  arb_mul(s3.v, s3.v, s.v, p);
  arb_set_si(dx.v, 4);
  arb_div(dx.v, dx.v, s3.v, p);
  arb_mul_si(dc.v, n.v, -2, p);
  arb_div(dc.v, dc.v, s3.v, p);
}
void coefficients(const ctx& C, B& s, B& x, B& c, B& dx, B& dc, const B& n) {
  if (arb_is_exact(n.v)) return coefficients_at(C, s, x, c, dx, dc, n);
  B lo, hi, s2, x2, c2, dx2, dc2, r2;
  arf_t e;
  arf_init(e);
  arb_get_lbound_arf(e, n.v, C.prec);
  arb_set_arf(lo.v, e);
  arb_get_ubound_arf(e, n.v, C.prec);
  arb_set_arf(hi.v, e);
  arf_clear(e);
  coefficients_at(C, s, x, c, dx, dc, lo);
  coefficients_at(C, s2, x2, c2, dx2, dc2, hi);
  arb_union(s.v, s.v, s2.v, C.prec);
  arb_union(x.v, x.v, x2.v, C.prec);
  arb_union(c.v, c.v, c2.v, C.prec);
  arb_union(dx.v, dx.v, dx2.v, C.prec);
  arb_union(dc.v, dc.v, dc2.v, C.prec);
  arb_sqrt_ui(r2.v, 2, C.prec);  // |dc/dn| peaks at n = sqrt 2
  if (arb_overlaps(n.v, r2.v)) {
    coefficients_at(C, s2, x2, c2, dx2, dc2, r2);
    arb_union(dc.v, dc.v, dc2.v, C.prec);
  }
}
void clip(B& v) {
  B unit;
  arb_zero_pm_one(unit.v);
  if (!arb_is_finite(v.v) || !arb_contains(unit.v, v.v)) arb_set(v.v, unit.v);
}
// R = q^2 + q'^2 and dR/dn at t: q = c sin(alpha) cos(beta), q' = cos(alpha) cos(beta) - x sin(alpha)
// sin(beta), alpha = s t/2, beta = n t/2.
void R_and_slope(const ctx& C, B& R, B& dR, const B& n, const B& t) {
  const long p = C.prec;
  B s, x, c, dx, dc, a, b, da, db, sa, ca, sb, cb, q, qd, dq, dqd, u, w;
  coefficients(C, s, x, c, dx, dc, n);
  arb_mul(a.v, s.v, t.v, p);
  arb_mul_2exp_si(a.v, a.v, -1);
  arb_mul(b.v, n.v, t.v, p);
  arb_mul_2exp_si(b.v, b.v, -1);
  arb_mul(da.v, x.v, t.v, p);
  arb_mul_2exp_si(da.v, da.v, -1);
  arb_mul_2exp_si(db.v, t.v, -1);
  arb_sin_cos(sa.v, ca.v, a.v, p);
  arb_sin_cos(sb.v, cb.v, b.v, p);
  clip(sa), clip(ca), clip(sb), clip(cb);
  arb_mul(q.v, sa.v, cb.v, p);
  arb_mul(q.v, q.v, c.v, p);
  arb_mul(dq.v, sa.v, cb.v, p);
  arb_mul(dq.v, dq.v, dc.v, p);
  arb_mul(u.v, ca.v, cb.v, p);
  arb_mul(u.v, u.v, da.v, p);
  arb_mul(w.v, sa.v, sb.v, p);
  arb_mul(w.v, w.v, db.v, p);
  arb_sub(u.v, u.v, w.v, p);
  arb_mul(u.v, u.v, c.v, p);
  arb_add(dq.v, dq.v, u.v, p);
  arb_mul(qd.v, ca.v, cb.v, p);
  arb_mul(u.v, sa.v, sb.v, p);
  arb_mul(u.v, u.v, x.v, p);
  arb_sub(qd.v, qd.v, u.v, p);
  arb_mul(dqd.v, sa.v, cb.v, p);
  arb_mul(dqd.v, dqd.v, da.v, p);
  arb_mul(u.v, ca.v, sb.v, p);
  arb_mul(u.v, u.v, db.v, p);
  arb_add(dqd.v, dqd.v, u.v, p);
  arb_neg(dqd.v, dqd.v);
  arb_mul(u.v, sa.v, sb.v, p);
  arb_mul(u.v, u.v, dx.v, p);
  arb_sub(dqd.v, dqd.v, u.v, p);
  arb_mul(u.v, ca.v, sb.v, p);
  arb_mul(u.v, u.v, da.v, p);
  arb_mul(w.v, sa.v, cb.v, p);
  arb_mul(w.v, w.v, db.v, p);
  arb_add(u.v, u.v, w.v, p);
  arb_mul(u.v, u.v, x.v, p);
  arb_sub(dqd.v, dqd.v, u.v, p);
  arb_mul(R.v, q.v, q.v, p);
  arb_mul(u.v, qd.v, qd.v, p);
  arb_add(R.v, R.v, u.v, p);
  arb_mul(dR.v, q.v, dq.v, p);
  arb_mul(u.v, qd.v, dqd.v, p);
  arb_add(dR.v, dR.v, u.v, p);
  arb_mul_2exp_si(dR.v, dR.v, 1);
}
// [inf, sup] of R(T) over n in [sqrt a, sqrt b], as two balls' outer ends.
void end_point(const ctx& C, const coupling& a, const coupling& b, B& lo_out, B& hi_out) {
  const long p = C.prec;
  B na, nb, N, mid, R, dR, Rm, dRm, r, unit, t;
  arf_t l, h;
  arf_init(l);
  arf_init(h);
  arb_set_fmpz(na.v, a.P.v);
  arb_div_fmpz(na.v, na.v, a.Q.v, p);
  arb_sqrt(na.v, na.v, p);
  arb_set_fmpz(nb.v, b.P.v);
  arb_div_fmpz(nb.v, nb.v, b.Q.v, p);
  arb_sqrt(nb.v, nb.v, p);
  arb_get_lbound_arf(l, na.v, p);
  arb_get_ubound_arf(h, nb.v, p);
  arb_set_interval_arf(N.v, l, h, p);
  arb_set_arf(mid.v, l);
  arb_set_arf(r.v, h);
  arb_add(mid.v, mid.v, r.v, ARF_PREC_EXACT);
  arb_mul_2exp_si(mid.v, mid.v, -1);
  arb_set_arf(t.v, h);
  arb_sub_arf(r.v, t.v, l, ARF_PREC_EXACT);
  arb_mul_2exp_si(r.v, r.v, -1);
  arf_clear(l);
  arf_clear(h);
  t = ball_q(C.T, p);
  R_and_slope(C, R, dR, N, t);
  R_and_slope(C, Rm, dRm, mid, t);
  arb_zero_pm_one(unit.v);
  arb_mul(dR.v, dR.v, r.v, p);
  arb_mul(dR.v, dR.v, unit.v, p);
  arb_add(Rm.v, Rm.v, dR.v, p);
  // The intersection of the two enclosures (each holds R over the interval).
  bool any = false;
  for (const B* v : {&R, &Rm}) {
    if (!arb_is_finite(v->v)) continue;
    B lo, hi;
    arf_t e;
    arf_init(e);
    arb_get_lbound_arf(e, v->v, p);
    arb_set_arf(lo.v, e);
    arb_get_ubound_arf(e, v->v, p);
    arb_set_arf(hi.v, e);
    arf_clear(e);
    if (!any || arb_gt(lo.v, lo_out.v)) lo_out = lo;
    if (!any || arb_lt(hi.v, hi_out.v)) hi_out = hi;
    any = true;
  }
  if (!any) throw undecided{};
  if (arb_is_negative(lo_out.v)) arb_zero(lo_out.v);
}

// The end point's bound, proved by halving [a, b] (in n^2) until every piece's enclosure is on the
// safe side of the printed bound (at most 2^10 pieces): absorption sup R(T) <= printed,
// containment inf R(T) >= printed. A point of the interval where R(T) is proved on the wrong
// side refutes the bound at once.
Qr n2_of(const coupling& c) {
  Qr q;
  fmpq_set_fmpz_frac(q.v, c.P.v, c.Q.v);
  return q;
}
void end_point_bound(const ctx& C, const coupling& a, const coupling& b, const B& printed, bool absorption, int depth,
                     const std::string& where) {
  if (++*C.pieces > band_max_pieces)
    throw fails("work bound: the end point needs more than " + std::to_string(band_max_pieces) + " pieces in all");
  B lo, hi;
  end_point(C, a, b, lo, hi);
  if (absorption ? arb_le(hi.v, printed.v) : arb_ge(lo.v, printed.v)) return;
  Qr m = n2_of(a), t = n2_of(b);
  fmpq_add(m.v, m.v, t.v);
  fmpq_div_fmpz(m.v, m.v, Z(2).v);
  const coupling c = coupling_of(m);
  B plo, phi;
  end_point(C, c, c, plo, phi);  // R(T) at the middle coupling itself
  if (absorption ? arb_gt(plo.v, printed.v) : arb_lt(phi.v, printed.v))
    throw fails(where + ": bound is " + (absorption ? "below the recomputed upper bound (R(T) exceeds it inside)"
                                                    : "above the recomputed lower bound (R(T) is below it inside)"));
  if (depth >= 10)
    throw fails(where + ": bound is " + (absorption ? "below the recomputed upper bound" : "above the recomputed lower bound") +
                " (the end point not proved within 1024 pieces)");
  end_point_bound(C, a, c, printed, absorption, depth + 1, where);
  end_point_bound(C, c, b, printed, absorption, depth + 1, where);
}

// ---- One interval.
struct interval {
  Qr a2, b2;
  std::string kind;
  Z K, k;
  bool reached = false, unreached = false;
  std::string bound;
};

// The printed bound against the recomputed one: absorption needs printed >= upper (the
// recomputed ball's upper end), containment printed <= lower.
void against(const B& recomputed, const B& printed, bool absorption, const std::string& where) {
  if (absorption) {
    if (arb_le(recomputed.v, printed.v)) return;
    if (arb_gt(recomputed.v, printed.v)) throw fails(where + ": bound is below the recomputed upper bound");
  } else {
    if (arb_ge(recomputed.v, printed.v)) return;
    if (arb_lt(recomputed.v, printed.v)) throw fails(where + ": bound is above the recomputed lower bound");
  }
  throw undecided{};
}

void check_interval(const ctx& C, const interval& J, bool absorption, const std::string& where) {
  const coupling a = coupling_of(J.a2), b = coupling_of(J.b2);
  const at_x A = balls_of(C, a), Bb = balls_of(C, b);
  const B printed = ball_of(J.bound, C.prec);
  long work = 0;
  point pa, pb;
  pa.c = &a;
  pb.c = &b;
  if (absorption) {
    if (J.unreached) throw fails(where + ": unreached must be false in an absorption cover");
    Z K = cut_lobe(C, A);
    fmpz_sub_ui(K.v, K.v, 1);
    if (J.reached) {
      fmpz_add_ui(K.v, K.v, 1);
      if (!reached_on(C, K, a, b, A, Bb)) throw fails(where + ": reached is true, but lobe k_c(a) is not proved reached on the interval");
    }
    if (!fmpz_equal(K.v, J.K.v)) throw fails(where + ": K is not " + std::string(J.reached ? "k_c(a)" : "k_c(a) - 1") + " = " + text_of(K));
    if ((J.kind == "end_point" || J.kind == "lobes") && !fmpz_is_zero(J.k.v)) throw fails(where + ": k must be 0 for kind " + J.kind);
    if (J.kind == "end_point") return end_point_bound(C, a, b, printed, true, 0, where);
    if (fmpz_sgn(K.v) < 0) throw fails(where + ": kind " + J.kind + " needs K >= 0 (no lobe is admissible)");
    if (J.kind == "lobes") {
      if (fmpz_is_zero(K.v)) return against(V(C, A, C.half, +1), printed, true, where);
      B top = ball_qd(a.F, F_of(a, K), C.prec), fb = ball_qd(b.F, F_of(b, K), C.prec);
      arb_max(top.v, top.v, fb.v, C.prec);
      Z cap;
      fmpz_mul_ui(cap.v, K.v, 2);
      fmpz_sub_ui(cap.v, cap.v, 1);
      if (auto odd = least_of_parity(pa, pb, true, cap, work)) {  // the peak lemma (item 3)
        B peak;
        arb_one(peak.v);
        arb_div_fmpz(peak.v, peak.v, odd->q.v, C.prec);
        arb_mul_2exp_si(peak.v, peak.v, -1);
        arb_max(top.v, top.v, peak.v, C.prec);
      }
      return against(V(C, A, top, +1), printed, true, where);
    }
    // The line kinds: (a, b) holds no fraction of denominator <= 2K, and nu_k is f_K there.
    if (J.kind != "line_falling" && J.kind != "line_rising" && J.kind != "line_turning" && J.kind != "line_unproved")
      throw fails(where + ": kind " + J.kind + " is not an absorption bound");
    if (fmpz_sgn(J.k.v) <= 0 || fmpz_cmp(J.k.v, K.v) > 0) throw fails(where + ": the line's k must be in [1, K]");
    const frac s = simplest(pa, pb, work);
    Z twoK;
    fmpz_mul_ui(twoK.v, K.v, 2);
    if (fmpz_cmp(s.q.v, twoK.v) <= 0) throw fails(where + ": kind " + J.kind + ", but (a, b) holds a fraction of denominator <= 2K");
    coupling sc;  // the simplest fraction as an exact rational point (D = 0)
    sc.x.p = s.p;
    sc.x.r = s.q;
    if (cmp(sc.F, nu_of(sc, J.k), F_of(sc, K)) != 0) throw fails(where + ": the line's k is not the smallest nu_k inside the interval");
    // Rising iff mu_k < 0 inside (kx - 1/2 - j > 0, increasing).
    const bool rising = sign(sc.F, mu_of(sc, J.k)) < 0;
    const B na = ball_qd(a.F, nu_of(a, J.k), C.prec), nb = ball_qd(b.F, nu_of(b, J.k), C.prec);
    if (J.kind == "line_falling") {
      if (rising) throw fails(where + ": kind line_falling, but the line rises");
      return against(V(C, A, na, +1), printed, true, where);
    }
    if (!rising) throw fails(where + ": kind " + J.kind + ", but the line falls");
    if (J.kind == "line_unproved") return against(V(C, A, nb, +1), printed, true, where);
    if (J.kind == "line_rising") {  // g >= g(b, u+), u+ = H_a^{-1}(pi nu_k(b)) upper end
      const B g = g_at(C, J.k, Bb, root_end(C, A, nb, +1));
      if (!arb_is_positive(g.v)) {
        if (arb_is_nonpositive(g.v)) throw fails(where + ": kind line_rising, but g > 0 is not proved");
        throw undecided{};
      }
      return against(V(C, Bb, nb, +1), printed, true, where);
    }
    const B g = g_at(C, J.k, A, root_end(C, Bb, na, -1));  // line_turning: g <= g(a, u-)
    if (!arb_is_negative(g.v)) {
      if (arb_is_nonnegative(g.v)) throw fails(where + ": kind line_turning, but g < 0 is not proved");
      throw undecided{};
    }
    return against(V(C, A, na, +1), printed, true, where);
  }
  // Containment.
  if (J.reached) throw fails(where + ": reached must be false in a containment cover");
  if (!fmpz_is_zero(J.k.v)) throw fails(where + ": k must be 0 in a containment cover");
  Z K = cut_lobe(C, Bb);
  if (J.unreached) {
    if (!unreached_on(C, K, a, b, A, Bb)) throw fails(where + ": unreached is true, but lobe k_c(b) is not proved unreached on the interval");
    fmpz_sub_ui(K.v, K.v, 1);
  }
  if (!fmpz_equal(K.v, J.K.v)) throw fails(where + ": K is not " + std::string(J.unreached ? "k_c(b) - 1" : "k_c(b)") + " = " + text_of(K));
  if ((J.kind == "end_point") != J.unreached) throw fails(where + ": kind end_point goes with unreached true, kind lobes with false");
  if (J.kind != "lobes" && J.kind != "end_point") throw fails(where + ": kind " + J.kind + " is not a containment bound");
  if (arb_is_zero(printed.v)) return;  // inf M >= 0 always (item 4)
  // The lobes 0..K with no centre inside (item 4, lower): min(V_a(F_K(a)), V_b(F_K(b))).
  B lobes;
  bool have_lobes = fmpz_sgn(K.v) >= 0;
  if (have_lobes) {
    if (fmpz_is_zero(K.v)) lobes = V(C, Bb, C.half, -1);
    else {
      Z cap;
      fmpz_mul_ui(cap.v, K.v, 2);
      if (least_of_parity(pa, pb, false, cap, work)) throw fails(where + ": bound > 0, but (a, b) holds a centre of the lobes 1..K");
      const B fa = ball_qd(a.F, F_of(a, K), C.prec), fb = ball_qd(b.F, F_of(b, K), C.prec);
      const B va = V(C, A, fa, -1), vb = V(C, Bb, fb, -1);
      arb_min(lobes.v, va.v, vb.v, C.prec);
    }
  }
  if (J.kind == "lobes") {
    if (!have_lobes) return against(B(), printed, false, where);
    return against(lobes, printed, false, where);
  }
  if (have_lobes) against(lobes, printed, false, where);
  end_point_bound(C, a, b, printed, false, 0, where);
}

// ---- One claim.
void check_claim_side(const json& j, const std::string& which, const Qr& n1sq, const Qr& n2sq, const Qr& T,
                      const std::string& horizon_text, long digits, long prec0, long& pieces) {
  const bool absorption = which == "absorption";
  exact_keys(j, {"value", "at", "cover"}, which);
  const bracket value = bracket_field(j["value"], which + ".value", band_max_field_chars);
  const Qr lo = decimal_value(value.lo, which + ".value"), hi = decimal_value(value.hi, which + ".value");
  if (fmpq_sgn(lo.v) < 0 || fmpq_cmp(lo.v, hi.v) > 0) throw fails(which + ".value must have 0 <= lo <= hi");
  // The attaining coupling: in the band, the same horizon, its own certificate re-proved.
  const json& at = j["at"];
  if (!at.is_object() || !at.contains("n2") || !at.contains("horizon") || !at.contains("minimum"))
    throw malformed(which + ".at must be a coupling certificate");
  if (!at.contains("below") || !at["below"].is_null()) throw malformed(which + ".at.below must be null: the band does not use it");
  const Qr at2 = rational_of(at["n2"], which + ".at.n2");
  if (fmpq_cmp(at2.v, n1sq.v) < 0 || fmpq_cmp(at2.v, n2sq.v) > 0) throw fails(which + ".at: the coupling is not in the band");
  if (at["horizon"] != horizon_text) throw fails(which + ".at: its horizon is not the certificate's");
  const verdict v = check_coupling_certificate(at.dump());
  if (v.status != 0) throw fails(which + ".at: " + v.message);
  const bracket h = bracket_field(at["minimum"]["h_min"], which + ".at.h_min", band_max_field_chars);
  if (absorption && fmpq_cmp(lo.v, decimal_value(h.lo, "h_min").v) > 0)
    throw fails("absorption.value: lo is above the attaining coupling's minimum (h_min lo)");
  if (!absorption && fmpq_cmp(decimal_value(h.hi, "h_min").v, hi.v) > 0)
    throw fails("containment.value: hi is below the attaining coupling's minimum (h_min hi)");
  // The cover.
  const json& cover = j["cover"];
  if (!cover.is_array() || cover.empty()) throw malformed(which + ".cover must be a non-empty array");
  if (cover.size() > band_max_intervals)
    throw fails("work bound: " + which + ".cover has more than " + std::to_string(band_max_intervals) + " intervals");
  std::vector<interval> Js;
  for (std::size_t i = 0; i < cover.size(); ++i) {
    const std::string where = which + ".cover[" + std::to_string(i) + "]";
    const json& c = cover[i];
    exact_keys(c, {"a", "b", "kind", "K", "k", "reached", "unreached", "bound"}, where);
    interval J;
    J.a2 = rational_of(c["a"], where + ".a");
    J.b2 = rational_of(c["b"], where + ".b");
    if (!c["kind"].is_string()) throw malformed(where + ".kind must be a string");
    J.kind = c["kind"].get<std::string>();
    static const std::set<std::string> kinds{"lobes", "line_falling", "line_rising", "line_turning", "line_unproved", "end_point"};
    if (!kinds.count(J.kind)) throw malformed(where + ".kind is not a known kind");
    J.K = signed_integer(c["K"], where + ".K");
    J.k = signed_integer(c["k"], where + ".k");
    if (fmpz_sgn(J.k.v) < 0) throw malformed(where + ".k must be >= 0");
    if (!c["reached"].is_boolean() || !c["unreached"].is_boolean()) throw malformed(where + ": reached, unreached must be true or false");
    J.reached = c["reached"].get<bool>();
    J.unreached = c["unreached"].get<bool>();
    J.bound = decimal_field(c["bound"], where + ".bound", band_max_field_chars);
    const Qr bq = decimal_value(J.bound, where + ".bound");
    if (fmpq_sgn(bq.v) < 0) throw fails(where + ".bound must be >= 0");
    if (fmpq_cmp(J.a2.v, J.b2.v) >= 0) throw fails(where + ": a must be < b");
    if (i == 0 && !fmpq_equal(J.a2.v, n1sq.v)) throw fails(where + ".a is not n1^2: the cover does not start at the band's end");
    if (i > 0 && !fmpq_equal(J.a2.v, Js.back().b2.v)) throw fails(where + ".a is not the previous interval's b (a gap or an overlap)");
    if (i + 1 == cover.size() && !fmpq_equal(J.b2.v, n2sq.v)) throw fails(where + ".b is not n2^2: the cover does not reach the band's end");
    // The claim's side (R = 2 H_q).
    Qr two;
    fmpq_mul_si(two.v, absorption ? hi.v : lo.v, 2);
    if (absorption ? fmpq_cmp(bq.v, two.v) > 0 : fmpq_cmp(bq.v, two.v) < 0)
      throw fails(where + ".bound is " + (absorption ? "above 2 hi" : "below 2 lo") + " of " + which + ".value");
    Js.push_back(J);
  }
  (void)digits;
  for (std::size_t i = 0; i < Js.size(); ++i) {
    const std::string where = which + ".cover[" + std::to_string(i) + "]";
    bool done = false;
    for (long prec = prec0; !done; prec *= 2) {
      if (prec > band_max_prec_bits) throw fails("work bound: " + where + " is not decided within " + std::to_string(band_max_prec_bits) + " bits");
      ctx C{prec, T, B(), B(), &pieces};
      arb_const_pi(C.pi.v, prec);
      arb_set_d(C.half.v, 0.5);
      try {
        check_interval(C, Js[i], absorption, where);
        done = true;
      } catch (const undecided&) {
      }
    }
  }
}

}  // namespace

verdict check_band_certificate(const std::string& json_text) {
  return verdict_of<verdict>([&]() -> verdict {
    if (json_text.size() > (std::size_t(4) << 20)) throw fails("work bound: the certificate is larger than 4 MiB");
    json j = parse_without_duplicate_keys(json_text);
    exact_keys(j, {"format", "theorem", "n1", "n2", "horizon", "digits", "absorption", "containment"}, "the certificate");
    if (j["format"] != band_certificate_format) throw malformed(std::string("format is not ") + band_certificate_format);
    if (j["theorem"] != "band-theorem/1") throw fails("theorem is not band-theorem/1 (the one this checker knows)");
    const long digits = integer_in(j["digits"], "digits", 1, 1L << 30);
    if (digits > band_max_digits) throw fails("work bound: digits above " + std::to_string(band_max_digits));
    const Qr n1 = rational_of(j["n1"], "n1"), n2 = rational_of(j["n2"], "n2"), T = rational_of(j["horizon"], "horizon");
    if (fmpq_cmp(n1.v, n2.v) >= 0) throw fails("the band needs n1 < n2");
    Qr n1sq, n2sq;
    fmpq_mul(n1sq.v, n1.v, n1.v);
    fmpq_mul(n2sq.v, n2.v, n2.v);
    // Precision: the digits of the bounds' slack and the phases' size (alpha_T ~ T sqrt(n^2 + 4)).
    Qr scale;
    fmpq_add_si(scale.v, n2sq.v, 4);
    fmpq_mul(scale.v, scale.v, T.v);
    const long size = std::max<long>(0, long(fmpz_bits(fmpq_numref(scale.v))) - long(fmpz_bits(fmpq_denref(scale.v))));
    const long prec0 = long(3.33 * double(digits + 12)) + 64 + 2 * size;
    const std::string horizon_text = j["horizon"].get<std::string>();
    long pieces = 0;
    check_claim_side(j["absorption"], "absorption", n1sq, n2sq, T, horizon_text, digits, prec0, pieces);
    check_claim_side(j["containment"], "containment", n1sq, n2sq, T, horizon_text, digits, prec0, pieces);
    return {0, "certificate holds (band-theorem/1): the absorption guarantee lies in " +
                   j["absorption"]["value"][0].get<std::string>() + " .. " + j["absorption"]["value"][1].get<std::string>() +
                   ", the containment guarantee in " + j["containment"]["value"][0].get<std::string>() + " .. " +
                   j["containment"]["value"][1].get<std::string>() + " (H_q), every interval's bound re-proved"};
  });
}

}  // namespace gyrores_checker
