// gyrores' own methods, and plain Boost TOMS 748 on the naive formulation.
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdio>
#include <memory>
#include <sstream>

#include "case_support.hpp"
#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/certify/certificate.hpp>
#include <gyrores/inscribed/global_search.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include "methods.hpp"
#include "reference.hpp"

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

// Evaluations of u - atan(s - u) made by u_plus_tan_u_root(s) (same solver, same tolerance).
template <class T> std::uint64_t u_plus_tan_u_evaluations(const T& s) {
  using std::atan;
  if (s == 0) return 0;
  std::uint64_t n = 0;
  auto phi = [&](const T& u) {
    ++n;
    return T(u - atan(s - u));
  };
  T h = real_pi<T>() / 2, lo = -h;
  root_bracketed(phi, lo, h, phi(lo), phi(h), detail::asy_u_tolerance(s), "count", detail::asy_budget<T>());
  return n;
}

template <class T> T paper_s(const bench_pair& bp) {
  const big_int a = bp.order(), b = bp.delta();
  big_int k = paper_fast_node(a, b).k;
  return real_pi<T>() * real_from_ratio<T>(big_int(a - 2 * k * b), big_int(2 * b));
}

template <class T> T star_s(const bench_pair& bp) {
  return real_pi<T>() * real_from_ratio<T>(big_int(bp.p.strand_offset_min()), big_int(2 * bp.delta()));
}

// TOMS 748 in local coordinates at full precision T: the lattice method's bracket(s) (one per
// site, lattice.hpp), each q' root solved by TOMS 748 in T (detail::lattice_solve), the smallest R;
// no double scout, no Newton.
template <class T, class L, pair_integer I> inscribed_result<T> toms748_local_impl(const resonant_pair<I>& p) {
  const L tau = L(p.tau()), a = L(p.order()), b = L(p.delta());
  auto sites = detail::lattice_sites(tau, a, b, 2 * b >= a, false);
  auto c = resonant_constants_of<T>(p, T(1));
  std::size_t best = 0;
  std::uintmax_t evals = 0;
  std::vector<detail::scout_root<T>> roots;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const auto& s = sites[i];
    if (s.den == 0) {
      const T h = c.pi / 2;
      roots.push_back(detail::lattice_solve(c, s.frame, a, T(-h), h));
    } else {
      roots.push_back(detail::lattice_solve(c, s.frame, a, lobe_u_at(c, s.frame, a, s.lo_num, s.den),
                                            lobe_u_at(c, s.frame, a, s.hi_num, s.den)));
    }
    evals += roots.back().evaluations;
    if (roots[i].radius_sq < roots[best].radius_sq) best = i;
  }
  inscribed_result<T> r;
  r.method = inscribed_method::lattice;
  r.critical_points = sites.size();
  r.evaluations = evals;
  detail::lattice_fill(r, c, sites[best].frame, a, b, roots[best].u, roots[best].radius_sq, p.strand_offset_min());
  return r;
}

template <class T> inscribed_result<T> toms748_local(const bench_pair& bp) {
  if (bp.fits_int128_lattice()) return toms748_local_impl<T, int128>(bp.p64());
  return toms748_local_impl<T, big_int>(bp.p);
}

// Plain Boost TOMS 748 on the naive q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) over
// the fast half-period [i pi/tau, (i+1) pi/tau] that holds theta_first (q' has the sign (-1)^i
// at its ends), tolerance eps_tolerance(bits - 2); then r = rho0 |sin(tau theta) + sin(sigma theta)|.
template <class T> struct naive_result {
  T theta, r;
  std::uintmax_t evaluations;
};
template <class T> naive_result<T> naive_toms748(const big_int& tau_i, const big_int& sigma_i, const big_int& i) {
  using std::cos;
  using std::fabs;
  using std::sin;
  using std::sqrt;
  const T tau = real_from_int<T>(tau_i), sigma = real_from_int<T>(sigma_i), pi = real_pi<T>();
  const T w1 = sqrt(tau / sigma), w2 = sqrt(sigma / tau), rho0 = 1 / (w1 + w2);
  auto qdot = [&](const T& th) { return T(w1 * cos(tau * th) + w2 * cos(sigma * th)); };
  const T lo = pi * real_from_int<T>(i) / tau, hi = pi * real_from_int<T>(big_int(i + 1)) / tau;
  boost::uintmax_t iters = 1000;
  auto br = boost::math::tools::toms748_solve(qdot, lo, hi,
                                              boost::math::tools::eps_tolerance<T>(real_bits<T>() - 2), iters);
  const T th = (br.first + br.second) / 2;
  return {th, rho0 * fabs(sin(tau * th) + sin(sigma * th)), iters};
}

