// The report's summary of findings (sections.hpp): the sentences the sections recorded in
// context::findings, each linked to its section by the heading's GitHub anchor, and the share of
// H_q(0) that the sentences give for an energy (report/scales.hpp's proved share, in plain text).
#include <cctype>
#include <cstdlib>
#include <sstream>

#include <gyrores/report/scales.hpp>

#include "frontend/number_text.hpp"
#include "report/sections.hpp"

namespace gyrores::report {

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

std::string share_of_initial_energy(const enclosure& e) {
  constexpr unsigned digits = 3;
  if (e.hi_rational() == 0) return "0% of H_q(0)";
  const enclosure share = scaled(e, share_factor());
  if (const auto r = share.rounded(digits)) return frontend::plain(*r) + "% of H_q(0)";
  const auto [lo, hi] = share.outward(digits);
  return frontend::plain(lo) + "-" + frontend::plain(hi) + "% of H_q(0)";
}

std::string share_of_initial_energy(const proved_real& share) { return frontend::plain(share) + "% of H_q(0)"; }

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
