// include/gyrores/report/coupling_report.hpp
#include <gyrores/report/coupling_report.hpp>

#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/refine.hpp>

namespace gyrores {
namespace {

// |n| = sqrt(n^2) and pi/|n|, proved: the correct roundings of enclosures (the precision doubles
// until both ends round alike; sqrt(n^2) is rounded once from the rational when n^2 is a square).
// pi/|n| is a time: times sqrt(time2) in the report's units (report/scales.hpp).
void prove_coupling_numbers(coupling_report& r, unsigned digits, const big_rational& time2, const stop_token& stop) {
  const big_rational& n2 = r.spec.n2;
  big_int rp, rq;
  const bool rational = int_is_square(big_int(numerator(n2)), rp) && int_is_square(big_int(denominator(n2)), rq);
  refine(precision_plan{mpfr_prec_t(digits10_to_bits(digits) + 32)}, stop, "coupling: |n| or pi/|n|",
         [&](mpfr_prec_t bits, proof_status& status) {
           fixed_mpfi n(bits), t(bits);
           mpfi_set_q(n, n2.backend().data());
           mpfi_sqrt(n, n);
           mpfi_const_pi(t);
           mpfi_div(t, t, n);
           if (time2 != 1) {
             fixed_mpfi k(bits);
             mpfi_set_q(k, time2.backend().data());
             mpfi_sqrt(k, k);
             mpfi_mul(t, t, k);
           }
           auto abs_n = rational ? enclosure::exact(big_rational(rp, rq)).rounded(digits) : enclosure(n).rounded(digits);
           auto t_min = enclosure(t).rounded(digits);
           if (!abs_n || !t_min) {
             status = proof_status::undecided("a rounding of |n| or pi/|n|");
             return std::optional<bool>();
           }
           r.abs_n = std::move(*abs_n);
           r.t_min_paper = std::move(*t_min);
           return std::optional<bool>(true);
         });
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

std::vector<coupling_convergent> proved_convergents(const coupling_spec& spec, std::size_t count, unsigned digits,
                                                    const big_rational& qdot0, const stop_token& stop) {
  std::vector<coupling_convergent> out;
  for (auto& c : coupling_convergents(spec, count)) {
    coupling_convergent row{c, std::nullopt, std::nullopt};
    if (c.p > c.q) {
      row.pair = resonant_pair<big_int>(c.p, c.q);
      row.values = prove_pair_values(*row.pair, digits, qdot0, stop);
    }
    out.push_back(row);
  }
  return out;
}

}  // namespace

coupling_report analyse_coupling(const coupling_spec& spec, const coupling_report_options& opt) {
  check_report_digits(opt.digits);
  if (opt.horizon.value < 0) throw usage_error("the horizon must be >= 0, got " + opt.horizon.str());
  if (opt.below && *opt.below < 0) throw usage_error("the level E must be >= 0, got " + rational_str(*opt.below));
  coupling_report r;
  r.spec = spec;
  r.n_negative = spec.n && *spec.n < 0;
  r.pair = coupling_resonant_pair(spec);
  if (r.pair) r.pair_values = prove_pair_values(*r.pair, opt.digits, opt.pair_qdot0, opt.stop);
  prove_coupling_numbers(r, opt.digits, opt.scales.time2, opt.stop);
  r.horizon = report_horizon_minimum(spec, opt.horizon, opt.digits, opt.stop, opt.use, opt.scales);
  if (opt.below) r.below = report_first_below(spec, *opt.below, opt.digits, opt.stop, opt.use, opt.scales);
  set_infimum(r);
  r.convergents = proved_convergents(spec, opt.convergents, opt.digits, opt.pair_qdot0, opt.stop);
  return r;
}

}  // namespace gyrores
