// include/gyrores/io/sweep_rows.hpp: the run description, CSV fields, rows written and read back.
#include <gyrores/io/sweep_rows.hpp>

#include <charconv>
#include <fstream>
#include <functional>
#include <map>
#include <tuple>
#include <utility>

#include <gyrores/core/error.hpp>

namespace gyrores {

json sweep_run_json(const sweep_config& c, const std::string& type, unsigned digits) {
  json j;
  j["min_order"] = c.min_order < 3 ? 3 : c.min_order;
  j["max_order"] = c.max_order;
  j["shard"] = {c.shard_index, c.shard_count};
  j["checks"] = sweep_check_names(c.checks);
  j["max_examples"] = c.max_examples;
  j["type"] = type;
  j["digits"] = digits;
  j["method"] = sweep_rows_method;
  if (c.certified) j["certified"] = true;  // absent in uncertified runs (files of earlier versions)
  return j;
}

json sweep_run_of_version(json run, std::int64_t version, const std::string& path) {
  if (version == sweep_format_version) return run;
  if (version != 1)
    throw usage_error("'" + path + "' is a sweep output of format version " + std::to_string(version) +
                      ", which this gyrores does not read (it reads versions 1 and " +
                      std::to_string(sweep_format_version) + ")");
  for (const auto& name : run.at("checks"))
    if (name == "cross-check")
      throw usage_error("'" + path + "' (sweep format version 1) ran the check cross-check, which sweeps no longer "
                        "have: merge it with the gyrores that wrote it, or run that sweep again");
  run.erase("cross_check_max_order");
  return run;
}

std::string sweep_run_mismatch(const json& found, const json& wanted) {
  if (!found.is_object() || !found.contains("method"))
    return "it was written by an earlier version of gyrores, whose rows came from the lattice method's solver "
           "(these come from the theorem's root, " + std::string(sweep_rows_method) + ")";
  std::string keys;
  for (const auto& [k, v] : wanted.items())
    if (!found.contains(k) || found.at(k) != v) keys += (keys.empty() ? "" : ", ") + k;
  for (const auto& [k, v] : found.items())
    if (!wanted.contains(k)) keys += (keys.empty() ? "" : ", ") + k;
  if (keys.empty()) keys = "the order of its keys";
  return "it differs in " + keys + " (" + found.dump() + " vs " + wanted.dump() + ")";
}

void csv_append_field(std::string& out, std::string_view v) {
  if (v.find_first_of(",\"\n\r") == std::string_view::npos) {
    out += v;
    return;
  }
  out += '"';
  for (char ch : v) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
}

std::vector<std::string> csv_split_line(std::string_view line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted && ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cur += '"';  // a doubled quote inside quotes
      ++i;
    } else if (ch == '"') {
      quoted = !quoted;
    } else if (ch == ',' && !quoted) {
      out.push_back(std::move(cur));
      cur.clear();
    } else {
      cur += ch;
    }
  }
  out.push_back(std::move(cur));
  return out;
}

sweep_format sweep_parse_format(const std::string& s) {
  if (s == "csv") return sweep_format::csv;
  if (s == "jsonl") return sweep_format::jsonl;
  throw usage_error("rows format must be csv or jsonl, got '" + s + "'");
}

const char* sweep_format_name(sweep_format f) { return f == sweep_format::csv ? "csv" : "jsonl"; }

const std::vector<std::string>& sweep_row_columns() {
  static const std::vector<std::string> cols = {
      "tau", "sigma", "order", "delta_mod4", "r_res", "theta_first", "t_first", "t_min_paper", "t_first_over_proxy",
      "first_at_paper_node", "paper_lobe_min", "asy_error", "asy_bound", "asy_ratio", "asy_constant",
      "minimiser_count", "strand_offset_min", "check_degeneracy", "check_paper_node", "check_asy_bound",
      "check_structure", "failed", "note"};
  return cols;
}

// Appends the fields of one row in order: integers and booleans bare, text quoted (CSV: only
// when needed; JSON: always), null = not applicable (empty CSV field, JSON null). Not in an
// anonymous namespace: sweep_format_row's instances use it.
struct sweep_row_writer {
  std::string& out;
  sweep_format fmt;
  std::size_t col = 0;

