// The run description of a sweep, which its rows file, summary and resume state carry, and the
// rows file (`gyrores sweep --out FILE`) written and read back for a merge. Keys, columns and
// framing lines: docs/formats.md (sweep rows, `{run}`, sweep format versions).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <gyrores/core/real.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/sweep/sweep.hpp>

namespace gyrores {

// {min_order (at least 3), max_order, shard, checks, max_examples, type, digits, method[,
// certified: true]}; `digits` is that of the rows' reals (17 for double).
json sweep_run_json(const sweep_config& c, const std::string& type, unsigned digits);
template <class T> json sweep_run_json(const sweep_config& c) {
  return sweep_run_json(c, sweep_type_name<T>(c), std::is_same_v<T, double> ? 17u : c.digits);
}

// Version 1 (the rows' first line had no version) had the check cross-check, its rows column and
// the run's cross_check_max_order.
inline constexpr int sweep_format_version = 2;

// A run description read from a file of format `version` (1 or 2), as this version writes it:
// version 1's cross_check_max_order dropped (its rows' values are the same). usage_error naming
// `path` for a version-1 run that checked cross-check, whose verdicts this version cannot carry.
json sweep_run_of_version(json run, std::int64_t version, const std::string& path);

// The rows come from the lattice theorem's root (sweep/evaluate.hpp). Files of earlier versions
// have no `method`: a resume or a merge refuses to mix them with these.
inline constexpr const char* sweep_rows_method = "lattice-theorem/1";

// Why a file described by `found` cannot continue or join the sweep described by `wanted`: one
// clause without a full stop.
std::string sweep_run_mismatch(const json& found, const json& wanted);

// A finished sweep output read back (rows file or shard summary), for a merge.
struct sweep_input {
  std::string path;
  json run;               // shard included
  sweep_accumulator acc;  // with every t_first/proxy value
  double seconds = 0;
};

// One CSV field, quoted (quotes doubled) only if it holds a comma, a quote or a line break; and
// the fields of one line read back (RFC 4180, no line breaks inside fields).
void csv_append_field(std::string& out, std::string_view v);
std::vector<std::string> csv_split_line(std::string_view line);

enum class sweep_format { csv, jsonl };
sweep_format sweep_parse_format(const std::string& s);  // "csv" or "jsonl"
const char* sweep_format_name(sweep_format f);
const std::vector<std::string>& sweep_row_columns();

// Appends one row (with its newline); reals as sweep_real_text(v, digits). Compiled for the
// compiled reals (core/real.hpp).
template <class T> void sweep_format_row(std::string& out, const sweep_row<T>& r, sweep_format fmt, unsigned digits);

// The first line(s), carrying `run`, and the end line.
std::string sweep_rows_header(const json& run, sweep_format fmt);
std::string sweep_rows_trailer(std::uint64_t pairs, double seconds, sweep_format fmt);

// A rows file read back, its reals' exact text kept for types wider than double. usage_error if
// it is not a rows file, is malformed, has no end line (its sweep did not finish) or is of a
// version sweep_run_of_version refuses.
sweep_input sweep_read_rows(const std::string& path);

}  // namespace gyrores
