// Explicit instantiations of the sweep templates for the compiled reals (declared extern in the
// headers of include/gyrores/sweep/, macro GYRORES_FOR_COMPILED_REALS of core/real.hpp).
#include <gyrores/sweep/sweep.hpp>

namespace gyrores {
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_REAL_TEXT_INSTANCES, )
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_EVALUATE_INSTANCES, )
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_RECORD_INSTANCES, )
GYRORES_FOR_COMPILED_REALS(GYRORES_SWEEP_ENGINE_INSTANCES, )
}  // namespace gyrores
