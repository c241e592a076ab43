// Explicit instantiations of the global search for long double (declared extern in the headers of
// include/gyrores/search/). One file per real type so that a parallel build spreads them.
#include <gyrores/search/cross_check.hpp>

namespace gyrores {
GYRORES_DEGENERATE_INSTANCES(, long double)
GYRORES_GLOBAL_SEARCH_INSTANCES(, long double)
GYRORES_CROSS_CHECK_INSTANCES(, long double)
}  // namespace gyrores
