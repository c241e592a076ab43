// The proof steps of reference/proof_steps.hpp (proofs/global-minimality.md).
#include "reference/proof_steps.hpp"

#include <atomic>

#include <gyrores/core/error.hpp>
#include "reference/interval_newton.hpp"

#include "reference/lattice.hpp"
#include "reference/mutation.hpp"

namespace gyrores::proof {

namespace {
std::atomic<mutation> current_mutation{mutation::none};
bool mutated(mutation m) { return current_mutation.load(std::memory_order_relaxed) == m; }
}  // namespace

mutation active_mutation() { return current_mutation.load(); }
scoped_mutation::scoped_mutation(mutation m) : previous_(current_mutation.exchange(m)) {}
scoped_mutation::~scoped_mutation() { current_mutation.store(previous_); }

constants constants_of(const resonant_pair<big_int>& p) {
  return {resonant_constants_of<I>(p, I(1)), p.tau(), p.sigma(), p.order(), big_int(p.delta())};
}

I mu_of(const constants& k, const big_int& m) { return k.c.pi * real_from_int<I>(m) / (2 * real_from_int<I>(k.a)); }

I f_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  I f = cos(U) * sin(W) - k.c.x * sin(U) * cos(W);
  return mutated(mutation::f_sign_flip) ? I(-f) : f;
}

I df_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return -(1 + k.c.x * k.c.x) * sin(U) * sin(W) - 2 * k.c.x * cos(U) * cos(W);
}

I g_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return k.c.x * sin(U) * sin(W) + cos(U) * cos(W);
}

I radius_sq_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  I su = sin(U), sw = sin(W);
  I q = k.c.s1mx2 * su * sw;
  I f = cos(U) * sw - k.c.x * su * cos(W);
  return interval_sqr(q) + interval_sqr(f);
}

I abs_q_of(const constants& k, const I& mu, const I& U) {
  I W = mu - k.c.x * U;
  return interval_abs(k.c.s1mx2 * sin(U) * sin(W));
}

I rayleigh_lower(const constants& k, const I& c2_lower) {
  I omx2 = 1 - k.c.x * k.c.x;
  return omx2 * c2_lower * c2_lower / (2 * omx2 * c2_lower + k.c.x * k.c.x);
}

bool meets_digits(const I& x, unsigned digits) {
  P w = interval_rel_width(x);
  P lim = pow(P(10), -int(digits));
  return w <= lim;
}

std::optional<I> certify_root(const constants& k, const I& mu, const P& guess, const P& scale) {
  if (mutated(mutation::root_always)) return interval_of(P(guess - scale), P(guess + scale));
  if (mutated(mutation::root_never)) return std::nullopt;
  return interval_newton([&](const I& U) { return f_of(k, mu, U); }, [&](const I& U) { return df_of(k, mu, U); },
                         guess, scale, 40);
}

bool certify_basin(const constants& k, const I& mu, const I& Y) {
  if (mutated(mutation::basin_always)) return true;
  if (mutated(mutation::basin_never)) return false;
  I lo = interval_point(interval_lower(Y)), hi = interval_point(interval_upper(Y));
  I flo = f_of(k, mu, lo), fhi = f_of(k, mu, hi);
  bool sign_change = (certainly_positive(flo) && certainly_negative(fhi)) ||
                     (certainly_negative(flo) && certainly_positive(fhi));
  return sign_change && certainly_nonzero(df_of(k, mu, Y)) && certainly_nonzero(g_of(k, mu, Y));
}

lobe lobe_at(const constants& k, const big_int& kk) {
  big_int j = int_floor_div(big_int(k.b * kk), k.a);
  return {kk, j};
}

namespace {

bool inside_a_basin(const I& U, const std::vector<I>& basins) {
  for (const auto& Y : basins)
    if (certainly_subset(U, Y)) return true;
  return false;
}

// R/v^2 > bound on U, by the Rayleigh bound (counted in st) or by the enclosure of R.
bool above_bound(const constants& k, const I& mu, const I& U, const I& bound, cover_stats& st) {
  I W = mu - k.c.x * U;
  I sw2 = interval_sqr(sin(W));
  if (certainly_less(bound, rayleigh_lower(k, interval_point(interval_lower(sw2))))) {
    ++st.rayleigh_hits;
    return true;
  }
  return certainly_less(bound, radius_sq_of(k, mu, U));
}

// Where to cut [lo, hi]: at a basin end inside it when there is one (so basins are cut out
// exactly), else at the midpoint.
P split_point(const P& lo, const P& hi, const std::vector<I>& basins) {
  for (const auto& Y : basins) {
    P yl = interval_lower(Y), yh = interval_upper(Y);
    if (lo < yl && yl < hi) return yl;
    if (lo < yh && yh < hi) return yh;
  }
  return (lo + hi) / 2;
}

}  // namespace

