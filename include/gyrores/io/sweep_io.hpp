// Sweep files: per-pair rows, the JSON summary, the resume state, and the merge of shards.
// Needs nlohmann-json (header-only); the umbrella header gyrores.hpp does not include this file.
//
// Rows (--out FILE, CSV or JSON Lines), one per pair in enumeration order, framed by two
// metadata lines so that a file describes itself:
//   CSV:   "# gyrores-sweep-rows {run}", the column header, rows, "# end {pairs, seconds}"
//   JSONL: {"gyrores_sweep_rows": {run}}, one object per row, {"gyrores_sweep_end": {...}}
// {run} holds the sweep configuration (orders, shard, checks, cross-check limit, real type,
// digits). Columns: sweep_row_columns(). Reals are text (JSON strings): doubles in the shortest
// form that reads back exactly, wider types with `digits` correctly rounded digits. Not
// applicable: empty field (CSV) or null (JSONL). Check columns: "pass", "fail" or empty.
// The file is written as FILE.part and renamed to FILE when the sweep completes, so FILE is
// never partial.
//
// Summary (--summary FILE, written to FILE.part then renamed): the keys of the issue (pairs,
// degenerate, checks{name: {violations, examples, checked}}, asy_ratio_max and sharp_constant
// {value, pair}, t_first_over_proxy {count, min, p01, p10, median, p90, p99, max}, seconds) plus
// errors, first_at_paper_node, run (the configuration) and values_file.
//
// Merge design. A summary is exactly reproducible from (a) the counts, (b) the first few
// violating pairs per check, (c) the two extremes with their pairs, and (d) every value of
// t_first/(pi/|n|) (the quantiles need all of them). (a)-(c) are in the summary JSON itself;
// (d) is in the rows, or, for a shard run with --summary, in the binary side file
// SUMMARY.values (8-byte IEEE doubles, host byte order, after a 16-byte header
// "GYRVAL01" + count). `gyrores merge` accepts row files (any shard run with --out) and shard
// summaries (any shard run with --summary); it checks that the inputs come from one sweep
// configuration, are complete, and cover every shard 0..N-1 exactly once, then merges the
// accumulators (sweep.hpp) and prints the same summary a single run gives.
//
// Resume. The rows go to FILE.part as blocks finish, in order. A checkpoint (every
// checkpoint_seconds, and whenever the run stops early: signal, max_pairs) flushes FILE.part,
// appends the new t_first/proxy values to STATE.values and then atomically replaces STATE, a
// JSON file recording the configuration, the number of pairs done (always a prefix of the
// shard's enumeration), the length of FILE.part and of STATE.values at that moment, and the
// accumulator. --resume truncates FILE.part and STATE.values to the recorded lengths (anything
// written after the last checkpoint is recomputed), restores the accumulator and continues with
// the next pair. STATE defaults to OUT.resume, else SUMMARY.resume, else gyrores-sweep.resume;
// it and STATE.values are removed when the sweep completes.
#pragma once
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include <gyrores/sweep/sweep.hpp>

