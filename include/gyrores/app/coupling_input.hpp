// What `gyrores coupling` and gyrores.coupling were given, chosen once for both front ends: which
// coupling (N, its square n^2, a resonant pair's, or a physical plant's, docs/units.md), in which
// units (the impulse qdot0, or the plant's joules and seconds), over which horizon (model time, or
// seconds with a plant), and which band (N1:N2, or a tolerance around the coupling). The front ends
// parse each argument (model/inputs.hpp parsers, naming it), call select_coupling, and print; a
// conflict between arguments is one usage_error line spelled with the caller's names.
#pragma once
#include <optional>
#include <string>
#include <utility>

#include <gyrores/app/band.hpp>
#include <gyrores/app/coupling.hpp>
#include <gyrores/app/plant.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores::app {

// Each argument as the caller spells it in a message: the CLI's "N", "--n2 P/Q", "--mass, ...";
// Python's "n", "n2", "plant".
struct coupling_names {
  std::string n, n2, pair, plant, qdot0, horizon, horizon_s, band, tolerance, certificate;
};

// The arguments given, parsed; none (or empty) when not given.
struct coupling_given {
  std::optional<big_rational> n, n2;
  std::optional<resonant_pair<big_int>> pair;
  std::optional<plant_inputs> plant;
  std::optional<big_rational> qdot0;
  std::optional<horizon_time> horizon;    // model time t omega0 (default 100)
  std::optional<horizon_time> horizon_s;  // seconds (a plant's)
  std::optional<std::pair<big_rational, big_rational>> band;  // N1:N2
  std::string tolerance;                  // "P%" as given (read around the coupling by model/inputs.hpp)
  bool certificate = false;
  unsigned digits = 12;                   // of the plant's numbers and of a horizon in seconds
};

struct coupling_selection {
  std::optional<coupling_spec> spec;  // none: a band alone
  big_rational qdot0 = 1;
  std::optional<plant_inputs> plant;
  std::optional<plant_numbers> numbers;  // the plant's own numbers at `digits`
  std::optional<plant_horizon> horizon_s;  // the horizon in seconds as the model's
  horizon_time horizon = horizon_time(big_rational(100));  // what the proofs take (model time)
  std::optional<std::pair<big_rational, big_rational>> band;
  // A tolerance around an irrational n: the band's ends enclose n (1 -+ P%) outward; `coupling`
  // names n ("sqrt(1/12)") for the text that says so.
  bool band_outward = false;
  std::string coupling;
  // H_q(0)'s factor over the unit impulse's: an absolute level E is the unit level E / this
  // (parse_energy_level); qdot0^2, or a plant's m V^2 (J).
  big_rational energy_scale() const;
};

// usage_error (one line, the caller's names) for: a coupling given twice, or none without a band;
// a plant with N, n^2, a pair, qdot0 or --band; a horizon in seconds without a plant, or with a
// horizon in model time; a band with a tolerance; a certificate with qdot0 or a plant; a horizon
// in seconds whose model horizon is outside the limits; a tolerance as model/inputs.hpp reads it.
coupling_selection select_coupling(const coupling_given& given, const coupling_names& names);

// The requests of a selection, without digits, level, convergents, certificate or stop (the
// front ends' own): the coupling's (needs spec) and the band's (needs band).
coupling_request coupling_request_of(const coupling_selection& s);
band_request band_request_of(const coupling_selection& s);

// The units in the JSON of `gyrores coupling --json` (docs/formats.md): "qdot0" (when not 1);
// with a plant "plant", "horizon_s" (as given, else null) and "horizon_exact"; and with either,
// below.level_given, the level as given (below.level is the unit impulse's).
void add_units_json(json& j, const coupling_selection& s, const std::optional<std::string>& horizon_s_given,
                    const std::optional<std::string>& below_given);

}  // namespace gyrores::app
