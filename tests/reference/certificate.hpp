// The tests' reference of the retired cover certificate ("gyrores-certificate/1", docs/formats.md,
// "Retired"): the data a certificate holds, the options shared by the producer and the checker,
// and the checker's verdict.
//
// Not part of the product: the library and the tool refuse /1 files (io/certificate_json.hpp).
// The tests keep this proof, which does not use the lattice theorem (it proves global minimality
// by an interval cover of the lobes), as an independent oracle: the theorem's certificates must
// agree with it (tests/test_theorem_certificate.cpp), and the proof programs (proofs/) use its
// steps. Built as the static library gyrores_reference (tests/reference/CMakeLists.txt); include
// as "reference/<name>.hpp".
//
// A certificate states interval enclosures of r_res, theta_first and t_first for v = qdot0 = 1
// (r_res scales linearly with v), with the obligations the proof rests on:
//   local-root  interval Newton proves a unique root of q' in X and encloses r_res = |q| there;
//   basin       on Y around X, q' is strictly monotone with a sign change and z' != 0, so the
//               root is the only critical point of R in Y;
//   symmetry    the other minimisers are the exact images theta -> 2 pi - theta (and theta + pi
//               for odd tau, sigma), with equal R;
//   cover       R > r_hi^2 everywhere outside the basins (cover.hpp);
//   rayleigh    the Rayleigh cut-off of the "slow-nodes" cover;
//   degenerate  delta = 2 mod 4: r_res = 0 by integer arithmetic (search/degenerate.hpp).
// The producer is certify.hpp (certify_pair), the independent checker check.hpp
// (check_certificate), the JSON form certificate_json.hpp, the written argument
// proofs/global-minimality.md.
#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores {

inline constexpr const char* certificate_format = "gyrores-certificate/1";

struct certificate_obligation {
  std::string id;         // local-root, basin, symmetry, cover, rayleigh, degenerate
  std::string statement;  // what was proved, in words
  std::map<std::string, std::string> data;  // inputs and results, decimal strings
};

struct certificate {
  std::string format = certificate_format;
  big_int tau, sigma;
  unsigned digits = 0, working_bits = 0, cover_bits = 0;
  bool degenerate = false;
  bool global_minimality = false;  // false: only r_res <= r_res.second is claimed
  std::string global_minimality_note;
  std::pair<std::string, std::string> r_res, theta_first, t_first;  // empty strings when not claimed
  std::size_t minimiser_count = 0;                                   // 0 when not claimed
  std::vector<certificate_obligation> obligations;
};

// Limits of the producer and the checker.
struct certify_options {
  std::int64_t max_lobes = 20000;  // "all-lobes" cover up to this order tau + sigma
  std::int64_t max_nodes = 20000;  // "slow-nodes" cover up to this many nodes b = tau - sigma
  unsigned start_bits = 64;        // first working precision of the producer
  unsigned max_bits = 1u << 17;    // highest working precision (producer and checker)
};

// The checker's verdict: holds, or the first failing claim/obligation by name.
struct check_verdict {
  bool holds = false;
  std::string failure;
};

// Decimal digits of the numbers a certificate records at `bits` of precision: the digits the
// precision carries plus 3 (claims, X); the cover level adds 6 more for Y and 2 for the bound.
inline unsigned certificate_digits_for_bits(unsigned bits) { return bits_to_digits10(bits) + 3u; }

// The texts the producer writes and the checker requires: the global-minimality note of a
// degenerate pair and of a proved cover, and the cover's bound r_hi^2 (rounded up, at the digits
// of cover_bits plus 2).
inline constexpr const char* degenerate_note = "proved (integer arithmetic: delta = 2 mod 4)";
inline std::string proved_note(const std::string& strategy) { return "proved (" + strategy + ")"; }
std::string cover_bound_text(const mpfr_real& bound, unsigned cover_bits);

// The obligation with this id, or nullptr.
const certificate_obligation* find_obligation(const certificate& c, const std::string& id);

}  // namespace gyrores
