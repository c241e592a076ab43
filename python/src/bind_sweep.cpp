// gyrores.enumerate_pairs (model/enumerate.hpp, lazily) and gyrores.sweep (sweep/engine.hpp in
// double, the GIL released while the workers run): the rows as NumPy columns, which
// gyrores/__init__.py assembles into a structured array, and the summary of `gyrores sweep
// --json` (io/sweep_summary.hpp).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <map>
#include <vector>

#include <gyrores/io/sweep_run.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/model/enumerate.hpp>
#include <gyrores/sweep/sweep.hpp>

#include "common.hpp"
#include "row_columns.hpp"

namespace gyrores::python {
namespace {

// A Python iterator over (tau, sigma): the library's lazy enumeration, one pair per __next__.
class pair_iterator {
 public:
  pair_iterator(std::int64_t max_order, std::int64_t min_order) : pairs_(check(min_order, max_order)), it_(pairs_.begin()) {}
  py::tuple next() {
    if (it_ == std::default_sentinel) throw py::stop_iteration();
    const auto p = *it_;
    ++it_;
    return py::make_tuple(p.tau(), p.sigma());
  }

 private:
  // The enumeration's int64 arithmetic is exact up to the sweeps' order limit (sweep/checks.hpp).
  static coprime_pairs check(std::int64_t min_order, std::int64_t max_order) {
    if (max_order > sweep_max_order_limit) throw usage_error("max_order must be <= 2^40, got " + std::to_string(max_order));
    return coprime_pairs(min_order, max_order);
  }
  coprime_pairs pairs_;
  coprime_pairs::iterator it_;
};

// The engine's blocks are evaluated on workers in any order; their rows wait here, by first
// index, until on_block takes them in enumeration order.
struct pending_rows {
  std::mutex mtx;
  std::map<std::uint64_t, std::vector<sweep_row<double>>> blocks;
};

// Called on the calling thread between blocks, GIL released: the progress callback (with the
// GIL) and Ctrl-C. A Python exception stops the run (the engine rethrows it after the workers).
void report_progress(const py::object& progress, std::uint64_t done, std::uint64_t total) {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (!progress.is_none()) progress(done, total);
}

sweep_config config_of(std::int64_t max_order, std::int64_t min_order, const std::string& checks,
                       std::int64_t examples) {
  sweep_config cfg;
  cfg.max_order = max_order;
  cfg.min_order = min_order;
  cfg.checks = sweep_parse_checks(checks);
  if (examples < 0) throw usage_error("examples must be >= 0");
  cfg.max_examples = std::size_t(examples);
  sweep_validate(cfg);
  return cfg;
}

py::tuple run_sweep(std::int64_t max_order, std::int64_t min_order, bool rows, const py::object& progress,
                    const std::string& checks, unsigned threads, std::int64_t examples) {
  const sweep_config cfg = config_of(max_order, min_order, checks, examples);
  const std::uint64_t total = sweep_total_pairs(cfg.min_order, cfg.max_order);
  sweep_accumulator acc;
  acc.max_examples = cfg.max_examples;
  row_columns cols;
  pending_rows pending;
  sweep_engine_options eo;
  eo.threads = threads;
  auto evaluate = [&](const std::vector<resonant_pair<std::int64_t>>& pairs, sweep_block& blk) {
    std::vector<sweep_row<double>> out;
    for (const auto& p : pairs) {
      auto row = sweep_evaluate<double>(p, cfg);
      blk.summary.add(sweep_record_of(row, cfg.digits));
      if (rows) out.push_back(std::move(row));
    }
    std::lock_guard<std::mutex> lk(pending.mtx);
    pending.blocks[blk.first] = std::move(out);
  };
  auto on_block = [&](sweep_block& blk) {
    acc.merge(blk.summary);
    std::vector<sweep_row<double>> done;
    {
      std::lock_guard<std::mutex> lk(pending.mtx);
      done = std::move(pending.blocks.at(blk.first));
      pending.blocks.erase(blk.first);
    }
    for (const auto& r : done) cols.add(r);
    report_progress(progress, blk.first + blk.count, total);
  };
  const auto t0 = std::chrono::steady_clock::now();
  json summary = call_library([&] {
    sweep_run_blocks(cfg, eo, evaluate, on_block);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return sweep_summary_json(acc, sweep_run_json<double>(cfg), seconds);
  });
  return py::make_tuple(rows ? py::object(columns_dict(cols)) : py::none(), to_python(summary));
}

}  // namespace

void bind_sweep(py::module_& m) {
  py::class_<pair_iterator>(m, "_PairIterator", "Lazy iterator over the resonant pairs (tau, sigma) by order.")
      .def("__iter__", [](pair_iterator& self) -> pair_iterator& { return self; })
      .def("__next__", &pair_iterator::next);
  m.def("_enumerate_pairs", [](std::int64_t max_order, std::int64_t min_order) { return pair_iterator(max_order, min_order); },
        py::arg("max_order"), py::arg("min_order"), "A _PairIterator. Use gyrores.enumerate_pairs.");
  m.def("_sweep_pairs", &sweep_total_pairs, py::arg("min_order"), py::arg("max_order"),
        "The number of pairs with min_order <= tau + sigma <= max_order (exact, without enumerating them).");
  m.def("_sweep", &run_sweep, py::arg("max_order"), py::arg("min_order"), py::arg("rows"), py::arg("progress"),
        py::arg("checks"), py::arg("threads"), py::arg("examples"),
        "(row columns or None, summary dict) of a sweep in double. Use gyrores.sweep.");
}

}  // namespace gyrores::python