// ---- skip rules -----------------------------------------------------------------------------

const char* kOnly30 = "30 digits serve only the certified-vs-uncertified comparison (exact, certified, one_eval)";

// Full-precision TOMS 748 at 10000 digits: 30-60 evaluations of ~17 ms sines (1-3 s per call).
std::string skip_toms748_10000(const bench_pair& bp, const precision& pr) {
  if (pr.name == "mp10000" && bp.name != "(6,5)" && bp.name != "(1000,1)" && bp.name != "(10^12+1,10^12)")
    return "TOMS 748 at 10000 digits needs 30-60 evaluations of ~17 ms sines (1-3 s per call); three pairs (low, "
           "mid, huge) show it within the run's 10-minute budget";
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

// Global search cost per call: 4 tau root solves at full precision. Beyond the limits below a
// single call takes more than ~1 s on this machine (measured: (1000,1) at 50 digits 2.2 s,
// (6,5) at 1000 digits 0.7 s), and it adds no digit over the exact method.
std::string skip_global(const bench_pair& bp, const precision& pr) {
  if (bp.order() > 100000)
    return "the global search is O(tau) (4 tau root solves) and limited to order <= 1e5 "
           "(global_search_options::max_order): 10^6+1 would take ~1 s per call in double, 10^12+1 ~10 days";
  if (pr.name == "mp30") return kOnly30;
  if (pr.name == "mp10000")
    return "4 tau TOMS 748 solves at 10000 digits: ~30 s per call even for (6,5) (one 10000-digit sine costs "
           "~17 ms here); no digit beyond the exact method";
  if (pr.name == "mp1000" && bp.order() > 20)
    return "4 tau TOMS 748 solves at 1000 digits: ~0.7 s x tau/6 per call (~2 min for (101,100)), beyond the "
           "run's 10-minute budget";
  if ((pr.name == "mp50" || pr.name == "mp100") && bp.order() > 500)
    return "4 tau TOMS 748 solves at 50/100 digits: ~2 s per call for (1000,1), beyond the run's budget";
  return "";
}

std::string skip_fixed_only_mp(const precision& pr, const char* why) { return pr.is_mp() ? "" : why; }

}  // namespace

