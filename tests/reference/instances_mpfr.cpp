// Explicit instantiations of the pre-theorem lattice method and the floating paper asymptotics
// for ::gyrores::mpfr_real (declared extern in lattice.hpp and asymptotic.hpp), compiled once for every test.
#include "reference/asymptotic.hpp"

namespace gyrores {
GYRORES_LATTICE_INSTANCES(, ::gyrores::mpfr_real)
GYRORES_ASYMPTOTIC_INSTANCES(, ::gyrores::mpfr_real)
}  // namespace gyrores
