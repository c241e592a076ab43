// The lobe functions in MPFI and their roots (reference/lobe_intervals.hpp).
#include "reference/lobe_intervals.hpp"

#include "reference/interval_newton.hpp"

namespace gyrores::proof {

constants constants_of(const resonant_pair<big_int>& p) {
  return {resonant_constants_of<I>(p, I(1)), p.tau(), p.sigma(), p.order(), big_int(p.delta())};
}

I mu_of(const constants& k, const big_int& m) { return k.c.pi * real_from_int<I>(m) / (2 * real_from_int<I>(k.a)); }

I f_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return cos(U) * sin(W) - k.c.x * sin(U) * cos(W);
}

I df_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return -(1 + k.c.x * k.c.x) * sin(U) * sin(W) - 2 * k.c.x * cos(U) * cos(W);
}

I g_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return k.c.x * sin(U) * sin(W) + cos(U) * cos(W);
}

std::optional<I> certify_root(const constants& k, const I& mu, const P& guess, const P& scale) {
  return interval_newton([&](const I& U) { return f_of(k, mu, U); }, [&](const I& U) { return df_of(k, mu, U); },
                         guess, scale, 40);
}

}  // namespace gyrores::proof
