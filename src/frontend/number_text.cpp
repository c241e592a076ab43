// src/frontend/number_text.hpp
#include "frontend/number_text.hpp"

#include <algorithm>
#include <cstdlib>

namespace gyrores::frontend {

std::string plain(const std::string& s) {
  const std::size_t e = s.find('e');
  if (e == std::string::npos || e + 1 >= s.size()) return s;
  const bool negative = s[0] == '-';
  std::string digits;
  for (std::size_t i = negative ? 1 : 0; i < e; ++i) {
    if (s[i] == '.') continue;
    if (s[i] < '0' || s[i] > '9') return s;
    digits += s[i];
  }
  if (digits.empty()) return s;
  if (digits.find_first_not_of('0') == std::string::npos) return "0";
  char* end = nullptr;
  const long e10 = std::strtol(s.c_str() + e + 1, &end, 10);
  if (*end != '\0' || e10 < plain_exponent_min || e10 > plain_exponent_max) return s;
  std::string out = negative ? "-" : "";
  if (e10 < 0) return out + "0." + std::string(std::size_t(-e10 - 1), '0') + digits;
  const std::size_t units = std::size_t(e10) + 1;
  if (digits.size() < units) return s;
  out += digits.substr(0, units);
  if (digits.size() > units) out += "." + digits.substr(units);
  return out;
}

std::string energy_text(const std::string& energy, const std::string& share) {
  const std::string e = plain(energy);
  if (e == "0") return "0 (exact)";
  return e + "  (" + plain(share) + "% of H_q(0))";
}

std::string decimal_text(const big_rational& v, unsigned digits) {
  big_int den = boost::multiprecision::denominator(v);
  int twos = 0, fives = 0;
  while (den % 2 == 0) den /= 2, ++twos;
  while (den % 5 == 0) den /= 5, ++fives;
  if (den != 1 || std::max(twos, fives) > 60) {
    // A correct rounding; its exponent may be outside plain's range: then scientific.
    return "~" + plain(format_rational_scientific(v, digits));
  }
  const int k = std::max(twos, fives);
  const big_rational scaled = abs(v) * big_rational(boost::multiprecision::pow(big_int(10), unsigned(k)));
  std::string text = big_int(boost::multiprecision::numerator(scaled)).str();
  if (k > 0) {
    if (int(text.size()) <= k) text.insert(0, std::string(std::size_t(k + 1 - int(text.size())), '0'));
    text.insert(text.size() - std::size_t(k), ".");
  }
  return (v < 0 ? "-" : "") + text;
}

}  // namespace gyrores::frontend
