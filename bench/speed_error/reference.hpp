// The reference every error is measured against, and the error metric.
//
// Reference: src/testing/high_precision_reference.hpp (hp_reference), an independent method: the
// naive resonant forms (sin(tau theta) formed directly) made safe by brute precision
// (bits + 2 log2(a) + 96 guard bits), bisection then Newton with precision doubling; it uses
// none of the library's numerical code (no lobe frames, local coordinates, TOMS 748 wrapper or
// lattice). Orders <= 1e5: every one of the 4 tau critical points is examined (global mode).
// Larger orders: local mode around a guess (theta_first of the reference lattice from before
// the theorem, pre_theorem.hpp, at modest precision, used only to pick fast half-periods; +-4
// of them around the guess and its symmetry images are solved independently). The paper's lobe
// root theta_c (x < 1/2) is found the same way (hp_lobe_root): the lobe |alpha - k pi| < pi/2,
// k = round(a/(2b)) (the smaller on a tie), is covered by the fast half-periods
// [i pi/tau, (i+1) pi/tau] with i in [floor((2k-1) tau/a), floor((2k+1) tau/a)]; each holds one
// root of q', solved independently, and the one inside the lobe is theta_c.
//
// Error metric (defined once): correct digits = -log10(|x - ref| / |ref|), clipped to
// [0, reference digits]; x and ref are compared at the reference's precision. A method that
// computes several quantities is credited with the smallest of their digits.
#pragma once
#include <string>
#include <vector>

#include "core.hpp"

namespace gyrores::bench {

struct reference {
  unsigned digits = 0;                 // decimal digits of accuracy
  std::string r_res, theta_first;      // amplitude v = 1
  std::vector<std::string> minimisers;  // every global minimiser in [0, 2 pi), ascending
  std::string theta_c;                 // the paper's lobe root (x < 1/2), else empty
  big_int first_half_period;           // i with theta_first in [i pi/tau, (i+1) pi/tau]
  bool global = false;                 // hp global mode (all critical points) or local mode
  double seconds = 0;                  // time to compute it
};

reference compute_reference(const bench_pair& bp, unsigned digits);

// Correct digits of `value` against `ref` (both decimal text), at `ref_digits` digits.
double correct_digits(const std::string& value, const std::string& ref, unsigned ref_digits);

// Correct digits against the nearest of several references.
double correct_digits_nearest(const std::string& value, const std::vector<std::string>& refs, unsigned ref_digits);

// Fills m.digits_theta / m.digits_r from an outcome; notes whether a proved enclosure
// contains the reference.
void score(measurement& m, const outcome& o, const reference& ref);

}  // namespace gyrores::bench
