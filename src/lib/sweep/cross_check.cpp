// sweep_cross_check (include/gyrores/sweep/evaluate.hpp): the opt-in check of a row against the
// global search, which assumes nothing about the minimisers. The comparison is the library's one
// (search/cross_check.hpp: the same r_res and minimisers to 1e-9 relative, and a clear gap
// to the next critical value); this is the only sweep file that includes the global search.
#include <gyrores/core/error.hpp>
#include <gyrores/search/cross_check.hpp>
#include <gyrores/sweep/evaluate.hpp>

namespace gyrores {

void sweep_cross_check(sweep_row_info& r, const resonant_pair<std::int64_t>& p, double r_res,
                       std::span<const double> minimisers) {
  inscribed_result<double> theorem{};
  theorem.r_res = r_res;
  theorem.minimisers.assign(minimisers.begin(), minimisers.end());
  theorem.degenerate = false;
  try {
    cross_check_global(p, 1.0, theorem);
    r.status[int(sweep_check::cross_check)] = sweep_status::pass;
  } catch (const compute_error& e) {
    r.status[int(sweep_check::cross_check)] = sweep_status::fail;
    r.note += std::string(r.note.empty() ? "" : "; ") + e.what();
  }
}

}  // namespace gyrores
