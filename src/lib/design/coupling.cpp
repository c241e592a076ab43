// include/gyrores/design/coupling.hpp
#include <gyrores/design/coupling.hpp>

namespace gyrores {

GYRORES_FOR_COMPILED_REALS(GYRORES_HORIZON_MINIMUM_INSTANCES, )

}  // namespace gyrores
