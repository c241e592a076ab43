// include/gyrores/design/coupling_report.hpp
#include <gyrores/design/coupling_report.hpp>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/verified_digits.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {
namespace {

void check_horizon(const big_rational& value) {
  if (value < 0) throw usage_error("horizon must be >= 0, got " + rational_str(value));
}

template <class T> T horizon_in(const exact_horizon& h) {
  T t = real_from_rational<T>(h.value);
  if (h.times_pi) t = T(t * real_pi<T>());
  return t;
}

// horizon_minimum in T for |n| and qdot0 = 1; its minimum, first time (and radius) as fields
// "h_min<suffix>", "t_min<suffix>" (and "r_min<suffix>").
template <class T>
horizon_min_result<T> put_horizon_fields(real_fields& f, const coupling_spec& c, const exact_horizon& h,
                                         const std::string& suffix, bool radius) {
  using std::sqrt;
  auto r = horizon_minimum<T>(c.abs_n<T>(), T(1), horizon_in<T>(h));
  put_field(f, "h_min" + suffix, r.h_min);
  put_field(f, "t_min" + suffix, r.t_min);
  if (radius) put_field(f, "r_min" + suffix, T(sqrt(2 * r.h_min)));
  return r;
}

// horizon >= t_first, decided on the proved enclosure of t_first (more digits until the horizon
// lies outside it; t_first is irrational for every pair, so this ends).
bool horizon_covers_first(const resonant_pair<big_int>& p, const big_rational& horizon) {
  for (unsigned digits = 20; digits <= report_digits_max; digits *= 4) {
    const pair_report r = prove_pair_values(p, digits);
    if (horizon >= parse_rational(r.t_first.enclosure.second, "t_first")) return true;
    if (horizon < parse_rational(r.t_first.enclosure.first, "t_first")) return false;
  }
  throw compute_error("coupling: the horizon " + rational_str(horizon) + " could not be compared with t_first of " +
                      p.str());
}

// |n| = sqrt(n^2) and pi/|n|, proved: the correct roundings of enclosures (the precision doubles
// until both ends round alike; sqrt(n^2) is rounded once from the rational when n^2 is a square).
void prove_coupling_numbers(coupling_report& r, unsigned digits) {
  const big_rational& n2 = r.spec.n2;
  big_int rp, rq;
  const bool rational = int_is_square(big_int(numerator(n2)), rp) && int_is_square(big_int(denominator(n2)), rq);
  for (unsigned bits = digits10_to_bits(digits) + 32; bits <= (1u << 20); bits *= 2) {
    fixed_mpfi n(bits), t(bits);
    mpfi_set_q(n, n2.backend().data());
    mpfi_sqrt(n, n);
    mpfi_const_pi(t);
    mpfi_div(t, t, n);
    if (rational) r.abs_n = format_rational_scientific(big_rational(rp, rq), digits);
    else if (!enclosure_rounding(n.left(), n.right(), digits, r.abs_n)) continue;
    if (enclosure_rounding(t.left(), t.right(), digits, r.t_min_paper)) return;
  }
  throw compute_error("coupling: |n| or pi/|n| was not decided to " + std::to_string(digits) + " digits");
}

// |n| and pi/|n| (proved) and, unless the pair analysis answers it, the minimum over [0, T]:
// verified (two runs, core/verified_digits.hpp), not proved.
void coupling_numbers(coupling_report& r, const coupling_report_options& opt, bool covers_first) {
  prove_coupling_numbers(r, opt.digits);
  if (covers_first) {
    r.h_min_horizon = r.pair_values->h_min.value;
    r.t_min_horizon = r.pair_values->t_first.value;
    r.horizon_source = "the pair analysis: the horizon contains t_first, where the global minimum H_min is first attained";
    return;
  }
  bool at_end = false;
  std::size_t crit = 0;
  const exact_horizon horizon{opt.horizon, false};
  const verified_run run = compute_verified_per_type(opt.digits, false, [&](auto tag) {
    using T = decltype(tag);
    real_fields f;
    auto h = put_horizon_fields<T>(f, r.spec, horizon, "_horizon", false);
    at_end = h.at_horizon_end;
    crit = h.critical_points;
    return f;
  });
  r.horizon_proved = false;
  r.h_min_horizon = run.fields.at("h_min_horizon")[0];
  r.t_min_horizon = run.fields.at("t_min_horizon")[0];
  r.min_at_horizon_end = at_end;
  r.horizon_source = "critical points of H_q (roots of q' and z' bracketed exactly, " + std::to_string(crit) +
                     " examined) and the end point" + std::string(at_end ? "; the minimum is at the end point t = T" : "");
}

void set_infimum(coupling_report& r) {
  if (r.pair) {
    r.inf_all_time = r.pair_values->h_min.value;
    r.inf_attained = true;
    r.inf_reason = "resonant pair " + r.pair->str() + ": the motion is periodic; min H_q = r_res^2/2, first attained at t_first = " +
                   r.pair_values->t_first.value + (r.pair->degenerate() ? " (delta = 2 mod 4: H_q = 0 exactly)" : "");
    return;
  }
  r.inf_all_time = "0";
  r.inf_attained = false;
  r.inf_reason = "W1/W2 is irrational (n^2 (n^2 + 4) = D/Q^2 with D = " + r.spec.discriminant().str() +
                 " not a perfect square): the line (W1 t, W2 t) is dense on the torus and passes arbitrarily close to "
                 "(pi/2, -pi/2), where q = q' = 0; the infimum 0 is approached but never attained";
}

std::vector<coupling_convergent> verified_convergents(const coupling_spec& spec, std::size_t count, unsigned digits) {
  std::vector<coupling_convergent> out;
  for (auto& c : coupling_convergents(spec, count)) {
    coupling_convergent row{c, std::nullopt, std::nullopt};
    if (c.p > c.q) {
      row.pair = resonant_pair<big_int>(c.p, c.q);
      row.values = prove_pair_values(*row.pair, digits);
    }
    out.push_back(row);
  }
  return out;
}

}  // namespace

verified_horizon_min verify_horizon_minimum(const coupling_spec& c, const exact_horizon& horizon, unsigned digits) {
  check_verified_digits(digits);
  check_horizon(horizon.value);
  verified_horizon_min v;
  const verified_run run = compute_verified_per_type(digits, false, [&](auto tag) {
    using T = decltype(tag);
    real_fields f;
    auto r = put_horizon_fields<T>(f, c, horizon, "", true);
    v.at_horizon_end = r.at_horizon_end;
    v.critical_points = r.critical_points;
    return f;
  });
  v.h_min = run.fields.at("h_min")[0];
  v.t_min = run.fields.at("t_min")[0];
  v.r_min = run.fields.at("r_min")[0];
  return v;
}

coupling_report analyse_coupling(const coupling_spec& spec, const coupling_report_options& opt) {
  check_verified_digits(opt.digits);
  check_horizon(opt.horizon);
  coupling_report r;
  r.spec = spec;
  r.n_negative = spec.n && *spec.n < 0;
  r.pair = coupling_resonant_pair(spec);
  bool covers_first = false;
  if (r.pair) {
    r.pair_values = prove_pair_values(*r.pair, opt.digits);
    covers_first = horizon_covers_first(*r.pair, opt.horizon);
  }
  coupling_numbers(r, opt, covers_first);
  set_infimum(r);
  r.convergents = verified_convergents(spec, opt.convergents, opt.digits);
  return r;
}

}  // namespace gyrores
