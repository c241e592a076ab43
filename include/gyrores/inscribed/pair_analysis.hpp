// Everything gyrores reports about one resonant pair, computed in one real type T.
//
// analyse_pair runs the chosen solver (lattice by default; the global search on request),
// cross-checks a lattice result against the global search up to a given order, and adds the
// model quantities (n, W1, W2, rho0) and the paper's first-hit proxy T_min ~ pi/|n| (a
// heuristic, paper §IV; the exact first-hit time is inscribed.t_first), and the paper's
// asymptotics (asymptotic.hpp).
#pragma once
#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/inscribed/cross_check.hpp>
#include <gyrores/inscribed/global_search.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

enum class solver_choice { lattice, global_search };

struct analysis_options {
  solver_choice solver = solver_choice::lattice;
  // Cross-check the lattice method against the global search for orders up to this (0: never).
  std::int64_t cross_check_max_order = cross_check_default_max_order;
  global_search_options global;
};

template <class T> struct pair_analysis {
  T qdot0, n, omega1, omega2, rho0;
  T beat_ratio;   // (tau + sigma)/(tau - sigma)
  T t_min_paper;  // pi/|n|: the paper's proxy for the first-hit time (heuristic)
  inscribed_result<T> inscribed;
  bool cross_checked = false;
  asymptotic_report<T> asymptotic;  // the paper's theta_asy per lobe, and the observed r_res_asy
  // The asymptotics are a diagnostic: when they cannot be computed in T (compute_error), this
  // says why, `asymptotic` is left empty (not applicable) and the answer stands.
  std::string asymptotic_failure;
};

template <class T, pair_integer I>
pair_analysis<T> analyse_pair(const resonant_pair<I>& p, const T& v, const analysis_options& opt = {}) {
  check_amplitude(v);
  auto c = resonant_constants_of<T>(p, v);
  pair_analysis<T> r;
  r.qdot0 = v;
  r.n = c.n;
  r.omega1 = c.omega1;
  r.omega2 = c.omega2;
  r.rho0 = c.rho0;
  r.beat_ratio = real_from_int<T>(p.order()) / real_from_int<T>(wide_int<I>(p.delta()));
  r.t_min_paper = c.pi / c.n;
  if (opt.solver == solver_choice::global_search) {
    r.inscribed = inscribed_global<T>(p, v, opt.global);
  } else {
    r.inscribed = inscribed_lattice<T>(p, v);
    if (!p.degenerate() && to_big(p.order()) <= big_int(opt.cross_check_max_order)) {
      cross_check_lattice(p, v, r.inscribed);
      r.cross_checked = true;
    }
  }
  try {
    r.asymptotic = paper_asymptotics<T>(p, v);
  } catch (const compute_error& e) {
    r.asymptotic = {};
    r.asymptotic_failure = e.what();
  }
  return r;
}

// Compiled once in src/lib/inscribed/ for double, long double, float128 and mpfr_real.
#define GYRORES_PAIR_ANALYSIS_INSTANCES(PREFIX, T) \
  PREFIX template pair_analysis<T> analyse_pair<T, std::int64_t>(const resonant_pair<std::int64_t>&, const T&, const analysis_options&); \
  PREFIX template pair_analysis<T> analyse_pair<T, big_int>(const resonant_pair<big_int>&, const T&, const analysis_options&);
GYRORES_FOR_COMPILED_REALS(GYRORES_PAIR_ANALYSIS_INSTANCES, extern)

}  // namespace gyrores
