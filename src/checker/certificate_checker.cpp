// The independent checker (certificate_checker.hpp). What it proves, in order:
//   1. the pair: tau > sigma >= 1 coprime; a = tau + sigma, b = tau - sigma;
//   2. the integer facts of the theorem (proofs/lattice-theorem.md, items 4-5): m_min from
//      a mod 4; exactly 2 lobes (4 when m_min = 2), each 0 <= k < a with (2j+1) a - 2 k b = m and
//      |m| = m_min, pairwise distinct, listed in theta order (a k = 0 lobe with m < 0 last);
//      distinct lobes with |m| = m_min, as many as the theorem counts, are all of them;
//   3. the bracket of u*: 0 < u_lo < u_hi < pi/2 and H(u_lo) < mu_min < H(u_hi), with
//      H(u) = x u + atan(x tan u) increasing (theorem, Step A), so u* lies in [u_lo, u_hi]
//      (degenerate pairs: u_star is exactly ["0", "0"]);
//   4. every claim [lo, hi] contains the checker's own enclosure, exactly (the claim's decimal
//      ends are read as balls and must lie outside the enclosure), and has relative width at
//      most 10^-digits (r_res of a degenerate pair: exactly 0).
// A decision the balls cannot make at one precision is retried at twice the precision (4 times);
// an inequality that still cannot be decided fails the certificate, never passes it.
#include "certificate_checker.hpp"

#include "checker_support.hpp"

#include <arb.h>
#include <flint/fmpz.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <array>
#include <stdexcept>
#include <vector>

