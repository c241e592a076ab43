// include/gyrores/io/sweep_files.hpp: the rows file, checkpoints, the resume state, the end.
#include <gyrores/io/sweep_files.hpp>

#include <unistd.h>

#include <algorithm>
#include <string_view>

#include <gyrores/core/error.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/io/sweep_values_file.hpp>

namespace gyrores {

std::size_t sweep_default_values_in_memory() {
  constexpr std::size_t most = std::size_t(1) << 27, least = std::size_t(1) << 20;
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return least;
  const double eighth = double(pages) * double(page) / 8 / sizeof(double);
  return eighth >= double(most) ? most : std::max(least, std::size_t(eighth));
}

std::string sweep_default_state_path(const sweep_files& f) {
  if (!f.state_path.empty()) return f.state_path;
  if (!f.rows_path.empty()) return f.rows_path + ".resume";
  if (!f.summary_path.empty()) return f.summary_path + ".resume";
  return "gyrores-sweep.resume";
}

namespace {

const char* const state_format = "gyrores-sweep-state";

// The state file's content, parsed and checked against this sweep's run description.
json read_state(const std::string& state, const json& run_files) {
  if (!file_exists(state))
    throw usage_error("cannot resume: no resume state at '" + state +
                      "' (nothing to resume, or a different rows, summary or state path)");
  json st;
  try {
    st = json_parse_strict(read_file(state, sweep_json_read_limit, "a resume state"));
  } catch (const json::exception& e) {
    throw usage_error("cannot resume: '" + state + "' is not a resume state: " + e.what());
  }
  if (st.value("format", "") != state_format) throw usage_error("cannot resume: '" + state + "' is not a resume state");
  // Version 1 (docs/formats.md) is refused: its rows file has the cross-check's column, and rows
  // of two layouts in one file would be worse than a new run.
  if (!st.contains("version") || st.at("version") != sweep_format_version) {
    const std::string version = st.contains("version") ? st.at("version").dump() : "none";
    throw usage_error("cannot resume: the state at '" + state + "' has sweep format version " + version +
                      (version == "1" ? " (its rows carry the retired cross-check)" : "") +
                      "; this gyrores continues only version " + std::to_string(sweep_format_version) +
                      ": start the sweep again with --fresh");
  }
  if (st.at("run") != run_files)
    throw usage_error("cannot resume: the state at '" + state + "' is for another sweep: " +
                      sweep_run_mismatch(st.at("run"), run_files) + "; start it again without --resume");
  return st;
}

}  // namespace

sweep_file_session::sweep_file_session(const sweep_config& cfg, const sweep_files& files, const json& run,
                                       const sweep_progress& progress)
    : cfg_(cfg),
      files_(files),
      progress_(progress),
      run_(run),
      run_files_(run),
      state_(sweep_default_state_path(files)),
      values_(state_ + ".values"),
      rows_part_(files.rows_path + ".part"),
      rows_(!files.rows_path.empty()) {
  run_files_["rows"] = rows_ ? json({{"path", files.rows_path}, {"format", sweep_format_name(files.rows_format)}})
                             : json(nullptr);
  if (cfg.max_order <= sweep_count_limit)
    total_ = sweep_shard_pairs(sweep_total_pairs(cfg.min_order, cfg.max_order), cfg.shard_index, cfg.shard_count);
  acc_.max_examples = cfg.max_examples;
  check_paths_and_lock();
  // A run killed while replacing one of these leaves PATH.tmp.PID behind (never the final name).
  for (const std::string& p : {state_, files.summary_path, files.summary_path + ".values"})
    if (!p.empty() && p != ".values") remove_stale_temporaries(p);
  if (files.resume) {
    // A state whose fields are missing or of the wrong type is bad input, like one that is not
    // JSON (read_state): usage_error, not the JSON library's exception.
    try {
      restore();
    } catch (const json::exception& e) {
      throw usage_error("cannot resume: '" + state_ + "' is not a valid resume state: " + e.what());
    } catch (const json_value_error& e) {
      throw usage_error("cannot resume: '" + state_ + "' is not a valid resume state: " + e.what());
    } catch (const compute_error& e) {  // a real that does not parse (sweep/real_text)
      throw usage_error("cannot resume: '" + state_ + "' is not a valid resume state: " + e.what());
    }
  } else {
    start_fresh();
  }
  done_ = start_;
  // A run whose values fit the memory budget (one per pair at most) keeps them all in memory,
  // with room for them reserved up front (the vector then never moves them; address space
  // only, pages are touched as values arrive). A larger run, or one of unknown size, would only
  // fill the budget to write it out: its values go to the file through a buffer of 2^20 (8 MB).
  if (total_ > start_ && total_ - start_ <= files_.values_in_memory) {
    spill_at_ = files_.values_in_memory;
    acc_.t_ratios.reserve(std::size_t(total_ - start_));
  } else {
    spill_at_ = std::min(files_.values_in_memory, std::size_t(1) << 20);
  }
  t0_ = std::chrono::steady_clock::now();
}

// Before the first pair: no two of the run's files are one file, each can be written, and no
// other gyrores run holds them; a saved state is never discarded silently.
void sweep_file_session::check_paths_and_lock() {
  const bool shard_values = !files_.summary_path.empty() && cfg_.shard_count > 1;
  const std::vector<named_path> paths{{"the rows file", files_.rows_path},
                                      {"the rows file's scratch", rows_ ? rows_part_ : std::string()},
                                      {"the summary", files_.summary_path},
                                      {"the summary's values file", shard_values ? files_.summary_path + ".values" : ""},
                                      {"the resume state", state_},
                                      {"the resume state's values", values_},
                                      // The lock files are written and removed too: a rows file
                                      // named SUMMARY.lock would be lost at the end of the run.
                                      {"the resume state's lock file", path_lock_file(state_)},
                                      {"the summary's lock file", files_.summary_path.empty() ? "" : path_lock_file(files_.summary_path)},
                                      {"the rows file's lock file", rows_ ? path_lock_file(files_.rows_path) : std::string()}};
  check_distinct_paths(paths);
  for (const auto& p : paths)
    if (!p.path.empty()) check_output_path(p.path);
  // One lock per output the user named, so that two runs sharing any of them collide; the
  // state's lock also keeps merge and a resume away while this run holds it.
  locks_.push_back(path_lock::acquire(state_, files_.on_lock_wait));
  for (const std::string& p : {files_.summary_path, files_.rows_path})
    if (!p.empty()) locks_.push_back(path_lock::acquire(p));
  if (!files_.resume && file_exists(state_) && !files_.fresh)
    throw usage_error("a saved run exists at '" + state_ + "': use --resume to continue it, or --fresh to discard it");
}

double sweep_file_session::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
}

