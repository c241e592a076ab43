// Checks of REPORT.md's summary of findings and of its Pareto table (tests/test_figures.cpp's
// report test). Each returns the problems it finds, one line each, so that a test can also feed it
// a damaged report and see it complain. The anchor rule is written here again from GitHub's
// description, not taken from src/report.
#pragma once
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace gyrores::test {

struct md_heading {
  int level;
  std::string text;
  std::size_t pos;  // of its first '#'
};

inline std::vector<md_heading> md_headings(const std::string& md) {
  std::vector<md_heading> out;
  std::size_t pos = 0;
  while (pos < md.size()) {
    std::size_t end = md.find('\n', pos);
    if (end == std::string::npos) end = md.size();
    const std::string line = md.substr(pos, end - pos);
    std::size_t k = 0;
    while (k < line.size() && line[k] == '#') ++k;
    if (k > 0 && k < line.size() && line[k] == ' ') out.push_back({int(k), line.substr(k + 1), pos});
    pos = end + 1;
  }
  return out;
}

// GitHub's heading anchor: lower case; letters, digits, '-' and '_' kept; each space made '-';
// every other character dropped.
inline std::string github_anchor(const std::string& heading) {
  std::string a;
  for (unsigned char ch : heading) {
    if (std::isalnum(ch) || ch == '_' || ch == '-')
      a += char(std::tolower(ch));
    else if (ch == ' ')
      a += '-';
  }
  return a;
}

// The text under heading i: up to the next heading of the same or a higher level.
inline std::string md_section_text(const std::string& md, const std::vector<md_heading>& hs, std::size_t i) {
  std::size_t end = md.size();
  for (std::size_t j = i + 1; j < hs.size(); ++j)
    if (hs[j].level <= hs[i].level) {
      end = hs[j].pos;
      break;
    }
  return md.substr(hs[i].pos, end - hs[i].pos);
}

// Whether `number` occurs in `text` as a whole number (not inside a longer one).
inline bool has_number(const std::string& text, const std::string& number) {
  const auto digit = [&](std::size_t i) { return i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); };
  for (std::size_t p = text.find(number); p != std::string::npos; p = text.find(number, p + 1)) {
    const std::size_t q = p + number.size();
    const bool before_ok = p == 0 || !(digit(p - 1) || text[p - 1] == '.');
    const bool after_ok = !digit(q) && !(q < text.size() && (text[q] == '.' || text[q] == 'e') && (digit(q + 1) || (q + 1 < text.size() && (text[q + 1] == '+' || text[q + 1] == '-'))));
    if (before_ok && after_ok) return true;
  }
  return false;
}

// The summary: a "## Summary of findings" above the first numbered section, 5 to 10 bullets, each
// ending with a link to an existing heading whose section prints every number of the bullet; a
// share "P% of H_q(0)" must be 200 times the number just before it, to P's last digit.
inline std::vector<std::string> summary_problems(const std::string& md) {
  std::vector<std::string> bad;
  const auto hs = md_headings(md);
  std::size_t summary = hs.size(), first_section = hs.size();
  for (std::size_t i = 0; i < hs.size(); ++i) {
    if (hs[i].level == 2 && hs[i].text == "Summary of findings" && summary == hs.size()) summary = i;
    if (hs[i].level == 2 && !hs[i].text.empty() && std::isdigit(static_cast<unsigned char>(hs[i].text[0])) && first_section == hs.size())
      first_section = i;
  }
  if (summary == hs.size()) return {"no '## Summary of findings'"};
  if (first_section == hs.size()) return {"no numbered section"};
  if (hs[summary].pos > hs[first_section].pos) bad.push_back("the summary comes after '" + hs[first_section].text + "'");
  const std::string body = md_section_text(md, hs, summary);
  std::vector<std::string> bullets;
  std::istringstream lines(body);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("- ", 0) == 0) bullets.push_back(line);
  if (bullets.size() < 5 || bullets.size() > 10) bad.push_back("the summary has " + std::to_string(bullets.size()) + " bullets");
  const std::regex link(R"(\(\[[^\]]*\]\(#([^)]+)\)\)\s*$)");
  const std::regex share(R"((\d+(?:\.\d+)?)% of H_q\(0\))");
  const std::regex number(R"(\d+(?:\.\d+)?(?:e[+-]?\d+)?)");
  for (const auto& b : bullets) {
    std::smatch m;
    if (!std::regex_search(b, m, link)) {
      bad.push_back("no section link at the end of: " + b);
      continue;
    }
    const std::string anchor = m[1], text = b.substr(0, std::size_t(m.position(0)));
    std::size_t target = hs.size();
    for (std::size_t i = 0; i < hs.size(); ++i)
      if (github_anchor(hs[i].text) == anchor) target = i;
    if (target == hs.size() || target == summary) {
      bad.push_back("the link #" + anchor + " names no section");
      continue;
    }
    const std::string section = md_section_text(md, hs, target);
    // The shares: P% of H_q(0) against the number before it.
    std::string rest = text;
    for (std::sregex_iterator it(text.begin(), text.end(), share), end; it != end; ++it) {
      const std::string before = text.substr(0, std::size_t(it->position(0)));
      std::string last;
      for (std::sregex_iterator n(before.begin(), before.end(), number); n != std::sregex_iterator(); ++n) last = n->str();
      const std::string p = (*it)[1];
      const auto dot = p.find('.');
      const double unit = std::pow(10.0, -double(dot == std::string::npos ? 0 : p.size() - dot - 1));
      const double expected = 200 * std::strtod(last.c_str(), nullptr), printed = std::strtod(p.c_str(), nullptr);
      if (last.empty() || std::fabs(printed - expected) > 0.5 * unit * (1 + 1e-9))
        bad.push_back(p + "% is not 200 x " + (last.empty() ? std::string("(no number)") : last) + " in: " + b);
      rest.replace(rest.find(it->str()), it->str().size(), std::string(it->str().size(), ' '));
    }
    for (std::sregex_iterator n(rest.begin(), rest.end(), number), end; n != end; ++n)
      if (!has_number(section, n->str())) bad.push_back(n->str() + " is not in section '" + hs[target].text + "': " + b);
  }
  return bad;
}

