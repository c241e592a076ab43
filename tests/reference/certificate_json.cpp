// The retired /1 certificates as JSON text (reference/certificate_json.hpp).
#include "reference/certificate_json.hpp"

#include <map>

#include <gyrores/core/error.hpp>

namespace gyrores {

namespace {

using claim_text = std::pair<std::string, std::string>;

json claim_json(const claim_text& claim) {
  return claim.first.empty() ? json(nullptr) : json::array({claim.first, claim.second});
}

json obligations_json(const std::vector<certificate_obligation>& obligations) {
  json out = json::array();
  for (auto& o : obligations) {
    json data;  // null when there is no field (never the case for gyrores' obligations)
    for (auto& [key, value] : o.data) data[key] = value;
    out.push_back(json{{"id", o.id}, {"statement", o.statement}, {"data", data}});
  }
  return out;
}

[[noreturn]] void malformed(const std::string& what) { throw usage_error("malformed certificate: " + what); }

// The text of every number at the top level of a JSON object, as written: nlohmann-json holds
// integers of 64 bits and reads a longer one as a double, so the digits of tau and sigma of a
// pair such as (10^30 + 1, 10^30) survive only in the text (docs/formats.md: integers of any
// size).
class top_level_numbers : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::map<std::string, std::string> text;

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t v) override { return record(std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override { return record(std::to_string(v)); }
  bool number_float(number_float_t, const string_t& s) override { return record(s); }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return ++depth_, true; }
  bool key(string_t& k) override {
    if (depth_ == 1) key_ = k;
    return true;
  }
  bool end_object() override { return --depth_, true; }
  bool start_array(std::size_t) override { return ++depth_, true; }
  bool end_array() override { return --depth_, true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::json::exception&) override { return false; }

 private:
  bool record(const std::string& number) {
    if (depth_ == 1) text[key_] = number;
    return true;
  }
  int depth_ = 0;
  std::string key_;
};

bool integer_literal(const std::string& s) {
  std::size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}

// An integer of any size, from the text of the JSON number.
big_int read_integer(const nlohmann::json& j, const top_level_numbers& numbers, const char* key) {
  auto it = numbers.text.find(key);
  if (!j.at(key).is_number() || it == numbers.text.end() || !integer_literal(it->second))
    malformed(std::string(key) + " is not an integer");
  return big_int(it->second);
}

claim_text read_claim(const nlohmann::json& claims, const char* key) {
  const auto& v = claims.at(key);
  if (v.is_null()) return {};
  if (!v.is_array() || v.size() != 2 || !v[0].is_string() || !v[1].is_string())
    malformed(std::string("claims.") + key + " must be [\"lo\", \"hi\"]");
  return {v[0].get<std::string>(), v[1].get<std::string>()};
}

certificate_obligation read_obligation(const nlohmann::json& jo) {
  certificate_obligation o;
  o.id = jo.at("id").get<std::string>();
  o.statement = jo.at("statement").get<std::string>();
  const auto& data = jo.at("data");
  for (auto it = data.begin(); it != data.end(); ++it) o.data[it.key()] = it.value().get<std::string>();
  return o;
}

certificate read_certificate(const nlohmann::json& j, const top_level_numbers& numbers) {
  certificate c;
  c.format = j.at("format").get<std::string>();
  c.tau = read_integer(j, numbers, "tau");
  c.sigma = read_integer(j, numbers, "sigma");
  c.digits = json_to_unsigned(j.at("digits"), "digits");
  c.working_bits = json_to_unsigned(j.at("working_bits"), "working_bits");
  c.cover_bits = json_to_unsigned(j.at("cover_bits"), "cover_bits");
  c.degenerate = j.at("degenerate").get<bool>();
  c.global_minimality = j.at("global_minimality").get<bool>();
  c.global_minimality_note = j.value("global_minimality_note", "");
  const auto& claims = j.at("claims");
  c.r_res = read_claim(claims, "r_res");
  c.theta_first = read_claim(claims, "theta_first");
  c.t_first = read_claim(claims, "t_first");
  const auto& count = j.at("minimiser_count");
  c.minimiser_count = count.is_null() ? 0 : json_to_uint64(count, "minimiser_count");
  for (const auto& jo : j.at("obligations")) c.obligations.push_back(read_obligation(jo));
  return c;
}

}  // namespace

json certificate_to_json(const certificate& c) {
  json claims{{"r_res", claim_json(c.r_res)}, {"theta_first", claim_json(c.theta_first)},
              {"t_first", claim_json(c.t_first)}};
  return json{{"format", c.format},
              {"tau", json_integer(c.tau)},
              {"sigma", json_integer(c.sigma)},
              {"digits", c.digits},
              {"working_bits", c.working_bits},
              {"cover_bits", c.cover_bits},
              {"degenerate", c.degenerate},
              {"global_minimality", c.global_minimality},
              {"global_minimality_note", c.global_minimality_note},
              {"claims", claims},
              {"minimiser_count", c.minimiser_count == 0 ? json(nullptr) : json(c.minimiser_count)},
              {"obligations", obligations_json(c.obligations)}};
}

certificate certificate_from_text(const std::string& text) {
  try {
    auto j = nlohmann::json::parse(text);
    top_level_numbers numbers;
    nlohmann::json::sax_parse(text, &numbers);
    return read_certificate(j, numbers);
  } catch (const usage_error&) {
    throw;
  } catch (const std::exception& e) {
    malformed(e.what());
  }
}

}  // namespace gyrores
