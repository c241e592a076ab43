// The per-pair rows of a sweep (sweep/evaluate.hpp, in double) as NumPy columns, one per column
// of `gyrores sweep --out` (io/sweep_rows.hpp names), which gyrores/__init__.py assembles into a
// structured array: gyrores.sweep and gyrores.pairs share them.
#pragma once
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gyrores/sweep/evaluate.hpp>

namespace gyrores::python {

namespace py = pybind11;

// Not applicable is NaN for reals, -1 for flags. Filled without the GIL.
struct row_columns {
  std::vector<std::int64_t> tau, sigma, order;
  std::vector<std::int8_t> delta_mod4, first_at_paper_node, paper_lobe_min, failed;
  std::vector<double> r_res, theta_first, t_first, t_min_paper, t_ratio, asy_error, asy_bound, asy_ratio, asy_constant;
  std::vector<std::int32_t> minimiser_count, strand_offset;
  std::array<std::vector<std::int8_t>, sweep_check_count> checks;
  std::vector<std::string> notes;
  void add(const sweep_row<double>& r);
};

// The columns by name (needs the GIL).
py::dict columns_dict(const row_columns& c);

}  // namespace gyrores::python
