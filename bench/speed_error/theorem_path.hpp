// The theorem's path as the benchmarks time it (include/gyrores/theorem/): the proved minimum at
// the precision a number of digits needs, its enclosures' midpoints as text, and the first
// minimiser in double (the start of the root refiners that skip a scout: the Arb peer, the
// reference Newton polish, the point of one_eval). Used by gyrores-bench and bench_engine.
#pragma once
#include <mpfi.h>
#include <mpfr.h>

#include <numbers>
#include <string>
#include <utility>

#include <gyrores/core/error.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/real.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/theorem/minimum.hpp>
#include <gyrores/theorem/root.hpp>
#include "testing/test_support.hpp"

namespace gyrores::bench {

// The precision the proved minimum starts at for `digits` digits: 32 guard bits, as
// theorem/pair_report.cpp starts without the paper's asymptotics.
inline unsigned proved_start_bits(unsigned digits) { return digits10_to_bits(digits) + 32; }

// The proved minimum of p (v = 1) with `digits` digits: set_theorem_constants and prove_minimum
// (theorem/minimum.hpp) at proved_start_bits(digits), the precision doubled until u* is proved and
// the enclosures of r_res and theta_first have relative width <= 2^-(bits of the digits + 4).
// Calls use(M) on that enclosure and returns its precision; compute_error beyond 2^20 bits.
template <class Use> unsigned with_proved_minimum(const resonant_pair<big_int>& p, unsigned digits, Use&& use) {
  const int need = int(digits10_to_bits(digits)) + 4;
  const bool degenerate = p.strand_offset_min() == 0;  // r_res = 0 exactly
  for (unsigned bits = proved_start_bits(digits); bits <= (1u << 20); bits *= 2) {
    theorem_constants K(bits);
    set_theorem_constants(K, p);
    fixed_mpfi v(bits);
    mpfi_set_ui(v, 1);
    minimum_enclosure M(bits);
    if (!prove_minimum(M, K, p, v)) continue;
    if (!(degenerate || fixed_narrow(M.r_res, need)) || !fixed_narrow(*M.minimisers.front(), need)) continue;
    use(M);
    return bits;
  }
  throw compute_error("with_proved_minimum: not proved within 2^20 bits");
}

// The midpoint of an enclosure as decimal text, at its precision plus 3 digits.
inline std::string enclosure_mid_text(const fixed_mpfi& A) {
  const mpfr_prec_t prec = mpfi_get_prec(A);
  fixed_mpfr m(prec);
  mpfi_mid(m, A);
  char* s = nullptr;
  mpfr_asprintf(&s, "%.*Re", int(bits_to_digits10(unsigned(prec)) + 3), static_cast<mpfr_srcptr>(m));
  std::string out(s);
  mpfr_free_str(s);
  return out;
}

// The ends of an enclosure as decimal text, rounded outward, at its precision plus 3 digits.
inline std::pair<std::string, std::string> enclosure_ends_text(const fixed_mpfi& A) {
  const int d = int(bits_to_digits10(unsigned(mpfi_get_prec(A))) + 3);
  char *lo = nullptr, *hi = nullptr;
  mpfr_asprintf(&lo, "%.*RDe", d, A.left());
  mpfr_asprintf(&hi, "%.*RUe", d, A.right());
  std::pair<std::string, std::string> out(lo, hi);
  mpfr_free_str(lo);
  mpfr_free_str(hi);
  return out;
}

// The theorem's first minimiser in double: its lobe (theorem/lobes.hpp minimiser_lobes, the
// first in theta order) and the local coordinate u = sign(m) u*, u* = theorem_root_double(x,
// pi m_min/(2a)) (0 for degenerate pairs). Pairs of any size: the integers are exact, x and mu
// are rounded to double.
struct first_minimiser {
  lobe_frame<big_int> frame;
  double u;
};
inline first_minimiser theorem_first_minimiser(const resonant_pair<big_int>& p) {
  const big_int a = p.order(), b = big_int(p.delta());
  const lobe_frame<big_int> f = minimiser_lobes(a, b).front();
  const int m_min = theorem_m_min(a);
  if (m_min == 0) return {f, 0.0};
  const double x = real_from_ratio<double>(b, a);
  const double u = theorem_root_double(x, std::numbers::pi * m_min / (2 * a.convert_to<double>()));
  return {f, f.m < 0 ? -u : u};
}

}  // namespace gyrores::bench
