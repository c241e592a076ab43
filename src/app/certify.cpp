// include/gyrores/app/certify.hpp
#include <gyrores/app/certify.hpp>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/io/certificate_json.hpp>

#include "band_checker.hpp"
#include "certificate_checker.hpp"
#include "horizon_checker.hpp"

namespace gyrores::app {

theorem_certificate run_certify(const certify_request& request) {
  check_report_digits(request.digits);
  // What certify writes, check must read (src/checker/certificate_checker.hpp).
  const std::size_t tau_digits = request.pair.tau().str().size();
  if (tau_digits > gyrores_checker::max_pair_digits)
    throw usage_error("TAU has " + std::to_string(tau_digits) + " digits; certificates are limited to " +
                      std::to_string(gyrores_checker::max_pair_digits) + " (what gyrores check reads)");
  return certify_by_theorem(request.pair, request.digits, 1u << 17, request.stop);
}

check_verdict run_check(const std::string& text) {
  const std::string format = certificate_format_of(text);
  if (format == retired_certificate_format) return {2, retired_certificate_message(), true};
  const auto v = format == gyrores_checker::coupling_certificate_format ? gyrores_checker::check_coupling_certificate(text)
                 : format == gyrores_checker::band_certificate_format ? gyrores_checker::check_band_certificate(text)
                                                                     : gyrores_checker::check_theorem_certificate(text);
  return {v.status, v.message, false};
}

}  // namespace gyrores::app
