// Verified digits of the quantities the design, Pareto, coupling and report commands print for a
// resonant pair: n, r_res, h_min, t_first, theta_first, t_min_paper (pi/|n|). Same contract as
// `gyrores pair`: two runs (the plan's type, MPFR with 64 more bits), Ziv's test, analyse_pair
// with the lattice method cross-checked against the global search up to order 20000.
#pragma once
#include <string>

#include <gyrores/gyrores.hpp>

#include "cli_output.hpp"
#include "precision.hpp"

namespace gyrores::cli {

struct pair_values {
  std::string n, r_res, h_min, t_first, theta_first, t_min_paper;
  bool degenerate = false, cross_checked = false;
};

inline pair_values pair_values_verified(const resonant_pair<big_int>& p, unsigned digits) {
  if (digits < 1 || digits > 10000) throw usage_error("--digits must be in [1, 10000], got " + std::to_string(digits));
  const bool needs_mpfr = boost::multiprecision::msb(p.order()) > 900;
  const bool small = pair_fits_int64(p);
  bool checked = false, cross_checked = false;
  auto compute = [&](const precision_plan& plan) {
    bool do_check = !checked;
    real_fields f = with_real_type(plan, [&](auto tag) {
      using T = decltype(tag);
      analysis_options opt;
      if (!do_check) opt.cross_check_max_order = 0;
      auto run = [&](const auto& pp) {
        auto a = analyse_pair<T>(pp, T(1), opt);
        real_fields out;
        out["n"] = {real_to_mpfr(a.n)};
        out["r_res"] = {real_to_mpfr(a.inscribed.r_res)};
        out["h_min"] = {real_to_mpfr(a.inscribed.h_min)};
        out["t_first"] = {real_to_mpfr(a.inscribed.t_first)};
        out["theta_first"] = {real_to_mpfr(a.inscribed.theta_first)};
        out["t_min_paper"] = {real_to_mpfr(a.t_min_paper)};
        if (a.cross_checked) cross_checked = true;
        return out;
      };
      if (small) return run(pair_cast<std::int64_t>(p));
      return run(p);
    });
    checked = true;
    return f;
  };
  verified_run run = compute_verified(digits, needs_mpfr, compute);
  pair_values v;
  v.n = run.fields.at("n")[0];
  v.r_res = run.fields.at("r_res")[0];
  v.h_min = run.fields.at("h_min")[0];
  v.t_first = run.fields.at("t_first")[0];
  v.theta_first = run.fields.at("theta_first")[0];
  v.t_min_paper = run.fields.at("t_min_paper")[0];
  v.degenerate = p.degenerate();
  v.cross_checked = cross_checked;
  return v;
}

inline pair_values pair_values_verified(std::int64_t tau, std::int64_t sigma, unsigned digits) {
  return pair_values_verified(resonant_pair<big_int>(big_int(tau), big_int(sigma)), digits);
}

// {"tau", "sigma", "n", "r_res", "h_min", "t_first", "t_min_paper", "degenerate"}.
inline json pair_values_json(const resonant_pair<big_int>& p, const pair_values& v) {
  json j;
  j["tau"] = json_integer(p.tau().str());
  j["sigma"] = json_integer(p.sigma().str());
  j["n"] = v.n;
  j["r_res"] = v.r_res;
  j["h_min"] = v.h_min;
  j["t_first"] = v.t_first;
  j["t_min_paper"] = v.t_min_paper;
  j["degenerate"] = v.degenerate;
  return j;
}

// Zero prints as "0 (exact)" for degenerate pairs in text output.
inline std::string radius_text(const pair_values& v) { return v.degenerate ? "0 (exact, delta = 2 mod 4)" : v.r_res; }

}  // namespace gyrores::cli
