// The paper's lobe for the proof programs (proofs/lobe_roots.hpp).
#include "lobe_roots.hpp"

#include <cmath>

#include "reference/interval_newton.hpp"
#include "reference/asymptotic.hpp"

namespace gyrores::proofs {

paper_lobe paper_lobe_of(const proof::constants& K, const big_int& m) {
  return {proof::mu_of(K, m), K.c.pi * real_from_int<I>(m) / (2 * real_from_int<I>(K.b))};
}

lobe_guesses double_guesses(std::int64_t a, std::int64_t b, std::int64_t m) {
  double x = double(b) / double(a), mu = M_PI * double(m) / (2.0 * double(a)), s = M_PI * double(m) / (2.0 * double(b));
  return {lobe_equation_root<double>(x, mu, s, M_PI), u_plus_tan_u_root<double>(s)};
}

std::optional<I> certify_u_plus_tan(const I& s, const P& guess) {
  P scale = abs(guess) > P("1e-300") ? abs(guess) : P(1);
  return interval_newton([&](const I& u) { return I(u + tan(u) - s); },
                         [](const I& u) { return I(2 + interval_sqr(tan(u))); }, guess, scale, 60);
}

}  // namespace gyrores::proofs
