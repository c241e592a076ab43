// include/gyrores/app/sweep.hpp: a sweep in its working type with its files or in memory, and the
// merge of shard outputs.
#include <gyrores/app/sweep.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <gyrores/core/error.hpp>
#include <gyrores/io/files.hpp>
#include <gyrores/io/sweep_summary.hpp>

namespace gyrores::app {

template <class T>
sweep_report sweep_to_files(const sweep_config& cfg_in, const sweep_files& files, const sweep_engine_options& eo_in,
                            const sweep_progress& progress) {
  sweep_config cfg = cfg_in;
  if (cfg.min_order < 3) cfg.min_order = 3;
  sweep_validate(cfg);
  sweep_file_session session(cfg, files, sweep_run_json<T>(cfg), progress);
  sweep_row_sink<T> format_row;
  if (!files.rows_path.empty())
    format_row = [f = files.rows_format, digits = cfg.digits](sweep_block& b, const sweep_row<T>& r) {
      sweep_format_row(b.rows, r, f, digits);
    };
  sweep_engine_options eo = eo_in;
  eo.start = session.start();
  sweep_outcome out;
  try {
    out = sweep_run<T>(cfg, eo, [&](sweep_block& b) { session.on_block(b); }, format_row);
  } catch (...) {
    try {
      session.checkpoint();  // keep what is finished: the prefix delivered so far
    } catch (...) {
    }
    throw;
  }
  return session.finish(out);
}

GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_FILES_INSTANCES, )

namespace {

// The caps (docs/formats.md, "Size caps"): pairs, and scratch bytes (the values file, 8 bytes a
// pair, plus the rows: ~190 bytes a row in csv, ~390 in jsonl at 17 digits, measured at order
// 2000).
constexpr double large_sweep_pairs = 1e10, large_sweep_bytes = 100e9;
constexpr double row_bytes_csv = 200, row_bytes_jsonl = 400;

// The sweep's cost before it starts: pairs (counted, or 3 M^2 / (2 pi^2) coprime pairs beyond the
// counting limit) and scratch bytes; refused beyond the caps unless allowed.
void check_sweep_size(const sweep_request& r) {
  const sweep_config& cfg = r.config;
  const std::int64_t lo_order = std::max<std::int64_t>(cfg.min_order, 3);
  const double m = double(cfg.max_order), lo = double(lo_order);
  const double all = cfg.max_order <= sweep_count_limit ? double(sweep_total_pairs(lo_order, cfg.max_order))
                                                       : 3.0 / (2 * 9.869604401089358) * (m * m - lo * lo);
  const double pairs = all / double(cfg.shard_count);
  const double per_row = r.files.rows_path.empty()                       ? 0
                         : r.files.rows_format == sweep_format::jsonl ? row_bytes_jsonl
                                                                         : row_bytes_csv;
  const double bytes = pairs * (8 + per_row * std::max(1.0, double(cfg.digits) / 17));
  if (r.allow_large || (pairs <= large_sweep_pairs && bytes <= large_sweep_bytes)) return;
  char buf[128];
  std::snprintf(buf, sizeof buf, "this sweep has about %.3g pairs and needs about %.3g GB", pairs, bytes / 1e9);
  throw usage_error(std::string(buf) +
                    " of scratch and output (limits: 1e10 pairs, 100 GB): add --allow-large to run it anyway, or shard it");
}

}  // namespace

sweep_report run_sweep(const sweep_request& r) {
  sweep_validate(r.config);
  check_sweep_size(r);
  sweep_engine_options eo = r.engine;
  // Without rows a pair costs ~0.2 us (src/lib/sweep/fast.cpp): blocks of 1024 would be handed
  // out ~10^4 times a second, and the hand-over shows; 8192 keep it below 1%.
  if (r.files.rows_path.empty()) eo.block_size = 8192;
  if (r.config.digits <= 15) return sweep_to_files<double>(r.config, r.files, eo, r.progress);
  if (r.config.digits <= 30) return sweep_to_files<float128>(r.config, r.files, eo, r.progress);
  return sweep_to_files<mpfr_real>(r.config, r.files, eo, r.progress);
}

json run_sweep_in_memory(const sweep_in_memory_request& r) {
  const sweep_config& cfg = r.config;
  sweep_validate(cfg);
  const std::uint64_t total = sweep_total_pairs(cfg.min_order, cfg.max_order);
  sweep_accumulator acc;
  acc.max_examples = cfg.max_examples;
  sweep_engine_options eo;
  eo.threads = r.threads;
  sweep_row_sink<double> keep;
  if (r.keep_rows) keep = [](sweep_block& b, const sweep_row<double>& row) { b.kept.push_back(row); };
  auto on_block = [&](sweep_block& blk) {
    acc.merge(blk.summary);
    if (r.on_block) r.on_block(blk.kept, blk.first + blk.count, total);
  };
  const auto t0 = std::chrono::steady_clock::now();
  sweep_run<double>(cfg, eo, on_block, keep);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return sweep_summary_json(acc, sweep_run_json<double>(cfg), seconds);
}

json run_merge(const std::vector<std::string>& inputs, const std::string& summary_path) {
  // Before reading anything: the output is writable, is none of the inputs (nor their values
  // files), and no other run writes it; the inputs are checked by sweep_merge.
  path_lock lock;
  if (!summary_path.empty()) {
    // The lock file too: merge writes and removes it (an input named OUT.lock would be lost).
    std::vector<named_path> paths{{"--summary", summary_path}, {"the lock file of --summary", path_lock_file(summary_path)}};
    for (const auto& f : inputs) {
      paths.push_back({"input", f});
      paths.push_back({"the values file of input", f + ".values"});
    }
    check_distinct_paths(paths);
    check_output_path(summary_path);
    lock = path_lock::acquire(summary_path);
  }
  json s = sweep_merge(inputs);
  if (!summary_path.empty()) write_file_atomically(summary_path, s.dump(2) + "\n");
  return s;
}

}  // namespace gyrores::app
