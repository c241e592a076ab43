// include/gyrores/app/pair.hpp
#include <gyrores/app/pair.hpp>

namespace gyrores::app {

pair_report run_pair(const pair_request& request) { return prove_pair(request.pair, request.options); }

}  // namespace gyrores::app
