// A physical plant in the model's terms (docs/units.md): `gyrores coupling --mass M --stiffness K
// --gyro G --velocity V` and gyrores.plant. Two equal-frequency modes, m q'' + g z' + k q = 0,
// m z'' - g q' + k z = 0, struck so that q'(0) = V, are the model q'' + n z' + q = 0 (time
// t omega0) with
//   omega0 = sqrt(k/m),  n = g / sqrt(m k) (n^2 = g^2/(m k), exact),  t_s = t sqrt(m/k),
//   the energy kept in q (m q'^2 + k q^2)/2 = m V^2 H_q(unit impulse), in joules (exact factor),
//   the amplitude sqrt(q^2 + (q'/omega0)^2) = V sqrt(m/k) r(unit impulse), in metres.
// Every number printed is the correct rounding of a proved enclosure: the irrational scales
// (sqrt(m/k)) are enclosed by MPFI and multiply the proved enclosures inside the report's
// precision loop (report/scales.hpp).
#pragma once
#include <optional>
#include <string>

#include <gyrores/io/json.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/report/scales.hpp>

namespace gyrores::app {

// The report's units for a plant: energies times m V^2 (J), radii times V sqrt(m/k) (m), times
// times sqrt(m/k) (s).
report_scales plant_scales(const plant_inputs& p);

// The plant's own numbers, each rounded to `digits` significant digits (correct roundings of
// proved enclosures; exact values rounded once).
struct plant_numbers {
  std::string omega0;     // sqrt(k/m), rad/s
  std::string n;          // g / sqrt(m k)
  big_rational n2;        // exact
  std::string time_scale;  // 1/omega0 = sqrt(m/k), s
  big_rational energy_scale;  // m V^2, J: H_q(unit impulse) times this is the energy in q
  big_rational h_q0;      // H_q(0) = m V^2 / 2, J
};
plant_numbers plant_numbers_of(const plant_inputs& p, unsigned digits);

// A horizon in seconds as the model's horizon T = T_s sqrt(k/m): exact when k/m is the square of
// a rational; else the rational upper end of an enclosure of T with `digits` + 20 significant
// digits (`exact` false; `lower` its lower end), over which the minimum is then proved.
struct plant_horizon {
  horizon_time model;  // what the proofs take
  big_rational lower;  // the lower end (= model.value when exact)
  bool exact = true;
};
plant_horizon plant_horizon_of(const plant_inputs& p, const horizon_time& seconds, unsigned digits);

// The "plant" object of `gyrores coupling --json` (docs/formats.md): the inputs as exact
// rationals, omega0, n, n2, time_scale, energy_scale, h_q0 and the units of the report.
json plant_json(const plant_inputs& p, const plant_numbers& numbers);

}  // namespace gyrores::app