// Section 5's table: at most 15 pairs, its first and last rows the ends of the front, and
// pareto-front.csv (`csv`) holds the whole front (as many lines as the section says the front has),
// each table row among them with the same r_res and t_first.
inline std::vector<std::string> pareto_table_problems(const std::string& md, const std::string& csv) {
  std::vector<std::string> bad;
  const auto hs = md_headings(md);
  std::size_t five = hs.size();
  for (std::size_t i = 0; i < hs.size(); ++i)
    if (hs[i].level == 2 && hs[i].text.rfind("5. Pareto front", 0) == 0) five = i;
  if (five == hs.size()) return {"no section 5"};
  const std::string sec = md_section_text(md, hs, five);
  std::smatch m;
  if (!std::regex_search(sec, m, std::regex(R"((\d+) of (\d+) pairs are non-dominated)"))) return {"no front size in section 5"};
  const std::size_t front = std::stoul(m[1]);
  std::vector<std::string> csv_rows;
  std::istringstream cl(csv);
  std::string line;
  std::getline(cl, line);  // the header
  if (line.rfind("tau,sigma,", 0) != 0) bad.push_back("pareto-front.csv has no header");
  while (std::getline(cl, line))
    if (!line.empty()) csv_rows.push_back(line);
  if (csv_rows.size() != front)
    bad.push_back("pareto-front.csv has " + std::to_string(csv_rows.size()) + " pairs, the front " + std::to_string(front));
  // Table rows: "| (t, s) | delta | n | r_res | t_first | proxy |".
  const std::regex row(R"(\| \((\d+), (\d+)\) \| \d+ \| [^|]+ \| ([^|]+) \| ([^|]+) \| [^|]+ \|)");
  std::vector<std::string> keys;
  std::istringstream ml(sec);
  while (std::getline(ml, line)) {
    std::smatch r;
    if (!std::regex_match(line, r, row)) continue;
    std::string r_res = r[3].str(), t = r[4].str();
    r_res = r_res.substr(0, r_res.find(' '));  // "0 (exact)" -> "0"
    const std::string key = r[1].str() + "," + r[2].str() + ",";
    keys.push_back(key);
    bool found = false;
    for (const auto& c : csv_rows)
      if (c.rfind(key, 0) == 0) {
        found = true;
        std::vector<std::string> f;
        std::istringstream cs(c);
        for (std::string x; std::getline(cs, x, ',');) f.push_back(x);
        // tau,sigma,order,delta,degenerate,n,r_res,t_first,t_min_paper
        const bool same_r = f.size() > 7 && (f[6] == r_res || (r_res == "0" && f[4] == "true"));
        if (!same_r || f[7] != t) bad.push_back("the row of (" + r[1].str() + ", " + r[2].str() + ") differs from the CSV: " + c);
      }
    if (!found) bad.push_back("(" + r[1].str() + ", " + r[2].str() + ") of the table is not in the CSV");
  }
  if (keys.size() > 15) bad.push_back("the Pareto table has " + std::to_string(keys.size()) + " rows");
  if (keys.empty()) bad.push_back("the Pareto table has no rows");
  if (!keys.empty() && !csv_rows.empty() && (csv_rows.front().rfind(keys.front(), 0) != 0 || csv_rows.back().rfind(keys.back(), 0) != 0))
    bad.push_back("the table does not start and end with the front's ends");
  return bad;
}

}  // namespace gyrores::test