  // The separator and, in JSON, the next column's key.
  void next_key() {
    if (fmt == sweep_format::csv) {
      if (col) out += ',';
    } else {
      out += col ? ",\"" : "{\"";
      out += sweep_row_columns()[col];
      out += "\":";
    }
    ++col;
  }
  void integer(std::int64_t v) {
    next_key();
    out += std::to_string(v);
  }
  void boolean(bool v) {
    next_key();
    out += v ? "true" : "false";
  }
  void null() {
    next_key();
    if (fmt == sweep_format::jsonl) out += "null";
  }
  void text(const std::string& v) {
    next_key();
    if (fmt == sweep_format::csv) csv_append_field(out, v);
    else out += json(v).dump(-1, ' ', false, json::error_handler_t::replace);
  }
  void tri(int v) {  // -1: null, else a boolean
    if (v < 0) null();
    else boolean(v != 0);
  }
};

template <class T> void sweep_format_row(std::string& out, const sweep_row<T>& r, sweep_format fmt, unsigned digits) {
  sweep_row_writer w{out, fmt};
  auto real = [&](bool have, const T& v) {
    if (have) w.text(sweep_real_text(v, digits));
    else w.null();
  };
  const bool ok = !r.failed;
  w.integer(r.tau);
  w.integer(r.sigma);
  w.integer(r.tau + r.sigma);
  w.integer(r.delta_mod4);
  real(ok, r.r_res);
  real(ok, r.theta_first);
  real(ok, r.t_first);
  real(ok, r.t_min_paper);
  real(ok && r.has_ratio, r.t_ratio);
  w.tri(ok ? r.first_at_paper_node : -1);
  w.tri(ok ? r.paper_lobe_min : -1);
  real(ok && r.has_asy, r.asy_error);
  real(ok && r.has_asy, r.asy_bound);
  real(ok && r.has_asy, r.asy_ratio);
  real(ok && r.has_asy, r.asy_constant);
  if (ok) w.integer(r.minimiser_count);
  else w.null();
  w.integer(r.strand_offset);
  for (int i = 0; i < sweep_check_count; ++i) {
    if (r.status[i] == sweep_status::none) w.null();
    else w.text(sweep_status_text(r.status[i]));
  }
  w.boolean(r.failed);
  if (r.note.empty()) w.null();
  else w.text(r.note);
  out += fmt == sweep_format::csv ? "\n" : "}\n";
}

#define GYRORES_SWEEP_ROWS_INSTANCES(PREFIX, T) \
  PREFIX template void sweep_format_row<T>(std::string&, const sweep_row<T>&, sweep_format, unsigned);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ROWS_INSTANCES, )

std::string sweep_rows_header(const json& run, sweep_format fmt) {
  if (fmt == sweep_format::csv) {
    std::string h = "# gyrores-sweep-rows/" + std::to_string(sweep_format_version) + " " + run.dump() + "\n";
    const auto& cols = sweep_row_columns();
    for (std::size_t i = 0; i < cols.size(); ++i) h += (i ? "," : "") + cols[i];
    return h + "\n";
  }
  json j;
  j["gyrores_sweep_rows"] = run;
  j["version"] = sweep_format_version;
  return j.dump() + "\n";
}

std::string sweep_rows_trailer(std::uint64_t pairs, double seconds, sweep_format fmt) {
  json e;
  e["pairs"] = pairs;
  e["seconds"] = seconds;
  if (fmt == sweep_format::csv) return "# end " + e.dump() + "\n";
  json j;
  j["gyrores_sweep_end"] = e;
  return j.dump() + "\n";
}

namespace {

// The CSV first line: "# gyrores-sweep-rows/2 {run}"; version 1 had no "/1".
const std::string csv_tag = "# gyrores-sweep-rows";
const std::string csv_end_tag = "# end ";

// The version and the run of a CSV first line (after the tag).
std::pair<std::int64_t, json> csv_first_line(const std::string& rest, const std::string& path) {
  if (rest.rfind(' ', 0) == 0) return {1, json_parse_strict(rest.substr(1))};
  const std::size_t space = rest.find(' ');
  std::int64_t version = 0;
  if (rest.rfind('/', 0) != 0 || space == std::string::npos ||
      std::from_chars(rest.data() + 1, rest.data() + space, version).ptr != rest.data() + space)
    throw usage_error("'" + path + "' is not a gyrores sweep rows file");
  return {version, json_parse_strict(rest.substr(space + 1))};
}

// A row's field by column name, as text ("" = not applicable).
using field_getter = std::function<std::string(const char*)>;

std::int64_t integer_field(const field_getter& get, const char* k) {
  const std::string v = get(k);
  std::int64_t x = 0;
  auto res = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || res.ec != std::errc() || res.ptr != v.data() + v.size())
    throw compute_error(std::string("row field ") + k + " is not an integer: '" + v + "'");
  return x;
}

