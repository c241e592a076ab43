// include/gyrores/model/inputs.hpp: the user's inputs, parsed once.
#include <gyrores/model/inputs.hpp>

#include <gyrores/core/error.hpp>
#include <gyrores/core/quote.hpp>

namespace gyrores {

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
  return t;
}

big_rational parse_energy_level(const std::string& given, const std::string& what) {
  std::string text = given;
  big_rational e;
  if (!text.empty() && text.back() == '%') {
    text.pop_back();
    e = parse_rational(text, what) / 200;
  } else e = parse_rational(text, what);
  if (e < 0) throw usage_error(what + " must be >= 0, got " + shown_input(given));
  return e;
}

void check_band(const big_rational& n1, const big_rational& n2, const std::string& what) {
  if (!(n1 > 0) || !(n2 > n1)) throw usage_error(what + " needs 0 < n1 < n2, got " + rational_str(n1) + ":" + rational_str(n2));
}

std::pair<big_rational, big_rational> parse_band(const std::string& text, const std::string& what) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw usage_error(what + " must be N1:N2, got " + shown_input(text));
  return {parse_rational(text.substr(0, colon), what + " N1"), parse_rational(text.substr(colon + 1), what + " N2")};
}

std::pair<big_rational, big_rational> parse_tolerance_band(const big_rational& n, const std::string& tolerance,
                                                           const std::string& what) {
  std::string t = tolerance;
  if (t.empty() || t.back() != '%') throw usage_error(what + " must be a percentage such as 1%, got " + shown_input(tolerance));
  t.pop_back();
  const big_rational p = parse_rational(t, what) / 100;
  if (!(p > 0) || !(p < 1)) throw usage_error(what + " must be in (0%, 100%), got " + shown_input(tolerance));
  const big_rational an = n < 0 ? big_rational(-n) : n;
  return {big_rational(an * (1 - p)), big_rational(an * (1 + p))};
}

}  // namespace gyrores