// A new sweep: an old state goes, the rows file starts with its header.
void sweep_file_session::start_fresh() {
  remove_file(state_);
  remove_file(values_);  // created when values first go there (short runs need no file)
  if (!rows_) return;
  rows_file_ = append_file(rows_part_, append_file::mode::create);
  keep_mode_of(files_.rows_path, rows_part_);  // a mode-600 rows file is not readable by others meanwhile
  const std::string h = sweep_rows_header(run_, files_.rows_format);
  rows_file_.write(h);
  rows_bytes_ = h.size();
}

// Continue from the last checkpoint: anything written after it is cut off and recomputed.
void sweep_file_session::restore() {
  const json st = read_state(state_, run_files_);
  // get<std::uint64_t> on a floating value (an integer beyond 64 bits) is undefined behaviour.
  for (const char* k : {"done", "values_count", "rows_bytes"})
    if (st.contains(k) && !st.at(k).is_number_unsigned())
      throw usage_error("cannot resume: '" + state_ + "' has " + k + " = " + st.at(k).dump());
  start_ = st.at("done").get<std::uint64_t>();
  seconds_before_ = st.at("seconds").get<double>();
  acc_ = sweep_accumulator_from_json(st.at("summary"), cfg_.max_examples);
  // The counts must agree with each other: a state edited (or mixed up) outside gyrores would
  // otherwise skip or repeat pairs and print a wrong count with exit 0.
  const std::uint64_t values_count = st.at("values_count").get<std::uint64_t>();
  check_state_counts(values_count);
  restore_values(values_count);
  if (!rows_) return;
  rows_bytes_ = st.at("rows_bytes").get<std::uint64_t>();
  // A run stopped after renaming its finished rows file but before removing the state (the last
  // two steps of finish_complete): the file is taken back, its end line cut below and rewritten.
  if (!file_exists(rows_part_) && file_exists(files_.rows_path)) rename_file(files_.rows_path, rows_part_);
  // Longer than recorded is what a kill between checkpoints leaves (cut off and recomputed);
  // shorter means the file was changed from outside: never padded (truncate would add zeros).
  if (!file_exists(rows_part_))
    throw usage_error("cannot resume: the rows file '" + rows_part_ + "' is missing (the state records " +
                      std::to_string(rows_bytes_) + " bytes)");
  if (const std::uint64_t have = file_size(rows_part_); have < rows_bytes_)
    throw usage_error("cannot resume: the rows file '" + rows_part_ + "' has " + std::to_string(have) +
                      " bytes, fewer than the " + std::to_string(rows_bytes_) +
                      " its state records (changed from outside?): start again with --fresh");
  check_rows_boundary();
  truncate_file(rows_part_, rows_bytes_);
  rows_file_ = append_file(rows_part_, append_file::mode::append);
}