std::vector<method_def> library_methods(const run_config& cfg) {
  std::vector<method_def> out;

  out.push_back(
      {"theta_asy", "theta_asy",
       "the paper's theta_asy alone (asymptotic.hpp theta_asy_only<T>: k = round(a/(2b)), one TOMS 748 root of "
       "u + tan u = s, no root of q'); heuristic, approximates the lobe root theta_c; evaluations: u - atan(s - u)",
       skip_asymptotic, [](const bench_pair& bp, const precision& pr, const reference&) {
         return dispatch_real(pr, [&](auto tag) {
           using T = typename decltype(tag)::type;
           const bool f64 = bp.fits64();
           const auto p = bp.p;
           const auto p64 = f64 ? bp.p64() : resonant_pair<std::int64_t>(2, 1);
           return make_case(
               "theta_asy", pr, bp,
               [=] { return f64 ? theta_asy_only<T>(p64) : theta_asy_only<T>(p); },
               [=](const T& th) {
                 outcome o;
                 o.theta = real_text(th);
                 o.theta_is_c = true;
                 o.evaluations = u_plus_tan_u_evaluations(paper_s<T>(bench_pair{"", "", p}));
                 return o;
               });
         });
       }});

  out.push_back({"r_res_asy", "r_res_asy",
                 "the observed closed form r_res_asy = v x |sin u* tan u*|, u* + tan u* = pi m_min/(2b) (docs/mathematics.md §3, "
                 "asymptotic.hpp): one root of u + tan u = s; heuristic",
                 skip_asymptotic, [](const bench_pair& bp, const precision& pr, const reference&) {
                   return dispatch_real(pr, [&](auto tag) {
                     using T = typename decltype(tag)::type;
                     const bool f64 = bp.fits64();
                     const auto p = bp.p;
                     const auto p64 = f64 ? bp.p64() : resonant_pair<std::int64_t>(2, 1);
                     return make_case(
                         "r_res_asy", pr, bp,
                         [=] { return f64 ? r_res_asy_only<T>(p64) : r_res_asy_only<T>(p); },
                         [=](const T& r) {
                           outcome o;
                           o.r_res = real_text(r);
                           o.evaluations = u_plus_tan_u_evaluations(star_s<T>(bench_pair{"", "", p}));
                           return o;
                         });
                   });
                 }});

  out.push_back(
      {"exact", "exact",
       "inscribed_lattice<T>: the exact r_res and every minimiser in O(log tau). double: a root of q' in local "
       "coordinates (safeguarded Newton for x < 1/2, TOMS 748 otherwise); other types: that double scout, then "
       "Newton (MPFR: with precision doubling, lattice_polish); evaluations: q' evaluations of all root solvers",
       [](const bench_pair&, const precision&) { return std::string(); },
       [](const bench_pair& bp, const precision& pr, const reference&) {
         return dispatch_real(pr, [&](auto tag) {
           using T = typename decltype(tag)::type;
           const bool f64 = bp.fits64();
           const auto p = bp.p;
           const auto p64 = f64 ? bp.p64() : resonant_pair<std::int64_t>(2, 1);
           return make_case(
               "exact", pr, bp,
               [=] { return f64 ? inscribed_lattice<T>(p64, T(1)) : inscribed_lattice<T>(p, T(1)); },
               [](const inscribed_result<T>& r) {
                 outcome o;
                 o.theta = real_text(r.theta_first);
                 o.r_res = real_text(r.r_res);
                 o.evaluations = r.evaluations;
                 return o;
               });
         });
       }});

  out.push_back(
      {"toms748_local", "toms748_local",
       "TOMS 748 in local coordinates at full precision T (the lattice method's bracket solved by TOMS 748 in T: no "
       "double scout, no Newton, no precision ladder)",
       [](const bench_pair& bp, const precision& pr) {
         if (pr.kind == real_kind::dbl)
           return std::string("in double the exact method's own root solve is the counterpart (TOMS 748 in local "
                              "coordinates, Newton first for x < 1/2)");
         if (pr.name == "mp30") return std::string(kOnly30);
         return skip_toms748_10000(bp, pr);
       },
       [](const bench_pair& bp, const precision& pr, const reference&) {
         return dispatch_real(pr, [&](auto tag) {
           using T = typename decltype(tag)::type;
           return make_case(
               "toms748_local", pr, bp, [bp] { return toms748_local<T>(bp); },
               [](const inscribed_result<T>& r) {
                 outcome o;
                 o.theta = real_text(r.theta_first);
                 o.r_res = real_text(r.r_res);
                 o.evaluations = r.evaluations;
                 return o;
               });
         });
       }});

  out.push_back(
      {"newton_doubling", "newton_doubling",
       "the Newton polish alone (lattice.hpp detail::lattice_polish) from the double root of the first minimiser's "
       "frame: MPFR with precision doubling, fixed types plain Newton; the exact method minus its double scout",
       [](const bench_pair&, const precision& pr) {
         if (pr.kind == real_kind::dbl) return std::string("the double scout is the start: nothing to polish in double");
         if (pr.name == "mp30") return std::string(kOnly30);
         return std::string();
       },
       [](const bench_pair& bp, const precision& pr, const reference&) {
         auto r0 = inscribed_lattice<double>(bp.p, 1.0);
         const lobe_frame<big_int> fb{r0.first.k, r0.first.j, r0.first.m};
         const double u0 = r0.first.u;
         return dispatch_real(pr, [&](auto tag) {
           using T = typename decltype(tag)::type;
           const auto p = bp.p;
           const big_int a = bp.order();
           if (bp.fits_int128_lattice()) {
             const auto p64 = bp.p64();
             const lobe_frame<int128> f{int128(std::int64_t(fb.k)), int128(std::int64_t(fb.j)), int128(std::int64_t(fb.m))};
             const int128 a128 = p64.order();
             return make_case(
                 "newton_doubling", pr, bp, [=] { return lobe_root_polish(p64, T(1), f, a128, T(u0), 53); },
                 [=](const lobe_polish_result<T>& r) {
                   using std::sqrt;
                   auto c = resonant_constants_of<T>(p64, T(1));
                   outcome o;
                   o.theta = real_text(lobe_theta(c, f, a128, r.u));
                   o.r_res = real_text(T(sqrt(r.radius_sq)));
                   o.evaluations = r.evaluations;
                   return o;
                 });
           }
           return make_case(
               "newton_doubling", pr, bp, [=] { return lobe_root_polish(p, T(1), fb, a, T(u0), 53); },
               [=](const lobe_polish_result<T>& r) {
                 using std::sqrt;
                 auto c = resonant_constants_of<T>(p, T(1));
                 outcome o;
                 o.theta = real_text(lobe_theta(c, fb, a, r.u));
                 o.r_res = real_text(T(sqrt(r.radius_sq)));
                 o.evaluations = r.evaluations;
                 return o;
               });
         });
       }});

  out.push_back({"global", "global",
                 "inscribed_global<T>: all 4 tau critical points (roots of q' and z'), each by TOMS 748 in local "
                 "coordinates at full precision; assumes nothing about where the minimum is",
                 skip_global, [](const bench_pair& bp, const precision& pr, const reference&) {
                   return dispatch_real(pr, [&](auto tag) {
                     using T = typename decltype(tag)::type;
                     const auto p64 = bp.p64();
                     return make_case(
                         "global", pr, bp, [=] { return inscribed_global<T>(p64, T(1)); },
                         [](const inscribed_result<T>& r) {
                           outcome o;
                           o.theta = real_text(r.theta_first);
                           o.r_res = real_text(r.r_res);
                           o.evaluations = r.evaluations;
                           return o;
                         });
                   });
                 }});

  out.push_back(
      {"certified", "certified",
       "certify_pair(pair, digits): MPFI enclosures of r_res and theta_first with at least `digits` digits, plus "
       "the proof of global minimality (interval Newton, basin, symmetry, cover); scored at the enclosure midpoint",
       [cfg](const bench_pair& bp, const precision& pr) {
         if (!pr.is_mp()) return std::string("certificates are MPFI enclosures with a decimal-digits target (30 to 10000)");
         if (pr.name == "mp10000" && bp.name != "(6,5)")
           return std::string("~2 s or more per call at 10000 digits (precision doubled from 64 bits, MPFI at each "
                              "level); (6,5) alone shows the scaling");
         return std::string();
       },
       [](const bench_pair& bp, const precision& pr, const reference&) {
         const auto p = bp.p;
         const unsigned digits = pr.digits;
         bench_case c;
         c.method = "certified";
         c.precision = pr.name;
         c.pair = bp.name;
         c.timed = [=] { benchmark::DoNotOptimize(certify_pair(p, digits)); };
         c.pilot = [=] {
           auto cert = certify_pair(p, digits);
           outcome o;
           scoped_digits d(digits + 30);
           auto mid = [](const std::pair<std::string, std::string>& e) {
             mpfr_real lo(e.first), hi(e.second);
             return real_text(mpfr_real((lo + hi) / 2));
           };
           if (cert.global_minimality) {
             o.r_res = mid(cert.r_res);
             o.theta = mid(cert.theta_first);
             o.r_enclosure = cert.r_res;
           } else {
             o.r_res = real_text(mpfr_real(cert.r_res.second));
             o.note = "global minimality not proved: " + cert.global_minimality_note;
           }
           return o;
         };
         return c;
       }});

  out.push_back(
      {"one_eval", "one_eval",
       "one evaluation of (q, q', z, z') at the first minimiser (resonant.hpp lobe_eval: four sines/cosines), "
       "constants precomputed: the unit of work",
       [](const bench_pair&, const precision&) { return std::string(); },
       [](const bench_pair& bp, const precision& pr, const reference&) {
         auto r0 = inscribed_lattice<double>(bp.p, 1.0);
         const lobe_frame<big_int> fb{r0.first.k, r0.first.j, r0.first.m};
         const double u0 = r0.first.u;
         return dispatch_real(pr, [&](auto tag) {
           using T = typename decltype(tag)::type;
           struct state {
             resonant_constants<T> c;
             lobe_frame_real<T> fr;
             T u;
           };
           auto st = std::make_shared<std::optional<state>>();
           const auto p = bp.p;
           const big_int a = bp.order();
           return make_case(
               "one_eval", pr, bp,
               [=] {
                 if (!*st) {
                   auto c = resonant_constants_of<T>(p, T(1));
                   auto fr = lobe_frame_real_of(c, fb, a);
                   st->emplace(state{c, fr, T(u0)});
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
       }});

  out.push_back(
      {"naive_toms748", "naive_toms748",
       "peer (c), the obvious implementation: plain boost::math::tools::toms748_solve with eps_tolerance(bits - 2) "
       "on the naive q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) (tau theta formed directly) over the fast "
       "half-period [i pi/tau, (i+1) pi/tau] holding theta_first (the paper's lobe when it carries the minimum), "
       "then r = rho0 |sin tau theta + sin sigma theta|",
       [](const bench_pair& bp, const precision& pr) {
         return pr.name == "mp30" ? std::string(kOnly30) : skip_toms748_10000(bp, pr);
       },
       [](const bench_pair& bp, const precision& pr, const reference& ref) {
         return dispatch_real(pr, [&](auto tag) {
           using T = typename decltype(tag)::type;
           const big_int tau = bp.p.tau(), sigma = bp.p.sigma(), i = ref.first_half_period;
           return make_case(
               "naive_toms748", pr, bp, [=] { return naive_toms748<T>(tau, sigma, i); },
               [](const naive_result<T>& r) {
                 outcome o;
                 o.theta = real_text(r.theta);
                 o.r_res = real_text(r.r);
                 o.evaluations = r.evaluations;
                 return o;
               });
         });
       }});
  (void)skip_fixed_only_mp;
  return out;
}

}  // namespace gyrores::bench
