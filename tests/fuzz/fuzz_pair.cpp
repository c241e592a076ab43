// Fuzz target: the pair arguments TAU SIGMA as the CLI reads them (parse_pair_arguments in
// src/cli/cli_options.cpp: parse_big_int, then resonant_pair of model/pair.hpp). The input is
// "TAU\nSIGMA". An accepted pair is coprime with tau > sigma >= 1; when it fits int64 the
// int64 pair agrees on order, delta and degeneracy.
#include <limits>

#include <gyrores/core/error.hpp>
#include <gyrores/model/pair.hpp>

#include "cli_options.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;
  const auto args = gyrores::fuzz::split(gyrores::fuzz::as_text(data, size), "\n", 2);
  if (args.size() != 2) return -1;
  try {
    const auto p = gyrores::cli::parse_pair_arguments(args[0], args[1]);
    using gyrores::big_int;
    if (!(p.tau() > p.sigma() && p.sigma() >= 1 && gcd(p.tau(), p.sigma()) == 1)) std::abort();
    const big_int lim(std::numeric_limits<std::int64_t>::max());
    if (p.tau() <= lim) {
      const gyrores::resonant_pair<std::int64_t> q(p.tau().convert_to<std::int64_t>(), p.sigma().convert_to<std::int64_t>());
      if (gyrores::to_decimal(q.order()) != gyrores::to_decimal(p.order()) || big_int(q.delta()) != p.delta() ||
          q.degenerate() != p.degenerate())
        std::abort();
    }
  } catch (const gyrores::usage_error&) {
  }
  return 0;
}