namespace gyrores_checker {

namespace {

using namespace support;

// A non-negative integer written as a decimal string without sign or leading zeros, or
// "-" followed by one (when signed is allowed).
Z integer_field(const json& j, const std::string& name, bool allow_sign) {
  if (!j.is_string()) throw malformed(name + " must be a decimal string");
  std::string s = j.get<std::string>();
  std::size_t from = allow_sign && !s.empty() && s[0] == '-' ? 1 : 0;
  if (s.size() > max_pair_digits + 100) throw malformed(name + " has more than " + std::to_string(max_pair_digits + 100) + " characters");
  if (!all_digits(s, from) || (s[from] == '0' && s.size() > from + 1) || s == "-0")
    throw malformed(name + " is not an integer: '" + s.substr(0, 40) + "'");
  Z z;
  fmpz_set_str(z.v, s.c_str(), 10);
  return z;
}

// Everything the certificate says, read and type-checked; nothing is trusted yet.
struct certificate {
  Z tau, sigma;
  long digits = 0, m_min = -1, count = 0;
  bool degenerate = false;
  std::vector<Z> k, j, m;
  bracket u_star, r_res, theta_first, t_first;
};

constexpr std::array<std::string_view, 11> top_keys{"format", "theorem", "tau", "sigma", "digits", "degenerate",
                                                    "m_min", "minimiser_count", "minimiser_lobes", "u_star", "claims"};

certificate read(const std::string& text) {
  json j = parse_without_duplicate_keys(text);
  if (!j.is_object()) throw malformed("not a JSON object");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (std::count(top_keys.begin(), top_keys.end(), it.key()) == 0) throw malformed("unknown field '" + it.key() + "'");
  for (const std::string_view key : top_keys)
    if (!j.contains(key)) throw malformed("missing field '" + std::string(key) + "'");
  if (j["format"] != "gyrores-certificate/2") throw malformed("format is not gyrores-certificate/2");
  if (j["theorem"] != "lattice-theorem/1") throw fails("theorem is not lattice-theorem/1 (the one this checker knows)");
  certificate c;
  c.tau = integer_field(j["tau"], "tau", false);
  c.sigma = integer_field(j["sigma"], "sigma", false);
  if (!j["degenerate"].is_boolean()) throw malformed("degenerate must be a boolean");
  c.digits = integer_in(j["digits"], "digits", 1, 10000);
  c.m_min = integer_in(j["m_min"], "m_min", 0, 2);
  c.count = integer_in(j["minimiser_count"], "minimiser_count", 0, 4);
  c.degenerate = j["degenerate"].get<bool>();
  const auto& lobes = j["minimiser_lobes"];
  if (!lobes.is_array() || lobes.size() > 4) throw malformed("minimiser_lobes must be an array of at most 4 lobes");
  for (const auto& l : lobes) {
    if (!l.is_object() || l.size() != 3 || !l.contains("k") || !l.contains("j") || !l.contains("m"))
      throw malformed("a lobe must be {\"k\", \"j\", \"m\"}");
    c.k.push_back(integer_field(l["k"], "lobe k", true));
    c.j.push_back(integer_field(l["j"], "lobe j", true));
    c.m.push_back(integer_field(l["m"], "lobe m", true));
  }
  const std::size_t max_len = std::size_t(c.digits) + 60;
  c.u_star = bracket_field(j["u_star"], "u_star", max_len);
  const auto& claims = j["claims"];
  if (!claims.is_object() || claims.size() != 3 || !claims.contains("r_res") || !claims.contains("theta_first") ||
      !claims.contains("t_first"))
    throw malformed("claims must hold r_res, theta_first, t_first");
  c.r_res = bracket_field(claims.at("r_res"), "r_res", max_len);
  c.theta_first = bracket_field(claims.at("theta_first"), "theta_first", max_len);
  c.t_first = bracket_field(claims.at("t_first"), "t_first", max_len);
  return c;
}

// Step 2: the integer facts; sets a and b.
void check_integers(const certificate& c, Z& a, Z& b) {
  Z g;
  fmpz_gcd(g.v, c.tau.v, c.sigma.v);
  if (fmpz_cmp_si(c.sigma.v, 1) < 0 || fmpz_cmp(c.tau.v, c.sigma.v) <= 0 || !fmpz_is_one(g.v))
    throw fails("(tau, sigma) is not a coprime pair with tau > sigma >= 1");
  fmpz_add(a.v, c.tau.v, c.sigma.v);
  fmpz_sub(b.v, c.tau.v, c.sigma.v);
  long a4 = long(fmpz_fdiv_ui(a.v, 4));
  long m_min = a4 == 0 ? 0 : (a4 % 2 == 1 ? 1 : 2);
  if (c.m_min != m_min) throw fails("m_min is " + std::to_string(m_min) + ", not " + std::to_string(c.m_min));
  if (c.degenerate != (m_min == 0)) throw fails("degenerate must be " + std::string(m_min == 0 ? "true" : "false"));
  const long count = m_min == 2 ? 4 : 2;
  if (c.count != count || long(c.k.size()) != count)
    throw fails("the theorem gives exactly " + std::to_string(count) + " minimisers (lobes)");
  Z prev_key(-1), t, key;
  for (std::size_t i = 0; i < c.k.size(); ++i) {
    // (2j+1) a - 2 k b = m
    fmpz_mul_2exp(t.v, c.j[i].v, 1);
    fmpz_add_ui(t.v, t.v, 1);
    fmpz_mul(t.v, t.v, a.v);
    fmpz_submul(t.v, c.k[i].v, b.v);
    fmpz_submul(t.v, c.k[i].v, b.v);
    if (!fmpz_equal(t.v, c.m[i].v)) throw fails("lobe " + std::to_string(i) + ": (2j+1) a - 2 k b != m");
    if (fmpz_cmp_si(c.m[i].v, m_min) != 0 && fmpz_cmp_si(c.m[i].v, -m_min) != 0)
      throw fails("lobe " + std::to_string(i) + ": |m| != m_min");
    if (fmpz_sgn(c.k[i].v) < 0 || fmpz_cmp(c.k[i].v, a.v) >= 0) throw fails("lobe " + std::to_string(i) + ": k not in [0, a)");
    // theta order: key k, or a for k = 0 with m < 0 (u = -u* < 0 wraps to 2 pi).
    fmpz_set(key.v, fmpz_is_zero(c.k[i].v) && fmpz_sgn(c.m[i].v) < 0 ? a.v : c.k[i].v);
    if (fmpz_cmp(key.v, prev_key.v) <= 0) throw fails("minimiser lobes are not distinct and in theta order");
    prev_key = key;
  }
}

// The pair's constants as balls at prec bits.
struct constants {
  B x, s1mx2, sqrt_ts, pi, mu, a;
};

constants constants_of(const certificate& c, const Z& a, const Z& b, long prec) {
  constants K;
  B t;
  arb_set_fmpz(K.a.v, a.v);
  arb_set_fmpz(K.x.v, b.v);
  arb_div(K.x.v, K.x.v, K.a.v, prec);
  arb_set_fmpz(K.sqrt_ts.v, c.tau.v);
  arb_mul_fmpz(K.sqrt_ts.v, K.sqrt_ts.v, c.sigma.v, prec);
  arb_sqrt(K.sqrt_ts.v, K.sqrt_ts.v, prec);
  arb_mul_2exp_si(K.s1mx2.v, K.sqrt_ts.v, 1);
  arb_div(K.s1mx2.v, K.s1mx2.v, K.a.v, prec);  // sqrt(1 - x^2) = 2 sqrt(tau sigma)/a
  arb_const_pi(K.pi.v, prec);
  arb_mul_si(K.mu.v, K.pi.v, c.m_min, prec);
  arb_div(K.mu.v, K.mu.v, K.a.v, prec);
  arb_mul_2exp_si(K.mu.v, K.mu.v, -1);
  return K;
}

// H(u) = x u + atan(x tan u).
B h_of(const constants& K, const B& u, long prec) {
  B h, t;
  arb_tan(t.v, u.v, prec);
  arb_mul(t.v, t.v, K.x.v, prec);
  arb_atan(t.v, t.v, prec);
  arb_mul(h.v, K.x.v, u.v, prec);
  arb_add(h.v, h.v, t.v, prec);
  return h;
}

// Step 3. Returns 1 proved, 0 undecided at this precision; throws fails for a false statement.
int check_bracket(const certificate& c, const constants& K, B& lo, B& hi, long prec) {
  if (c.m_min == 0) {
    lo = ball_of(c.u_star.lo, prec);
    hi = ball_of(c.u_star.hi, prec);
    if (!arb_is_zero(lo.v) || !arb_is_zero(hi.v)) throw fails("u_star of a degenerate pair must be [0, 0]");
    return 1;
  }
  lo = ball_of(c.u_star.lo, prec);
  hi = ball_of(c.u_star.hi, prec);
  B half_pi;
  arb_mul_2exp_si(half_pi.v, K.pi.v, -1);
  if (arb_le(lo.v, B().v) || arb_ge(lo.v, hi.v) || arb_ge(hi.v, half_pi.v))
    throw fails("u_star must satisfy 0 < u_lo < u_hi < pi/2");
  if (!arb_is_positive(lo.v) || !arb_lt(lo.v, hi.v) || !arb_lt(hi.v, half_pi.v)) return 0;
  B hlo = h_of(K, lo, prec), hhi = h_of(K, hi, prec);
  if (arb_ge(hlo.v, K.mu.v) || arb_le(hhi.v, K.mu.v)) throw fails("u_star does not bracket u* (H(u_lo) < mu_min < H(u_hi) is false)");
  return arb_lt(hlo.v, K.mu.v) && arb_lt(K.mu.v, hhi.v) ? 1 : 0;
}

// Step 4 for one claim: 1 holds, 0 undecided; fails when false.
int check_claim(const bracket& claim, const B& enclosure, long digits, bool exact_zero, const std::string& name, long prec) {
  return claim_holds(claim, enclosure, digits, exact_zero ? " of a degenerate pair must be [0, 0]" : nullptr, name, prec);
}

// sqrt(G(u)) = x sqrt(1-x^2) sin^2 u / sqrt(cos^2 u + x^2 sin^2 u).
B radius_of(const constants& K, const B& u, long prec) {
  B s, co, r, e, t;
  arb_sin_cos(s.v, co.v, u.v, prec);
  arb_sqr(s.v, s.v, prec);
  arb_sqr(co.v, co.v, prec);
  arb_sqr(t.v, K.x.v, prec);
  arb_mul(t.v, t.v, s.v, prec);
  arb_add(e.v, co.v, t.v, prec);
  arb_sqrt(e.v, e.v, prec);
  arb_mul(r.v, K.x.v, K.s1mx2.v, prec);
  arb_mul(r.v, r.v, s.v, prec);
  arb_div(r.v, r.v, e.v, prec);
  return r;
}

// theta = 2 (k pi + sign(m) u)/a of the first lobe.
B theta_of(const certificate& c, const constants& K, const B& u, long prec) {
  B th;
  arb_mul_fmpz(th.v, K.pi.v, c.k[0].v, prec);
  if (fmpz_sgn(c.m[0].v) < 0) arb_sub(th.v, th.v, u.v, prec);
  else arb_add(th.v, th.v, u.v, prec);
  arb_mul_2exp_si(th.v, th.v, 1);
  arb_div(th.v, th.v, K.a.v, prec);
  return th;
}

// Steps 3-4 at one precision: 1 all proved, 0 something undecided. r and theta are monotone
// in u on [0, pi/2) (sqrt(G) increases, theorem Step C), so their enclosures over [u_lo, u_hi]
// are the hulls of their values at the two ends.
int check_reals(const certificate& c, const Z& a, const Z& b, long prec) {
  constants K = constants_of(c, a, b, prec);
  B lo, hi;
  if (!check_bracket(c, K, lo, hi, prec)) return 0;
  if (fmpz_is_zero(c.k[0].v) && fmpz_sgn(c.m[0].v) < 0) throw fails("the first lobe cannot wrap past 2 pi");
  B r, th, tf;
  arb_union(r.v, radius_of(K, lo, prec).v, radius_of(K, hi, prec).v, prec);
  arb_union(th.v, theta_of(c, K, lo, prec).v, theta_of(c, K, hi, prec).v, prec);
  arb_mul(tf.v, th.v, K.sqrt_ts.v, prec);
  return check_claim(c.r_res, r, c.digits, c.m_min == 0, "r_res", prec) &&
         check_claim(c.theta_first, th, c.digits, false, "theta_first", prec) &&
         check_claim(c.t_first, tf, c.digits, false, "t_first", prec);
}

}  // namespace

verdict check_theorem_certificate(const std::string& json_text) {
  return verdict_of<verdict>([&]() -> verdict {
    certificate c = read(json_text);
    Z a, b;
    check_integers(c, a, b);
    // Precision: the claims' digits, the bits of the order (theta = 2 (k pi + u)/a with k < a)
    // and a margin; doubled when a ball is too wide to decide.
    std::size_t longest = 0;
    for (const auto* cl : {&c.u_star, &c.r_res, &c.theta_first, &c.t_first})
      longest = std::max({longest, cl->lo.size(), cl->hi.size()});
    const long prec = long(3.33 * double(longest)) + long(fmpz_bits(a.v)) + 64;
    return first_decided<verdict>(prec, [&](long p) {
      return check_reals(c, a, b, p) ? "certificate holds (lattice-theorem/1): r_res, theta_first, t_first of (" +
                                           text_of(c.tau) + ", " + text_of(c.sigma) + ") to " + std::to_string(c.digits) +
                                           " digits"
                                     : std::string();
    });
  });
}

}  // namespace gyrores_checker