sweep_status status_field(const field_getter& get, int i) {
  const std::string s = get(sweep_check_column(i));
  if (s.empty()) return sweep_status::none;
  if (s == "pass") return sweep_status::pass;
  if (s == "fail") return sweep_status::fail;
  throw compute_error(std::string("row field ") + sweep_check_column(i) + " must be pass, fail or empty: '" + s + "'");
}

// A row as the summary needs it; keep_text: keep the extremes' text (types wider than double).
sweep_record record_from_fields(const field_getter& get, bool keep_text) {
  sweep_record r;
  r.tau = integer_field(get, "tau");
  r.sigma = integer_field(get, "sigma");
  r.delta_mod4 = int(integer_field(get, "delta_mod4"));
  r.failed = get("failed") == "true";
  for (int i = 0; i < sweep_check_count; ++i) r.status[i] = status_field(get, i);
  const std::string fp = get("first_at_paper_node");
  r.first_at_paper_node = fp.empty() ? -1 : fp == "true" ? 1 : 0;
  const std::string tr = get("t_first_over_proxy");
  if (!tr.empty()) {
    r.has_ratio = true;
    r.t_ratio = sweep_text_double(tr);
  }
  const std::string ar = get("asy_ratio"), ac = get("asy_constant");
  if (!ar.empty()) {
    r.has_asy = true;
    r.asy_ratio = sweep_text_double(ar);
    r.asy_constant = sweep_text_double(ac);
    if (keep_text) {
      r.asy_ratio_text = ar;
      r.asy_constant_text = ac;
    }
  }
  return r;
}

}  // namespace

sweep_input sweep_read_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw usage_error("cannot read '" + path + "'");
  sweep_input r;
  r.path = path;
  std::string line;
  if (!std::getline(in, line)) throw usage_error("'" + path + "' is empty");
  // CSV: the first line, the column header, rows, "# end {...}". JSON Lines: the first line,
  // one object per row, {"gyrores_sweep_end": ...}.
  const bool csv = line.rfind(csv_tag, 0) == 0;
  std::vector<std::string> header, fields;
  std::map<std::string, std::size_t> index;
  json row;
  const field_getter get = [&](const char* k) -> std::string {
    if (csv) return fields.at(index.at(k));
    const auto& v = row.at(k);
    if (v.is_null()) return "";
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    return v.dump();
  };
  bool ended = false;
  try {
    json run;
    std::int64_t version = 1;
    if (csv) {
      std::tie(version, run) = csv_first_line(line.substr(csv_tag.size()), path);
    } else {
      row = json_parse_strict(line);
      if (!row.contains("gyrores_sweep_rows")) throw usage_error("'" + path + "' is not a gyrores sweep rows file");
      if (row.contains("version")) version = json_to_int64(row.at("version"), "version");
      run = row.at("gyrores_sweep_rows");
    }
    r.run = sweep_run_of_version(run, version, path);
    const bool keep_text = run.at("type").get<std::string>() != "double";
    r.acc.max_examples = json_to_uint64(run.at("max_examples"), "max_examples");
    if (csv) {
      if (!std::getline(in, line)) throw usage_error("'" + path + "' has no column header");
      header = csv_split_line(line);
      for (std::size_t i = 0; i < header.size(); ++i) index[header[i]] = i;
      for (auto& c : sweep_row_columns())
        if (!index.count(c)) throw usage_error("'" + path + "' lacks the column " + c);
    }
    json end;
    while (!ended && std::getline(in, line)) {
      if (csv && line.rfind(csv_end_tag, 0) == 0) {
        end = json_parse_strict(line.substr(csv_end_tag.size()));
        ended = true;
      } else if (csv) {
        fields = csv_split_line(line);
        if (fields.size() != header.size()) throw usage_error("'" + path + "': malformed row: " + line);
        r.acc.add(record_from_fields(get, keep_text));
      } else if ((row = json_parse_strict(line)).contains("gyrores_sweep_end")) {
        end = row.at("gyrores_sweep_end");
        ended = true;
      } else {
        r.acc.add(record_from_fields(get, keep_text));
      }
    }
    if (ended) r.seconds = end.at("seconds").get<double>();
  } catch (const json::exception& e) {
    throw usage_error("'" + path + "' is malformed: " + e.what());
  }
  if (!ended) throw usage_error("'" + path + "' has no end line: the sweep that wrote it did not finish");
  return r;
}

}  // namespace gyrores
