// Umbrella header: the whole library, in the order the data flows.
#pragma once
#include "error.hpp"          // usage_error (bad input), compute_error (could not compute honestly)
#include "integer.hpp"        // int64/int128/big_int helpers: gcd, v2, inverse mod
#include "pair.hpp"           // resonant_pair<I>: number theory of (tau, sigma)
#include "enumerate.hpp"      // coprime_pairs: lazy enumeration by order
#include "real.hpp"           // real types (double ... mpfr_real, mpfi_real), conversions
#include "model.hpp"          // the model for any real n: frequencies, impulse response, energies, envelope
#include "resonant.hpp"       // resonant parametrisation and exact local (lobe-frame) coordinates
#include "roots.hpp"          // the TOMS 748 wrapper
#include "result.hpp"         // inscribed_result<T>
#include "degenerate.hpp"     // delta = 2 mod 4: r_res = 0 by integer arithmetic
#include "global_search.hpp"  // reference method: all critical points
#include "lattice.hpp"        // O(log tau) method for any pair
#include "cross_check.hpp"      // lattice vs global search
#include "decimal.hpp"          // exact decimal output, Ziv rounding test
#include "asymptotic.hpp"       // the paper's theta_asy, error bound, r_res_asy
#include "pair_analysis.hpp"    // everything reported about one pair
#include "certificate.hpp"      // interval certificates and their checker
#include "coupling.hpp"         // any n: exact resonance test, min of H_q over a horizon, convergents
#include "design.hpp"           // design problems (absorb/contain) and the Pareto front
#include "figures.hpp"          // data behind the figures (trajectory, envelope, circles, energies)
#include "sweep.hpp"            // sweeps over all pairs up to an order: checks, mergeable summary
