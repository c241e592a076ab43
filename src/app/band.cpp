// include/gyrores/app/band.hpp
#include <gyrores/app/band.hpp>

#include <algorithm>

#include <gyrores/app/plant.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/model/coupling.hpp>

#include "band_checker.hpp"

namespace gyrores::app {

namespace {

band_attained attained(const band_coupling& c) {
  return {c, coupling_resonant_pair(c.spec), std::nullopt, std::nullopt};
}

inline constexpr const char* band_format = "gyrores-band/2";

json rounded_or_null(const enclosure& e, unsigned digits, bool settled) {
  if (!settled) return nullptr;
  const auto v = e.rounded(digits);
  return v ? json(*v) : json(nullptr);
}

json outward_json(const enclosure& e, unsigned digits) {
  const auto [lo, hi] = e.outward(digits + 3);
  return json::array({lo, hi});
}

// Where an extreme is attained: {"n2", "x", "pair"} of its coupling, with its minimum's place
// {"h_min", "lobe", "at_horizon_end", "t_min"} or its first time below.
json attained_json(const band_attained& a) {
  json j{{"n2", rational_str(a.coupling.spec.n2)}, {"x", a.coupling.x.str()}, {"pair", a.pair ? pair_json(*a.pair) : json(nullptr)}};
  if (a.minimum) {
    const horizon_minimum_report& r = *a.minimum;
    j.update(json{{"h_min", r.h_min.value},
                  {"lobe", r.lobe ? json(json_integer(r.lobe->k)) : json(nullptr)},
                  {"at_horizon_end", r.proof.at_horizon_end},
                  {"t_min", r.t_min.value}});
  }
  if (a.first_below) j["t_below"] = a.first_below->never ? json(nullptr) : json(a.first_below->t_below.value);
  return j;
}

json attained_json(const std::optional<band_attained>& a) { return a ? attained_json(*a) : json(nullptr); }

// One guarantee; `at` is where it is attained.
json extreme_json(const band_extreme& e, unsigned digits, const json& at) {
  return json{{"h_min", rounded_or_null(e.value, digits, e.settled)},
              {"enclosure", outward_json(e.value, digits)},
              {"settled", e.settled},
              {"interrupted", e.interrupted},
              {"reason", e.unsettled_reason.empty() ? json(nullptr) : json(e.unsettled_reason)},
              {"at", at},
              {"intervals", e.intervals},
              {"couplings", e.couplings}};
}

json first_below_json(const band_first_below& b, unsigned digits, const json& at) {
  return json{{"level", rational_str(b.level)},
              {"never", b.never},
              {"reason", b.reason},
              {"t_below", b.never ? json(nullptr) : rounded_or_null(b.time, digits, b.settled)},
              {"enclosure", b.never ? json(nullptr) : outward_json(b.time, digits)},
              {"settled", b.settled},
              {"interrupted", b.interrupted},
              {"at", at},
              {"intervals", b.intervals},
              {"couplings", b.couplings}};
}

// The band-wide first time below, in the units sqrt(time2) (a plant's seconds; 1: model time).
// The proof settles the model time's rounding; the scaled enclosure (report/scales.hpp) may still
// straddle a rounding boundary, so the proof is asked for guard digits, and more while the
// scaled rounding is undecided. The bracket of an interrupted proof is scaled alike.
band_first_below first_below_in(const band_request& request, band_options opt, const big_rational& time2) {
  if (time2 == 1) return prove_band_first_below(request.n1, request.n2, *request.below, opt);
  const mpfr_prec_t bits = mpfr_prec_t(digits10_to_bits(request.digits + 20));
  for (unsigned guard = 3;; guard *= 2) {
    opt.digits = std::min(request.digits + guard, unsigned(report_digits_max));
    band_first_below b = prove_band_first_below(request.n1, request.n2, *request.below, opt);
    if (b.never) return b;
    const enclosure t = scaled_sqrt(b.time, time2, bits);
    const bool decided = t.rounded(request.digits).has_value();
    if (b.settled && !decided && opt.digits < report_digits_max && guard < 200) continue;
    b.time = t;
    b.at_time = scaled_sqrt(b.at_time, time2, bits);
    if (b.settled && !decided) b.unsettled_reason = "the rounding of the time in seconds was not decided";
    b.settled = b.settled && decided;
    return b;
  }
}

}  // namespace

band_result run_band(const band_request& request) {
  check_band(request.n1, request.n2, "the band");
  check_report_digits(request.digits);
  // The envelope of the inputs (model/limits.hpp), before any work.
  check_coupling_limits(request.n1 * request.n1, "the band's lower end squared");
  check_coupling_limits(request.n2 * request.n2, "the band's upper end squared");
  check_horizon_limits(request.horizon, "the horizon");
  if (request.below) check_level_limits(*request.below, "the level");
  if (!(request.qdot0 > 0)) throw usage_error("qdot0 must be > 0, got " + rational_str(request.qdot0));
  if (request.certificate && request.qdot0 != 1)
    throw usage_error("a band certificate states the unit impulse (qdot0 = 1): drop qdot0 or the certificate");
  if (request.plant && request.qdot0 != 1) throw usage_error("give a plant's velocity or qdot0, not both");
  if (request.plant && request.certificate)
    throw usage_error("a band certificate states the unit impulse in model units: drop the plant or the certificate");
  if (request.certificate) {  // what a band certificate states, gyrores check must read
    check_certificate_horizon(request.horizon, "a band certificate");
    if (request.digits > unsigned(gyrores_checker::band_max_digits))
      throw usage_error("band certificates are limited to " + std::to_string(gyrores_checker::band_max_digits) +
                        " digits (what gyrores check reads), got " + std::to_string(request.digits));
  }
  band_options opt;
  opt.record_cover = request.certificate;
  opt.digits = request.digits;
  opt.max_intervals = request.max_intervals;
  opt.stop = request.stop;
  opt.progress = request.progress;
  const report_scales scales = request.plant ? plant_scales(*request.plant) : report_scales::of_qdot0(request.qdot0);
  opt.energy_scale = scales.energy;
  band_result r;
  r.absorption = prove_band_absorption(request.n1, request.n2, request.horizon, opt);
  if (!r.absorption.interrupted) r.containment = prove_band_containment(request.n1, request.n2, request.horizon, opt);
  r.interrupted = r.absorption.interrupted || (r.containment && r.containment->interrupted);
  if (request.below && !r.interrupted) {
    r.below = first_below_in(request, opt, scales.time2);
    r.interrupted = r.below->interrupted;
  }
  if (r.interrupted) return r;
  if (request.certificate) {
    r.certificate = band_certificate_of(request.n1, request.n2, request.horizon, request.digits, r.absorption, *r.containment);
    // What a band certificate states, gyrores check must read (its work bounds, band_checker.hpp).
    for (const band_certificate_claim* c : {&r.certificate->absorption, &r.certificate->containment}) {
      if (c->cover.size() > gyrores_checker::band_max_intervals)
        throw compute_error("band certificate: a cover of " + std::to_string(c->cover.size()) + " intervals, more than the " +
                            std::to_string(gyrores_checker::band_max_intervals) + " gyrores check reads");
      for (const band_certificate_interval& I : c->cover)
        for (const std::string& s : {rational_str(I.a), rational_str(I.b), I.K.str(), I.bound})
          if (s.size() > gyrores_checker::band_max_field_chars)
            throw compute_error("band certificate: a number of " + std::to_string(s.size()) + " characters, more than the " +
                                std::to_string(gyrores_checker::band_max_field_chars) + " gyrores check reads");
    }
  }
  // Each extreme's own coupling, its lobe and time (the horizon theorem at the digits asked).
  r.absorption_at = attained(r.absorption.at);
  r.containment_at = attained(r.containment->at);
  r.absorption_at->minimum =
      report_horizon_minimum(r.absorption.at.spec, request.horizon, request.digits, request.stop, proof_use::report, scales);
  r.containment_at->minimum =
      report_horizon_minimum(r.containment->at.spec, request.horizon, request.digits, request.stop, proof_use::report, scales);
  if (r.below) {
    r.below_at = attained(r.below->at);
    r.below_at->first_below =
        report_first_below(r.below->at.spec, *request.below, request.digits, request.stop, proof_use::report, scales);
  }
  return r;
}

json band_result_json(const band_request& request, const band_result& r) {
  json j{{"format", band_format},
         {"theorem", band_theorem_id},
         {"n1", rational_str(request.n1)},
         {"n2", rational_str(request.n2)},
         {"horizon", request.horizon.str()},
         {"digits", request.digits},
         {"interrupted", r.interrupted},
         {"absorption", extreme_json(r.absorption, request.digits, attained_json(r.absorption_at))},
         {"containment", r.containment ? extreme_json(*r.containment, request.digits, attained_json(r.containment_at))
                                       : json(nullptr)}};
  j["first_below"] = r.below ? first_below_json(*r.below, request.digits, attained_json(r.below_at)) : json(nullptr);
  return j;
}

}  // namespace gyrores::app
