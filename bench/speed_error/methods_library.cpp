// gyrores' own methods: the theorem's path (theorem_double, theorem_proved, theorem_report,
// certificate), the methods from before the theorem as references (the lattice scout and
// polish, TOMS 748 in local coordinates, the global search, the paper's asymptotics), the unit
// of work (one_eval); and the obvious peer, plain Boost TOMS 748 on the naive formulation.
#include <cstdio>
#include <memory>
#include <sstream>
#include <type_traits>

#include "case_support.hpp"
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/report/pair_report.hpp>
#include "methods.hpp"
#include "pre_theorem.hpp"
#include "reference.hpp"
#include "theorem_path.hpp"
#include "testing/naive_toms748.hpp"  // src/testing/: the obvious implementation (the naive peer)
#include "testing/test_support.hpp"

namespace gyrores::bench {

std::string real_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17e", v);
  return buf;
}
std::string real_text(long double v) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "%.21Le", v);
  return buf;
}
std::string real_text(const float128& v) { return v.str(36, std::ios_base::scientific); }
std::string real_text(const mpfr_real& v) {
  return v.str(std::streamsize(v.precision() + 5), std::ios_base::scientific);
}

namespace {

// ---- computations -------------------------------------------------------------------------

// The observed closed form r_res_asy = v x |sin u* tan u*|, u* + tan u* = pi m_min/(2b)
// (asymptotic.hpp, docs/mathematics.md §3), alone: one root of u + tan u = s.
template <class T, pair_integer I> T r_res_asy_only(const resonant_pair<I>& p) {
  using std::fabs;
  using std::sin;
  using std::tan;
  using L = wide_int<I>;
  const L a = p.order(), b = L(p.delta());
  const T x = real_from_ratio<T>(b, a);
  const T s = real_pi<T>() * real_from_ratio<T>(L(p.strand_offset_min()), L(2 * b));
  const T u = u_plus_tan_u_root(s);
  return x * fabs(sin(u) * tan(u));
}

// s of the paper's lobe k = round(a/(2b)): pi (a - 2 k b)/(2b).
template <class T> T paper_s(const big_int& a, const big_int& b) {
  big_int k = paper_fast_node(a, b).k;
  return real_pi<T>() * real_from_ratio<T>(big_int(a - 2 * k * b), big_int(2 * b));
}

// s* = pi m_min/(2b).
template <class T> T star_s(int m_min, const big_int& b) {
  return real_pi<T>() * real_from_ratio<T>(big_int(m_min), big_int(2 * b));
}

// ---- cases: the paper's asymptotics (reference implementation, pre-theorem) -----------------

// The pair as the library's int64 instance when `fits`, else as big_int: fn(pair).
struct pair_arg {
  bool fits;
  resonant_pair<big_int> p;
  resonant_pair<std::int64_t> p64;
  pair_arg(const bench_pair& bp, bool fits_int64)
      : fits(fits_int64), p(bp.p), p64(fits_int64 ? bp.p64() : resonant_pair<std::int64_t>(2, 1)) {}
  template <class Fn> auto operator()(Fn&& fn) const { return fits ? fn(p64) : fn(p); }
};

// theta_asy and r_res_asy: solve(tag, pair) computes the quantity in T from one root of
// u + tan u = s, s = s_of(tag); evaluations: that root's (u_plus_tan_u_solve, both bracket ends
// included). `theta`: the quantity approximates theta_c (else r_res).
template <class Solve, class SOf>
bench_case asymptotic_case(const std::string& name, const bench_pair& bp, const precision& pr, bool theta, Solve solve,
                           SOf s_of) {
  const pair_arg pa(bp, bp.fits64());
  return typed_case(
      name, pr, bp, [pa, solve](auto tag) { return pa([&](const auto& p) { return solve(tag, p); }); },
      [theta, s_of](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        outcome o;
        (theta ? o.theta : o.r_res) = real_text(v);
        o.theta_is_c = theta;
        o.evaluations = u_plus_tan_u_solve(s_of(type_tag<T>{})).evaluations;
        return o;
      });
}

bench_case theta_asy_case(const bench_pair& bp, const precision& pr, const reference&) {
  const big_int a = bp.order(), b = bp.delta();
  return asymptotic_case(
      "theta_asy", bp, pr, true, [](auto tag, const auto& p) { return theta_asy_only<real_of<decltype(tag)>>(p); },
      [a, b](auto tag) { return paper_s<real_of<decltype(tag)>>(a, b); });
}

bench_case r_res_asy_case(const bench_pair& bp, const precision& pr, const reference&) {
  const int m_min = bp.p.strand_offset_min();
  const big_int b = bp.delta();
  return asymptotic_case(
      "r_res_asy", bp, pr, false, [](auto tag, const auto& p) { return r_res_asy_only<real_of<decltype(tag)>>(p); },
      [m_min, b](auto tag) { return star_s<real_of<decltype(tag)>>(m_min, b); });
}

// ---- the theorem's path (include/gyrores/theorem/, certify/theorem_certificate.hpp) ----------

// theorem_minimum_double: the minimum in double from the theorem (int64 pairs below order 2^62,
// the int128 overload up to order 2^120).
bench_case theorem_double_case(const bench_pair& bp, const precision& pr, const reference&) {
  auto convert = [](const auto& m) {
    outcome o;
    o.theta = real_text(m.theta_first);
    o.r_res = real_text(m.r_res);
    return o;
  };
  if (bp.fits64()) {
    const auto p64 = bp.p64();
    return make_case("theorem_double", pr, bp, [p64] { return theorem_minimum_double(p64); }, convert);
  }
  const auto p = bp.p;
  return make_case("theorem_double", pr, bp, [p] { return theorem_minimum_double(p); }, convert);
}

// The proved minimum at the precision of pr's digits (theorem_path.hpp with_proved_minimum):
// timed whole (constants, u* proved, the enclosures); scored at the enclosures' midpoints, and
// the reference must lie in the r_res enclosure.
bench_case theorem_proved_case(const bench_pair& bp, const precision& pr, const reference&) {
  const auto p = bp.p;
  const unsigned digits = pr.digits;
  bench_case c = new_case("theorem_proved", pr, bp);
  c.timed = [=] { with_proved_minimum(p, digits, [](const minimum_enclosure& M) { benchmark::DoNotOptimize(&M); }); };
  c.pilot = [=] {
    outcome o;
    const unsigned bits = with_proved_minimum(p, digits, [&](const minimum_enclosure& M) {
      o.r_res = enclosure_mid_text(M.r_res);
      o.theta = enclosure_mid_text(*M.minimisers.front());
      o.r_enclosure = enclosure_ends_text(M.r_res);
    });
    if (bits != proved_start_bits(digits))
      o.note = "proved at " + std::to_string(bits) + " bits (started at " +
               std::to_string(proved_start_bits(digits)) + ")";
    return o;
  };
  return c;
}

// prove_pair: everything `gyrores pair --digits D` prints, each real correctly rounded from a
// proved enclosure; scored on the rounded r_res and theta_first.
bench_case theorem_report_case(const bench_pair& bp, const precision& pr, const reference&) {
  const auto p = bp.p;
  pair_report_options opt;
  opt.digits = pr.digits;
  bench_case c = new_case("theorem_report", pr, bp);
  c.timed = [=] { benchmark::DoNotOptimize(prove_pair(p, opt)); };
  c.pilot = [=] {
    const pair_report r = prove_pair(p, opt);
    outcome o;
    o.r_res = r.r_res.value;
    o.theta = r.theta_first.value;
    return o;
  };
  return c;
}

// The midpoint of a certified enclosure [lo, hi] (decimal text), as text.
std::string enclosure_mid(const std::pair<std::string, std::string>& e) {
  mpfr_real lo(e.first), hi(e.second);
  return real_text(mpfr_real((lo + hi) / 2));
}

bench_case certificate_case(const bench_pair& bp, const precision& pr, const reference&) {
  const auto p = bp.p;
  const unsigned digits = pr.digits;
  bench_case c = new_case("certificate", pr, bp);
  c.timed = [=] { benchmark::DoNotOptimize(certify_by_theorem(p, digits)); };
  c.pilot = [=] {
    auto cert = certify_by_theorem(p, digits);
    outcome o;
    scoped_digits d(digits + 30);
    o.r_res = enclosure_mid(cert.r_res);
    o.theta = enclosure_mid(cert.theta_first);
    o.r_enclosure = cert.r_res;
    return o;
  };
  return c;
}

// ---- references from before the theorem (pre_theorem.hpp) -----------------------------------

template <class T> outcome inscribed_outcome(const inscribed_result<T>& r) {
  outcome o;
  o.theta = real_text(r.theta_first);
  o.r_res = real_text(r.r_res);
  o.evaluations = r.evaluations;
  return o;
}

// A method returning an inscribed_result: solve(tag) in T.
template <class Solve>
bench_case inscribed_case(const std::string& name, const bench_pair& bp, const precision& pr, Solve solve) {
  return typed_case(name, pr, bp, solve, [](const auto& r) { return inscribed_outcome(r); });
}

bench_case ref_lattice_case(const bench_pair& bp, const precision& pr, const reference&) {
  const pair_arg pa(bp, bp.fits64());
  return inscribed_case("ref_lattice", bp, pr, [pa](auto tag) {
    using T = real_of<decltype(tag)>;
    return pa([](const auto& p) { return inscribed_lattice<T>(p, T(1)); });
  });
}

bench_case ref_toms748_local_case(const bench_pair& bp, const precision& pr, const reference&) {
  const auto p = bp.p;
  return inscribed_case("ref_toms748_local", bp, pr, [p](auto tag) {
    using T = real_of<decltype(tag)>;
    return inscribed_lattice<T>(p, T(1), lattice_options{.solver = lattice_solver::toms748_full});
  });
}

bench_case ref_global_case(const bench_pair& bp, const precision& pr, const reference&) {
  const auto p64 = bp.p64();
  return inscribed_case("ref_global", bp, pr, [p64](auto tag) {
    using T = real_of<decltype(tag)>;
    return inscribed_global<T>(p64, T(1));
  });
}

// The Newton polish alone (lobe_root_polish) in frame f from the double root u0; the pair in I,
// the frame's integers in L.
template <class I, class L>
bench_case polish_case(const bench_pair& bp, const precision& pr, const resonant_pair<I>& p, const lobe_frame<L>& f,
                       const L& a, double u0) {
  return typed_case(
      "ref_newton_polish", pr, bp,
      [=](auto tag) {
        using T = real_of<decltype(tag)>;
        return lobe_root_polish(p, T(1), f, a, T(u0), 53);
      },
      [=](const auto& r) {
        using T = std::decay_t<decltype(r.u)>;
        using std::sqrt;
        auto c = resonant_constants_of<T>(p, T(1));
        outcome o;
        o.theta = real_text(lobe_theta(c, f, a, r.u));
        o.r_res = real_text(T(sqrt(r.radius_sq)));
        o.evaluations = r.evaluations;
        return o;
      });
}

// Started from the theorem's first minimiser in double (theorem_path.hpp).
bench_case ref_newton_polish_case(const bench_pair& bp, const precision& pr, const reference&) {
  const first_minimiser fm = theorem_first_minimiser(bp.p);
  const lobe_frame<big_int>& fb = fm.frame;
  if (bp.fits_int128_lattice()) {
    const lobe_frame<int128> f{int128(std::int64_t(fb.k)), int128(std::int64_t(fb.j)), int128(std::int64_t(fb.m))};
    const auto p64 = bp.p64();
    return polish_case(bp, pr, p64, f, int128(p64.order()), fm.u);
  }
  return polish_case(bp, pr, bp.p, fb, bp.order(), fm.u);
}

// ---- the unit of work, and the naive peer -----------------------------------------------------

// One evaluation of (q, q', z, z') at the theorem's first minimiser; the constants and the frame
// are computed at the first call (untimed: the pilot runs first) and kept.
bench_case one_eval_case(const bench_pair& bp, const precision& pr, const reference&) {
  const first_minimiser fm = theorem_first_minimiser(bp.p);
  const auto p = bp.p;
  const big_int a = bp.order();
  return dispatch_real(pr, [&](auto tag) {
    using T = real_of<decltype(tag)>;
    struct state {
      resonant_constants<T> c;
      lobe_frame_real<T> fr;
      T u;
    };
    auto st = std::make_shared<std::optional<state>>();
    return make_case(
        "one_eval", pr, bp,
        [=] {
          if (!*st) {
            auto c = resonant_constants_of<T>(p, T(1));
            auto fr = lobe_frame_real_of(c, fm.frame, a);
            st->emplace(state{c, fr, T(fm.u)});
          }
          const state& s = **st;
          return lobe_eval(s.c, s.fr, s.u);
        },
        [](const lobe_values<T>&) {
          outcome o;
          o.evaluations = 1;
          return o;
        });
  });
}

bench_case naive_toms748_case(const bench_pair& bp, const precision& pr, const reference& ref) {
  const big_int tau = bp.p.tau(), sigma = bp.p.sigma(), i = ref.first_half_period;
  return typed_case(
      "naive_toms748", pr, bp, [=](auto tag) { return test::naive_toms748<real_of<decltype(tag)>>(tau, sigma, i); },
      [](const auto& r) {
        outcome o;
        o.theta = real_text(r.theta);
        o.r_res = real_text(r.r);
        o.evaluations = r.evaluations;
        return o;
      });
}

// ---- skip rules -----------------------------------------------------------------------------

const char* kOnly30 =
    "30 digits serve the certificate's comparisons (certificate, theorem_proved, theorem_report, ref_lattice, "
    "one_eval, the theorem-aware Arb peers)";

std::string skip_never(const bench_pair&, const precision&) { return ""; }

std::string skip_theorem_double(const bench_pair& bp, const precision& pr) {
  if (pr.kind != real_kind::dbl)
    return "the theorem's point path is double only (theorem_minimum_double); every other precision takes the "
           "proved path (theorem_proved)";
  if (boost::multiprecision::msb(bp.order()) >= 120)
    return "theorem_minimum_double takes pairs of order below 2^120 (int128); larger pairs take the proved path "
           "(theorem_proved)";
  return "";
}

// In double only for the pairs theorem_minimum_double does not take (order >= 2^120): there the
// proved minimum at 16 digits is gyrores' double answer (headline L1).
std::string skip_theorem_proved(const bench_pair& bp, const precision& pr) {
  if (pr.kind == real_kind::dbl && boost::multiprecision::msb(bp.order()) < 120)
    return "in double the theorem's path is theorem_double (the proved path runs in double only for the pairs of "
           "order >= 2^120, and at 19 digits and up)";
  return "";
}

std::string skip_decimal_only(const bench_pair&, const precision& pr) {
  if (!pr.is_mp()) return "its precision is a number of decimal digits (30 to 10000): it runs at the mp precisions";
  return "";
}

// Full-precision TOMS 748 at 10000 digits: 30-60 evaluations of ~17 ms sines (1-3 s per call).
std::string skip_toms748_10000(const bench_pair& bp, const precision& pr) {
  if (pr.name == "mp10000" && bp.name != "(6,5)" && bp.name != "(1000,1)" && bp.name != "(10^12+1,10^12)")
    return "TOMS 748 at 10000 digits needs 30-60 evaluations of ~17 ms sines (1-3 s per call); three pairs (low, "
           "mid, huge) show it, and the other six would add several minutes to the run";
  return "";
}

std::string skip_asymptotic(const bench_pair& bp, const precision& pr) {
  if (!bp.small_x())
    return "x = b/a >= 1/2: the paper's lobe asymptotics do not apply (theta_asy_only throws usage_error)";
  if (pr.name == "mp30") return kOnly30;
  if (pr.name == "mp10000")
    return "the asymptotic error O(x^2/a) caps the digits at about log10(a/x^2) (at most ~95 for these pairs), "
           "already reached at 100 digits; 10000 digits would only cost more";
  return "";
}

std::string skip_toms748_local(const bench_pair& bp, const precision& pr) {
  if (pr.kind == real_kind::dbl)
    return "in double the reference lattice's own root solve is the counterpart (TOMS 748 in local coordinates, "
           "Newton first for x < 1/2)";
  if (pr.name == "mp30") return kOnly30;
  return skip_toms748_10000(bp, pr);
}

std::string skip_newton_polish(const bench_pair&, const precision& pr) {
  if (pr.kind == real_kind::dbl) return "the double root is the start: nothing to polish in double";
  if (pr.name == "mp30") return kOnly30;
  return "";
}

// Global search cost per call: 4 tau root solves at full precision. Beyond the limits below a
// single call takes more than ~1 s on this machine (measured: (1000,1) at 50 digits 2.2 s,
// (6,5) at 1000 digits 0.7 s), and it adds no digit over the other methods.
std::string skip_global(const bench_pair& bp, const precision& pr) {
  if (bp.order() > 100000)
    return "the global search is O(tau) (4 tau root solves) and limited to order <= 1e5 "
           "(global_search_options::max_order): 10^6+1 would take ~1 s per call in double, 10^12+1 ~10 days";
  if (pr.name == "mp30") return kOnly30;
  if (pr.name == "mp10000")
    return "4 tau TOMS 748 solves at 10000 digits: ~30 s per call even for (6,5) (one 10000-digit sine costs "
           "~17 ms here); no digit beyond the theorem's";
  if (pr.name == "mp1000" && bp.order() > 20)
    return "4 tau TOMS 748 solves at 1000 digits: ~0.7 s x tau/6 per call (~2 min for (101,100)), longer than "
           "the rest of the run together";
  if ((pr.name == "mp50" || pr.name == "mp100") && bp.order() > 500)
    return "4 tau TOMS 748 solves at 50/100 digits: ~2 s per call for (1000,1), minutes per row";
  return "";
}

std::string skip_naive_toms748(const bench_pair& bp, const precision& pr) {
  return pr.name == "mp30" ? std::string(kOnly30) : skip_toms748_10000(bp, pr);
}

}  // namespace

