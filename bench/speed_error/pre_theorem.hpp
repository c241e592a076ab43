// The library's methods from before the lattice theorem, kept as comparison methods of the
// benchmark ("reference (pre-theorem)"): the lattice scout and Newton polish (inscribed_lattice,
// lobe_root_polish, toms748_full) and the paper's asymptotics in floating point (theta_asy_only,
// u_plus_tan_u_root), now the tests' references (tests/reference/, gyrores_reference); and the
// global search over all 4 tau critical points (inscribed_global, include/gyrores/search/, the
// opt-in cross-validation). The one place the benchmark includes them.
#pragma once
#include <gyrores/search/global_search.hpp>

#include "reference/asymptotic.hpp"
#include "reference/lattice.hpp"
