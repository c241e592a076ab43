// Explicit instantiations of the inscribed-radius templates for double (declared extern in the
// headers). One file per real type so that a parallel build spreads them over the cores.
#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/inscribed/cross_check.hpp>

namespace gyrores {
GYRORES_DEGENERATE_INSTANCES(, double)
GYRORES_GLOBAL_SEARCH_INSTANCES(, double)
GYRORES_LATTICE_INSTANCES(, double)
GYRORES_CROSS_CHECK_INSTANCES(, double)
GYRORES_ASYMPTOTIC_INSTANCES(, double)
}  // namespace gyrores