namespace gyrores {

using sweep_json = nlohmann::ordered_json;

enum class sweep_format { csv, jsonl };

inline sweep_format sweep_parse_format(const std::string& s) {
  if (s == "csv") return sweep_format::csv;
  if (s == "jsonl") return sweep_format::jsonl;
  throw usage_error("--format must be csv or jsonl, got '" + s + "'");
}

inline const std::vector<std::string>& sweep_row_columns() {
  static const std::vector<std::string> cols = {
      "tau", "sigma", "order", "delta_mod4", "r_res", "theta_first", "t_first", "t_min_paper", "t_first_over_proxy",
      "first_at_paper_node", "paper_lobe_min", "asy_error", "asy_bound", "asy_ratio", "asy_constant",
      "minimiser_count", "strand_offset_min", "check_degeneracy", "check_paper_node", "check_asy_bound",
      "check_structure", "check_cross_check", "failed", "note"};
  return cols;
}

// The run description written into rows, summaries and states; inputs to a merge or a resume
// must agree on it (except the shard index).
template <class T> sweep_json sweep_run_json(const sweep_config& c) {
  sweep_json j;
  j["min_order"] = c.min_order < 3 ? 3 : c.min_order;
  j["max_order"] = c.max_order;
  j["shard"] = {c.shard_index, c.shard_count};
  j["checks"] = sweep_check_names(c.checks);
  j["cross_check_max_order"] = c.cross_check_max_order;
  j["max_examples"] = c.max_examples;
  j["type"] = real_type_name<T>();
  j["digits"] = std::is_same_v<T, double> ? 17u : c.digits;
  return j;
}

inline sweep_config sweep_config_from_json(const sweep_json& j) {
  sweep_config c;
  c.min_order = j.at("min_order").get<std::int64_t>();
  c.max_order = j.at("max_order").get<std::int64_t>();
  c.shard_index = j.at("shard").at(0).get<std::int64_t>();
  c.shard_count = j.at("shard").at(1).get<std::int64_t>();
  c.checks = 0;
  for (auto& n : j.at("checks")) c.checks |= sweep_parse_checks(n.get<std::string>());
  c.cross_check_max_order = j.at("cross_check_max_order").get<std::int64_t>();
  c.max_examples = j.at("max_examples").get<std::size_t>();
  c.digits = j.at("digits").get<unsigned>();
  return c;
}

// The run description without the shard index (what shards of one sweep share).
inline sweep_json sweep_run_identity(sweep_json run) {
  run.erase("shard");
  run.erase("threads");
  run.erase("complete");
  run.erase("merged_shards");
  return run;
}

// ---------------------------------------------------------------------------------------------
// Rows

namespace detail {

inline void sweep_csv_field(std::string& out, const std::string& v) {
  if (v.find_first_of(",\"\n\r") == std::string::npos) {
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

inline void sweep_json_string(std::string& out, const std::string& v) {
  out += '"';
  for (unsigned char ch : v) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (ch < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", ch);
          out += buf;
        } else {
          out += char(ch);
        }
    }
  }
  out += '"';
}

// Field kinds: integer / boolean (bare in JSON), text (quoted), null (not applicable).
enum class sweep_kind { integer, boolean, text, null };

}  // namespace detail

// Appends one row (with its newline) in the given format.
template <class T> void sweep_format_row(std::string& out, const sweep_row<T>& r, sweep_format fmt, unsigned digits) {
  using detail::sweep_kind;
  const auto& cols = sweep_row_columns();
  std::size_t col = 0;
  auto put = [&](sweep_kind kind, const std::string& v) {
    if (fmt == sweep_format::csv) {
      if (col) out += ',';
      if (kind != sweep_kind::null) detail::sweep_csv_field(out, v);
    } else {
      out += col ? ",\"" : "{\"";
      out += cols[col];
      out += "\":";
      if (kind == sweep_kind::null) out += "null";
      else if (kind == sweep_kind::text) detail::sweep_json_string(out, v);
      else out += v;
    }
    ++col;
  };
  auto integer = [&](std::int64_t v) { put(sweep_kind::integer, std::to_string(v)); };
  auto real = [&](bool have, const T& v) {
    if (have) put(sweep_kind::text, sweep_real_text(v, digits));
    else put(sweep_kind::null, "");
  };
  auto tri = [&](int v) {
    if (v < 0) put(sweep_kind::null, "");
    else put(sweep_kind::boolean, v ? "true" : "false");
  };
  const bool ok = !r.failed;
  integer(r.tau);
  integer(r.sigma);
  integer(r.tau + r.sigma);
  integer(r.delta_mod4);
  real(ok, r.r_res);
  real(ok, r.theta_first);
  real(ok, r.t_first);
  real(ok, r.t_min_paper);
  real(ok && r.has_ratio, r.t_ratio);
  tri(ok ? r.first_at_paper_node : -1);
  tri(ok ? r.paper_lobe_min : -1);
  real(ok && r.has_asy, r.asy_error);
  real(ok && r.has_asy, r.asy_bound);
  real(ok && r.has_asy, r.asy_ratio);
  real(ok && r.has_asy, r.asy_constant);
  if (ok) integer(r.minimiser_count);
  else put(sweep_kind::null, "");
  integer(r.strand_offset);
  for (int i = 0; i < sweep_check_count; ++i) {
    if (r.status[i] == sweep_status::none) put(sweep_kind::null, "");
    else put(sweep_kind::text, sweep_status_text(r.status[i]));
  }
  put(sweep_kind::boolean, r.failed ? "true" : "false");
  if (r.note.empty()) put(sweep_kind::null, "");
  else put(sweep_kind::text, r.note);
  out += fmt == sweep_format::csv ? "\n" : "}\n";
}

inline std::string sweep_rows_header(const sweep_json& run, sweep_format fmt) {
  if (fmt == sweep_format::csv) {
    std::string h = "# gyrores-sweep-rows " + run.dump() + "\n";
    const auto& cols = sweep_row_columns();
    for (std::size_t i = 0; i < cols.size(); ++i) h += (i ? "," : "") + cols[i];
    return h + "\n";
  }
  sweep_json j;
  j["gyrores_sweep_rows"] = run;
  return j.dump() + "\n";
}

inline std::string sweep_rows_trailer(std::uint64_t pairs, double seconds, sweep_format fmt) {
  sweep_json e;
  e["pairs"] = pairs;
  e["seconds"] = seconds;
  if (fmt == sweep_format::csv) return "# end " + e.dump() + "\n";
  sweep_json j;
  j["gyrores_sweep_end"] = e;
  return j.dump() + "\n";
}

namespace detail {

// Split one CSV line (RFC 4180 quoting, no embedded newlines in our files).
inline std::vector<std::string> sweep_csv_split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    char ch = line[i];
    if (quoted) {
      if (ch == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          cur += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        cur += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  out.push_back(cur);
  return out;
}

// A row as the summary needs it, from its text fields (empty string: not applicable).
inline sweep_record sweep_record_from_fields(const std::function<std::string(const char*)>& get, bool keep_text) {
  sweep_record r;
  auto integer = [&](const char* k) {
    std::string v = get(k);
    std::int64_t x = 0;
    auto res = std::from_chars(v.data(), v.data() + v.size(), x);
    if (v.empty() || res.ec != std::errc() || res.ptr != v.data() + v.size())
      throw compute_error(std::string("row field ") + k + " is not an integer: '" + v + "'");
    return x;
  };
  r.tau = integer("tau");
  r.sigma = integer("sigma");
  r.delta_mod4 = int(integer("delta_mod4"));
  r.failed = get("failed") == "true";
  for (int i = 0; i < sweep_check_count; ++i) {
    std::string s = get(sweep_check_column(i));
    r.status[i] = s == "pass" ? sweep_status::pass : s == "fail" ? sweep_status::fail : sweep_status::none;
    if (!s.empty() && r.status[i] == sweep_status::none)
      throw compute_error(std::string("row field ") + sweep_check_column(i) + " must be pass, fail or empty: '" + s + "'");
  }
  std::string fp = get("first_at_paper_node");
  r.first_at_paper_node = fp.empty() ? -1 : fp == "true" ? 1 : 0;
  std::string tr = get("t_first_over_proxy");
  if (!tr.empty()) {
    r.has_ratio = true;
    r.t_ratio = sweep_text_double(tr);
  }
  std::string ar = get("asy_ratio"), ac = get("asy_constant");
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

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Accumulator <-> JSON

namespace detail {
inline sweep_json sweep_pairs_json(const std::vector<sweep_pair_id>& v) {
  sweep_json a = sweep_json::array();
  for (auto& p : v) a.push_back({p.first, p.second});
  return a;
}
inline std::vector<sweep_pair_id> sweep_pairs_from_json(const sweep_json& a) {
  std::vector<sweep_pair_id> v;
  for (auto& p : a) v.push_back({p.at(0).get<std::int64_t>(), p.at(1).get<std::int64_t>()});
  return v;
}
inline sweep_json sweep_extreme_json(const sweep_extreme& e) {
  if (!e.set) return nullptr;
  sweep_json j;
  j["value"] = e.str();
  j["pair"] = {e.pair.first, e.pair.second};
  return j;
}
inline sweep_extreme sweep_extreme_from_json(const sweep_json& j) {
  sweep_extreme e;
  if (j.is_null()) return e;
  e.set = true;
  e.text = j.at("value").get<std::string>();
  e.value = sweep_text_double(e.text);
  if (sweep_double_text(e.value) == e.text) e.text.clear();
  e.pair = {j.at("pair").at(0).get<std::int64_t>(), j.at("pair").at(1).get<std::int64_t>()};
  return e;
}
}  // namespace detail

// Everything of the accumulator except the t_first/proxy values. `checks` selects the checks
// listed (the others are zero anyway).
inline sweep_json sweep_accumulator_json(const sweep_accumulator& a, sweep_check_set checks) {
  sweep_json j;
  j["pairs"] = a.pairs;
  j["degenerate"] = a.degenerate;
  sweep_json cj = sweep_json::object();
  for (int i = 0; i < sweep_check_count; ++i) {
    if (!((checks >> i) & 1u)) continue;
    sweep_json t;
    t["violations"] = a.checks[i].violations;
    t["examples"] = detail::sweep_pairs_json(a.checks[i].examples);
    t["checked"] = a.checks[i].checked;
    cj[sweep_check_name(i)] = t;
  }
  j["checks"] = cj;
  j["asy_ratio_max"] = detail::sweep_extreme_json(a.asy_ratio_max);
  j["sharp_constant"] = detail::sweep_extreme_json(a.sharp_constant);
  j["first_at_paper_node"] = a.first_at_paper_node;
  j["errors"] = {{"count", a.errors.violations}, {"examples", detail::sweep_pairs_json(a.errors.examples)}};
  return j;
}

inline sweep_accumulator sweep_accumulator_from_json(const sweep_json& j, std::size_t max_examples) {
  sweep_accumulator a;
  a.max_examples = max_examples;
  a.pairs = j.at("pairs").get<std::uint64_t>();
  a.degenerate = j.at("degenerate").get<std::uint64_t>();
  for (int i = 0; i < sweep_check_count; ++i) {
    auto f = j.at("checks").find(sweep_check_name(i));
    if (f == j.at("checks").end()) continue;
    a.checks[i].violations = f->at("violations").get<std::uint64_t>();
    a.checks[i].checked = f->at("checked").get<std::uint64_t>();
    a.checks[i].examples = detail::sweep_pairs_from_json(f->at("examples"));
  }
  a.asy_ratio_max = detail::sweep_extreme_from_json(j.at("asy_ratio_max"));
  a.sharp_constant = detail::sweep_extreme_from_json(j.at("sharp_constant"));
  a.first_at_paper_node = j.at("first_at_paper_node").get<std::uint64_t>();
  a.errors.violations = j.at("errors").at("count").get<std::uint64_t>();
  a.errors.examples = detail::sweep_pairs_from_json(j.at("errors").at("examples"));
  return a;
}

// The summary JSON of a finished sweep (computes the quantiles: reorders a.t_ratios).
inline sweep_json sweep_summary_json(sweep_accumulator& a, const sweep_json& run, double seconds) {
  sweep_check_set checks = 0;
  for (auto& n : run.at("checks")) checks |= sweep_parse_checks(n.get<std::string>());
  sweep_json acc = sweep_accumulator_json(a, checks);
  sweep_json j;
  j["format"] = "gyrores-sweep-summary";
  j["version"] = 1;
  j["pairs"] = acc["pairs"];
  j["degenerate"] = acc["degenerate"];
  j["checks"] = acc["checks"];
  j["asy_ratio_max"] = acc["asy_ratio_max"];
  j["sharp_constant"] = acc["sharp_constant"];
  auto q = a.quantiles();
  sweep_json tq;
  tq["count"] = q.count;
  if (q.count) {
    tq["min"] = sweep_double_text(q.min);
    tq["p01"] = sweep_double_text(q.p01);
    tq["p10"] = sweep_double_text(q.p10);
    tq["median"] = sweep_double_text(q.median);
    tq["p90"] = sweep_double_text(q.p90);
    tq["p99"] = sweep_double_text(q.p99);
    tq["max"] = sweep_double_text(q.max);
  } else {
    for (const char* k : {"min", "p01", "p10", "median", "p90", "p99", "max"}) tq[k] = nullptr;
  }
  j["t_first_over_proxy"] = tq;
  j["first_at_paper_node"] = acc["first_at_paper_node"];
  j["errors"] = acc["errors"];
  j["seconds"] = seconds;
  j["run"] = run;
  j["values_file"] = nullptr;
  return j;
}

// The parts of a summary that a merge must reproduce exactly (drops seconds, run, values_file).
inline sweep_json sweep_summary_core(sweep_json j) {
  j.erase("seconds");
  j.erase("run");
  j.erase("values_file");
  return j;
}

// A human-readable rendering of a summary JSON.
inline std::string sweep_summary_text(const sweep_json& s) {
  std::ostringstream os;
  const auto& run = s.at("run");
  const double sec = s.at("seconds").get<double>();
  const auto pairs = s.at("pairs").get<std::uint64_t>();
  os << "gyrores sweep: orders " << run.at("min_order").get<std::int64_t>() << ".." << run.at("max_order").get<std::int64_t>();
  auto shard = run.at("shard");
  if (shard.at(1).get<std::int64_t>() > 1)
    os << ", shard " << shard.at(0).get<std::int64_t>() << "/" << shard.at(1).get<std::int64_t>();
  if (run.contains("merged_shards")) os << ", merged from " << run.at("merged_shards").get<std::int64_t>() << " shards";
  os << "; " << run.at("type").get<std::string>();
  if (run.contains("threads") && !run.at("threads").is_null()) {
    const unsigned t = run.at("threads").get<unsigned>();
    os << ", " << t << (t == 1 ? " thread" : " threads");
  }
  os << "\n";
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.2f s (%.0f pairs/s)", sec, sec > 0 ? double(pairs) / sec : 0.0);
  os << "  pairs visited       " << pairs << "  in " << buf << "\n";
  os << "  degenerate pairs    " << s.at("degenerate").get<std::uint64_t>() << "  (delta = 2 mod 4)\n";
  const auto& err = s.at("errors");
  if (err.at("count").get<std::uint64_t>() > 0) {
    os << "  ERRORS              " << err.at("count").get<std::uint64_t>() << " pairs could not be computed, first:";
    for (auto& p : err.at("examples")) os << " (" << p.at(0).get<std::int64_t>() << "," << p.at(1).get<std::int64_t>() << ")";
    os << "\n";
  }
  os << "  checks              violations / pairs checked   (first violating pairs)\n";
  for (auto& [name, t] : s.at("checks").items()) {
    std::string label = "    " + name;
    label.resize(24, ' ');
    os << label << t.at("violations").get<std::uint64_t>() << " / " << t.at("checked").get<std::uint64_t>();
    if (!t.at("examples").empty()) {
      os << "   ";
      for (auto& p : t.at("examples")) os << " (" << p.at(0).get<std::int64_t>() << "," << p.at(1).get<std::int64_t>() << ")";
    }
    if (name == "cross-check") os << "   [orders <= " << run.at("cross_check_max_order").get<std::int64_t>() << "]";
    if (name == "asy-bound") os << "   [x < 1/2]";
    if (name == "paper-node") os << "   [non-degenerate]";
    os << "\n";
  }
  auto extreme = [&](const char* key, const char* label) {
    const auto& e = s.at(key);
    os << label;
    if (e.is_null()) os << "n/a\n";
    else os << e.at("value").get<std::string>() << "  at (" << e.at("pair").at(0).get<std::int64_t>() << ","
            << e.at("pair").at(1).get<std::int64_t>() << ")\n";
  };
  extreme("asy_ratio_max", "  worst asy ratio     |theta_c - theta_asy| / (pi^3 x^2/a) = ");
  extreme("sharp_constant", "  sharp constant      sup |theta_c - theta_asy| a/x^2 = ");
  const auto& q = s.at("t_first_over_proxy");
  os << "  t_first/(pi/|n|)    over " << q.at("count").get<std::uint64_t>() << " non-degenerate pairs";
  if (q.at("count").get<std::uint64_t>() > 0)
    os << ": min " << q.at("min").get<std::string>() << ", p01 " << q.at("p01").get<std::string>() << ", p10 "
       << q.at("p10").get<std::string>() << ", median " << q.at("median").get<std::string>() << ", p90 "
       << q.at("p90").get<std::string>() << ", p99 " << q.at("p99").get<std::string>() << ", max "
       << q.at("max").get<std::string>();
  os << "\n";
  os << "  first minimiser in the paper's lobe k = round(a/(2b)): " << s.at("first_at_paper_node").get<std::uint64_t>()
     << " non-degenerate pairs\n";
  return os.str();
}

// ---------------------------------------------------------------------------------------------
// Files

namespace detail {

[[noreturn]] inline void sweep_io_fail(const std::string& what, const std::string& path) {
  throw compute_error(what + " '" + path + "': " + std::strerror(errno));
}

// Flush a FILE* to the disk (fflush + fsync); compute_error on failure.
inline void sweep_sync(std::FILE* f, const std::string& path) {
  if (std::fflush(f) != 0) sweep_io_fail("cannot write", path);
  if (::fsync(::fileno(f)) != 0) sweep_io_fail("cannot sync", path);
}

inline std::string sweep_read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw usage_error("cannot read '" + path + "'");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

inline bool sweep_file_exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

}  // namespace detail

// Write `content` to `path` atomically: path.part is written, synced, then renamed over path.
// On any failure path.part is removed and compute_error thrown; path is untouched.
inline void sweep_write_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".part";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) detail::sweep_io_fail("cannot create", tmp);
  bool ok = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  ok = ok && std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  int err = errno;
  ok = (std::fclose(f) == 0) && ok;
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    if (ok) err = errno;
    std::remove(tmp.c_str());
    errno = err;
    detail::sweep_io_fail("cannot write", path);
  }
}

// Binary values file: "GYRVAL01", uint64 count, then count doubles (host byte order).
inline void sweep_write_values_atomic(const std::string& path, const std::vector<double>& v) {
  std::string content = "GYRVAL01";
  std::uint64_t n = v.size();
  content.append(reinterpret_cast<const char*>(&n), sizeof n);
  content.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  sweep_write_atomic(path, content);
}
inline std::vector<double> sweep_read_values(const std::string& path) {
  std::string c = detail::sweep_read_text(path);
  std::uint64_t n = 0;
  if (c.size() < 16 || c.compare(0, 8, "GYRVAL01") != 0) throw usage_error("'" + path + "' is not a gyrores values file");
  std::memcpy(&n, c.data() + 8, sizeof n);
  if (c.size() != 16 + n * sizeof(double)) throw usage_error("'" + path + "' is truncated");
  std::vector<double> v(n);
  std::memcpy(v.data(), c.data() + 16, n * sizeof(double));
  return v;
}

// ---------------------------------------------------------------------------------------------
// Reading sweep outputs back (for merge)

struct sweep_input {
  std::string path;
  sweep_json run;           // the run description (shard included)
  sweep_accumulator acc;    // with every t_first/proxy value
  double seconds = 0;
};

// A rows file (CSV or JSONL, detected from its first line). Requires the end line.
inline sweep_input sweep_read_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw usage_error("cannot read '" + path + "'");
  sweep_input r;
  r.path = path;
  std::string line;
  if (!std::getline(in, line)) throw usage_error("'" + path + "' is empty");
  const std::string csv_tag = "# gyrores-sweep-rows ";
  const bool csv = line.rfind(csv_tag, 0) == 0;
  bool keep_text = false;
  std::size_t max_examples = 5;
  auto set_run = [&](const sweep_json& run) {
    r.run = run;
    keep_text = run.at("type").get<std::string>() != "double";
    max_examples = run.at("max_examples").get<std::size_t>();
    r.acc.max_examples = max_examples;
  };
  bool ended = false;
  try {
    if (csv) {
      set_run(sweep_json::parse(line.substr(csv_tag.size())));
      if (!std::getline(in, line)) throw usage_error("'" + path + "' has no column header");
      auto header = detail::sweep_csv_split(line);
      std::map<std::string, std::size_t> index;
      for (std::size_t i = 0; i < header.size(); ++i) index[header[i]] = i;
      for (auto& c : sweep_row_columns())
        if (!index.count(c)) throw usage_error("'" + path + "' lacks the column " + c);
      std::vector<std::string> fields;
      auto get = [&](const char* k) -> std::string { return fields.at(index.at(k)); };
      while (std::getline(in, line)) {
        if (line.rfind("# end ", 0) == 0) {
          r.seconds = sweep_json::parse(line.substr(6)).at("seconds").get<double>();
          ended = true;
          break;
        }
        fields = detail::sweep_csv_split(line);
        if (fields.size() != header.size()) throw usage_error("'" + path + "': malformed row: " + line);
        r.acc.add(detail::sweep_record_from_fields(get, keep_text));
      }
    } else {
      auto head = sweep_json::parse(line);
      if (!head.contains("gyrores_sweep_rows")) throw usage_error("'" + path + "' is not a gyrores sweep rows file");
      set_run(head.at("gyrores_sweep_rows"));
      sweep_json row;
      auto get = [&](const char* k) -> std::string {
        const auto& v = row.at(k);
        if (v.is_null()) return "";
        if (v.is_string()) return v.get<std::string>();
        if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
        return v.dump();
      };
      while (std::getline(in, line)) {
        row = sweep_json::parse(line);
        if (row.contains("gyrores_sweep_end")) {
          r.seconds = row.at("gyrores_sweep_end").at("seconds").get<double>();
          ended = true;
          break;
        }
        r.acc.add(detail::sweep_record_from_fields(get, keep_text));
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw usage_error("'" + path + "' is malformed: " + e.what());
  }
  if (!ended) throw usage_error("'" + path + "' has no end line: the sweep that wrote it did not finish");
  return r;
}

// A summary JSON of a shard (needs its values file).
inline sweep_input sweep_read_summary(const std::string& path) {
  sweep_input r;
  r.path = path;
  sweep_json j;
  try {
    j = sweep_json::parse(detail::sweep_read_text(path));
  } catch (const nlohmann::json::exception& e) {
    throw usage_error("'" + path + "' is not JSON: " + e.what());
  }
  if (j.value("format", "") != "gyrores-sweep-summary") throw usage_error("'" + path + "' is not a gyrores sweep summary");
  r.run = j.at("run");
  if (!r.run.value("complete", false)) throw usage_error("'" + path + "' is the summary of an unfinished sweep");
  r.seconds = j.at("seconds").get<double>();
  r.acc = sweep_accumulator_from_json(j, r.run.at("max_examples").get<std::size_t>());
  if (j.at("values_file").is_null())
    throw usage_error("'" + path + "' has no values file (only shard runs write one); merge the row files instead");
  std::string vf = j.at("values_file").get<std::string>();
  if (vf.find('/') == std::string::npos) {
    auto slash = path.rfind('/');
    if (slash != std::string::npos) vf = path.substr(0, slash + 1) + vf;
  }
  r.acc.t_ratios = sweep_read_values(vf);
  return r;
}

// Either kind, detected from the content.
inline sweep_input sweep_read_output(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw usage_error("cannot read '" + path + "'");
  std::string first;
  std::getline(in, first);
  in.close();
  if (first.rfind("# gyrores-sweep-rows ", 0) == 0 || first.find("\"gyrores_sweep_rows\"") != std::string::npos)
    return sweep_read_rows(path);
  return sweep_read_summary(path);
}

// Merge shard outputs into the summary of the whole sweep; checks they belong together.
inline sweep_json sweep_merge(const std::vector<std::string>& paths) {
  if (paths.empty()) throw usage_error("merge needs at least one file");
  std::vector<sweep_input> in;
  for (auto& p : paths) in.push_back(sweep_read_output(p));
  const sweep_json ident = sweep_run_identity(in[0].run);
  const std::int64_t n = in[0].run.at("shard").at(1).get<std::int64_t>();
  std::set<std::int64_t> seen;
  for (auto& x : in) {
    if (sweep_run_identity(x.run) != ident)
      throw usage_error("'" + x.path + "' comes from a different sweep (" + sweep_run_identity(x.run).dump() + " vs " +
                        ident.dump() + ")");
    if (x.run.at("shard").at(1).get<std::int64_t>() != n)
      throw usage_error("'" + x.path + "' is a shard of " + std::to_string(x.run.at("shard").at(1).get<std::int64_t>()) +
                        ", the others of " + std::to_string(n));
    std::int64_t i = x.run.at("shard").at(0).get<std::int64_t>();
    if (!seen.insert(i).second) throw usage_error("shard " + std::to_string(i) + "/" + std::to_string(n) + " given twice");
  }
  for (std::int64_t i = 0; i < n; ++i)
    if (!seen.count(i)) throw usage_error("shard " + std::to_string(i) + "/" + std::to_string(n) + " is missing");
  const auto max_examples = ident.at("max_examples").get<std::size_t>();
  sweep_accumulator acc;
  acc.max_examples = max_examples;
  double seconds = 0;
  // Each shard must hold exactly its share of the pairs (counted when max_order <= sweep_count_limit).
  const std::int64_t max_order = ident.at("max_order").get<std::int64_t>();
  const bool counted = max_order <= sweep_count_limit;
  const std::uint64_t total = counted ? sweep_total_pairs(ident.at("min_order").get<std::int64_t>(), max_order) : 0;
  for (auto& x : in) {
    const std::int64_t i = x.run.at("shard").at(0).get<std::int64_t>();
    if (counted && x.acc.pairs != sweep_shard_pairs(total, i, n))
      throw usage_error("'" + x.path + "' holds " + std::to_string(x.acc.pairs) + " pairs, shard " + std::to_string(i) +
                        "/" + std::to_string(n) + " has " + std::to_string(sweep_shard_pairs(total, i, n)));
    acc.merge(x.acc);
    seconds += x.seconds;
  }
  sweep_json run = ident;
  run["shard"] = {0, 1};
  run["threads"] = nullptr;
  run["complete"] = true;
  run["merged_shards"] = n;
  return sweep_summary_json(acc, run, seconds);
}

// ---------------------------------------------------------------------------------------------
// The driver: a sweep with rows, summary, resume state and atomic files.

struct sweep_files {
  std::string rows_path;  // empty: no rows
  sweep_format rows_format = sweep_format::csv;
  std::string summary_path;  // empty: no summary file
  std::string state_path;    // empty: derived (see the header comment)
  bool resume = false;
  double checkpoint_seconds = 300;  // periodic checkpoints (0: only when stopping early)
};

struct sweep_progress_info {
  std::uint64_t done = 0, total = 0;  // pairs of the shard; total 0 when unknown
  double seconds = 0;                 // this run
  std::uint64_t done_this_run = 0;
};

struct sweep_report {
  sweep_json summary;       // complete runs only (null otherwise)
  bool complete = false;
  std::uint64_t done = 0;   // pairs of the shard done
  std::uint64_t total = 0;  // pairs of the shard (0 if not counted)
  std::string state_path;   // where the resume state is (incomplete runs)
  unsigned threads = 1;
  double seconds = 0;       // this run
};

inline std::string sweep_default_state_path(const sweep_files& f) {
  if (!f.state_path.empty()) return f.state_path;
  if (!f.rows_path.empty()) return f.rows_path + ".resume";
  if (!f.summary_path.empty()) return f.summary_path + ".resume";
  return "gyrores-sweep.resume";
}

template <class T>
sweep_report sweep_to_files(const sweep_config& cfg_in, const sweep_files& files, const sweep_engine_options& eo_in,
                            const std::function<void(const sweep_progress_info&)>& progress = {}) {
  sweep_config cfg = cfg_in;
  if (cfg.min_order < 3) cfg.min_order = 3;
  sweep_validate(cfg);
  // MPFR: the working precision (digits + 8 guard digits) is set once, before any thread starts
  // and before the run description (which names the precision) is formed.
  std::optional<scoped_digits> digits_scope;
  if constexpr (is_variable_precision_v<T>) digits_scope.emplace(cfg.digits + 8);
  const sweep_json run = sweep_run_json<T>(cfg);
  sweep_json run_files = run;
  run_files["rows"] = files.rows_path.empty() ? sweep_json(nullptr)
                                              : sweep_json({{"path", files.rows_path},
                                                            {"format", files.rows_format == sweep_format::csv ? "csv" : "jsonl"}});
  const std::string state = sweep_default_state_path(files), values = state + ".values";
  const std::string rows_part = files.rows_path + ".part";
  const bool rows = !files.rows_path.empty();

  sweep_report rep;
  rep.state_path = state;
  if (cfg.max_order <= sweep_count_limit)
    rep.total = sweep_shard_pairs(sweep_total_pairs(cfg.min_order, cfg.max_order), cfg.shard_index, cfg.shard_count);

  sweep_accumulator acc;
  acc.max_examples = cfg.max_examples;
  std::uint64_t start = 0;
  double seconds_before = 0;
  std::uint64_t values_written = 0;  // values already in the values file
  std::uint64_t rows_bytes = 0;      // bytes of rows_part holding whole, delivered blocks
  std::FILE* rf = nullptr;
  struct closer {
    std::FILE*& f;
    ~closer() {
      if (f) std::fclose(f);
    }
  } close_rows{rf};

  if (files.resume) {
    if (!detail::sweep_file_exists(state))
      throw usage_error("--resume: no resume state at '" + state + "' (nothing to resume, or a different --out/--summary/--state)");
    sweep_json st;
    try {
      st = sweep_json::parse(detail::sweep_read_text(state));
    } catch (const nlohmann::json::exception& e) {
      throw usage_error("--resume: '" + state + "' is not a resume state: " + e.what());
    }
    if (st.value("format", "") != "gyrores-sweep-state") throw usage_error("--resume: '" + state + "' is not a resume state");
    if (st.at("run") != run_files)
      throw usage_error("--resume: the state at '" + state + "' is for another sweep: " + st.at("run").dump() +
                        "; this one is " + run_files.dump());
    start = st.at("done").get<std::uint64_t>();
    seconds_before = st.at("seconds").get<double>();
    acc = sweep_accumulator_from_json(st.at("summary"), cfg.max_examples);
    values_written = st.at("values_count").get<std::uint64_t>();
    {
      // The values file may hold more than recorded (a checkpoint interrupted before the state
      // was replaced): keep the recorded prefix.
      std::FILE* vf = std::fopen(values.c_str(), "rb");
      if (!vf) detail::sweep_io_fail("--resume: cannot read", values);
      acc.t_ratios.resize(values_written);
      std::size_t got = std::fread(acc.t_ratios.data(), sizeof(double), values_written, vf);
      std::fclose(vf);
      if (got != values_written) throw usage_error("--resume: '" + values + "' is shorter than its state records");
      if (::truncate(values.c_str(), off_t(values_written * sizeof(double))) != 0)
        detail::sweep_io_fail("--resume: cannot truncate", values);
    }
    if (rows) {
      rows_bytes = st.at("rows_bytes").get<std::uint64_t>();
      if (::truncate(rows_part.c_str(), off_t(rows_bytes)) != 0) detail::sweep_io_fail("--resume: cannot truncate", rows_part);
      rf = std::fopen(rows_part.c_str(), "ab");
      if (!rf) detail::sweep_io_fail("--resume: cannot open", rows_part);
    }
  } else {
    std::remove(state.c_str());
    std::remove(values.c_str());
    if (rows) {
      rf = std::fopen(rows_part.c_str(), "wb");
      if (!rf) detail::sweep_io_fail("cannot create", rows_part);
      std::string h = sweep_rows_header(run, files.rows_format);
      if (std::fwrite(h.data(), 1, h.size(), rf) != h.size()) detail::sweep_io_fail("cannot write", rows_part);
      rows_bytes = h.size();
    }
  }

  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  std::uint64_t done = start;
  sweep_pair_id last{0, 0};
  double last_checkpoint = 0;

  auto checkpoint = [&] {
    if (rows) detail::sweep_sync(rf, rows_part);
    {
      std::FILE* vf = std::fopen(values.c_str(), "ab");
      if (!vf) detail::sweep_io_fail("cannot write", values);
      std::size_t n = acc.t_ratios.size() - values_written;
      bool ok = std::fwrite(acc.t_ratios.data() + values_written, sizeof(double), n, vf) == n;
      ok = ok && std::fflush(vf) == 0 && ::fsync(::fileno(vf)) == 0;
      ok = (std::fclose(vf) == 0) && ok;
      if (!ok) detail::sweep_io_fail("cannot write", values);
    }
    sweep_json st;
    st["format"] = "gyrores-sweep-state";
    st["version"] = 1;
    st["run"] = run_files;
    st["done"] = done;
    st["next_after"] = {last.first, last.second};
    st["rows_bytes"] = rows_bytes;
    st["values_count"] = acc.t_ratios.size();
    st["seconds"] = seconds_before + elapsed();
    st["summary"] = sweep_accumulator_json(acc, sweep_all_checks);
    sweep_write_atomic(state, st.dump() + "\n");
    values_written = acc.t_ratios.size();
    last_checkpoint = elapsed();
  };

  sweep_row_formatter<T> fmt;
  if (rows) {
    const sweep_format f = files.rows_format;
    const unsigned digits = cfg.digits;
    fmt = [f, digits](std::string& out, const sweep_row<T>& r) { sweep_format_row(out, r, f, digits); };
  }
  sweep_engine_options eo = eo_in;
  eo.start = start;
  auto on_block = [&](sweep_block& b) {
    if (rows && !b.rows.empty() && std::fwrite(b.rows.data(), 1, b.rows.size(), rf) != b.rows.size())
      detail::sweep_io_fail("cannot write", rows_part);
    rows_bytes += b.rows.size();
    acc.merge(b.summary);
    done = b.first + b.count;
    if (b.count) last = b.last;
    if (progress) progress({done, rep.total, elapsed(), done - start});
    if (files.checkpoint_seconds > 0 && elapsed() - last_checkpoint >= files.checkpoint_seconds) checkpoint();
  };

  sweep_outcome out;
  try {
    out = sweep_run<T>(cfg, eo, on_block, fmt);
  } catch (...) {
    // Keep what is finished: a checkpoint of the prefix delivered so far.
    try {
      checkpoint();
    } catch (...) {
    }
    throw;
  }
  rep.threads = out.threads;
  rep.done = out.done;
  rep.seconds = elapsed();
  if (!out.complete) {
    checkpoint();
    rep.complete = false;
    return rep;
  }

  const double seconds = seconds_before + elapsed();
  sweep_json srun = run;
  srun["threads"] = out.threads;
  srun["complete"] = true;
  sweep_json summary = sweep_summary_json(acc, srun, seconds);
  if (!files.summary_path.empty()) {
    if (cfg.shard_count > 1) {
      const std::string vpath = files.summary_path + ".values";
      sweep_write_values_atomic(vpath, acc.t_ratios);
      auto slash = vpath.rfind('/');
      summary["values_file"] = slash == std::string::npos ? vpath : vpath.substr(slash + 1);
    }
    sweep_write_atomic(files.summary_path, summary.dump(2) + "\n");
  }
  if (rows) {
    std::string tr = sweep_rows_trailer(acc.pairs, seconds, files.rows_format);
    if (std::fwrite(tr.data(), 1, tr.size(), rf) != tr.size()) detail::sweep_io_fail("cannot write", rows_part);
    detail::sweep_sync(rf, rows_part);
    std::fclose(rf);
    rf = nullptr;
    if (std::rename(rows_part.c_str(), files.rows_path.c_str()) != 0) detail::sweep_io_fail("cannot rename", rows_part);
  }
  std::remove(state.c_str());
  std::remove(values.c_str());
  rep.complete = true;
  rep.summary = summary;
  return rep;
}

}  // namespace gyrores