bool exclude_lobe(const constants& k, const lobe& L, const std::vector<I>& basins, const I& bound, cover_stats& st) {
  if (mutated(mutation::exclude_always)) return true;
  if (mutated(mutation::exclude_never)) return false;
  big_int m = (2 * L.j + 1) * k.a - 2 * L.k * k.b;
  I mu = mu_of(k, m);
  I half_pi = k.c.pi / 2;
  std::vector<I> stack{interval_of(-interval_upper(half_pi), interval_upper(half_pi))};
  P min_width = ldexp(P(1), -int(real_bits<P>() / 2));
  ++st.lobes;
  while (!stack.empty()) {
    I U = stack.back();
    stack.pop_back();
    ++st.boxes;
    if (inside_a_basin(U, basins) || above_bound(k, mu, U, bound, st)) continue;
    P lo = interval_lower(U), hi = interval_upper(U);
    if (hi - lo < min_width) return false;
    P mid = split_point(lo, hi, basins);
    stack.push_back(interval_of(lo, mid));
    stack.push_back(interval_of(mid, hi));
  }
  return true;
}

I theta_of(const constants& k, const big_int& kk, const I& U) {
  big_int kr = int_mod(big_int(mutated(mutation::theta_off_by_one) ? kk + 1 : kk), k.a);
  return 2 * (k.c.pi * real_from_int<I>(kr) + U) / real_from_int<I>(k.a);
}

std::vector<image> images_of(const constants& k, const big_int& kk, const big_int& jj, bool with_shift) {
  std::vector<image> out{{kk, jj, false}, {k.a - kk, k.b - 1 - jj, true}};
  if (mutated(mutation::images_no_mirror)) out.pop_back();
  if (with_shift) {
    big_int ks = kk + k.a / 2, js = jj + k.b / 2;
    out.push_back({ks, js, false});
    out.push_back({k.a - ks, k.b - 1 - js, true});
  }
  return out;
}

namespace {

// The q' root of the minimiser's frame: the lattice method's u as the guess, proved by
// interval Newton (scale |u|, at least |mu|/1024 so that a root near 0 is found absolutely).
I certified_root(const resonant_pair<big_int>& p, const constants& K, const I& mu, const P& guess) {
  P scale = abs(guess);
  P floor = abs(interval_lower(mu)) / 1024;
  if (scale < floor) scale = floor;
  auto X = certify_root(K, mu, guess, scale);
  if (!X)
    throw compute_error("certify: interval Newton could not prove the root of q' near u = " +
                        format_scientific(guess, 20) + " for " + p.str());
  return *X;
}

// Index of the smallest theta; throws when two thetas are not separated.
std::size_t first_theta(const resonant_pair<big_int>& p, const std::vector<I>& thetas) {
  for (std::size_t i = 0; i < thetas.size(); ++i)
    for (std::size_t j = 0; j < thetas.size(); ++j)
      if (i != j && !certainly_less(thetas[i], thetas[j]) && !certainly_less(thetas[j], thetas[i]))
        throw compute_error("certify: minimiser images of " + p.str() + " are not separated at " +
                            std::to_string(real_bits<P>()) + " bits");
  std::size_t first = 0;
  for (std::size_t i = 1; i < thetas.size(); ++i)
    if (certainly_less(thetas[i], thetas[first])) first = i;
  return first;
}

}  // namespace

minimiser_enclosures enclose_minimisers(const resonant_pair<big_int>& p, const constants& K) {
  auto lat = inscribed_lattice<mpfr_real>(p, mpfr_real(1));
  minimiser_enclosures out;
  out.frame = {lat.first.k, lat.first.j, lat.first.m};
  I mu = mu_of(K, out.frame.m);
  out.X = certified_root(p, K, mu, lat.first.u);
  out.r = abs_q_of(K, mu, out.X);
  out.images = images_of(K, out.frame.k, out.frame.j, p.strand_offset_min() == 2);
  for (auto& im : out.images) out.thetas.push_back(theta_of(K, im.k, im.negate_u ? I(-out.X) : out.X));
  out.theta_first = out.thetas[first_theta(p, out.thetas)];
  out.t_first = K.c.sqrt_ts * out.theta_first;
  return out;
}

}  // namespace gyrores::proof
