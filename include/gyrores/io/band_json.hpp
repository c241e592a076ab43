// The JSON form of a band's guarantees (docs/formats.md, "Band guarantees", version
// "gyrores-band/2"): each extreme with its settled value (null when not settled), its proved
// enclosure rounded outward, whether it was interrupted or capped, and where it is attained (the
// coupling's exact n^2, its pair, its own minimum's lobe and time).
#pragma once
#include <optional>

#include <gyrores/io/json.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/theorem/band.hpp>
#include <gyrores/report/horizon_report.hpp>

namespace gyrores {

inline constexpr const char* band_format = "gyrores-band/2";

// {"n2", "x", "pair"} of a coupling of the band.
json band_coupling_json(const band_coupling& c, const std::optional<resonant_pair<big_int>>& pair);

// One guarantee: {"h_min", "enclosure", "settled", "interrupted", "reason", "at", "intervals",
// "couplings"}, "at" with the coupling's own "h_min", "lobe", "t_min" (from its horizon report).
json band_extreme_json(const band_extreme& e, unsigned digits, const json& at);

// The band-wide first time below E: {"level", "never", "reason", "t_below", "enclosure", ...}.
json band_first_below_json(const band_first_below& b, unsigned digits, const json& at);

// A horizon minimum's place, for "at": {"h_min", "lobe", "t_min"}.
json horizon_place_json(const horizon_minimum_report& r);

}  // namespace gyrores
