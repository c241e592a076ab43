// gyrores.pairs: the sweep's row (sweep/evaluate.hpp, in double, or from the proofs with
// certified) of every pair of two int64 arrays, on worker threads without the GIL, as the
// columns of row_columns.hpp. Ctrl-C stops it between chunks (interruptible.hpp).
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
#include "row_columns.hpp"

namespace gyrores::python {
namespace {

// Pairs per chunk a worker takes: a few milliseconds of work in double, so that a stop is seen
// soon and the workers stay balanced.
constexpr std::size_t chunk_pairs = 256;

// Every row of (taus[i], sigmas[i]), in input order; usage_error naming the first invalid pair.
std::vector<sweep_row<double>> evaluate_rows(const std::vector<std::int64_t>& taus, const std::vector<std::int64_t>& sigmas,
                                             const sweep_config& cfg, unsigned threads, const stop_token& stop) {
  const std::size_t n = taus.size();
  std::vector<sweep_row<double>> rows(n);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex error_mtx;
  std::exception_ptr error;
  std::size_t error_index = n;
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
            rows[i] = sweep_evaluate<double>(resonant_pair<std::int64_t>(taus[i], sigmas[i]), cfg);
          } catch (const usage_error& e) {
            std::lock_guard<std::mutex> lk(error_mtx);
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
      std::lock_guard<std::mutex> lk(error_mtx);
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
  return rows;
}

py::dict pairs_columns(py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> taus,
                       py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> sigmas,
                       const std::string& checks, bool certified, unsigned threads) {
  if (taus.ndim() != 1 || sigmas.ndim() != 1 || taus.size() != sigmas.size())
    throw usage_error("pairs(): taus and sigmas must be one-dimensional and of the same length");
  // Copies: on Ctrl-C the work may outlive this call (interruptible.hpp).
  std::vector<std::int64_t> t(taus.data(), taus.data() + taus.size()), s(sigmas.data(), sigmas.data() + sigmas.size());
  sweep_config cfg;
  cfg.checks = sweep_parse_checks(checks);
  cfg.certified = certified;
  auto cols = run_interruptible<std::shared_ptr<row_columns>>(
      [t = std::move(t), s = std::move(s), cfg, threads](stop_token stop) {
        const auto rows = evaluate_rows(t, s, cfg, threads, stop);
        auto c = std::make_shared<row_columns>();
        for (const auto& r : rows) c->add(r);
        return c;
      });
  return columns_dict(*cols);
}

}  // namespace

void bind_pairs(py::module_& m) {
  m.def("_pairs", &pairs_columns, py::arg("taus"), py::arg("sigmas"), py::arg("checks"), py::arg("certified"),
        py::arg("threads"), "The sweep's row columns of every (taus[i], sigmas[i]). Use gyrores.pairs.");
}

}  // namespace gyrores::python
