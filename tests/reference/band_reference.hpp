// An independent reference for the band tests (tests/test_band.cpp): the minimum of H_q over
// [0, T] at one coupling n by the plain loop over every lobe (the horizon theorem's statement,
// proofs/horizon-theorem.md item 2, evaluated naively in double: every lobe's offset
// ||k x - 1/2|| from k x directly, the smallest over the admissible lobes, its lobe value by
// bisection on H, the end point R(T) from the impulse response), and the first time below a
// level by a scan of R. None of the library's numerics (no rotation recursion, no Stern-Brocot
// search, no enclosure): accurate to about 1e-9 relative for T up to 1e5, which the tests allow.
#pragma once

namespace gyrores::reference {

// min over t in [0, T] of H_q (qdot0 = 1) at the coupling n > 0.
double band_minimum(double n, double T);

// The first t >= 0 with H_q(t) <= E at the coupling n (qdot0 = 1), searched up to t_max by a scan
// of step `step` refined by bisection; a negative value when not found by t_max.
double band_first_below(double n, double E, double t_max, double step = 1e-3);

}  // namespace gyrores::reference
