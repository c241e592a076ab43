// A consumer of an installed gyrores: one header-only entry point (model/resonant.hpp, a
// template instantiated here) and compiled entry points (theorem_minimum_double and prove_pair,
// in the static library), so that the installed headers and the library
// must both be found and linked through gyrores::gyrores.
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/report/pair_report.hpp>

int main() {
  // Header-only: the degenerate pair (11, 9) and its amplitude rho0 = v sqrt(tau sigma)/a.
  const gyrores::resonant_pair<std::int64_t> p(11, 9);
  const auto c = gyrores::resonant_constants_of<double>(p, 1.0);
  const double rho0 = std::sqrt(99.0) / 20.0;
  if (!p.degenerate() || std::fabs(c.rho0 - rho0) > 1e-15 * rho0) {
    std::fprintf(stderr, "consumer: resonant_constants_of(11, 9) gave rho0 = %.17g\n", c.rho0);
    return 1;
  }
  // Compiled: r_res of (6, 5) (the certificate in docs/formats.md: 5.0745805791033372e-02).
  const auto r = gyrores::theorem_minimum_double(gyrores::resonant_pair<std::int64_t>(6, 5));
  const double r_res = 5.074580579103337e-02;
  if (std::fabs(r.r_res - r_res) > 1e-12 * r_res) {
    std::fprintf(stderr, "consumer: theorem_minimum_double(6, 5) gave r_res = %.17g\n", r.r_res);
    return 1;
  }
  const auto proved = gyrores::prove_pair(gyrores::resonant_pair<gyrores::big_int>(6, 5));
  if (proved.r_res.value != "5.0745805791033372e-02") {
    std::fprintf(stderr, "consumer: prove_pair(6, 5) gave r_res = %s\n", proved.r_res.value.c_str());
    return 1;
  }
  return 0;
}