void sweep_file_session::check_state_counts(std::uint64_t values_count) const {
  auto inconsistent = [&](const std::string& why) {
    return usage_error("cannot resume: the state at '" + state_ + "' is inconsistent (" + why +
                       "; changed from outside?): start again with --fresh");
  };
  const std::uint64_t pairs = acc_.pairs;
  if (pairs != start_)
    throw inconsistent("done = " + std::to_string(start_) + ", but its summary counts " + std::to_string(pairs) + " pairs");
  if (total_ > 0 && start_ > total_)
    throw inconsistent("done = " + std::to_string(start_) + ", but the sweep has " + std::to_string(total_) + " pairs");
  if (acc_.degenerate > pairs || acc_.errors.violations > pairs)
    throw inconsistent("more degenerate or failed pairs than pairs");
  // One value per non-degenerate pair that did not fail (sweep/summary.hpp).
  const std::uint64_t most = pairs - acc_.degenerate;
  const std::uint64_t least = most > acc_.errors.violations ? most - acc_.errors.violations : 0;
  if (values_count > most || values_count < least)
    throw inconsistent("values_count = " + std::to_string(values_count) + " for " + std::to_string(most) +
                       " non-degenerate pairs");
}

// The recorded length of the rows must end a line (the header or a row): a length from
// elsewhere would leave half a row in the file.
void sweep_file_session::check_rows_boundary() const {
  const std::string header = sweep_rows_header(run_, files_.rows_format);
  bool ends_line = rows_bytes_ >= header.size();
  if (ends_line)
    read_file_range(rows_part_, rows_bytes_ - 1, 1, 1, [&](const void* p, std::size_t) {
      ends_line = *static_cast<const char*>(p) == '\n';
    });
  if (!ends_line)
    throw usage_error("cannot resume: the state at '" + state_ + "' records " + std::to_string(rows_bytes_) +
                      " bytes of rows, which do not end a line of '" + rows_part_ +
                      "' (changed from outside?): start again with --fresh");
}

// The values file may hold more than recorded (a checkpoint interrupted before the state was
// replaced): keep the recorded prefix.
void sweep_file_session::restore_values(std::uint64_t count) {
  if (!file_exists(values_) || file_size(values_) / sizeof(double) < count)
    throw usage_error("cannot resume: '" + values_ + "' is missing or shorter than its state records");
  truncate_file(values_, count * sizeof(double));
  values_written_ = memory_first_ = count;  // the earlier runs' values stay in the file
  values_file_ = append_file(values_, append_file::mode::append);
}

// The values in memory not yet in the values file go there (made durable by the caller's sync);
// memory keeps them.
void sweep_file_session::write_values() {
  const auto& v = acc_.t_ratios.memory();
  const std::uint64_t end = memory_first_ + v.size();
  if (end == values_written_) return;
  if (!values_file_.is_open()) values_file_ = append_file(values_, append_file::mode::append);
  const double* from = v.data() + (values_written_ - memory_first_);
  values_file_.write(std::string_view(reinterpret_cast<const char*>(from), (end - values_written_) * sizeof(double)));
  values_written_ = end;
}