// The table of methods: name, plot series (theorem_double and theorem_proved form one, the
// theorem's path from double up), what it computes (for the report; its
// first words say which kind: the theorem's path, a reference from before the theorem, the
// unit of work, a peer), when it is skipped, how a case is built.
std::vector<method_def> library_methods(const run_config&) {
  return {
      {"theorem_double", "theorem",
       "**theorem (double)**: theorem_minimum_double (theorem/minimum.hpp): m_min and the minimisers' lobes by "
       "integers (one extended Euclid), u* = H^{-1}(pi m_min/(2a)) from H's expansions, Newton in double by the "
       "sin/cos table where they are not close, and one double-double Newton step that carries the proof, without "
       "libm (theorem_root_refined), r_res, theta_first and t_first within one ulp (proved error bounds, no "
       "enclosure), and every minimiser; pairs of order below 2^120 (the sweep rows, design catalogue and figures)",
       skip_theorem_double, theorem_double_case},
      {"theorem_proved", "theorem",
       "**theorem, proved (MPFI+Arb)**: the proved minimum at the digits' precision (theorem/root.hpp, "
       "minimum.hpp): set_theorem_constants and prove_minimum at digits log2(10) + 32 bits (doubled if u* is not "
       "proved or r_res, theta_first are wider than the digits): the Newton ladder, Arb enclosures of the tangents "
       "at its last centre, a bracket of u* proved by the addition formula, enclosures of r_res and every "
       "minimiser; scored at the enclosures' midpoints",
       skip_theorem_proved, theorem_proved_case},
      {"theorem_report", "theorem_report",
       "**theorem, whole report**: prove_pair(pair, digits) (report/pair_report.hpp), everything `gyrores pair "
       "--digits D` prints (r_res, H_q min, H_z max, every minimiser, t_first, the paper's asymptotics for x < 1/2, "
       "...), each real correctly rounded from a proved enclosure (precision doubled until every rounding is "
       "decided); scored on the printed r_res and theta_first",
       skip_decimal_only, theorem_report_case},
      {"certificate", "certificate",
       "**certificate**: certify_by_theorem(pair, digits) (certify/theorem_certificate.hpp): the lattice-theorem "
       "certificate (integer facts, a bracket of u* with decimal ends proved, MPFI enclosures of r_res, "
       "theta_first and t_first with at least `digits` digits); scored at the enclosure midpoint",
       skip_decimal_only, certificate_case},
      {"theta_asy", "theta_asy",
       "the paper's theta_asy alone, heuristic; **reference (pre-theorem)** implementation "
       "(tests/reference/asymptotic.hpp theta_asy_only<T>: k = round(a/(2b)), one TOMS 748 root of u + tan u = s, "
       "no root of q'); approximates the lobe root theta_c; evaluations: u - atan(s - u)",
       skip_asymptotic, theta_asy_case},
      {"r_res_asy", "r_res_asy",
       "the observed closed form r_res_asy = v x |sin u* tan u*|, u* + tan u* = pi m_min/(2b) (docs/mathematics.md "
       "§3), heuristic; **reference (pre-theorem)** implementation (tests/reference/asymptotic.hpp): one root of "
       "u + tan u = s",
       skip_asymptotic, r_res_asy_case},
      {"ref_lattice", "ref_lattice",
       "**reference (pre-theorem)**: the lattice scout and Newton polish, inscribed_lattice<T> "
       "(tests/reference/lattice.hpp): the minimisers' sites by integers; double: a root of q' in local coordinates "
       "(safeguarded Newton for x < 1/2, TOMS 748 otherwise); other types: that double scout, then Newton (MPFR: "
       "with precision doubling, lobe_root_polish); nothing proved; evaluations: q' evaluations of all root solvers",
       skip_never, ref_lattice_case},
      {"ref_toms748_local", "ref_toms748_local",
       "**reference (pre-theorem)**: TOMS 748 in local coordinates at full precision T (inscribed_lattice<T> with "
       "lattice_solver::toms748_full: the lattice method's bracket solved by TOMS 748 in T; no double scout, no "
       "Newton, no precision ladder)",
       skip_toms748_local, ref_toms748_local_case},
      {"ref_newton_polish", "ref_newton_polish",
       "**reference (pre-theorem)**: the lattice's Newton polish alone (lobe_root_polish) from the "
       "theorem's double root of the first minimiser's lobe: MPFR with precision doubling, fixed types plain "
       "Newton; ref_lattice minus its double scout",
       skip_newton_polish, ref_newton_polish_case},
      {"ref_global", "ref_global",
       "**reference (pre-theorem)**: the global search, inscribed_global<T> (tests/reference/, the tests' "
       "cross-validation): all 4 tau critical points (roots of q' and z'), each by TOMS 748 in local coordinates at "
       "full precision; assumes nothing about where the minimum is",
       skip_global, ref_global_case},
      {"one_eval", "one_eval",
       "**unit of work**: one evaluation of (q, q', z, z') at the theorem's first minimiser (model/resonant.hpp "
       "lobe_eval: two real_sin_cos, for MPFR Arb's arb_sin_cos), constants precomputed",
       skip_never, one_eval_case},
      {"naive_toms748", "naive_toms748",
       "**peer, the obvious implementation**: plain boost::math::tools::toms748_solve with eps_tolerance(bits - "
       "2) on the naive q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) (tau theta formed directly) over the "
       "fast half-period [i pi/tau, (i+1) pi/tau] holding theta_first (the paper's lobe when it carries the "
       "minimum), then r = rho0 |sin tau theta + sin sigma theta|",
       skip_naive_toms748, naive_toms748_case},
  };
}

}  // namespace gyrores::bench
