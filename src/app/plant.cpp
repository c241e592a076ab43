// include/gyrores/app/plant.hpp: a physical plant's units.
#include <gyrores/app/plant.hpp>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/refine.hpp>

namespace gyrores::app {

namespace {

// sqrt(r) correctly rounded to `digits`: from the rational when r is a square, else from MPFI
// enclosures in the precision loop (an irrational square root is never a rounding tie).
std::string sqrt_text(const big_rational& r, unsigned digits) {
  if (const auto s = rational_sqrt(r)) return *enclosure::exact(*s).rounded(digits);
  const precision_plan plan{mpfr_prec_t(digits10_to_bits(digits) + 64), report_bits_cap};
  return refine(plan, stop_token(), "a square root of the plant", [&](mpfr_prec_t bits, proof_status& status) {
    fixed_mpfi v(bits);
    mpfi_set_q(v, r.backend().data());
    mpfi_sqrt(v, v);
    auto t = enclosure(v).rounded(digits);
    if (!t) status = proof_status::undecided("its rounding to the digits asked");
    return t;
  });
}

}  // namespace

report_scales plant_scales(const plant_inputs& p) {
  const big_rational t2 = p.mass / p.stiffness;
  return {p.mass * p.velocity * p.velocity, p.velocity * p.velocity * t2, t2};
}

plant_numbers plant_numbers_of(const plant_inputs& p, unsigned digits) {
  check_report_digits(digits);
  plant_numbers out;
  out.omega0 = sqrt_text(p.stiffness / p.mass, digits);
  out.n2 = p.n2();
  out.n = sqrt_text(out.n2, digits);
  out.time_scale = sqrt_text(p.mass / p.stiffness, digits);
  out.energy_scale = p.mass * p.velocity * p.velocity;
  out.h_q0 = out.energy_scale / 2;
  return out;
}

plant_horizon plant_horizon_of(const plant_inputs& p, const horizon_time& seconds, unsigned digits) {
  const big_rational w2 = p.stiffness / p.mass;  // omega0^2
  if (const auto w = rational_sqrt(w2)) {
    const horizon_time T(seconds.value * *w, seconds.times_pi);
    return {T, T.value, true};
  }
  if (seconds.value == 0) return {seconds, 0, true};
  // T omega0 = sqrt(a2) between m 10^-s and (m + 1) 10^-s, m = floor(sqrt(a2 10^(2s))), with
  // s chosen so that m has about D = digits + 20 digits.
  const big_rational a2 = seconds.value * seconds.value * w2;
  const long D = long(digits) + 20;
  const long mag = long(numerator(a2).str().size()) - long(denominator(a2).str().size());
  const long s = D - mag / 2 + 1;
  const big_rational ten_s = s >= 0 ? big_rational(boost::multiprecision::pow(big_int(10), unsigned(s)))
                                    : big_rational(big_int(1), boost::multiprecision::pow(big_int(10), unsigned(-s)));
  const big_int m = floor_sqrt(a2 * ten_s * ten_s);
  const big_rational unit = 1 / ten_s;
  return {horizon_time(big_rational(m + 1) * unit, seconds.times_pi), big_rational(m) * unit, false};
}

json plant_json(const plant_inputs& p, const plant_numbers& n) {
  return json{{"mass", rational_str(p.mass)},
              {"stiffness", rational_str(p.stiffness)},
              {"gyro", rational_str(p.gyro)},
              {"velocity", rational_str(p.velocity)},
              {"omega0", n.omega0},
              {"n", n.n},
              {"n2", rational_str(n.n2)},
              {"time_scale", n.time_scale},
              {"energy_scale", rational_str(n.energy_scale)},
              {"h_q0", rational_str(n.h_q0)},
              {"units", {{"mass", "kg"}, {"stiffness", "N/m"}, {"gyro", "N s/m"}, {"velocity", "m/s"},
                         {"omega0", "rad/s"}, {"time", "s"}, {"energy", "J"}, {"radius", "m"}}}};
}

}  // namespace gyrores::app
