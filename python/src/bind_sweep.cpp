// gyrores.enumerate_pairs (model/enumerate.hpp, lazily) and gyrores.sweep (app/sweep.hpp, a sweep
// in double in memory, the GIL released while the workers run): the rows written straight into
// the NumPy structured array gyrores/__init__.py allocates (row_record.hpp, as gyrores.pairs), and
// the summary of `gyrores sweep --json`.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include <gyrores/app/sweep.hpp>
#include <gyrores/model/enumerate.hpp>

#include "common.hpp"
#include "row_record.hpp"

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

// Called on the calling thread between blocks, GIL released: the progress callback (with the
// GIL) and Ctrl-C. A Python exception stops the run (the engine rethrows it after the workers).
void report_progress(const py::object& progress, std::uint64_t done, std::uint64_t total) {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (!progress.is_none()) progress(done, total);
}

// The rows go straight into `table` (a NumPy structured array of row_fields(), one record per
// pair in enumeration order, allocated by gyrores.sweep), written on this thread as the blocks
// arrive in order: no per-column vectors, no copies. Returns (the notes [(index, text)] of the
// few rows that have one, or None without a table; the summary).
py::tuple run_sweep(std::int64_t max_order, std::int64_t min_order, const py::object& table, const py::object& progress,
                    const std::string& checks, unsigned threads, std::int64_t examples) {
  app::sweep_in_memory_request r;
  r.config.max_order = max_order;
  r.config.min_order = min_order;
  r.config.checks = sweep_parse_checks(checks);
  if (examples < 0) throw usage_error("examples must be >= 0");
  r.config.max_examples = std::size_t(examples);
  r.threads = threads;
  r.keep_rows = !table.is_none();
  char* records = nullptr;
  std::uint64_t capacity = 0;
  row_layout layout{};
  if (r.keep_rows) {
    py::array t = table.cast<py::array>();
    if (t.ndim() != 1 || !(t.flags() & py::array::c_style) || !t.writeable())
      throw usage_error("sweep(): the table must be one-dimensional, contiguous and writeable");
    layout = row_layout::of(t);
    records = static_cast<char*>(t.mutable_data());
    capacity = std::uint64_t(t.size());
  }
  std::vector<std::pair<std::uint64_t, std::string>> notes;
  r.on_block = [&](std::vector<sweep_row<double>>& block, std::uint64_t done, std::uint64_t total) {
    if (records != nullptr) {
      if (total != capacity || done > capacity || block.size() > done)
        throw compute_error("sweep(): the table has " + std::to_string(capacity) + " records for " + std::to_string(total) + " pairs");
      std::uint64_t i = done - block.size();  // blocks arrive in enumeration order
      for (const auto& row : block) {
        layout.write(records + std::ptrdiff_t(i) * layout.itemsize, row);
        if (!row.note.empty()) notes.emplace_back(i, row.note);
        ++i;
      }
    }
    report_progress(progress, done, total);
  };
  json summary = call_library([&] { return app::run_sweep_in_memory(r); });
  py::object found = py::none();
  if (r.keep_rows) {
    py::list l;
    for (const auto& [index, text] : notes) l.append(py::make_tuple(index, text));
    found = l;
  }
  return py::make_tuple(found, to_python(summary));
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
  m.def("_sweep", &run_sweep, py::arg("max_order"), py::arg("min_order"), py::arg("table"), py::arg("progress"),
        py::arg("checks"), py::arg("threads"), py::arg("examples"),
        "(notes [(index, text)] or None, summary dict) of a sweep in double, its rows written into table "
        "(row_fields(), one record per pair) unless it is None. Use gyrores.sweep.");
}

}  // namespace gyrores::python
