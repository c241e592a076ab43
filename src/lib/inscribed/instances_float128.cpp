// Explicit instantiations of the inscribed-radius templates for ::gyrores::float128 (declared extern in the
// headers). One file per real type so that a parallel build spreads them over the cores.
#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/inscribed/cross_check.hpp>

namespace gyrores {
GYRORES_DEGENERATE_INSTANCES(, ::gyrores::float128)
GYRORES_GLOBAL_SEARCH_INSTANCES(, ::gyrores::float128)
GYRORES_LATTICE_INSTANCES(, ::gyrores::float128)
GYRORES_CROSS_CHECK_INSTANCES(, ::gyrores::float128)
GYRORES_ASYMPTOTIC_INSTANCES(, ::gyrores::float128)
}  // namespace gyrores
