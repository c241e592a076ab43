// The Arb/FLINT peer (Debian 12: libflint-arb-dev, Arb 2.23 on FLINT 2.9), optional.
//
//  arb_newton: arb_calc_refine_root_newton (Newton in ball arithmetic with precision doubling)
//    on q'(u) = cos u sin(mu - x u) - x sin u cos(mu - x u) in the first minimiser's lobe frame
//    (the same local coordinates as gyrores: mu = pi m/(2a), x = b/a), from the theorem's double
//    root u = sign(m) u* (theorem_path.hpp) as a ball of relative radius 2^-40; convergence region of
//    relative radius 2^-20, its factor from arb_calc_newton_conv_factor at 64 bits. Timed: the
//    constants x, mu at full precision, the convergence factor and the refinement: the root
//    alone (theta_first is formed from it untimed, to score it; r_res is not computed).
//  arb_one_eval: one call of that function with order 2 (f and f' from two arb_sin_cos): the
//    Arb counterpart of one_eval, to compare Arb's elementary functions with MPFR's.
// Precision: the same bits as mpfr_real at that many digits.
#include "methods.hpp"

#ifdef GYRORES_BENCH_HAVE_ARB
#include <arb.h>
#include <arb_calc.h>
#include <flint/flint.h>
#include <flint/fmpz.h>

#include <cmath>
#include <memory>

#include "arb_types.hpp"
#include "case_support.hpp"
#include "reference.hpp"
#include "reference/lobe_frames.hpp"  // lobe_theta: theta of the root, as the references form it
#include "theorem_path.hpp"
#include "testing/test_support.hpp"
#endif

