// Certificates from the lattice theorem ("gyrores-certificate/2"; proofs/lattice-theorem.md,
// docs/formats.md): the default certificate of `gyrores certify` for every coprime pair.
//
// What it states (v = qdot0 = 1):
//   theorem          the id of the theorem it rests on (lattice-theorem/1);
//   minimiser lobes  the 2 or 4 frames (k, j, m), 0 <= k < a, |m| = m_min, (2j+1) a - 2 k b = m,
//                    in theta order: by the theorem's count these are all of them;
//   u_star           decimal numbers u_lo < u_hi in (0, pi/2) with H(u_lo) < mu_min < H(u_hi),
//                    H(u) = x u + arctan(x tan u): as H increases, u* lies between them;
//   claims           r_res in sqrt(G([u_lo, u_hi])), theta_first = 2 (k pi + sign(m) u*)/a of the
//                    first lobe, t_first = sqrt(tau sigma) theta_first, each with relative width
//                    <= 10^-digits.
// Degenerate pairs (m_min = 0) state the two zero lobes, u* = 0 and r_res = 0 (P3).
// The producer proves every inequality in MPFI before writing it; the independent checker
// (src/checker/, Arb) re-proves them from the file alone.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/stop.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

inline constexpr const char* theorem_certificate_format = "gyrores-certificate/2";

struct theorem_certificate {
  std::string format = theorem_certificate_format;
  std::string theorem;
  big_int tau, sigma;
  unsigned digits = 0, bits = 0;
  int m_min = 0;
  std::vector<lobe_frame<big_int>> lobes;                       // the minimisers' lobes, theta order
  std::pair<std::string, std::string> u_star;                   // {"0", "0"} when degenerate
  std::pair<std::string, std::string> r_res, theta_first, t_first;
};

// Proves and writes the certificate of p with `digits` correct digits in every claim. Throws
// usage_error for digits outside [1, report_digits_max]; compute_error only when max_bits is
// reached before the digits (a resource limit, named in the message); interrupted when `stop`
// is set.
theorem_certificate certify_by_theorem(const resonant_pair<big_int>& p, unsigned digits, unsigned max_bits = 1u << 17,
                                       stop_token stop = {});

}  // namespace gyrores
