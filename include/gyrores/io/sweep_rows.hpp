// The rows file of a sweep (`gyrores sweep --out FILE`): one row per pair in CSV or JSON Lines,
// between a first line carrying the run description and an end line. Columns, kinds and the
// framing lines are documented in docs/formats.md (sweep rows); a merge reads rows back into
// the records the summary needs.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gyrores/io/json.hpp>
#include <gyrores/io/sweep_run.hpp>
#include <gyrores/sweep/sweep.hpp>

namespace gyrores {

enum class sweep_format { csv, jsonl };

// "csv" or "jsonl"; usage_error otherwise.
sweep_format sweep_parse_format(const std::string& s);
const char* sweep_format_name(sweep_format f);

// The columns of a row, in order.
const std::vector<std::string>& sweep_row_columns();

// Appends the fields of one row in order: integers and booleans bare, text quoted (CSV: only
// when needed; JSON: always), null = not applicable (empty CSV field, JSON null).
class sweep_row_writer {
 public:
  sweep_row_writer(std::string& out, sweep_format fmt) : out_(out), fmt_(fmt) {}
  void integer(std::int64_t v);
  void boolean(bool v);
  void tri(int v);  // -1: null, else a boolean
  void text(const std::string& v);
  void null();
  // The status columns, `failed`, `note`, and the end of the line (what every row ends with).
  void finish(const std::array<sweep_status, sweep_check_count>& status, bool failed, const std::string& note);

 private:
  void next_key();
  std::string& out_;
  sweep_format fmt_;
  std::size_t col_ = 0;
};

// Appends one row (with its newline) in the given format; reals with sweep_real_text(v, digits).
template <class T> void sweep_format_row(std::string& out, const sweep_row<T>& r, sweep_format fmt, unsigned digits) {
  sweep_row_writer w(out, fmt);
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
  w.finish(r.status, r.failed, r.note);
}

// Compiled once in src/io/sweep_rows.cpp for the compiled reals (core/real.hpp).
#define GYRORES_SWEEP_ROWS_INSTANCES(PREFIX, T) \
  PREFIX template void sweep_format_row<T>(std::string&, const sweep_row<T>&, sweep_format, unsigned);
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ROWS_INSTANCES, extern)

// The first line(s): CSV "# gyrores-sweep-rows/2 {run}" and the column header; JSONL
// {"gyrores_sweep_rows": run, "version": 2} (2: sweep_format_version).
std::string sweep_rows_header(const json& run, sweep_format fmt);
// The end line: {"pairs", "seconds"} after "# end " (CSV) or as {"gyrores_sweep_end": ...}.
std::string sweep_rows_trailer(std::uint64_t pairs, double seconds, sweep_format fmt);

// A rows file (CSV or JSONL, detected from its first line) read back: the run description (of
// this version: sweep_run_of_version) and the accumulator of its rows (exact text of the extremes
// kept for types wider than double). usage_error if the file cannot be read, is not a rows file,
// is malformed, has no end line (the sweep that wrote it did not finish), or is of a version
// sweep_run_of_version refuses.
sweep_input sweep_read_rows(const std::string& path);

}  // namespace gyrores
