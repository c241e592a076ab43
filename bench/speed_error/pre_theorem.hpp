// The library's methods from before the lattice theorem, kept as comparison methods of the
// benchmark ("reference (pre-theorem)"): the lattice scout and Newton polish (inscribed_lattice,
// lobe_root_polish, toms748_full), the paper's asymptotics in floating point (theta_asy_only,
// u_plus_tan_u_root) and the global search over all 4 tau critical points (inscribed_global),
// now the tests' references (tests/reference/, gyrores_reference). The one place the benchmark
// includes them.
#pragma once
#include "reference/asymptotic.hpp"
#include "reference/global_search.hpp"
#include "reference/lattice.hpp"
