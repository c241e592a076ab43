// Explicit instantiations of the pre-theorem lattice method and the floating paper asymptotics
// for ::gyrores::float128 (declared extern in lattice.hpp and asymptotic.hpp), compiled once for every test.
#include "reference/asymptotic.hpp"

namespace gyrores {
GYRORES_LATTICE_INSTANCES(, ::gyrores::float128)
GYRORES_ASYMPTOTIC_INSTANCES(, ::gyrores::float128)
}  // namespace gyrores