// Beyond the memory budget: every value goes to the values file and memory is emptied.
void sweep_file_session::spill_values() {
  write_values();
  acc_.t_ratios.clear_memory();
  memory_first_ = values_written_;
}

void sweep_file_session::on_block(const sweep_block& b) {
  if (rows_ && !b.rows.empty()) rows_file_.write(b.rows);
  rows_bytes_ += b.rows.size();
  acc_.merge(b.summary);
  // A sweep to order 10^5 has 10 GB of values: beyond the memory budget they go to the values
  // file as they pile up, and the summary's quantiles read them back from there
  // (sweep/values.hpp). Below it they stay in memory: writing every value and reading it back
  // took about a quarter of a short sweep's CPU time, most of it in the kernel.
  if (acc_.t_ratios.memory().size() >= spill_at_) spill_values();
  done_ = b.first + b.count;
  if (b.count) last_ = b.last;
  if (progress_) progress_({done_, total_, elapsed(), done_ - start_});
  if (files_.checkpoint_seconds > 0 && elapsed() - last_checkpoint_ >= files_.checkpoint_seconds) checkpoint();
}

void sweep_file_session::checkpoint() {
  if (rows_) rows_file_.sync();
  // The values file exists from the first checkpoint on, even empty: a resume requires it.
  if (!values_file_.is_open()) values_file_ = append_file(values_, append_file::mode::append);
  write_values();
  values_file_.sync();
  json st;
  st["format"] = state_format;
  st["version"] = sweep_format_version;
  st["run"] = run_files_;
  st["done"] = done_;
  st["next_after"] = {last_.first, last_.second};
  st["rows_bytes"] = rows_bytes_;
  st["values_count"] = values_written_;
  st["seconds"] = seconds_before_ + elapsed();
  st["summary"] = sweep_accumulator_json(acc_, sweep_all_checks);
  write_file_atomically(state_, st.dump() + "\n");
  last_checkpoint_ = elapsed();
}

sweep_report sweep_file_session::finish(const sweep_outcome& out) {
  sweep_report rep;
  rep.state_path = state_;
  rep.total = total_;
  rep.threads = out.threads;
  rep.done = out.done;
  rep.seconds = elapsed();
  if (out.complete) finish_complete(out.threads, rep);
  else checkpoint();
  return rep;
}

// The summary (and a shard's values file), the rows' end line and final name; the state goes.
void sweep_file_session::finish_complete(unsigned threads, sweep_report& rep) {
  const double seconds = seconds_before_ + elapsed();
  if (values_file_.is_open()) values_file_.close();
  // The values before memory_first_ are only in the values file (beyond the budget, or from the
  // runs before a resume): replayed from there, then memory's, in enumeration order.
  if (memory_first_ > 0) acc_.t_ratios.add_source(sweep_values_file_source(values_, 0, memory_first_), memory_first_);
  json srun = run_;
  srun["threads"] = threads;
  srun["complete"] = true;
  json summary = sweep_summary_json(acc_, srun, seconds);
  if (!files_.summary_path.empty()) {
    if (cfg_.shard_count > 1) {
      const std::string vpath = files_.summary_path + ".values";
      const json digest = sweep_write_values_file(vpath, acc_.t_ratios);
      auto slash = vpath.rfind('/');
      summary["values_file"] = slash == std::string::npos ? vpath : vpath.substr(slash + 1);
      summary["values_check"] = digest;
    }
    write_file_atomically(files_.summary_path, summary.dump(2) + "\n");
  }
  if (rows_) {
    rows_file_.write(sweep_rows_trailer(acc_.pairs, seconds, files_.rows_format));
    rows_file_.close();
    keep_mode_of(files_.rows_path, rows_part_);
    rename_file(rows_part_, files_.rows_path);
  }
  remove_file(state_);
  remove_file(values_);
  rep.complete = true;
  rep.summary = summary;
}

}  // namespace gyrores
