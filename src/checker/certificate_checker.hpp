// The independent checker of "gyrores-certificate/2" (lattice-theorem certificates).
//
// It shares no numeric code with the producer: it reads the JSON text itself (nlohmann-json),
// does the integer facts in FLINT's fmpz and every real inequality in Arb ball arithmetic, and
// includes no header of include/gyrores/ (ctest `checker_independent` enforces it). Its trusted
// base is listed in docs/formats.md ("The checker"): this file and certificate_checker.cpp,
// the theorem (proofs/lattice-theorem.md), FLINT/Arb, GMP, nlohmann-json, the C++ library.
#pragma once
#include <cstddef>
#include <string>

namespace gyrores_checker {

struct verdict {
  int status = 2;       // 0: the certificate holds; 1: a claim or fact is false or unproved; 2: malformed
  std::string message;  // one line: what holds, or the first thing that does not
};

// The largest pair a certificate may name: tau of at most this many decimal digits (`gyrores
// certify` refuses larger pairs, so that everything it writes, `gyrores check` reads). The
// checker reads integer fields of up to max_pair_digits + 100 characters (the lobes' k and j are
// below tau + sigma), and the whole file up to 4 MiB (the CLI's cap, io/files.hpp).
inline constexpr std::size_t max_pair_digits = 20000;

// Re-proves the certificate in `json_text` from its pair and its data alone.
verdict check_theorem_certificate(const std::string& json_text);

}  // namespace gyrores_checker
