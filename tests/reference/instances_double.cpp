// Explicit instantiations of the pre-theorem lattice method and the floating paper asymptotics
// for double (declared extern in lattice.hpp and asymptotic.hpp), compiled once for every test.
#include "reference/asymptotic.hpp"

namespace gyrores {
GYRORES_LATTICE_INSTANCES(, double)
GYRORES_ASYMPTOTIC_INSTANCES(, double)
}  // namespace gyrores
