// The application layer (docs/architecture.md): `gyrores coupling N` and gyrores.coupling, the
// analysis of one coupling (report/coupling_report.hpp), and with a certificate asked, the
// certificate of the horizon minimum and the first time below a level written from the very
// proofs the report rounded (certify/horizon_certificate.hpp): one computation. Also one element
// of gyrores.couplings: the same proofs, refined until every double is decided (a band of
// couplings: app/band.hpp).
#pragma once
#include <cstddef>
#include <optional>

#include <gyrores/certify/horizon_certificate.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/report/coupling_report.hpp>

namespace gyrores::app {

// The most digits `gyrores coupling` prints (the library's reports go to report_digits_max; a
// coupling's report also proves its convergents' pairs, so the front ends stop at 1000), and
// the most convergents of W1/W2 it lists.
inline constexpr unsigned coupling_digits_max = 1000;
inline constexpr std::size_t coupling_convergents_max = 60;

struct coupling_request {
  coupling_spec spec;
  coupling_report_options options;  // digits, horizon, below, convergents (<= coupling_convergents_max), stop
  bool certificate = false;         // also the certificate (T a rational > 0; qdot0 = 1, no plant)
  // The impulse q'(0) = qdot0 (model/inputs.hpp parse_qdot0): the energies times qdot0^2, the
  // radii times qdot0, the times unchanged; options.below is a unit-impulse level
  // (parse_energy_level with the energy scale qdot0^2).
  big_rational qdot0 = 1;
  // A physical plant (app/plant.hpp): spec must be its n^2; the horizon values and pi/|n| in
  // joules and seconds (options.horizon and options.below in model units: plant_horizon_of and
  // parse_energy_level with the energy scale m V^2); the pair's values stay in model units.
  std::optional<plant_inputs> plant;
};

struct coupling_result {
  coupling_report report;
  std::optional<horizon_certificate> certificate;  // when asked (with `below` when a level is given)
};

// usage_error for a request out of range, and for a certificate of a horizon that is not a
// positive rational (before any work); otherwise as analyse_coupling and horizon_certificate_of.
coupling_result run_coupling(const coupling_request& request);

// One element of gyrores.couplings: min H_q over [0, T], its first time and the first time
// H_q <= E (NaN when never), each the double nearest the exact value (the proofs refined until
// it is decided), and whether the minimum is at t = T and the coupling resonant.
struct coupling_doubles {
  double h_min = 0, t_min = 0, t_below = 0;
  bool at_end = false, resonant = false;
};
coupling_doubles run_coupling_doubles(const coupling_spec& spec, const horizon_time& horizon,
                                      const std::optional<big_rational>& level, stop_token stop = {});

}  // namespace gyrores::app
