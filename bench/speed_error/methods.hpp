// The methods and peers of the harness (one method_def each; see core.hpp).
#pragma once
#include <string>
#include <vector>

#include "core.hpp"

namespace gyrores::bench {

// gyrores itself: the theorem's path (theorem_double, theorem_proved, theorem_report,
// certificate), the references from before the theorem (theta_asy, r_res_asy, ref_lattice,
// ref_toms748_local, ref_newton_polish, ref_global), the unit of work one_eval; and the obvious
// peer, plain Boost TOMS 748 on the naive formulation.
std::vector<method_def> library_methods(const run_config& cfg);

// Boost.Odeint time-domain simulation (dopri5 at several tolerances, a symplectic RKN at
// several step sizes).
std::vector<method_def> odeint_methods(const run_config& cfg);

// The theorem-aware peers, written from proofs/lattice-theorem.md without gyrores' numerics
// (peer_theorem.cpp): peer_newton in double, and with Arb peer_arb_ball and peer_arb_calc.
std::vector<method_def> theorem_peer_methods(const run_config& cfg);

// Arb/FLINT: arb_calc_refine_root_newton from the double start, and one Arb evaluation.
// Empty when the harness was built without Arb (GYRORES_BENCH_HAVE_ARB).
std::vector<method_def> arb_methods(const run_config& cfg);
bool arb_available();
std::string arb_library_version();

}  // namespace gyrores::bench
