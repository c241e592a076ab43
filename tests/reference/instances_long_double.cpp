// Explicit instantiations for long double of the global search with its cross-check, the pre-theorem
// lattice method and the floating paper asymptotics (declared extern in their headers), compiled
// once for every test.
#include "reference/asymptotic.hpp"
#include "reference/cross_check.hpp"

namespace gyrores {
GYRORES_DEGENERATE_INSTANCES(, long double)
GYRORES_GLOBAL_SEARCH_INSTANCES(, long double)
GYRORES_CROSS_CHECK_INSTANCES(, long double)
GYRORES_LATTICE_INSTANCES(, long double)
GYRORES_ASYMPTOTIC_INSTANCES(, long double)
}  // namespace gyrores
