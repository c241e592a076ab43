// Explicit instantiations of the global search for ::gyrores::float128 (declared extern in the headers of
// include/gyrores/search/). One file per real type so that a parallel build spreads them.
#include <gyrores/search/cross_check.hpp>

namespace gyrores {
GYRORES_DEGENERATE_INSTANCES(, ::gyrores::float128)
GYRORES_GLOBAL_SEARCH_INSTANCES(, ::gyrores::float128)
GYRORES_CROSS_CHECK_INSTANCES(, ::gyrores::float128)
}  // namespace gyrores
