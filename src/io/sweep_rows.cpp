// include/gyrores/io/sweep_rows.hpp: writing rows, and reading them back for a merge.
#include <gyrores/io/sweep_rows.hpp>

#include <charconv>
#include <fstream>
#include <functional>
#include <map>
#include <utility>

#include <gyrores/core/error.hpp>
#include <gyrores/io/csv.hpp>

namespace gyrores {

GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ROWS_INSTANCES, )

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

// ---------------------------------------------------------------------------------------------
// Writing

// The separator and, in JSON, the next column's key.
void sweep_row_writer::next_key() {
  if (fmt_ == sweep_format::csv) {
    if (col_) out_ += ',';
  } else {
    out_ += col_ ? ",\"" : "{\"";
    out_ += sweep_row_columns()[col_];
    out_ += "\":";
  }
  ++col_;
}

void sweep_row_writer::integer(std::int64_t v) {
  next_key();
  out_ += std::to_string(v);
}

void sweep_row_writer::boolean(bool v) {
  next_key();
  out_ += v ? "true" : "false";
}

void sweep_row_writer::tri(int v) {
  if (v < 0) null();
  else boolean(v != 0);
}

void sweep_row_writer::text(const std::string& v) {
  next_key();
  if (fmt_ == sweep_format::csv) csv_append_field(out_, v);
  else out_ += json(v).dump(-1, ' ', false, json::error_handler_t::replace);
}

void sweep_row_writer::null() {
  next_key();
  if (fmt_ == sweep_format::jsonl) out_ += "null";
}

void sweep_row_writer::finish(const std::array<sweep_status, sweep_check_count>& status, bool failed,
                              const std::string& note) {
  for (int i = 0; i < sweep_check_count; ++i) {
    if (status[i] == sweep_status::none) null();
    else text(sweep_status_text(status[i]));
  }
  boolean(failed);
  if (note.empty()) null();
  else text(note);
  out_ += fmt_ == sweep_format::csv ? "\n" : "}\n";
}

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

// ---------------------------------------------------------------------------------------------
// Reading

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

// What a rows file's first line says: the run, and how to read the reals back.
struct rows_reader {
  sweep_input& r;
  bool keep_text = false;
  bool ended = false;

  void set_run(const json& run, std::int64_t version) {
    r.run = sweep_run_of_version(run, version, r.path);
    keep_text = run.at("type").get<std::string>() != "double";
    r.acc.max_examples = json_to_uint64(run.at("max_examples"), "max_examples");
  }
  void end(const json& e) {
    r.seconds = e.at("seconds").get<double>();
    ended = true;
  }
};

// CSV: the column header, then rows up to the "# end" line.
void read_csv_rows(std::istream& in, const std::string& path, rows_reader& rd) {
  std::string line;
  if (!std::getline(in, line)) throw usage_error("'" + path + "' has no column header");
  const auto header = csv_split_line(line);
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < header.size(); ++i) index[header[i]] = i;
  for (auto& c : sweep_row_columns())
    if (!index.count(c)) throw usage_error("'" + path + "' lacks the column " + c);
  std::vector<std::string> fields;
  const field_getter get = [&](const char* k) -> std::string { return fields.at(index.at(k)); };
  while (std::getline(in, line)) {
    if (line.rfind(csv_end_tag, 0) == 0) return rd.end(json_parse_strict(line.substr(csv_end_tag.size())));
    fields = csv_split_line(line);
    if (fields.size() != header.size()) throw usage_error("'" + path + "': malformed row: " + line);
    rd.r.acc.add(record_from_fields(get, rd.keep_text));
  }
}

// JSON Lines: one object per row up to the {"gyrores_sweep_end": ...} line.
void read_jsonl_rows(std::istream& in, rows_reader& rd) {
  json row;
  const field_getter get = [&](const char* k) -> std::string {
    const auto& v = row.at(k);
    if (v.is_null()) return "";
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    return v.dump();
  };
  std::string line;
  while (std::getline(in, line)) {
    row = json_parse_strict(line);
    if (row.contains("gyrores_sweep_end")) return rd.end(row.at("gyrores_sweep_end"));
    rd.r.acc.add(record_from_fields(get, rd.keep_text));
  }
}

}  // namespace

sweep_input sweep_read_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw usage_error("cannot read '" + path + "'");
  sweep_input r;
  r.path = path;
  rows_reader rd{r};
  std::string line;
  if (!std::getline(in, line)) throw usage_error("'" + path + "' is empty");
  try {
    if (line.rfind(csv_tag, 0) == 0) {
      const auto [version, run] = csv_first_line(line.substr(csv_tag.size()), path);
      rd.set_run(run, version);
      read_csv_rows(in, path, rd);
    } else {
      auto head = json_parse_strict(line);
      if (!head.contains("gyrores_sweep_rows")) throw usage_error("'" + path + "' is not a gyrores sweep rows file");
      const std::int64_t version = head.contains("version") ? json_to_int64(head.at("version"), "version") : 1;
      rd.set_run(head.at("gyrores_sweep_rows"), version);
      read_jsonl_rows(in, rd);
    }
  } catch (const json::exception& e) {
    throw usage_error("'" + path + "' is malformed: " + e.what());
  }
  if (!rd.ended) throw usage_error("'" + path + "' has no end line: the sweep that wrote it did not finish");
  return r;
}

}  // namespace gyrores
