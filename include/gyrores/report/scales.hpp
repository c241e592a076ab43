// The units a report prints its energies, radii and times in. The theorems work at the unit
// impulse qdot0 = 1 in the model's time (t omega0); the equations are linear, so an impulse qdot0
// multiplies H_q by qdot0^2 and the radius sqrt(2 H_q) by qdot0, and leaves the times alone; a
// physical plant (docs/units.md) multiplies the energies by m V^2 (joules) and the times by
// sqrt(m/k) (seconds). Every factor is a rational or the square root of one, so a scaled value is
// the proved enclosure times an exact rational, or times a proved enclosure of that square root:
// the report rounds the scaled enclosure inside its precision loop (report/horizon_report.hpp),
// never a rescaled decimal.
//
// An energy as a share of the initial energy H_q(0) = qdot0^2/2, in percent, is likewise the
// exact rational multiple 200/qdot0^2 of the energy: its text is the correct rounding of the
// energy's enclosure times that rational (core/enclosure.hpp), never a rescaled decimal.
#pragma once
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/rational.hpp>

namespace gyrores {

struct report_scales {
  big_rational energy = 1;   // H_q times this, exactly (qdot0^2; a plant's m V^2, in J)
  big_rational radius2 = 1;  // the radius times sqrt(radius2) (qdot0^2; a plant's V^2 m/k, in m)
  big_rational time2 = 1;    // every time times sqrt(time2) (a plant's m/k: seconds)
  bool unit() const { return energy == 1 && radius2 == 1 && time2 == 1; }
  static report_scales of_qdot0(const big_rational& qdot0) { return {qdot0 * qdot0, qdot0 * qdot0, 1}; }
};

// e times k > 0: exact when e is, else each end multiplied with outward rounding.
enclosure scaled(const enclosure& e, const big_rational& k);

// e times sqrt(k2) (k2 > 0), proved: exact when e is exact and k2 a rational square; else each end
// rounded outward, at 64 bits more than e's ends, or for an exact e at `bits` (+ 64): an exact
// value is rounded from its rational, so its product gets as narrow as the caller's digits need.
enclosure scaled_sqrt(const enclosure& e, const big_rational& k2, mpfr_prec_t bits);

// Significant digits of a share as the text outputs print it ("0.2575%").
inline constexpr unsigned share_digits = 4;

// 100 / H_q(0) = 200/qdot0^2 (qdot0 > 0).
big_rational share_factor(const big_rational& qdot0 = 1);

}  // namespace gyrores
