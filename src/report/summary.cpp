// The report's summary of findings (sections.hpp): the sentences the sections recorded in
// context::findings, each linked to its section by the heading's GitHub anchor, and the share of
// H_q(0) that the sentences give for an energy.
#include <cctype>
#include <cstdlib>
#include <sstream>

#include <gyrores/core/rational.hpp>

#include "report/sections.hpp"

namespace gyrores::report {
namespace {

// "2.58e-01" -> "0.258", "1.29e+01" -> "12.9", "1.00e+02" -> "100": the same digits in plain
// notation (format_rational_scientific's text, core/rational.hpp).
std::string plain(const std::string& sci) {
  const auto e = sci.find('e');
  std::string digits;
  for (char ch : sci.substr(0, e))
    if (std::isdigit(static_cast<unsigned char>(ch))) digits += ch;
  const long e10 = std::strtol(sci.c_str() + e + 1, nullptr, 10);
  const long point = e10 + 1;  // digits before the decimal point
  std::string out;
  if (point <= 0)
    out = "0." + std::string(std::size_t(-point), '0') + digits;
  else if (std::size_t(point) >= digits.size())
    out = digits + std::string(std::size_t(point) - digits.size(), '0');
  else
    out = digits.substr(0, std::size_t(point)) + "." + digits.substr(std::size_t(point));
  return (sci[0] == '-' ? "-" : "") + out;
}

}  // namespace

std::string markdown_anchor(const std::string& heading) {
  std::string out;
  for (char ch : heading) {
    const auto u = static_cast<unsigned char>(ch);
    if (std::isalnum(u))
      out += char(std::tolower(u));
    else if (ch == ' ' || ch == '-')
      out += '-';
    else if (ch == '_')
      out += '_';
  }
  return out;
}

std::string share_of_initial_energy(const big_rational& lo, const big_rational& hi) {
  constexpr unsigned digits = 3;
  if (hi == 0) return "0% of H_q(0)";
  const big_rational a = lo * 200, b = hi * 200;  // percent of 1/2
  const std::string ra = format_rational_scientific(a, digits), rb = format_rational_scientific(b, digits);
  if (ra == rb) return plain(ra) + "% of H_q(0)";
  return plain(format_rational_scientific(decimal_rounded(a, digits, -1), digits)) + "-" +
         plain(format_rational_scientific(decimal_rounded(b, digits, +1), digits)) + "% of H_q(0)";
}

std::string share_of_initial_energy(const proved_real& h) {
  if (!h.enclosure.first.empty())
    return share_of_initial_energy(parse_rational(h.enclosure.first, "enclosure"), parse_rational(h.enclosure.second, "enclosure"));
  // The value is the correct rounding of h to its digits: h lies within half a unit of its last digit.
  const big_rational v = parse_rational(h.value, "value");
  if (v == 0) return share_of_initial_energy(v, v);
  const auto e = h.value.find_first_of("eE");
  const std::string mantissa = h.value.substr(0, e);
  const auto dot = mantissa.find('.');
  const long decimals = dot == std::string::npos ? 0 : long(mantissa.size() - dot - 1);
  const long unit_exp = (e == std::string::npos ? 0 : std::strtol(h.value.c_str() + e + 1, nullptr, 10)) - decimals;
  big_rational half_unit(1, 2);
  for (long i = 0; i < (unit_exp < 0 ? -unit_exp : unit_exp); ++i) {
    if (unit_exp < 0)
      half_unit /= 10;
    else
      half_unit *= 10;
  }
  return share_of_initial_energy(v - half_unit, v + half_unit);
}

std::string summary_section(const std::vector<finding>& findings) {
  std::ostringstream md;
  md << "## Summary of findings\n\n";
  for (const auto& f : findings) {
    std::string number = f.heading.substr(0, f.heading.find(' '));  // "2." of "2. Case A ..."
    if (!number.empty() && number.back() == '.') number.pop_back();
    md << "- " << f.text << " ([section " << number << "](#" << markdown_anchor(f.heading) << "))\n";
  }
  md << "\nValues for the impulse qdot0 = 1, so H_q(0) = 1/2. Each number is the one its section prints; the "
        "shares of H_q(0) are rounded from the same proved enclosures.\n\n";
  return md.str();
}

}  // namespace gyrores::report
