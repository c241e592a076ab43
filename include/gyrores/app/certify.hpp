// The application layer (docs/architecture.md): `gyrores certify` / gyrores.certify, the
// lattice-theorem certificate of one pair (certify/theorem_certificate.hpp) as the text both
// write, and `gyrores check` / gyrores.check, the independent checkers (src/checker/) of both
// certificate formats, chosen by the text's "format".
#pragma once
#include <string>

#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores::app {

struct certify_request {
  resonant_pair<big_int> pair;
  unsigned digits = 30;  // [1, report_digits_max]
  stop_token stop;
};

// The certificate (io/certificate_json.hpp writes it). usage_error for digits out of range or a
// pair larger than `gyrores check` reads; otherwise as certify_by_theorem.
theorem_certificate run_certify(const certify_request& request);

// The verdict on a certificate's text: status 0 holds, 1 a claim or fact fails, 2 malformed or
// of the retired format /1 (refused without reading it); one line saying which.
struct check_verdict {
  int status = 2;
  std::string message;
  bool retired = false;  // refused as the retired format /1 (message: how to re-certify)
};
check_verdict run_check(const std::string& text);

}  // namespace gyrores::app