namespace gyrores::bench {

#ifndef GYRORES_BENCH_HAVE_ARB

bool arb_available() { return false; }
std::string arb_library_version() { return ""; }
std::vector<method_def> arb_methods(const run_config&) { return {}; }

#else

bool arb_available() { return true; }
std::string arb_library_version() { return std::string("Arb ") + arb_version + " on FLINT " + FLINT_VERSION; }

namespace {

// The lobe problem: x = b/a, mu = pi m/(2a); evaluations counted.
struct lobe_problem {
  arb_ball x, mu;
  std::uint64_t evaluations = 0;
  void set(const fmpz_t a, const fmpz_t b, const fmpz_t m, slong prec) {
    arb_set_fmpz(x.v, b);
    arb_div_fmpz(x.v, x.v, a, prec);
    arb_const_pi(mu.v, prec);
    arb_mul_fmpz(mu.v, mu.v, m, prec);
    arb_div_fmpz(mu.v, mu.v, a, prec);
    arb_mul_2exp_si(mu.v, mu.v, -1);
  }
};

// out[0] = f, out[1] = f', out[2] = f''/2 (as many as `order`), f = cos u sin w - x sin u cos w,
// w = mu - x u; f' = -(1 + x^2) sin u sin w - 2x cos u cos w,
// f'' = -(1 + 3x^2) cos u sin w + x (3 + x^2) sin u cos w.
int lobe_qdot(arb_ptr out, const arb_t u, void* param, slong order, slong prec) {
  auto* P = static_cast<lobe_problem*>(param);
  ++P->evaluations;
  arb_t w, su, cu, sw, cw, t, s, x2;
  arb_init(w); arb_init(su); arb_init(cu); arb_init(sw); arb_init(cw); arb_init(t); arb_init(s); arb_init(x2);
  arb_mul(w, P->x.v, u, prec);
  arb_sub(w, P->mu.v, w, prec);
  arb_sin_cos(su, cu, u, prec);
  arb_sin_cos(sw, cw, w, prec);
  arb_mul(t, su, cw, prec);  // su cw
  arb_mul(s, cu, sw, prec);  // cu sw
  arb_mul(out + 0, P->x.v, t, prec);
  arb_sub(out + 0, s, out + 0, prec);
  if (order > 1) {
    arb_mul(x2, P->x.v, P->x.v, prec);
    arb_t a1, a2;
    arb_init(a1); arb_init(a2);
    arb_mul(a1, su, sw, prec);
    arb_add_ui(a2, x2, 1, prec);
    arb_mul(a1, a1, a2, prec);   // (1 + x^2) su sw
    arb_mul(a2, cu, cw, prec);
    arb_mul(a2, a2, P->x.v, prec);
    arb_mul_2exp_si(a2, a2, 1);  // 2x cu cw
    arb_add(out + 1, a1, a2, prec);
    arb_neg(out + 1, out + 1);
    if (order > 2) {
      arb_mul_ui(a1, x2, 3, prec);
      arb_add_ui(a1, a1, 1, prec);
      arb_mul(a1, a1, s, prec);    // (1 + 3x^2) cu sw
      arb_add_ui(a2, x2, 3, prec);
      arb_mul(a2, a2, P->x.v, prec);
      arb_mul(a2, a2, t, prec);    // x (3 + x^2) su cw
      arb_sub(out + 2, a2, a1, prec);
      arb_mul_2exp_si(out + 2, out + 2, -1);
    }
    arb_clear(a1); arb_clear(a2);
  }
  arb_clear(w); arb_clear(su); arb_clear(cu); arb_clear(sw); arb_clear(cw); arb_clear(t); arb_clear(s); arb_clear(x2);
  return 0;
}

// Inputs shared by both Arb methods: the theorem's first minimiser lobe and its double root.
struct arb_inputs {
  big_int a, b, k, j, m;
  double u0;
  slong prec;
};

arb_inputs inputs_of(const bench_pair& bp, const precision& pr) {
  const first_minimiser fm = theorem_first_minimiser(bp.p);
  scoped_digits d(pr.digits);
  return {bp.order(), bp.delta(), fm.frame.k, fm.frame.j, fm.frame.m, fm.u, slong(real_bits<mpfr_real>())};
}

struct refine_result {
  std::shared_ptr<arb_ball> root;
  int status;
  std::uint64_t evaluations;
};

refine_result arb_refine(const arb_inputs& in) {
  fmpz_int a(in.a), b(in.b), m(in.m);
  lobe_problem P;
  P.set(a.v, b.v, m.v, in.prec + 16);
  // Start ball and convergence region around the double root.
  int e = 0;
  std::frexp(in.u0 == 0 ? 1.0 : in.u0, &e);
  arb_ball start, region;
  arb_set_d(start.v, in.u0);
  arb_add_error_2exp_si(start.v, e - 40);
  arb_set_d(region.v, in.u0);
  arb_add_error_2exp_si(region.v, e - 20);
  arf_t conv;
  arf_init(conv);
  arb_calc_newton_conv_factor(conv, lobe_qdot, &P, region.v, 64);
  auto root = std::make_shared<arb_ball>();
  int status = arb_calc_refine_root_newton(root->v, lobe_qdot, &P, start.v, region.v, conv, 16, in.prec);
  arf_clear(conv);
  return {root, status, P.evaluations};
}

std::string skip_arb(const bench_pair&, const precision& pr) {
  if (!pr.is_mp())
    return "Arb is a multiprecision ball library; its fixed-precision counterpart is the double start itself";
  if (pr.name == "mp30")
    return "30 digits serve the certificate's comparisons (certificate, theorem_proved, theorem_report, "
           "ref_lattice, one_eval, the theorem-aware Arb peers)";
  return "";
}

// theta of the refined root (untimed), and a note when Arb did not deliver the precision.
outcome arb_newton_outcome(const arb_inputs& in, const resonant_pair<big_int>& p, unsigned digits) {
  auto r = arb_refine(in);
  scoped_digits d(digits);
  mpfr_real u;
  arf_get_mpfr(u.backend().data(), arb_midref(r.root->v), MPFR_RNDN);
  auto cst = resonant_constants_of<mpfr_real>(p, mpfr_real(1));
  const lobe_frame<big_int> f{in.k, in.j, in.m};
  outcome o;
  o.theta = real_text(lobe_theta(cst, f, in.a, u));
  o.evaluations = r.evaluations;
  const slong acc = arb_rel_accuracy_bits(r.root->v);
  if (r.status != ARB_CALC_SUCCESS || acc + 64 < in.prec)
    o.note = "Arb status " + std::to_string(r.status) + ", enclosure of " + std::to_string(acc) + " bits";
  return o;
}

bench_case arb_newton_case(const bench_pair& bp, const precision& pr, const reference&) {
  const arb_inputs in = inputs_of(bp, pr);
  const auto p = bp.p;
  const unsigned digits = pr.digits;
  bench_case c = new_case("arb_newton", pr, bp);
  c.timed = [in] { benchmark::DoNotOptimize(arb_refine(in)); };
  c.pilot = [in, p, digits] { return arb_newton_outcome(in, p, digits); };
  return c;
}

// One evaluation of q' and q'' at the double root, with the problem set up once.
struct one_eval_state {
  lobe_problem P;
  arb_ball u;
  arb_struct out[2];
  one_eval_state() {
    arb_init(out + 0);
    arb_init(out + 1);
  }
  ~one_eval_state() {
    arb_clear(out + 0);
    arb_clear(out + 1);
  }
  one_eval_state(const one_eval_state&) = delete;
  one_eval_state& operator=(const one_eval_state&) = delete;
};

bench_case arb_one_eval_case(const bench_pair& bp, const precision& pr, const reference&) {
  const arb_inputs in = inputs_of(bp, pr);
  auto st = std::make_shared<one_eval_state>();
  {
    fmpz_int a(in.a), b(in.b), m(in.m);
    st->P.set(a.v, b.v, m.v, in.prec);
    arb_set_d(st->u.v, in.u0);
  }
  bench_case c = new_case("arb_one_eval", pr, bp);
  const slong prec = in.prec;
  c.timed = [st, prec] {
    lobe_qdot(st->out, st->u.v, &st->P, 2, prec);
    benchmark::DoNotOptimize(st->out);
  };
  c.pilot = [st, prec] {
    lobe_qdot(st->out, st->u.v, &st->P, 2, prec);
    outcome o;
    o.evaluations = 1;
    return o;
  };
  return c;
}

}  // namespace

std::vector<method_def> arb_methods(const run_config&) {
  return {
      {"arb_newton", "arb",
       "**peer, Arb**: Arb's arb_calc_refine_root_newton on q' in the first minimiser's lobe frame (local "
       "coordinates; its root is the theorem's u*), from the theorem's double root (ball of relative radius 2^-40), "
       "convergence factor at 64 bits; the root alone, enclosed (a ball)",
       skip_arb, arb_newton_case},
      {"arb_one_eval", "arb_one_eval",
       "**peer, Arb, unit of work**: one Arb evaluation of q' and its derivative (two arb_sin_cos) at the first "
       "minimiser: Arb's counterpart of one_eval",
       skip_arb, arb_one_eval_case},
  };
}

#endif

}  // namespace gyrores::bench
