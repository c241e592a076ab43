// include/gyrores/model/inputs.hpp: the user's inputs, parsed once.
#include <gyrores/model/inputs.hpp>

#include <gyrores/core/error.hpp>
#include <gyrores/model/limits.hpp>

namespace gyrores {

namespace {

big_int pow10(long e) { return boost::multiprecision::pow(big_int(10), unsigned(e)); }

// "10^e" for the messages (a rational near the limits can have thousands of digits).
std::string power_text(long e) { return "10^" + std::to_string(e); }

// About log10 |v| (v != 0), for the messages: the difference of the digit counts.
std::string magnitude_text(const big_rational& v) {
  const big_int num = abs(boost::multiprecision::numerator(v)), den = boost::multiprecision::denominator(v);
  const long e = long(num.str().size()) - long(den.str().size());
  return "about 10^" + std::to_string(e);
}

void check_chars(const big_rational& v, const std::string& what) {
  const std::size_t n = rational_str(v).size();
  if (n > limits::rational_chars)
    throw usage_error(what + " has " + std::to_string(n) + " characters as a reduced fraction p/q, more than the " +
                      std::to_string(limits::rational_chars) + " allowed");
}

}  // namespace

void check_horizon_limits(const horizon_time& T, const std::string& what) {
  if (T.value < 0) throw usage_error(what + " must be >= 0, got " + T.str());
  if (T.value == 0) return;
  const long e = limits::horizon_exponent;
  if (T.value > big_rational(pow10(e)))
    throw usage_error(what + " must be at most " + power_text(e) + " (the limit of the coupling inputs), got " +
                      magnitude_text(T.value));
  if (T.value < big_rational(big_int(1), pow10(e)))
    throw usage_error(what + " must be 0 or at least " + power_text(-e) + " (the limit of the coupling inputs), got " +
                      magnitude_text(T.value));
  check_chars(T.value, what);
}

void check_coupling_limits(const big_rational& n2, const std::string& what) {
  if (!(n2 > 0)) throw usage_error(what + " must be > 0, got " + rational_str(n2));
  const long e = limits::n2_exponent;
  if (n2 > big_rational(pow10(e)) || n2 < big_rational(big_int(1), pow10(e)))
    throw usage_error(what + " must lie in [" + power_text(-e) + ", " + power_text(e) +
                      "] (the limit of the coupling inputs; |n| in [10^-" + std::to_string(e / 2) + ", 10^" +
                      std::to_string(e / 2) + "]), got " + magnitude_text(n2));
  check_chars(n2, what);
}

void check_level_limits(const big_rational& E, const std::string& what) {
  if (E < 0) throw usage_error(what + " must be >= 0, got " + rational_str(E));
  const long e = limits::level_exponent;
  if (E != 0 && E < big_rational(big_int(1), pow10(e)))
    throw usage_error(what + " must be 0 or at least " + power_text(-e) + " (the limit of the coupling inputs), got " +
                      magnitude_text(E));
  check_chars(E, what);
}

horizon_time parse_horizon_time(const std::string& given, const std::string& what) {
  std::string text = given;
  bool pi = false;
  if (text.size() > 2 && text.compare(text.size() - 2, 2, "pi") == 0) {
    pi = true;
    text.resize(text.size() - 2);
    while (!text.empty() && (text.back() == '*' || text.back() == ' ')) text.pop_back();
  }
  horizon_time t(parse_rational(text, what), pi);
  if (t.value < 0) throw usage_error(what + " must be >= 0, got " + shown_input(given));
  check_horizon_limits(t, what);
  return t;
}

namespace {

// A value > 0 within [10^-100, 10^100] (qdot0 and the plant's quantities).
big_rational parse_positive(const std::string& given, const std::string& what) {
  const big_rational v = parse_rational(given, what);
  if (!(v > 0)) throw usage_error(what + " must be > 0, got " + shown_input(given));
  const long e = 100;
  if (v > big_rational(pow10(e)) || v < big_rational(big_int(1), pow10(e)))
    throw usage_error(what + " must lie in [" + power_text(-e) + ", " + power_text(e) + "], got " + magnitude_text(v));
  check_chars(v, what);
  return v;
}

}  // namespace

big_rational parse_qdot0(const std::string& text, const std::string& what) { return parse_positive(text, what); }

big_rational parse_energy_level(const std::string& given, const std::string& what, const big_rational& energy_scale) {
  const bool percent = !given.empty() && given.back() == '%';
  big_rational e = parse_rational(percent ? given.substr(0, given.size() - 1) : given, what);
  if (e < 0) throw usage_error(what + " must be >= 0, got " + shown_input(given));
  e /= percent ? big_rational(200) : energy_scale;
  check_level_limits(e, percent || energy_scale == 1 ? what : what + " (at the unit impulse)");
  return e;
}

big_rational pair_coupling_n2(const big_int& tau, const big_int& sigma) {
  const big_int b = tau - sigma;
  return big_rational(b * b, tau * sigma);
}

plant_inputs parse_plant(const std::string& mass, const std::string& stiffness, const std::string& gyro,
                         const std::string& velocity, const std::string (&names)[4]) {
  plant_inputs p{parse_positive(mass, names[0]), parse_positive(stiffness, names[1]), parse_positive(gyro, names[2]),
                 parse_positive(velocity, names[3])};
  check_coupling_limits(p.n2(), "the plant's coupling n^2 = g^2/(m k)");
  return p;
}

void check_band(const big_rational& n1, const big_rational& n2, const std::string& what) {
  if (!(n1 > 0) || !(n2 > n1)) throw usage_error(what + " needs 0 < n1 < n2, got " + rational_str(n1) + ":" + rational_str(n2));
}

std::pair<big_rational, big_rational> parse_band(const std::string& text, const std::string& what) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw usage_error(what + " must be N1:N2, got " + shown_input(text));
  std::pair<big_rational, big_rational> band{parse_rational(text.substr(0, colon), what + " N1"),
                                             parse_rational(text.substr(colon + 1), what + " N2")};
  check_band(band.first, band.second, what);
  check_coupling_limits(band.first * band.first, what + " N1 squared");
  check_coupling_limits(band.second * band.second, what + " N2 squared");
  return band;
}

