// Every user input that is more than a number, parsed and validated once, into typed values: the
// layers below take these types, never text. Each parser names the argument (`what`) in its one-
// line usage_error, so the CLI and the Python module report the user's own spelling.
//   horizons  "37", "1e30", "5/2", "100pi", "100*pi"   -> horizon_time (exact, or exact times pi)
//   levels    "1e-3", "1/200", "1%" (of H_q(0) = 1/2)  -> an exact energy E >= 0
//   bands     "N1:N2"; a tolerance "P%" around n        -> exact ends 0 < n1 < n2
//   qdot0     "1", "0.1", "1/3" (the impulse amplitude)  -> an exact rational > 0
//   a plant   mass, stiffness, gyroscopic coefficient, velocity (docs/units.md) -> exact rationals > 0
// Each value must also lie in the envelope of model/limits.hpp (the checks below, which the
// parsers and the app layer call): outside it, usage_error with the limit.
#pragma once
#include <string>
#include <utility>

#include <gyrores/core/rational.hpp>

namespace gyrores {

// A horizon T >= 0 given exactly: T = value, or T = value * pi (the paper's spans, e.g. 100 pi).
struct horizon_time {
  big_rational value = 0;
  bool times_pi = false;
  horizon_time() = default;
  horizon_time(const big_rational& v, bool pi = false) : value(v), times_pi(pi) {}
  std::string str() const { return rational_str(value) + (times_pi ? " pi" : ""); }
};

// T as text: a decimal, scientific or fraction, optionally times pi ("100pi", "100*pi", "1e30");
// usage_error naming `what` for anything else, a negative T or one outside the limits.
horizon_time parse_horizon_time(const std::string& text, const std::string& what);

// E as text: an energy (H_q(0) = qdot0^2/2 = 1/2), or a percentage of the initial energy
// ("1%" is 1/200); usage_error naming `what` for anything else, E < 0 or E outside the limits.
// At an impulse whose H_q(0) is `energy_scale` times the unit impulse's (qdot0^2, or m V^2 for a
// plant) it is the level the theorems take (unit impulse): a percentage is a share of H_q(0), the
// same at every impulse; an absolute energy E becomes E / energy_scale. The limits apply to that
// unit level.
big_rational parse_energy_level(const std::string& text, const std::string& what, const big_rational& energy_scale = 1);

// The impulse amplitude qdot0 = q'(0) > 0 as text (exact decimal or fraction); usage_error naming
// `what` unless 10^-100 <= qdot0 <= 10^100.
big_rational parse_qdot0(const std::string& text, const std::string& what);

// The coupling of a resonant pair: n^2 = (tau - sigma)^2 / (tau sigma), exactly.
big_rational pair_coupling_n2(const big_int& tau, const big_int& sigma);

// A physical plant (docs/units.md): two equal-frequency modes with mass m, stiffness k and
// gyroscopic coefficient g (m q'' + g z' + k q = 0, m z'' - g q' + k z = 0), struck so that
// q'(0) = V. Every value an exact rational > 0 in SI units (kg, N/m, N s/m, m/s).
struct plant_inputs {
  big_rational mass, stiffness, gyro, velocity;
  big_rational n2() const { return gyro * gyro / (mass * stiffness); }  // n = g / sqrt(m k)
};
// Each text parsed as an exact decimal or fraction, usage_error naming its flag (`names`: mass,
// stiffness, gyro, velocity in that order) unless > 0 and within [10^-100, 10^100]; the coupling
// n^2 = g^2/(m k) must lie within the coupling limits.
plant_inputs parse_plant(const std::string& mass, const std::string& stiffness, const std::string& gyro,
                         const std::string& velocity, const std::string (&names)[4]);

// The envelope (model/limits.hpp), each a usage_error naming `what` and the limit it breaks:
// T = 0 or 10^-1000 <= T <= 10^1000 (a pi: a within them); 10^-300 <= n^2 <= 10^300; E = 0 or
// E >= 10^-100; each of them, reduced, at most limits::rational_chars characters.
void check_horizon_limits(const horizon_time& T, const std::string& what);
void check_coupling_limits(const big_rational& n2, const std::string& what);
void check_level_limits(const big_rational& E, const std::string& what);

// "N1:N2" -> (n1, n2), the ends parsed as `what N1` and `what N2` (their order is check_band's),
// each with n^2 within the limits.
std::pair<big_rational, big_rational> parse_band(const std::string& text, const std::string& what);
// A tolerance "P%" around n: the band |n| (1 -+ P/100); usage_error unless 0 < P < 100 and both
// ends' n^2 lie within the limits.
std::pair<big_rational, big_rational> parse_tolerance_band(const big_rational& n, const std::string& tolerance,
                                                           const std::string& what);
// A tolerance "P%" around n = sqrt(n2) (n2 > 0 within the limits): when n is rational, the exact
// band n (1 -+ P/100) (exact = true); else rational ends n1 <= n (1 - P/100) and
// n2 >= n (1 + P/100) enclosing it outward, decimals with at least 30 significant digits from
// exact integer square roots (exact = false). A band's guarantees hold for every band inside it.
struct tolerance_band_ends {
  big_rational n1, n2;
  bool exact = true;
};
tolerance_band_ends parse_tolerance_band_n2(const big_rational& n2, const std::string& tolerance, const std::string& what);
// usage_error "<what> needs 0 < n1 < n2, got n1:n2" unless it holds.
void check_band(const big_rational& n1, const big_rational& n2, const std::string& what);

}  // namespace gyrores
