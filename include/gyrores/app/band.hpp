// `gyrores coupling --band N1:N2` / `--tolerance P%` and gyrores.coupling(band=..., tolerance=...):
// the designer's guarantees over a band of couplings (theorem/band.hpp, proofs/band-theorem.md),
// each with the coupling where it is attained and that coupling's own minimum (its lobe and time,
// the horizon theorem), and, with a level E, the band-wide first time below E (never the nominal
// coupling's alone).
#pragma once
#include <functional>
#include <optional>

#include <gyrores/certify/band_certificate.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/theorem/band.hpp>
#include <gyrores/report/horizon_report.hpp>

namespace gyrores::app {

struct band_request {
  big_rational n1, n2;            // 0 < n1 < n2
  horizon_time horizon;           // T >= 0
  std::optional<big_rational> below;  // a level E: the band-wide first time H_q <= E
  unsigned digits = 6;            // of every real, [1, report_digits_max]
  big_rational qdot0 = 1;         // the impulse: the guarantees times qdot0^2 (below: a unit-impulse level); no certificate
  // A physical plant (app/plant.hpp, docs/units.md; qdot0 = 1, no certificate): the guarantees
  // in joules (times m V^2, exactly), the first time below and the attained couplings' times in
  // seconds (times sqrt(m/k), a proved enclosure, the first time's proof refined until its
  // rounding in seconds is decided); n1, n2, the horizon and below stay model units.
  std::optional<plant_inputs> plant;
  std::size_t max_intervals = 100000;
  bool certificate = false;       // also the band certificate, from these very proofs (record_cover)
  stop_token stop;
  std::function<void(const band_progress&)> progress;
};

// Where an extreme is attained: the coupling, its resonant pair when x is rational, and its own
// minimum over [0, T] (lobe, time) at the request's digits.
struct band_attained {
  band_coupling coupling;
  std::optional<resonant_pair<big_int>> pair;
  std::optional<horizon_minimum_report> minimum;      // the guarantees' couplings
  std::optional<first_below_report> first_below;      // the first time below's coupling
};

struct band_result {
  band_extreme absorption;
  std::optional<band_extreme> containment;  // none when interrupted before it started
  std::optional<band_attained> absorption_at, containment_at;  // none when interrupted
  std::optional<band_first_below> below;
  std::optional<band_attained> below_at;
  bool interrupted = false;  // some proof stopped by the stop token: its bracket so far is reported
  std::optional<band_certificate> certificate;  // with request.certificate, when not interrupted
};

// The "band" object of the JSON outputs (docs/formats.md, "Band guarantees"): the request's band,
// horizon and digits, the two guarantees and the first time below, each with where it is attained.
json band_result_json(const band_request& request, const band_result& result);

// usage_error for a band that is not 0 < n1 < n2, a negative horizon or level, digits outside
// [1, report_digits_max], and (with request.certificate) a horizon that is not a rational > 0,
// before any work. A proof that stops on its cap is returned not settled, with the reason.
band_result run_band(const band_request& request);

}  // namespace gyrores::app
