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

// The row columns (io/sweep_rows.hpp names): not applicable is NaN for reals, -1 for flags.
struct row_columns {
  std::vector<std::int64_t> tau, sigma, order;
  std::vector<std::int8_t> delta_mod4, first_at_paper_node, paper_lobe_min, failed;
  std::vector<double> r_res, theta_first, t_first, t_min_paper, t_ratio, asy_error, asy_bound, asy_ratio, asy_constant;
  std::vector<std::int32_t> minimiser_count, strand_offset;
  std::array<std::vector<std::int8_t>, sweep_check_count> checks;
  std::vector<std::string> notes;
  void add(const sweep_row<double>& r);
};

void row_columns::add(const sweep_row<double>& r) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool ok = !r.failed;
  tau.push_back(r.tau);
  sigma.push_back(r.sigma);
  order.push_back(r.tau + r.sigma);
  delta_mod4.push_back(std::int8_t(r.delta_mod4));
  for (auto [col, v, have] : {std::tuple{&r_res, r.r_res, ok}, {&theta_first, r.theta_first, ok}, {&t_first, r.t_first, ok},
                              {&t_min_paper, r.t_min_paper, ok}, {&t_ratio, r.t_ratio, ok && r.has_ratio},
                              {&asy_error, r.asy_error, ok && r.has_asy}, {&asy_bound, r.asy_bound, ok && r.has_asy},
                              {&asy_ratio, r.asy_ratio, ok && r.has_asy}, {&asy_constant, r.asy_constant, ok && r.has_asy}})
    col->push_back(have ? v : nan);
  first_at_paper_node.push_back(std::int8_t(ok ? r.first_at_paper_node : -1));
  paper_lobe_min.push_back(std::int8_t(ok ? r.paper_lobe_min : -1));
  minimiser_count.push_back(ok ? r.minimiser_count : -1);
  strand_offset.push_back(r.strand_offset);
  for (int i = 0; i < sweep_check_count; ++i) {
    const sweep_status s = r.status[std::size_t(i)];
    checks[std::size_t(i)].push_back(std::int8_t(s == sweep_status::none ? -1 : s == sweep_status::pass ? 1 : 0));
  }
  failed.push_back(std::int8_t(r.failed));
  notes.push_back(r.note);
}

template <class V> py::array column(const V& v) {
  using T = typename V::value_type;
  return py::array_t<T>(py::ssize_t(v.size()), v.data());
}

py::dict columns_dict(const row_columns& c) {
  py::dict d;
  for (auto [name, v] : {std::pair{"tau", &c.tau}, {"sigma", &c.sigma}, {"order", &c.order}}) d[name] = column(*v);
  d["delta_mod4"] = column(c.delta_mod4);
  for (auto [name, v] : {std::pair{"r_res", &c.r_res}, {"theta_first", &c.theta_first}, {"t_first", &c.t_first},
                         {"t_min_paper", &c.t_min_paper}, {"t_first_over_proxy", &c.t_ratio}})
    d[name] = column(*v);
  d["first_at_paper_node"] = column(c.first_at_paper_node);
  d["paper_lobe_min"] = column(c.paper_lobe_min);
  for (auto [name, v] : {std::pair{"asy_error", &c.asy_error}, {"asy_bound", &c.asy_bound},
                         {"asy_ratio", &c.asy_ratio}, {"asy_constant", &c.asy_constant}})
    d[name] = column(*v);
  d["minimiser_count"] = column(c.minimiser_count);
  d["strand_offset_min"] = column(c.strand_offset);
  for (int i = 0; i < sweep_check_count; ++i) d[sweep_check_column(i)] = column(c.checks[std::size_t(i)]);
  d["failed"] = column(c.failed);
  d["note"] = py::cast(c.notes);
  return d;
}

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
                       std::int64_t cross_check_max_order, std::int64_t examples) {
  sweep_config cfg;
  cfg.max_order = max_order;
  cfg.min_order = min_order;
  cfg.checks = sweep_parse_checks(checks);
  cfg.cross_check_max_order = cross_check_max_order;
  if (examples < 0) throw usage_error("examples must be >= 0");
  cfg.max_examples = std::size_t(examples);
  sweep_validate(cfg);
  return cfg;
}

py::tuple run_sweep(std::int64_t max_order, std::int64_t min_order, bool rows, const py::object& progress,
                    const std::string& checks, unsigned threads, std::int64_t cross_check_max_order, std::int64_t examples) {
  const sweep_config cfg = config_of(max_order, min_order, checks, cross_check_max_order, examples);
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
  m.def("_sweep", &run_sweep, py::arg("max_order"), py::arg("min_order"), py::arg("rows"), py::arg("progress"),
        py::arg("checks"), py::arg("threads"), py::arg("cross_check_max_order"), py::arg("examples"),
        "(row columns or None, summary dict) of a sweep in double. Use gyrores.sweep.");
}

}  // namespace gyrores::python
