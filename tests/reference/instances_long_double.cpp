// Explicit instantiations of the pre-theorem lattice method and the floating paper asymptotics
// for long double (declared extern in lattice.hpp and asymptotic.hpp), compiled once for every test.
#include "reference/asymptotic.hpp"

namespace gyrores {
GYRORES_LATTICE_INSTANCES(, long double)
GYRORES_ASYMPTOTIC_INSTANCES(, long double)
}  // namespace gyrores
