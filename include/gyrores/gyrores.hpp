// Umbrella header: the whole mathematical library, layer by layer in the order the data flows
// (docs/architecture.md). File and JSON I/O is the separate io/ part: include <gyrores/io/...>.
#pragma once
// core: errors, integers, reals, decimal text, rationals, roots, exact quadratic numbers
#include <gyrores/core/error.hpp>            // usage_error (bad input), compute_error (could not compute honestly)
#include <gyrores/core/stop.hpp>             // stop_token, interrupted: Ctrl-C and the Python module stop long work
#include <gyrores/core/integer.hpp>          // int64/int128/big_int helpers: gcd, v2, inverse mod
#include <gyrores/core/real.hpp>             // real types (double ... mpfr_real, mpfi_real), conversions
#include <gyrores/core/decimal.hpp>          // exact decimal output, Ziv rounding test, decimal input
#include <gyrores/core/rational.hpp>         // exact rationals: parsing, printing
#include <gyrores/core/roots.hpp>            // the TOMS 748 wrapper, safeguarded Newton
#include <gyrores/core/quadratic.hpp>        // exact numbers of Q(sqrt d): the rotation number of any coupling
// model: pairs, enumeration, the model for any n, resonant frames
#include <gyrores/model/pair.hpp>            // resonant_pair<I>: number theory of (tau, sigma)
#include <gyrores/model/enumerate.hpp>       // coprime_pairs: lazy enumeration by order
#include <gyrores/model/model.hpp>           // the model for any real n: frequencies, impulse response, envelope
#include <gyrores/model/resonant.hpp>        // resonant parametrisation and exact local (lobe-frame) coordinates
#include <gyrores/model/coupling.hpp>        // any coupling n exactly: resonance test, convergents, x = sqrt(D)/(P + 4Q)
#include <gyrores/model/inputs.hpp>          // horizons, levels and bands as the user gives them, parsed once
#include <gyrores/model/rotation.hpp>        // the rotation by x, exactly: min ||k x - 1/2|| and first hits in O(log K)
// theorem: the lattice theorem at the centre (lobes, the roots, the minimum) and the horizon theorem
#include <gyrores/theorem/lobes.hpp>          // the minimisers' lobes and the paper's fast node, by integers
#include <gyrores/theorem/root.hpp>           // u* and the paper's root: points in double, proved enclosures
#include <gyrores/theorem/minimum.hpp>        // r_res, minimisers, theta_first, t_first
#include <gyrores/theorem/horizon.hpp>        // any coupling: min of H_q over [0, T], first time below a level
#include <gyrores/theorem/band.hpp>           // a band of couplings: worst and best minimum over [0, T], proved
// certificates
#include <gyrores/certify/theorem_certificate.hpp> // certificates from the lattice theorem ("gyrores-certificate/2")
#include <gyrores/certify/horizon_certificate.hpp> // certificates of any coupling's horizon minimum ("gyrores-coupling-certificate/1")
// reports: where proved enclosures become digits
#include <gyrores/report/pair_report.hpp>        // everything about one pair, every real proved and rounded
#include <gyrores/report/horizon_report.hpp>     // the horizon theorem's minimum and first time below, rounded
#include <gyrores/report/coupling_report.hpp>    // the coupling analysis, every number proved
// design, figures data, sweeps
#include <gyrores/design/design.hpp>         // design problems (absorb/contain) and the Pareto front
#include <gyrores/design/tolerance.hpp>      // design with a tolerance band on the coupling, proved over a horizon
#include <gyrores/design/figures.hpp>        // data behind the figures (trajectory, envelope, circles, energies)
#include <gyrores/sweep/sweep.hpp>           // sweeps over all pairs up to an order: checks, mergeable summary
