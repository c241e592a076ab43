// include/gyrores/sweep/certified.hpp: the enclosures of a sweep row, from theorem/root.hpp and
// theorem/minimum.hpp at an explicit precision (the sweep runs them on several threads; Boost's
// MPFR wrappers keep one process-wide default precision, so they are not used here).
#include <gyrores/sweep/certified.hpp>

#include <mpfi.h>

#include <algorithm>
#include <bit>

#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/root.hpp>

namespace gyrores {

namespace {

// sqrt(2) sin(k pi/4) and sqrt(2) cos(k pi/4) for odd k; sin, cos for even k (all in {0, +-1}).
int sin_quarter(std::int64_t k) {
  static const int t[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  return t[int_mod(k, std::int64_t(8))];
}
int cos_quarter(std::int64_t k) {
  static const int t[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  return t[int_mod(k, std::int64_t(8))];
}

// The relative width the asy error's difference must reach before its quotients are formed.
int narrow_bits(const sweep_proof_options& opt) { return int(opt.bits) + 8; }

// Every point of X rounds to the same value at opt.bits in direction rnd (exactly zero counts):
// the row then prints the exact value's rounding, whichever enclosure proved it (the certified
// filter, sweep/certified_filter.hpp, prints the same).
bool rounds_alike(const fixed_mpfi& X, const sweep_proof_options& opt, mpfr_rnd_t rnd) {
  fixed_mpfr lo(mpfr_prec_t(opt.bits)), hi(mpfr_prec_t(opt.bits));
  mpfr_set(lo, X.left(), rnd);
  mpfr_set(hi, X.right(), rnd);
  return mpfr_equal_p(lo, hi) != 0;
}

// The minimum at K's precision (header comment); false if a step is not proved or too wide.
bool prove_minimum_at(sweep_proof& pr, sweep_minimum_enclosure& M, const theorem_constants& K,
                      const resonant_pair<big_int>& p, const sweep_proof_options& opt) {
  const big_int a = p.order();
  root_enclosure z(K.prec);  // U = [0, 0]: the degenerate lobes' u
  if (pr.m_min == 0) {
    mpfi_set_ui(z.U, 0);
    mpfi_set_ui(M.r_res, 0);
  } else {
    if (!prove_theorem_root(z, K, big_int(pr.m_min))) return false;
    theorem_radius(M.r_res, K, z.T);
  }
  auto big_frame = [](const lobe_frame<int128>& f) { return lobe_frame<big_int>{to_big(f.k), to_big(f.j), to_big(f.m)}; };
  minimiser_theta(M.theta_first, K, a, big_frame(pr.lobes.front()), z.U);
  mpfi_mul(M.t_first, M.theta_first, K.sqrt_ts);
  mpfi_mul(M.t_min_paper, K.pi, K.sqrt_ts);
  mpfi_div(M.t_min_paper, M.t_min_paper, K.b);
  mpfi_mul(M.t_ratio, M.theta_first, K.b);
  mpfi_div(M.t_ratio, M.t_ratio, K.pi);
  // The printed values (t_ratio only for non-degenerate pairs), to nearest.
  for (const fixed_mpfi* X : {&M.r_res, &M.theta_first, &M.t_first, &M.t_min_paper})
    if (!rounds_alike(*X, opt, MPFR_RNDN)) return false;
  if (pr.m_min != 0 && !rounds_alike(M.t_ratio, opt, MPFR_RNDN)) return false;
  // r_res^2 <= R(pi/2) = N/(4 a^2).
  fixed_mpfi R(K.prec), r2(K.prec);
  mpfi_set_z(R, to_big(pr.quarter_R_scaled).backend().data());
  mpfi_div(R, R, K.a);
  mpfi_div(R, R, K.a);
  mpfi_div_ui(R, R, 4);
  mpfi_sqr(r2, M.r_res);
  pr.r_below_R_half_pi = mpfr_cmp(r2.right(), R.left()) <= 0;
  return true;
}

// The paper's error at K's precision: false if not proved or too wide.
//
// Why 2 log2(a) + 8 extra bits suffice (d = u_c - u_a, both for |m| >= 1, s = pi |m|/(2b),
// x < 1/2): f(u) = u + arctan(x tan u)/x - s has the root u_c (the theorem's equation divided by
// x) and f' = 1 + (1 + tan^2 u)/(1 + x^2 tan^2 u) in [2, 2 + tan^2 u]. With t = tan u_a = s - u_a,
// f(u_a) = arctan(x t)/x - t = -D, D = x^2 t^3 (1/3 - (x t)^2/5 + ...) (alternating, decreasing
// terms). As s <= pi/2: u_a < 0.72, t < 0.87, x t < 0.44, so D >= 0.29 x^2 t^3 and D < 0.06;
// d = D/f'(xi) for some xi in [u_a, u_c] (mean value theorem), u_c <= u_a + D/2 < 0.75, f'(xi) <
// 2.87, so d >= x^2 t^3/10. With u_a <= t and t >= s/2 >= pi/(4b): d/u_a >= x^2 t^2/10 >=
// pi^2/(160 a^2) > 1/(17 a^2). The two brackets are 2^-(prec - 16) relative about u_a ~ u_c, so
// the difference is 68 a^2 2^-(prec - 16) relative to d: 2 log2(a) + 7 bits lost at most.
bool prove_asy_at(sweep_asy_enclosure& E, const theorem_constants& K, std::int64_t a, std::int64_t b,
                  const sweep_proof_options& opt) {
  const auto node = paper_fast_node(a, b);  // the smaller k on a tie
  const std::int64_t m = a - 2 * node.k * b, am = m < 0 ? -m : m;
  fixed_mpfi d(K.prec);
  if (am == 0) {
    mpfi_set_ui(d, 0);  // s = 0: u_a = u_c = 0 exactly
  } else {
    root_enclosure uc(K.prec), ua(K.prec);
    if (!prove_theorem_root(uc, K, big_int(am)) || !prove_paper_root(ua, K, big_int(am))) return false;
    mpfi_sub(d, uc.U, ua.U);
    mpfi_abs(d, d);
    if (!fixed_narrow(d, narrow_bits(opt))) return false;
  }
  // error = 2 d/a, bound = pi^3 x^2/a, ratio = 2 d/(pi^3 x^2), constant = 2 d/x^2.
  mpfi_mul_2ui(E.error, d, 1);
  mpfi_div(E.error, E.error, K.a);
  mpfi_sqr(E.bound, K.pi);
  mpfi_mul(E.bound, E.bound, K.pi);
  mpfi_mul(E.bound, E.bound, K.x2);
  mpfi_div(E.bound, E.bound, K.a);
  mpfi_div(E.ratio, E.error, E.bound);
  mpfi_mul_2ui(E.constant, d, 1);
  mpfi_div(E.constant, E.constant, K.x2);
  // Printed to nearest (uncertified wide rows) or outward (certified rows: bound downward).
  const bool up = opt.outward_asy;
  return rounds_alike(E.error, opt, up ? MPFR_RNDU : MPFR_RNDN) &&
         rounds_alike(E.bound, opt, up ? MPFR_RNDD : MPFR_RNDN) &&
         rounds_alike(E.ratio, opt, up ? MPFR_RNDU : MPFR_RNDN) &&
         rounds_alike(E.constant, opt, up ? MPFR_RNDU : MPFR_RNDN);
}

void add_note(std::string& note, const std::string& what) { note += std::string(note.empty() ? "" : "; ") + what; }

}  // namespace

// With alpha = a pi/4, beta = b pi/4 (theta = pi/2) and v = 1: q = sqrt(1-x^2) sin alpha cos beta,
// q' = cos alpha cos beta - x sin alpha sin beta (docs/mathematics.md §1), so
// 4 a^2 R = 4 (a^2 - b^2) (sA cB)^2 + 4 (a cA cB - b sA sB)^2. For odd a (b odd too) every
// sine and cosine is +-1/sqrt(2), each product is (+-1)/2; for even a they are 0 or +-1.
int128 sweep_quarter_R_scaled(std::int64_t a, std::int64_t b) {
  const int sa = sin_quarter(a), ca = cos_quarter(a), sb = sin_quarter(b), cb = cos_quarter(b);
  const int128 A = a, B = b, diff = A * A - B * B;
  const int128 q = A * (ca * cb) - B * (sa * sb);
  if (a % 2 != 0) return diff + q * q;
  return 4 * diff * (sa * cb) * (sa * cb) + 4 * q * q;
}

sweep_proof sweep_prove_pair(const resonant_pair<std::int64_t>& p, const sweep_proof_options& opt) {
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  sweep_proof pr;
  pr.quarter_R_scaled = sweep_quarter_R_scaled(a, b);
  pr.m_min = theorem_m_min(a);
  pr.lobes = minimiser_lobes(int128(a), int128(b)).to_vector();
  pr.has_asy = opt.asy && 2 * b < a;
  const resonant_pair<big_int> pb(big_int(p.tau()), big_int(p.sigma()), known_coprime);
  // One precision for both (at sweep orders the extra bits of the asy error cost no more limbs).
  const mpfr_prec_t start = mpfr_prec_t(opt.bits) + 32 +
                            (pr.has_asy ? 2 * mpfr_prec_t(std::bit_width(std::uint64_t(a))) + 8 : 0);
  auto done = [&] { return pr.minimum && (pr.asy || !pr.has_asy); };
  for (mpfr_prec_t prec = start; prec <= 8 * start && !done(); prec *= 2) {
    theorem_constants K(prec);
    set_theorem_constants(K, pb);
    if (!pr.minimum) {
      auto M = std::make_unique<sweep_minimum_enclosure>(prec);
      if (prove_minimum_at(pr, *M, K, pb, opt)) pr.minimum = std::move(M);
    }
    if (pr.has_asy && !pr.asy) {
      auto E = std::make_unique<sweep_asy_enclosure>(prec);
      if (prove_asy_at(*E, K, a, b, opt)) pr.asy = std::move(E);
    }
  }
  const std::string limit = std::to_string(8 * start) + " bits";
  if (!pr.minimum) add_note(pr.note, "not proved: the bracket of u* was not decided within " + limit);
  if (pr.has_asy && !pr.asy) add_note(pr.note, "not proved: the asy error was not enclosed within " + limit);
  return pr;
}

}  // namespace gyrores
