// Explicit instantiations for mpfr_real of the global search with its cross-check, the
// pre-theorem lattice method and the floating paper asymptotics (declared extern in their
// headers), compiled once for every test.
#include "reference/asymptotic.hpp"
#include "reference/cross_check.hpp"

namespace gyrores {
GYRORES_DEGENERATE_INSTANCES(, ::gyrores::mpfr_real)
GYRORES_GLOBAL_SEARCH_INSTANCES(, ::gyrores::mpfr_real)
GYRORES_CROSS_CHECK_INSTANCES(, ::gyrores::mpfr_real)
GYRORES_LATTICE_INSTANCES(, ::gyrores::mpfr_real)
GYRORES_ASYMPTOTIC_INSTANCES(, ::gyrores::mpfr_real)
}  // namespace gyrores
