// include/gyrores/io/sweep_summary.hpp: summary JSON and text, accumulator <-> JSON.
#include <gyrores/io/sweep_summary.hpp>

#include <cstdio>
#include <sstream>

#include <gyrores/core/error.hpp>
#include <gyrores/theorem/lobes.hpp>

namespace gyrores {
namespace {

sweep_check_set sweep_checks_of_run(const json& run) {
  sweep_check_set checks = 0;
  for (auto& n : run.at("checks")) checks |= sweep_parse_checks(n.get<std::string>());
  return checks;
}

json pairs_json(const std::vector<sweep_pair_id>& v) {
  json a = json::array();
  for (auto& p : v) a.push_back({p.first, p.second});
  return a;
}

std::vector<sweep_pair_id> pairs_from_json(const json& a) {
  std::vector<sweep_pair_id> v;
  for (auto& p : a) v.push_back({json_to_int64(p.at(0), "tau"), json_to_int64(p.at(1), "sigma")});
  return v;
}

std::uint64_t count_from_json(const json& j) { return json_to_uint64(j, "a count"); }

json extreme_json(const sweep_extreme& e) {
  if (!e.set) return nullptr;
  json j;
  j["value"] = e.str();
  j["pair"] = {e.pair.first, e.pair.second};
  return j;
}

sweep_extreme extreme_from_json(const json& j) {
  sweep_extreme e;
  if (j.is_null()) return e;
  e.set = true;
  e.text = j.at("value").get<std::string>();
  e.value = sweep_text_double(e.text);
  if (sweep_double_text(e.value) == e.text) e.text.clear();
  e.pair = {json_to_int64(j.at("pair").at(0), "tau"), json_to_int64(j.at("pair").at(1), "sigma")};
  return e;
}

json quantiles_json(const sweep_accumulator& a) {
  const auto q = a.quantiles();
  json tq;
  tq["count"] = q.count;
  const std::pair<const char*, double> values[] = {{"min", q.min},       {"p01", q.p01}, {"p10", q.p10},
                                                   {"median", q.median}, {"p90", q.p90}, {"p99", q.p99},
                                                   {"max", q.max}};
  for (const auto& [key, v] : values) {
    if (q.count) tq[key] = sweep_double_text(v);
    else tq[key] = nullptr;
  }
  return tq;
}

// ---------------------------------------------------------------------------------------------
// The text rendering, one block of lines per step.

// " (tau,sigma)"
void put_pair(std::ostream& os, const json& p) {
  os << " (" << p.at(0).get<std::int64_t>() << "," << p.at(1).get<std::int64_t>() << ")";
}

void text_run_line(std::ostream& os, const json& run) {
  os << "gyrores sweep: orders " << run.at("min_order").get<std::int64_t>() << ".." << run.at("max_order").get<std::int64_t>();
  const auto& shard = run.at("shard");
  if (shard.at(1).get<std::int64_t>() > 1)
    os << ", shard " << shard.at(0).get<std::int64_t>() << "/" << shard.at(1).get<std::int64_t>();
  if (run.contains("merged_shards")) os << ", merged from " << run.at("merged_shards").get<std::int64_t>() << " shards";
  os << "; " << run.at("type").get<std::string>();
  if (run.contains("threads") && !run.at("threads").is_null()) {
    const unsigned t = run.at("threads").get<unsigned>();
    os << ", " << t << (t == 1 ? " thread" : " threads");
  }
  os << "\n";
}

void text_counts(std::ostream& os, const json& s) {
  const double sec = s.at("seconds").get<double>();
  const auto pairs = s.at("pairs").get<std::uint64_t>();
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.2f s (%.0f pairs/s)", sec, sec > 0 ? double(pairs) / sec : 0.0);
  os << "  pairs visited       " << pairs << "  in " << buf << "\n";
  os << "  degenerate pairs    " << s.at("degenerate").get<std::uint64_t>() << "  (delta = 2 mod 4)\n";
  const auto& err = s.at("errors");
  if (err.at("count").get<std::uint64_t>() > 0) {
    os << "  ERRORS              " << err.at("count").get<std::uint64_t>() << " pairs could not be computed, first:";
    for (auto& p : err.at("examples")) put_pair(os, p);
    os << "\n";
  }
}

void text_checks(std::ostream& os, const json& s) {
  os << "  checks              violations / pairs checked   (first violating pairs)\n";
  for (auto& [name, t] : s.at("checks").items()) {
    std::string label = "    " + name;
    label.resize(24, ' ');
    os << label << t.at("violations").get<std::uint64_t>() << " / " << t.at("checked").get<std::uint64_t>();
    if (!t.at("examples").empty()) {
      os << "   ";
      for (auto& p : t.at("examples")) put_pair(os, p);
    }
    if (name == "asy-bound") os << "   [x < 1/2]";
    if (name == "paper-node") os << "   [non-degenerate]";
    os << "\n";
  }
}

// Certified runs: which claims hold, proved, for every pair of the range.
void text_proved(std::ostream& os, const json& s) {
  if (!s.contains("proved")) return;
  os << "  certified           every pass above is a proof (exact integers, MPFI, " << s.at("theorem").get<std::string>()
     << ")\n";
  os << "  proved for every pair:";
  if (s.at("proved").empty()) os << " none";
  for (auto& n : s.at("proved")) os << " " << n.get<std::string>();
  os << "\n";
  for (auto& [name, t] : s.at("checks").items()) {
    const auto v = t.at("violations").get<std::uint64_t>();
    if (v == 0) continue;
    os << "  " << name << " fails for " << v << " pairs: "
       << (name == "paper-node" ? "each a proved counterexample (exact integers on the theorem's lobes)"
                                : "a counterexample or a resource limit, named in each row's note")
       << "\n";
  }
}

void text_extreme(std::ostream& os, const json& e, const char* label, const char* relation) {
  os << label << relation;
  if (e.is_null()) os << "n/a\n";
  else {
    os << e.at("value").get<std::string>() << "  at";
    put_pair(os, e.at("pair"));
    os << "\n";
  }
}

void text_ratios(std::ostream& os, const json& s) {
  const auto& q = s.at("t_first_over_proxy");
  os << "  t_first/(pi/|n|)    over " << q.at("count").get<std::uint64_t>() << " non-degenerate pairs";
  if (q.at("count").get<std::uint64_t>() > 0) {
    const char* sep = ": ";
    for (const char* k : {"min", "p01", "p10", "median", "p90", "p99", "max"}) {
      os << sep << k << " " << q.at(k).get<std::string>();
      sep = ", ";
    }
  }
  os << "\n";
  os << "  first minimiser in the paper's lobe k = round(a/(2b)): " << s.at("first_at_paper_node").get<std::uint64_t>()
     << " non-degenerate pairs\n";
}

}  // namespace

json sweep_accumulator_json(const sweep_accumulator& a, sweep_check_set checks) {
  json j;
  j["pairs"] = a.pairs;
  j["degenerate"] = a.degenerate;
  json cj = json::object();
  for (int i = 0; i < sweep_check_count; ++i) {
    if (!((checks >> i) & 1u)) continue;
    json t;
    t["violations"] = a.checks[i].violations;
    t["examples"] = pairs_json(a.checks[i].examples);
    t["checked"] = a.checks[i].checked;
    cj[sweep_check_name(i)] = t;
  }
  j["checks"] = cj;
  j["asy_ratio_max"] = extreme_json(a.asy_ratio_max);
  j["sharp_constant"] = extreme_json(a.sharp_constant);
  j["first_at_paper_node"] = a.first_at_paper_node;
  j["errors"] = {{"count", a.errors.violations}, {"examples", pairs_json(a.errors.examples)}};
  return j;
}

sweep_accumulator sweep_accumulator_from_json(const json& j, std::size_t max_examples) {
  sweep_accumulator a;
  a.max_examples = max_examples;
  a.pairs = count_from_json(j.at("pairs"));
  a.degenerate = count_from_json(j.at("degenerate"));
  for (int i = 0; i < sweep_check_count; ++i) {
    auto f = j.at("checks").find(sweep_check_name(i));
    if (f == j.at("checks").end()) continue;
    a.checks[i].violations = count_from_json(f->at("violations"));
    a.checks[i].checked = count_from_json(f->at("checked"));
    a.checks[i].examples = pairs_from_json(f->at("examples"));
  }
  a.asy_ratio_max = extreme_from_json(j.at("asy_ratio_max"));
  a.sharp_constant = extreme_from_json(j.at("sharp_constant"));
  a.first_at_paper_node = count_from_json(j.at("first_at_paper_node"));
  a.errors.violations = count_from_json(j.at("errors").at("count"));
  a.errors.examples = pairs_from_json(j.at("errors").at("examples"));
  return a;
}

json sweep_summary_json(const sweep_accumulator& a, const json& run, double seconds) {
  json acc = sweep_accumulator_json(a, sweep_checks_of_run(run));
  json j;
  j["format"] = "gyrores-sweep-summary";
  j["version"] = sweep_format_version;
  for (const char* k : {"pairs", "degenerate", "checks", "asy_ratio_max", "sharp_constant"}) j[k] = acc[k];
  j["t_first_over_proxy"] = quantiles_json(a);
  j["first_at_paper_node"] = acc["first_at_paper_node"];
  j["errors"] = acc["errors"];
  if (run.value("certified", false)) {
    // The checks decided by proof with no violation over the range.
    json proved = json::array();
    for (auto& [name, t] : acc["checks"].items())
      if (t.at("violations").get<std::uint64_t>() == 0 && acc["errors"]["count"] == 0)
        proved.push_back(name);
    j["proved"] = proved;
    j["theorem"] = lattice_theorem_id;
  }
  j["seconds"] = seconds;
  j["run"] = run;
  j["values_file"] = nullptr;
  return j;
}

std::string sweep_summary_text(const json& s) {
  std::ostringstream os;
  text_run_line(os, s.at("run"));
  text_counts(os, s);
  text_checks(os, s);
  text_proved(os, s);
  // A run without --certified computes these values without proving them (double rows: the
  // paper's columns within a few ulps, include/gyrores/sweep/evaluate.hpp), so its last digits may
  // be off: "~=" and a line saying so, never "=". A certified run prints proved upper bounds.
  const bool bounds = s.contains("proved");
  const char* relation = bounds ? "<= " : "~= ";
  text_extreme(os, s.at("asy_ratio_max"), "  worst asy ratio     |theta_c - theta_asy| / (pi^3 x^2/a) ", relation);
  text_extreme(os, s.at("sharp_constant"), "  sharp constant      sup |theta_c - theta_asy| a/x^2 ", relation);
  text_ratios(os, s);
  if (!bounds)
    os << "  (values after ~= and the t_first/(pi/|n|) quantiles are computed, not proved: their last digits may be "
          "off by a few units; --certified proves the asy bounds)\n";
  return os.str();
}

}  // namespace gyrores