namespace {

// P/100 from "P%", 0 < P < 100.
big_rational tolerance_fraction(const std::string& tolerance, const std::string& what) {
  std::string t = tolerance;
  if (t.empty() || t.back() != '%') throw usage_error(what + " must be a percentage such as 1%, got " + shown_input(tolerance));
  t.pop_back();
  const big_rational p = parse_rational(t, what) / 100;
  if (!(p > 0) || !(p < 1)) throw usage_error(what + " must be in (0%, 100%), got " + shown_input(tolerance));
  return p;
}

void check_band_ends(const std::pair<big_rational, big_rational>& band, const std::string& what) {
  check_coupling_limits(band.first * band.first, what + ": the band's lower end squared");
  check_coupling_limits(band.second * band.second, what + ": the band's upper end squared");
}

}  // namespace

std::pair<big_rational, big_rational> parse_tolerance_band(const big_rational& n, const std::string& tolerance,
                                                           const std::string& what) {
  const big_rational p = tolerance_fraction(tolerance, what);
  const big_rational an = n < 0 ? big_rational(-n) : n;
  const std::pair<big_rational, big_rational> band{big_rational(an * (1 - p)), big_rational(an * (1 + p))};
  check_band_ends(band, what);
  return band;
}

tolerance_band_ends parse_tolerance_band_n2(const big_rational& n2, const std::string& tolerance, const std::string& what) {
  check_coupling_limits(n2, "n^2");
  if (const auto n = rational_sqrt(n2)) {
    const auto band = parse_tolerance_band(*n, tolerance, what);
    return {band.first, band.second, true};
  }
  const big_rational p = tolerance_fraction(tolerance, what);
  // n (1 -+ p) = sqrt(n^2 (1 -+ p)^2): k decimals, the lower end rounded down and the upper up,
  // with k raised until the lower end has at least 30 significant digits.
  const big_rational lo2 = n2 * (1 - p) * (1 - p), hi2 = n2 * (1 + p) * (1 + p);
  long k = 30;
  big_int m = floor_sqrt(lo2 * big_rational(pow10(2 * k)));
  while (m.str().size() < 30) {
    k += 30 - long(m.str().size());
    m = floor_sqrt(lo2 * big_rational(pow10(2 * k)));
  }
  const big_rational hi_scaled = hi2 * big_rational(pow10(2 * k));
  big_int M = floor_sqrt(hi_scaled);
  if (big_rational(M * M) != hi_scaled) M += 1;  // the ceiling: sqrt(hi_scaled) is not an integer
  tolerance_band_ends band{big_rational(m, pow10(k)), big_rational(M, pow10(k)), false};
  check_band_ends({band.n1, band.n2}, what);
  return band;
}

}  // namespace gyrores
