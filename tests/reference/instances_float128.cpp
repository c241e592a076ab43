// Explicit instantiations for float128 of the global search with its cross-check, the pre-theorem
// lattice method and the floating paper asymptotics (declared extern in their headers), compiled
// once for every test.
#include "reference/asymptotic.hpp"
#include "reference/cross_check.hpp"

namespace gyrores {
GYRORES_DEGENERATE_INSTANCES(, float128)
GYRORES_GLOBAL_SEARCH_INSTANCES(, float128)
GYRORES_CROSS_CHECK_INSTANCES(, float128)
GYRORES_LATTICE_INSTANCES(, ::gyrores::float128)
GYRORES_ASYMPTOTIC_INSTANCES(, ::gyrores::float128)
}  // namespace gyrores
