// The sweep's per-pair row (sweep/evaluate.hpp, in double) written straight into a record of a
// NumPy structured array: gyrores.pairs fills a preallocated table from its worker threads, and
// gyrores.sweep from its calling thread as the blocks arrive, with no intermediate copy. The
// fields are the columns of `gyrores sweep --out` (io/sweep_rows.hpp names them).
#pragma once
#include <pybind11/numpy.h>

#include <array>
#include <cstddef>

#include <gyrores/sweep/evaluate.hpp>

namespace gyrores::python {

namespace py = pybind11;

// [(name, NumPy format)] of the row's fields, in the sweep's column order. The note is text of
// one character here (a table with an object field costs more to allocate than the sweep takes);
// row_layout::write leaves it alone and gyrores.pairs and sweep set the few notes there are.
py::list row_fields();

// Where each field lies in a record of a table whose dtype is row_fields() (read with the GIL).
struct row_layout {
  std::ptrdiff_t tau, sigma, order, delta_mod4, r_res, theta_first, t_first, t_min_paper, t_ratio;
  std::ptrdiff_t first_at_paper_node, paper_lobe_min, asy_error, asy_bound, asy_ratio, asy_constant;
  std::ptrdiff_t minimiser_count, strand_offset, failed;
  std::array<std::ptrdiff_t, sweep_check_count> checks;
  std::ptrdiff_t itemsize;

  static row_layout of(const py::array& table);
  // Writes r (not its note) into `record`; safe without the GIL.
  void write(char* record, const sweep_row<double>& r) const;
};

}  // namespace gyrores::python
