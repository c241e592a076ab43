// gyrores.pairs: the sweep's row (sweep/evaluate.hpp, in double, or from the proofs with
// certified) of every pair of two int64 arrays, written by worker threads without the GIL
// straight into a NumPy structured array (row_record.hpp). Ctrl-C stops it between chunks
// (interruptible.hpp).
#include <pybind11/numpy.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <gyrores/core/error.hpp>
#include <gyrores/core/thread_caches.hpp>
#include <gyrores/sweep/sweep.hpp>

#include "common.hpp"
#include "interruptible.hpp"
#include "row_record.hpp"

namespace gyrores::python {
namespace {

// Pairs per chunk a worker takes: a few milliseconds of work in double, so that a stop is seen
// soon and the workers stay balanced.
constexpr std::size_t chunk_pairs = 256;

// One note of a row that has one (most have none), for the table's object field.
struct row_note {
  std::size_t index;
  std::string text;
};

// Writes the row of (taus[i], sigmas[i]) into record i of `table` (n records of layout.itemsize
// bytes) on `threads` workers; returns the notes. usage_error naming the first invalid pair.
std::vector<row_note> fill_rows(const std::int64_t* taus, const std::int64_t* sigmas, std::size_t n, char* table,
                                const row_layout& layout, const sweep_config& cfg, unsigned threads,
                                const stop_token& stop) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex mtx;  // guards error, error_index and notes
  std::exception_ptr error;
  std::size_t error_index = n;
  std::vector<row_note> notes;
  auto work = [&] {
    try {
      for (;;) {
        const std::size_t first = next.fetch_add(chunk_pairs);
        if (first >= n || failed || stop.requested()) break;
        for (std::size_t i = first; i < std::min(n, first + chunk_pairs); ++i) {
          try {
            if (taus[i] > sweep_max_order_limit || sigmas[i] > sweep_max_order_limit ||
                taus[i] + sigmas[i] > sweep_max_order_limit)
              throw usage_error("tau + sigma must be <= 2^40 (use pair() beyond)");
            const auto row = sweep_evaluate<double>(resonant_pair<std::int64_t>(taus[i], sigmas[i]), cfg);
            layout.write(table + std::ptrdiff_t(i) * layout.itemsize, row);
            if (!row.note.empty()) {
              std::lock_guard<std::mutex> lk(mtx);
              notes.push_back({i, row.note});
            }
          } catch (const usage_error& e) {
            std::lock_guard<std::mutex> lk(mtx);
            if (i < error_index) {
              error_index = i;
              error = std::make_exception_ptr(usage_error("pairs(): (taus[" + std::to_string(i) + "], sigmas[" +
                                                          std::to_string(i) + "]) = (" + std::to_string(taus[i]) + ", " +
                                                          std::to_string(sigmas[i]) + "): " + e.what()));
            }
            failed = true;
            break;
          }
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> lk(mtx);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned count = unsigned(std::min<std::size_t>(threads == 0 ? hw : threads, (n + chunk_pairs - 1) / chunk_pairs));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < count; ++t)
    pool.emplace_back([&] {
      work();
      release_thread_caches();
    });
  work();  // this thread is a worker too (run_interruptible releases its caches)
  for (auto& t : pool) t.join();
  stop.throw_if_requested();
  if (error) std::rethrow_exception(error);
  return notes;
}

py::list pairs_into(py::array_t<std::int64_t, py::array::c_style> taus, py::array_t<std::int64_t, py::array::c_style> sigmas,
                const std::string& checks, bool certified, unsigned threads, py::array table) {
  if (taus.ndim() != 1 || sigmas.ndim() != 1 || taus.size() != sigmas.size() || table.ndim() != 1 ||
      table.size() != taus.size() || !(table.flags() & py::array::c_style) || !table.writeable())
    throw usage_error("pairs(): taus, sigmas and the table must be one-dimensional, contiguous and of the same length");
  const row_layout layout = row_layout::of(table);
  sweep_config cfg;
  cfg.checks = sweep_parse_checks(checks);
  cfg.certified = certified;
  const std::int64_t* t = taus.data();
  const std::int64_t* s = sigmas.data();
  char* out = static_cast<char*>(table.mutable_data());
  const auto n = std::size_t(taus.size());
  // The arrays stay alive: this call holds them, and on a stop it waits for the workers, which
  // look at the flag every chunk_pairs pairs (a millisecond or so).
  const auto notes = run_interruptible<std::vector<row_note>>(
      [=](stop_token stop) { return fill_rows(t, s, n, out, layout, cfg, threads, stop); }, on_stop::wait);
  py::list found;
  for (const auto& note : notes) found.append(py::make_tuple(note.index, note.text));
  return found;
}

}  // namespace

void bind_pairs(py::module_& m) {
  m.def("_row_fields", &row_fields, "[(name, format)] of a row's fields (the sweep's columns).");
  m.def("_pairs_into", &pairs_into, py::arg("taus"), py::arg("sigmas"), py::arg("checks"), py::arg("certified"),
        py::arg("threads"), py::arg("table"),
        "Writes the sweep's row of every (taus[i], sigmas[i]) into table[i] but its note; returns the "
        "notes [(i, text)] of the rows that have one. Use gyrores.pairs.");
}

}  // namespace gyrores::python
