// src/checker/checker_support.hpp
#include "checker_support.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <set>
#include <vector>

namespace gyrores_checker::support {

std::string text_of(const Z& z) {
  char* p = fmpz_get_str(nullptr, 10, z.v);
  std::string s(p);
  flint_free(p);
  return s.size() > 60 ? s.substr(0, 28) + "..." + s.substr(s.size() - 28) : s;
}

bool all_digits(const std::string& s, std::size_t from) {
  return from < s.size() && std::all_of(s.begin() + long(from), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string decimal_field(const json& j, const std::string& name, std::size_t max_len) {
  if (!j.is_string()) throw malformed(name + " must be a decimal string");
  const std::string s = j.get<std::string>();
  std::size_t i = s.size() && s[0] == '-' ? 1 : 0, start = i;
  while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i;
  bool ok = i > start;
  if (ok && i < s.size() && s[i] == '.') {
    std::size_t f = ++i;
    while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i;
    ok = i > f;
  }
  if (ok && i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t e = i;
    while (i < s.size() && std::isdigit((unsigned char)s[i])) ++i;
    ok = i > e && i - e <= 9;
  }
  if (!ok || i != s.size() || s.size() > max_len) throw malformed(name + " is not a decimal number: '" + s.substr(0, 40) + "'");
  return s;
}

bracket bracket_field(const json& j, const std::string& name, std::size_t max_len) {
  if (!j.is_array() || j.size() != 2) throw malformed(name + " must be [\"lo\", \"hi\"]");
  return {decimal_field(j[0], name + "[0]", max_len), decimal_field(j[1], name + "[1]", max_len)};
}

B ball_of(const std::string& decimal, long prec) {
  B b;
  if (arb_set_str(b.v, decimal.c_str(), prec) != 0) throw malformed("unreadable decimal '" + decimal + "'");
  return b;
}

json parse_without_duplicate_keys(const std::string& text) {
  std::vector<std::set<std::string>> open;
  const json::parser_callback_t on_event = [&](int, json::parse_event_t ev, json& parsed) {
    if (ev == json::parse_event_t::object_start) open.emplace_back();
    if (ev == json::parse_event_t::object_end && !open.empty()) open.pop_back();
    if (ev == json::parse_event_t::key && !open.empty() && !open.back().insert(parsed.get<std::string>()).second)
      throw malformed("the key '" + parsed.get<std::string>().substr(0, 60) + "' appears twice in one object");
    return true;
  };
  try {
    return json::parse(text, on_event);
  } catch (const malformed&) {
    throw;
  } catch (const std::exception& e) {
    throw malformed(std::string("not JSON: ") + e.what());
  }
}

std::string one_line(const std::string& s) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n') out += "\\n";
    else if (c < 0x20 || c == 0x7f) out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    else out += ch;
  }
  return out;
}

void exact_keys(const json& j, const std::set<std::string>& keys, const std::string& where) {
  if (!j.is_object()) throw malformed(where + " must be an object");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!keys.count(it.key())) throw malformed("unknown field '" + it.key() + "' in " + where);
  for (const auto& key : keys)
    if (!j.contains(key)) throw malformed("missing field '" + key + "' in " + where);
}

long integer_in(const json& j, const std::string& name, long lo, long hi) {
  // nlohmann reads 0..2^64-1 as unsigned, negatives as signed: compare before any conversion.
  const bool ok = j.is_number_unsigned() ? j.get<std::uint64_t>() <= std::uint64_t(hi) && long(j.get<std::uint64_t>()) >= lo
                  : j.is_number_integer() && j.get<std::int64_t>() >= lo && j.get<std::int64_t>() <= hi;
  if (!ok) throw malformed(name + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return long(j.get<std::int64_t>());
}

B lobe_H(const B& x, const B& u, long prec) {
  B s, co, h;
  arb_sin_cos(s.v, co.v, u.v, prec);
  arb_mul(s.v, s.v, x.v, prec);
  arb_atan2(h.v, s.v, co.v, prec);
  arb_addmul(h.v, x.v, u.v, prec);
  return h;
}

B lobe_G(const B& x2, const B& one_m_x2, const B& u, long prec) {
  B s, co, e, g;
  arb_sin_cos(s.v, co.v, u.v, prec);
  arb_sqr(s.v, s.v, prec);
  arb_sqr(co.v, co.v, prec);
  arb_mul(e.v, x2.v, s.v, prec);
  arb_add(e.v, e.v, co.v, prec);
  arb_sqr(g.v, s.v, prec);
  arb_mul(g.v, g.v, x2.v, prec);
  arb_mul(g.v, g.v, one_m_x2.v, prec);
  arb_div(g.v, g.v, e.v, prec);
  return g;
}

bool decimal_exact(const std::string& s, long max_exp10, fmpq_t out) {
  const auto e = s.find_first_of("eE");
  std::string mant = s.substr(0, e);
  long exp10 = e == std::string::npos ? 0 : std::stol(s.substr(e + 1));
  const auto dot = mant.find('.');
  if (dot != std::string::npos) {
    exp10 -= long(mant.size() - dot - 1);
    mant.erase(dot, 1);
  }
  if (exp10 > max_exp10 || exp10 < -max_exp10) return false;
  Z m, p;
  fmpz_set_str(m.v, mant.c_str(), 10);
  fmpz_set_ui(p.v, 10);
  fmpz_pow_ui(p.v, p.v, ulong(exp10 < 0 ? -exp10 : exp10));
  if (exp10 >= 0) {
    fmpz_mul(m.v, m.v, p.v);
    fmpq_set_fmpz_frac(out, m.v, Z(1).v);
  } else fmpq_set_fmpz_frac(out, m.v, p.v);
  return true;
}

int claim_holds(const bracket& claim, const B& enclosure, long digits, const char* zero_rule, const std::string& name,
                long prec) {
  B lo = ball_of(claim.lo, prec), hi = ball_of(claim.hi, prec), d;
  if (zero_rule) {
    if (!arb_is_zero(lo.v) || !arb_is_zero(hi.v)) throw fails(name + zero_rule);
    return 1;
  }
  if (arb_lt(enclosure.v, lo.v) || arb_gt(enclosure.v, hi.v)) throw fails(name + " does not contain the value");
  // lo <= every point of the enclosure <= hi, decided exactly (balls, never by rounding).
  arb_sub(d.v, enclosure.v, lo.v, prec);
  bool inside = arb_is_nonnegative(d.v);
  arb_sub(d.v, hi.v, enclosure.v, prec);
  inside = inside && arb_is_nonnegative(d.v);
  if (!inside) return 0;
  // Width: hi - lo <= 10^-digits lo (enclosures of positive values).
  if (!arb_is_positive(lo.v)) throw fails(name + ": a positive quantity needs a positive lower end");
  B w, lim;
  arb_sub(w.v, hi.v, lo.v, prec);
  arb_set_ui(lim.v, 10);
  arb_pow_ui(lim.v, lim.v, ulong(digits), prec);
  arb_mul(w.v, w.v, lim.v, prec);
  if (arb_gt(w.v, lo.v)) throw fails(name + " is wider than " + std::to_string(digits) + " digits");
  return arb_le(w.v, lo.v) ? 1 : 0;
}

}  // namespace gyrores_checker::support
