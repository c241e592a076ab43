// The application layer (include/gyrores/app/pair.hpp): `gyrores design` and gyrores.design. The
// design problems over resonant pairs (design/design.hpp), the proved values of the pairs they
// list (theorem/pair_report.hpp) and, when asked, each ranked pair's guarantee over a tolerance
// band on n (design/tolerance.hpp). Requests are checked here, their parameters named as in Python.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <gyrores/core/rational.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/design/design.hpp>
#include <gyrores/design/tolerance.hpp>
#include <gyrores/model/inputs.hpp>
#include <gyrores/report/pair_report.hpp>

namespace gyrores::app {

// The digits of the listed pairs' values: [1, listed_digits_max].
inline constexpr unsigned listed_digits_max = 1000;

// "absorb" or "contain"; usage_error otherwise.
design_problem parse_design_problem(const std::string& text);

// usage_error unless digits is in [1, listed_digits_max] and the filter's numbers are in range
// (exclude_low >= 0, delta >= 1, beat > 0).
void check_listed(unsigned digits, const pair_filter& f);

// The proved values of the first `count` pairs (prove_pair_values, `digits` digits).
std::vector<pair_report> prove_listed(const std::vector<design_point>& pairs, std::size_t count, unsigned digits);

// The guarantee over the band n0 (1 -+ fraction) of each ranked pair: H_q <= level before tmax
// (absorb), or H_q >= level on [0, horizon] (contain).
struct design_tolerance {
  big_rational fraction;                // in (0, 1)
  big_rational level;                   // an energy E >= 0 (H_q(0) = 1/2)
  std::optional<horizon_time> horizon;  // contain only; tmax when not given
};

struct design_request {
  design_options options;             // the problem, its constraints, the runners-up listed
  std::string tmax_text, beat_text;   // tmax and beat (empty: none) as given: the outputs echo them
  unsigned digits = 10;               // of the listed pairs' values
  std::optional<design_tolerance> tolerance;  // needs the exact time (not the proxy)
  stop_token stop;                    // looked at between the stages and by the band proofs
};

struct design_outcome {
  design_result result;               // ranked[0] is the chosen pair (more ranks with a tolerance)
  std::vector<pair_report> values;    // of ranked[0 .. candidates], proved
  bool chosen_exceeds_tmax = false;   // the proxy chose a pair whose exact first-hit time exceeds tmax
  std::optional<tolerance_result> tolerance;  // the ranked pairs walked, best first
};

// The constraints as the output states them: "t_first <= 17, beat (tau+sigma)/(tau-sigma) >= 10,
// tau+sigma <= 200".
std::string design_constraints_text(const design_request& r);

// usage_error for a parameter out of its range (digits, candidates [0, 1000], the filter's,
// tmax <= 0, max_order outside the catalogue's, a tolerance with the proxy or a horizon for
// absorb); compute_error when no pair is feasible; `interrupted` when r.stop is requested.
design_outcome run_design(const design_request& r);

}  // namespace gyrores::app
