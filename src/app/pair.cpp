// include/gyrores/app/pair.hpp
#include <gyrores/app/pair.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores::app {

pair_report run_pair(const pair_request& request) {
  check_report_digits(request.digits);
  if (!(request.qdot0 > 0)) throw usage_error("qdot0 must be > 0, got " + rational_str(request.qdot0));
  pair_report_options opt;
  opt.digits = request.digits;
  opt.qdot0 = request.qdot0;
  opt.enclosures = request.enclosures;
  opt.asymptotics = request.asymptotics;
  opt.stop = request.stop;
  return prove_pair(request.pair, opt);
}

}  // namespace gyrores::app
