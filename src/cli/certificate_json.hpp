// Certificates <-> JSON ("gyrores-certificate/1"). Reading is strict: a missing or mistyped
// field is "malformed" (usage_error), which `gyrores check` reports with exit 2.
#pragma once
#include <gyrores/certify/certificate.hpp>

#include "cli_output.hpp"

namespace gyrores::cli {

inline json certificate_to_json(const certificate& c) {
  json j;
  j["format"] = c.format;
  j["tau"] = json_integer(c.tau.str());
  j["sigma"] = json_integer(c.sigma.str());
  j["digits"] = c.digits;
  j["working_bits"] = c.working_bits;
  j["cover_bits"] = c.cover_bits;
  j["degenerate"] = c.degenerate;
  j["global_minimality"] = c.global_minimality;
  j["global_minimality_note"] = c.global_minimality_note;
  json claims;
  auto pair_or_null = [](const std::pair<std::string, std::string>& p) {
    return p.first.empty() ? json(nullptr) : json::array({p.first, p.second});
  };
  claims["r_res"] = pair_or_null(c.r_res);
  claims["theta_first"] = pair_or_null(c.theta_first);
  claims["t_first"] = pair_or_null(c.t_first);
  j["claims"] = claims;
  j["minimiser_count"] = c.minimiser_count == 0 ? json(nullptr) : json(c.minimiser_count);
  json obs = json::array();
  for (auto& o : c.obligations) {
    json jo;
    jo["id"] = o.id;
    jo["statement"] = o.statement;
    json d;
    for (auto& [k, v] : o.data) d[k] = v;
    jo["data"] = d;
    obs.push_back(jo);
  }
  j["obligations"] = obs;
  return j;
}

// Parses the text; throws usage_error("malformed certificate: ...") on any problem.
inline certificate certificate_from_text(const std::string& text) {
  certificate c;
  try {
    auto j = nlohmann::json::parse(text);
    auto integer = [&](const char* k) {
      const auto& v = j.at(k);
      if (!v.is_number_integer()) throw usage_error(std::string("malformed certificate: ") + k + " is not an integer");
      // Re-read the integer from the raw text of the number (any size).
      return big_int(v.dump());
    };
    c.format = j.at("format").get<std::string>();
    c.tau = integer("tau");
    c.sigma = integer("sigma");
    c.digits = j.at("digits").get<unsigned>();
    c.working_bits = j.at("working_bits").get<unsigned>();
    c.cover_bits = j.at("cover_bits").get<unsigned>();
    c.degenerate = j.at("degenerate").get<bool>();
    c.global_minimality = j.at("global_minimality").get<bool>();
    c.global_minimality_note = j.value("global_minimality_note", "");
    const auto& cl = j.at("claims");
    auto read_pair = [&](const char* k) -> std::pair<std::string, std::string> {
      const auto& v = cl.at(k);
      if (v.is_null()) return {};
      if (!v.is_array() || v.size() != 2 || !v[0].is_string() || !v[1].is_string())
        throw usage_error(std::string("malformed certificate: claims.") + k + " must be [\"lo\", \"hi\"]");
      return {v[0].get<std::string>(), v[1].get<std::string>()};
    };
    c.r_res = read_pair("r_res");
    c.theta_first = read_pair("theta_first");
    c.t_first = read_pair("t_first");
    const auto& mc = j.at("minimiser_count");
    c.minimiser_count = mc.is_null() ? 0 : mc.get<std::size_t>();
    for (const auto& jo : j.at("obligations")) {
      certificate_obligation o;
      o.id = jo.at("id").get<std::string>();
      o.statement = jo.at("statement").get<std::string>();
      for (auto it = jo.at("data").begin(); it != jo.at("data").end(); ++it) o.data[it.key()] = it.value().get<std::string>();
      c.obligations.push_back(o);
    }
  } catch (const usage_error&) {
    throw;
  } catch (const std::exception& e) {
    throw usage_error(std::string("malformed certificate: ") + e.what());
  }
  return c;
}

}  // namespace gyrores::cli
