// gyrores.coupling and gyrores.couplings: the coupling request of app/coupling.hpp (any coupling
// n) and the band request of app/band.hpp (its guarantees over a band of couplings) as the dict
// of `gyrores coupling [--band|--tolerance] --json`, and the horizon theorem's doubles (app/coupling.hpp) over arrays
// of couplings and horizons in one C++ loop (GIL released, the stop flag passed into every proof
// and looked at between elements). The horizon, level, band and tolerance texts are read as the
// CLI reads them ("1e100", "100pi", "1%", "N1:N2"), by the library's parsers (model/inputs.hpp).
#include <optional>
#include <utility>
#include <vector>

#include <gyrores/app/coupling.hpp>
#include <gyrores/app/coupling_input.hpp>
#include <gyrores/app/plant.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/model/coupling.hpp>
#include <gyrores/app/band.hpp>
#include <gyrores/theorem/band.hpp>

#include "common.hpp"
#include "interruptible.hpp"

namespace gyrores::python {
namespace {

horizon_time horizon_of(const std::string& text, const std::string& what) { return parse_horizon_time(text, what); }
big_rational level_of(const std::string& text, const big_rational& energy_scale = 1) {
  return parse_energy_level(text, "below", energy_scale);
}

coupling_spec spec_of(const std::string& text, bool is_n2, const std::string& what) {
  return is_n2 ? coupling_spec::from_n2(parse_rational(text, what)) : coupling_spec::from_n(parse_rational(text, what));
}

// The plant (mass, stiffness, gyro, velocity) as texts.
plant_inputs plant_of(const py::object& plant) {
  const py::tuple t = py::tuple(plant);
  if (t.size() != 4) throw usage_error("plant must be (mass, stiffness, gyro, velocity)");
  static const std::string names[4] = {"mass", "stiffness", "gyro", "velocity"};
  return parse_plant(t[0].cast<std::string>(), t[1].cast<std::string>(), t[2].cast<std::string>(), t[3].cast<std::string>(),
                     names);
}

// Python's spelling of each argument in a conflict's one-line message (app/coupling_input.hpp).
const app::coupling_names python_names{"n", "n2", "pair", "plant", "qdot0", "horizon", "horizon_s", "band", "tolerance",
                                       "certificate"};

struct coupling_and_band {
  std::optional<coupling_report> report;
  std::optional<app::band_result> band;
};

// The dict of `gyrores coupling --json`, with "band" when a band or tolerance is given; a band
// alone (no n, n2, pair or plant) gives the CLI's {"horizon", "theorem", "band"}. Every argument
// parsed here, the coupling, units, horizon and band chosen by the app layer, as the CLI does.
py::object coupling_dict(const py::object& n, const py::object& n2, const py::object& horizon_given,
                         const py::object& below, std::int64_t convergents, long long digits, const py::object& band,
                         const py::object& tolerance, long long band_digits, const std::string& qdot0, const py::object& pair,
                         const py::object& plant, const py::object& horizon_s) {
  app::coupling_given g;
  g.digits = checked_digits(digits, 1, report_digits_max);
  if (!n.is_none()) g.n = parse_rational(rational_text(n), "n");
  if (!n2.is_none()) g.n2 = parse_rational(rational_text(n2), "n2");
  if (!pair.is_none()) {
    const py::tuple t = py::tuple(pair);
    if (t.size() != 2) throw usage_error("pair must be (tau, sigma)");
    g.pair = pair_of(t[0], t[1]);
  }
  if (!plant.is_none()) g.plant = plant_of(plant);
  if (const big_rational q = parse_qdot0(qdot0, "qdot0"); q != 1) g.qdot0 = q;  // qdot0 = 1 is the default
  if (!horizon_given.is_none()) g.horizon = horizon_of(horizon_given.cast<std::string>(), "horizon");
  if (!horizon_s.is_none()) g.horizon_s = horizon_of(horizon_s.cast<std::string>(), "horizon_s");
  if (!band.is_none()) g.band = parse_band(band.cast<std::string>(), "band");
  if (!tolerance.is_none()) g.tolerance = tolerance.cast<std::string>();
  const app::coupling_selection s = app::select_coupling(g, python_names);
  if (convergents < 0 || convergents > std::int64_t(app::coupling_convergents_max))
    throw usage_error("convergents must be in [0, " + std::to_string(app::coupling_convergents_max) + "]");
  std::optional<big_rational> level;
  if (!below.is_none()) level = level_of(below.cast<std::string>(), s.energy_scale());
  app::coupling_request request;
  if (s.spec) {
    request = app::coupling_request_of(s);
    request.options.digits = g.digits;
    request.options.convergents = std::size_t(convergents);
    request.options.below = level;
  }
  app::band_request bq;
  if (s.band) {
    bq = app::band_request_of(s);
    bq.below = level;
    // 0: the coupling's own digits, as the CLI's --band-digits (17 when Python wants floats).
    bq.digits = band_digits > 0 ? checked_digits(band_digits, 1, report_digits_max) : g.digits;
  }
  // The stop flag goes into the library: on Ctrl-C the proofs end at their next safe point (a
  // band's bracket so far is then not returned: KeyboardInterrupt).
  const bool analyse = s.spec.has_value(), prove_band = s.band.has_value();
  const coupling_and_band r = run_interruptible<coupling_and_band>([analyse, prove_band, request, bq](stop_token stop) mutable {
    coupling_and_band out;
    request.options.stop = bq.stop = stop;
    if (analyse) out.report = app::run_coupling(request).report;
    if (prove_band) {
      out.band = app::run_band(bq);
      if (out.band->interrupted) throw interrupted();
    }
    return out;
  });
  // The horizon as the CLI's JSON states it: as given, or the model's horizon of horizon_s.
  const std::string horizon =
      s.horizon_s ? s.horizon.str() : horizon_given.is_none() ? std::string("100") : horizon_given.cast<std::string>();
  if (!analyse)
    return to_python(json{{"horizon", horizon}, {"theorem", band_theorem_id}, {"band", app::band_result_json(bq, *r.band)}});
  json input = !n.is_none() ? json{{"n", rational_text(n)}} : !n2.is_none() ? json{{"n2", rational_text(n2)}} : json::object();
  if (!pair.is_none()) {  // as the CLI echoes --pair TAU SIGMA
    const py::tuple t = py::tuple(pair);
    input["pair"] = json::array({py::str(t[0]).cast<std::string>(), py::str(t[1]).cast<std::string>()});
  }
  if (!plant.is_none()) {
    const py::tuple t = py::tuple(plant);
    input = json{{"mass", t[0].cast<std::string>()}, {"stiffness", t[1].cast<std::string>()},
                 {"gyro", t[2].cast<std::string>()}, {"velocity", t[3].cast<std::string>()}};
  }
  json j = coupling_report_json(input, horizon, g.digits, *r.report);
  app::add_units_json(j, s, horizon_s.is_none() ? std::nullopt : std::optional<std::string>(horizon_s.cast<std::string>()),
                      below.is_none() ? std::nullopt : std::optional<std::string>(below.cast<std::string>()));
  if (r.band) j["band"] = app::band_result_json(bq, *r.band);
  return to_python(j);
}

// The plant's own numbers (app/plant.hpp) as `gyrores coupling --json` gives them.
py::object plant_dict(const py::object& plant, long long digits) {
  const plant_inputs p = plant_of(plant);
  return to_python(app::plant_json(p, app::plant_numbers_of(p, checked_digits(digits, 1, report_digits_max))));
}

struct coupling_columns {
  std::vector<double> h_min, t_min, t_below;
  std::vector<bool> at_end, resonant;
};

// couplings[i] and horizons[i] as exact texts (Python broadcast them); the columns of the table.
py::tuple couplings_columns(const py::list& couplings, bool is_n2, const py::list& horizons, const py::object& below,
                            const py::object& progress) {
  if (couplings.size() != horizons.size()) throw usage_error("couplings and horizons differ in length");
  const std::string what = is_n2 ? "n2" : "n";
  std::vector<coupling_spec> specs;
  std::vector<horizon_time> times;
  for (std::size_t i = 0; i < couplings.size(); ++i) {  // every input checked before any work
    // This loop holds the GIL (about 1 us per element): Ctrl-C is looked at as it goes.
    if (i % 4096 == 0 && PyErr_CheckSignals() != 0) throw py::error_already_set();
    specs.push_back(spec_of(couplings[i].cast<std::string>(), is_n2, what + "[" + std::to_string(i) + "]"));
    times.push_back(horizon_of(horizons[i].cast<std::string>(), "horizon[" + std::to_string(i) + "]"));
  }
  std::optional<big_rational> level;
  if (!below.is_none()) level = level_of(below.cast<std::string>());
  // The progress callback is called from the worker thread with the GIL taken, and an exception
  // it raises stops the loop (rethrown here). It is held as a borrowed pointer (no reference
  // counting without the GIL): on_stop::wait keeps this call, and so the caller's reference,
  // alive until the worker ends, which is soon after Ctrl-C (the flag is looked at between
  // elements and inside every proof).
  PyObject* const callback = progress.is_none() ? nullptr : progress.ptr();
  // The inputs move into the work (no second copy to build, or to free before KeyboardInterrupt).
  auto work = [specs = std::move(specs), times = std::move(times), level, callback](stop_token stop) {
    coupling_columns c;
    const std::size_t total = specs.size();
    for (std::size_t i = 0; i < total; ++i) {
      stop.throw_if_requested();
      const app::coupling_doubles r = app::run_coupling_doubles(specs[i], times[i], level, stop);
      c.h_min.push_back(r.h_min);
      c.t_min.push_back(r.t_min);
      c.t_below.push_back(r.t_below);
      c.at_end.push_back(r.at_end);
      c.resonant.push_back(r.resonant);
      if (callback != nullptr && ((i + 1) % 64 == 0 || i + 1 == total)) {
        py::gil_scoped_acquire gil;
        py::handle fn(callback);
        fn(i + 1, total);
      }
    }
    return c;
  };
  const coupling_columns cols = run_interruptible<coupling_columns>(std::move(work), on_stop::wait);
  py::list h, t, tb, end, res;
  for (std::size_t i = 0; i < cols.h_min.size(); ++i) {
    h.append(cols.h_min[i]);
    t.append(cols.t_min[i]);
    tb.append(cols.t_below[i]);
    end.append(bool(cols.at_end[i]));
    res.append(bool(cols.resonant[i]));
  }
  return py::make_tuple(h, t, end, tb, res);
}

}  // namespace

void bind_coupling(py::module_& m) {
  m.def("_coupling", &coupling_dict, py::arg("n"), py::arg("n2"), py::arg("horizon"), py::arg("below"),
        py::arg("convergents"), py::arg("digits"), py::arg("band") = py::none(), py::arg("tolerance") = py::none(),
        py::arg("band_digits") = 0, py::arg("qdot0") = "1", py::arg("pair") = py::none(), py::arg("plant") = py::none(),
        py::arg("horizon_s") = py::none(),
        "The dict of `gyrores coupling --json` (with --band N1:N2 or --tolerance P%). Use gyrores.coupling.");
  m.def("_plant", &plant_dict, py::arg("plant"), py::arg("digits"),
        "The \"plant\" object of `gyrores coupling --json` with a plant. Use gyrores.plant.");
  m.def("_couplings", &couplings_columns, py::arg("couplings"), py::arg("is_n2"), py::arg("horizons"),
        py::arg("below"), py::arg("progress"),
        "Columns (h_min_horizon, t_min_horizon, min_at_horizon_end, t_below, resonant) of every "
        "(coupling, horizon), correctly rounded doubles. Use gyrores.couplings.");
}

}  // namespace gyrores::python
