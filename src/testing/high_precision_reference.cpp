// src/testing/high_precision_reference.hpp: the implementation.
//
// Precision bookkeeping: Boost 1.74's mpfr_real keeps the precision a variable was created with
// when an expression is evaluated into it, and a copy takes the source's precision. Where a
// variable is declared (inside or outside a scoped_digits) is therefore part of the numerics;
// the steps below take such variables by reference from the function that declares them, so
// that splitting the work into steps did not move a bit of the result.
#include "testing/high_precision_reference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "testing/naive_forms.hpp"

namespace gyrores::test::hp {

namespace {

unsigned bit_length(const big_int& v) {
  return v == 0 ? 1u : unsigned(boost::multiprecision::msb(boost::multiprecision::abs(v))) + 1u;
}

// Bits of accuracy wanted for `digits` decimal digits (8 guard bits).
unsigned want_bits_for(unsigned digits) { return unsigned(std::ceil(digits * 3.3219280948873623)) + 8; }

// floor(x) as an integer (x finite).
big_int floor_to_int(const mpfr_real& x) {
  big_int z;
  mpfr_get_z(z.backend().data(), x.backend().data(), MPFR_RNDD);
  return z;
}

mpfr_real pi_now() { return boost::math::constants::pi<mpfr_real>(); }

// The naive forms at the current default precision (rebuilt per precision level), and pi.
struct model : naive_forms<mpfr_real> {
  mpfr_real pi;
  model(const big_int& t, const big_int& s) : naive_forms<mpfr_real>(mpfr_real(t), mpfr_real(s)), pi(pi_now()) {}

  // kind 0: f = q'/rho0, kind 1: f = z'/rho0; and df/dtheta. Also q/rho0 and q'/rho0.
  struct values {
    mpfr_real f, df, q, qdot;
  };
  values eval(int kind, const mpfr_real& th) const {
    const auto [s1, c1, s2, c2] = phases(th);
    values out;
    out.q = s1 + s2;
    out.qdot = w1 * c1 + w2 * c2;
    if (kind == 0) {
      out.f = out.qdot;
      out.df = -(w1 * tau * s1 + w2 * sigma * s2);
    } else {
      out.f = w1 * s1 - w2 * s2;
      out.df = w1 * tau * c1 - w2 * sigma * c2;
    }
    return out;
  }
};

// One critical point: a root of q' (kind 0) or z' (kind 1) in bracket i (see bracket_nums).
struct critical_point {
  const big_int& tau;
  const big_int& sigma;
  int kind;
  const big_int& i;
  unsigned a_bits;  // bit length of tau + sigma

  std::string describe() const {
    std::ostringstream os;
    os << "(" << tau << ", " << sigma << ") kind " << kind << " bracket " << i;
    return os.str();
  }
};

// Bracket of critical point (kind, i) as theta = pi * num / (2 tau): q' root in
// [2i, 2i+2], z' root in [2i-1, 2i+1]; f has the sign (-1)^i at the left end for q' and
// (-1)^(i-1) for z' (z' = (-1)^i W1 + ... at (i + 1/2) pi/tau).
std::pair<big_int, big_int> bracket_nums(int kind, const big_int& i) {
  big_int lo = kind == 0 ? big_int(2 * i) : big_int(2 * i - 1);
  return {lo, big_int(lo + 2)};
}

struct refined {
  mpfr_real theta, radius_sq;
};

// Base level: phases accurate to 2^-(a_bits + 96), enough for the signs in a bracket of width
// pi/tau where |f'| may be as small as O(1) (delta = 1: f ~ 2 cos(a theta/2) cos(theta/2)).
// Sets the bracket [lo, hi] and th: `start` if it lies inside, else bisection to 2^-40 of the
// bracket.
void locate_at_base(const critical_point& cp, unsigned base, double start, mpfr_real& th, mpfr_real& lo,
                    mpfr_real& hi) {
  using std::ldexp;
  const auto [nlo, nhi] = bracket_nums(cp.kind, cp.i);
  gyrores::scoped_digits d(gyrores::digits10_for_bits(base));
  model m(cp.tau, cp.sigma);
  const mpfr_real den = 2 * m.tau;
  lo = m.pi * mpfr_real(nlo) / den;
  hi = m.pi * mpfr_real(nhi) / den;
  mpfr_real flo = m.eval(cp.kind, lo).f, fhi = m.eval(cp.kind, hi).f;
  if (flo == 0) {
    th = lo;
  } else if (fhi == 0) {
    th = hi;
  } else if ((flo < 0) == (fhi < 0)) {
    throw std::logic_error("hp reference: no sign change for " + cp.describe());
  } else if (!std::isnan(start)) {
    th = mpfr_real(start);
    if (th <= lo || th >= hi) th = (lo + hi) / 2;
  } else {
    const bool lo_neg = flo < 0;
    const mpfr_real width = ldexp(hi - lo, -40);
    while (hi - lo > width) {
      mpfr_real mid = (lo + hi) / 2;
      if ((m.eval(cp.kind, mid).f < 0) == lo_neg) lo = mid; else hi = mid;
    }
    th = (lo + hi) / 2;
  }
}

// Newton with precision doubling: `acc` = bits of theta known beyond 2^-a_bits; a level of
// 2 a_bits + 2 acc + 32 bits resolves the next doubling even where |f'| = O(1). The bracket
// [lo, hi] is a safeguard (a step leaving it bisects instead).
void newton_ladder(const critical_point& cp, unsigned base, unsigned full_bits, unsigned acc, mpfr_real& th,
                   const mpfr_real& lo, const mpfr_real& hi) {
  unsigned level = base;
  while (level < full_bits) {
    level = std::min(full_bits, std::max(level, 2 * cp.a_bits + 2 * acc + 32));
    gyrores::scoped_digits d(gyrores::digits10_for_bits(level));
    model m(cp.tau, cp.sigma);
    auto v = m.eval(cp.kind, th);
    mpfr_real next = th - v.f / v.df;
    if (next <= lo || next >= hi) next = (lo + hi) / 2;
    th = next;
    acc *= 2;
  }
}

// Full precision: steps until |step| <= 2^-(want_bits + a_bits + 8) (theta >= ~2^-a_bits, so
// this is a relative 2^-want_bits), at most 4; then R at the root (v = 1).
refined polish_full(const critical_point& cp, unsigned want_bits, unsigned full_bits, mpfr_real& th) {
  using std::fabs;
  using std::ldexp;
  gyrores::scoped_digits d(gyrores::digits10_for_bits(full_bits));
  model m(cp.tau, cp.sigma);
  const mpfr_real tol = ldexp(mpfr_real(1), -int(want_bits + cp.a_bits + 8));
  for (int it = 0;; ++it) {
    auto v = m.eval(cp.kind, th);
    mpfr_real step = v.f / v.df;
    th = th - step;
    if (fabs(step) <= tol) break;
    if (it == 4) throw std::logic_error("hp reference: Newton did not converge for " + cp.describe());
  }
  auto fin = m.eval(cp.kind, th);
  refined r;
  r.theta = th;
  mpfr_real q = m.rho0 * fin.q;
  if (cp.kind == 0) {
    r.radius_sq = q * q;  // q stationary at a q' root
  } else {
    mpfr_real qd = m.rho0 * fin.qdot;
    r.radius_sq = q * q + qd * qd;  // R stationary at a z' root
  }
  return r;
}

// Solve f_kind = 0 in bracket i to full precision P; R at the root (v = 1).
// want_bits = accuracy wanted in theta (absolute, theta = O(1)). `start`: a root estimate
// accurate to ~2^-20 of the bracket (e.g. from the double scan), or NaN: bisection to 2^-40 of
// the bracket first.
refined refine(const critical_point& cp, unsigned want_bits, unsigned full_bits, double start = std::nan("")) {
  const unsigned base = std::min(full_bits, 2 * cp.a_bits + 96);
  mpfr_real th, lo, hi;
  locate_at_base(cp, base, start, th, lo, hi);
  newton_ladder(cp, base, full_bits, std::isnan(start) ? 40 : 20, th, lo, hi);
  return polish_full(cp, want_bits, full_bits, th);
}

// A critical point to examine: (kind, i) and a double root estimate (NaN: none).
struct candidate {
  int kind;
  big_int i;
  double start;
};

// The naive forms in double, for the scan.
struct scan_forms {
  double t, s, w1, w2, rho0;
  scan_forms(std::int64_t tau, std::int64_t sigma)
      : t(double(tau)), s(double(sigma)), w1(std::sqrt(t / s)), w2(std::sqrt(s / t)), rho0(1 / (w1 + w2)) {}
  // q'/rho0 (kind 0) or z'/rho0 (kind 1).
  double f(int kind, double th) const {
    return kind == 0 ? w1 * std::cos(t * th) + w2 * std::cos(s * th) : w1 * std::sin(t * th) - w2 * std::sin(s * th);
  }
  // R at a root of f_kind: q^2 at a q' root (q stationary), q^2 + q'^2 at a z' root.
  double radius_sq(int kind, double th) const {
    const double q = rho0 * (std::sin(t * th) + std::sin(s * th));
    double r = q * q;
    if (kind == 1) {
      const double qd = rho0 * (w1 * std::cos(t * th) + w2 * std::cos(s * th));
      r += qd * qd;
    }
    return r;
  }
};

// The double root of f_kind in bracket i (Illinois false position to ~1e-7 of the bracket; R
// is stationary at the root). Throws if f has no sign change there: impossible in exact
// arithmetic (|W2| < W1); in double only if the phase error reached W1 - W2 =
// b/sqrt(tau sigma), far beyond the orders scanned.
double scan_root(const scan_forms& sf, int kind, std::int64_t i) {
  const double pi = boost::math::constants::pi<double>();
  const std::int64_t nlo = kind == 0 ? 2 * i : 2 * i - 1;
  const double lo = pi * double(nlo) / (2 * sf.t), hi = pi * double(nlo + 2) / (2 * sf.t);
  illinois_bracket br{lo, hi, sf.f(kind, lo), sf.f(kind, hi)};
  if ((br.flo < 0) == (br.fhi < 0) && br.flo != 0 && br.fhi != 0) {
    std::ostringstream os;
    os << "hp reference scan: no sign change for kind " << kind << " at bracket " << i << " of (" << std::int64_t(sf.t) << ", "
       << std::int64_t(sf.s) << ")";
    throw std::logic_error(os.str());
  }
  double c = 0.5 * (lo + hi);
  const double tol = 1e-7 * (hi - lo);
  for (int it = 0; it < 40 && br.hi - br.lo > tol; ++it) {
    c = br.next();
    const double fc = sf.f(kind, c);
    if (fc == 0) break;
    br.update(c, fc);
  }
  return c;
}

// Global mode: the double scan of all 4 tau critical points; the candidates are those within
// the slack of the smallest R. `examined` receives the number of critical points.
std::vector<candidate> scan_all(std::int64_t tau, std::int64_t sigma, std::size_t& examined) {
  const double pi = boost::math::constants::pi<double>();
  const scan_forms sf(tau, sigma);
  std::vector<std::pair<candidate, double>> all;  // (critical point, R there)
  all.reserve(std::size_t(4 * tau));
  double rmin = 1e300;
  for (std::int64_t i = 0; i < 2 * tau; ++i) {
    for (int kind = 0; kind < 2; ++kind) {
      const double c = scan_root(sf, kind, i);
      const double r = sf.radius_sq(kind, c);
      all.push_back({{kind, big_int(i), c}, r});
      rmin = std::min(rmin, r);
    }
  }
  examined = all.size();
  // Slack: tau*theta <= 2 pi tau is rounded to eps/2 relative and theta itself carries eps/2,
  // so each sine is off by <= ~2 pi a eps and |q| (or sqrt(R)) by dq below (x2 margin); the
  // root is located to 1e-7 of the bracket, which moves the stationary R by ~(1e-7 pi)^2.
  const double eps = 2.220446049250313e-16;
  const double dq = 4 * eps * (2 * pi * double(tau + sigma) + 4) + 1e-12;
  const double bound = (std::sqrt(rmin) + 2 * dq) * (std::sqrt(rmin) + 2 * dq);
  std::vector<candidate> out;
  for (const auto& [c, r] : all)
    if (r <= bound) out.push_back(c);
  return out;
}

// Local mode: the q' and z' roots in the 2K+1 intervals around the guess, its mirror
// 2 pi - guess and both shifted by pi (the symmetry theta -> theta + pi of pairs with tau, sigma
// odd; the extra centres are harmless for other pairs).
std::vector<candidate> local_candidates(const big_int& tau, unsigned a_bits, const mpfr_real& guess, int neighbours) {
  std::vector<candidate> cands;
  gyrores::scoped_digits d(gyrores::digits10_for_bits(a_bits + 128));
  const mpfr_real pi = pi_now();
  const mpfr_real g = mpfr_real(guess);
  for (const mpfr_real& c : {g, mpfr_real(2 * pi - g), mpfr_real(g < pi ? g + pi : g - pi),
                             mpfr_real(g < pi ? pi - g : 3 * pi - g)}) {
    big_int i0 = floor_to_int(c * mpfr_real(tau) / pi);
    for (int k = -neighbours; k <= neighbours; ++k) {
      big_int i = i0 + k;
      cands.push_back({0, i, std::nan("")});
      cands.push_back({1, i, std::nan("")});
    }
  }
  return cands;
}

// What the low-precision pass decides for the full one: which candidates to keep (R at most
// `keep`), lg = log2(1/r_res) as far as the low pass resolves it, and the full precision P.
struct full_plan {
  mpfr_real keep;
  long lg;
  unsigned full_bits;
};

// Runs inside a scoped_digits of low_bits (the caller's).
full_plan plan_full_pass(const std::vector<refined>& low, unsigned a_bits, unsigned want_bits, unsigned low_bits) {
  using std::ldexp;
  using std::sqrt;
  mpfr_real lmin = low.front().radius_sq;
  for (const auto& l : low)
    if (l.radius_sq < lmin) lmin = l.radius_sq;
  // Low-precision |q| is accurate to ~2^-(low_bits - a_bits) absolutely; dq is conservative.
  const mpfr_real dq = ldexp(mpfr_real(1), -int(low_bits - 2 * a_bits - 16));
  const mpfr_real keep = (sqrt(lmin) + 4 * dq) * (sqrt(lmin) + 4 * dq);
  // Full precision P = want + a_bits + lg + 96 with lg = log2(1/r_res) (at least a_bits, at most
  // the resolution of the low pass): the cancellation in q costs lg bits, the phase a_bits.
  long lg = long(a_bits);
  if (lmin > 0) {
    long e = 0;
    mpfr_real r0 = sqrt(lmin);
    mpfr_get_d_2exp(&e, r0.backend().data(), MPFR_RNDN);
    lg = std::clamp(-e + 1, long(a_bits), long(low_bits - a_bits - 16));
  } else {
    lg = long(low_bits - a_bits - 16);
  }
  return {keep, lg, want_bits + a_bits + unsigned(lg) + 96};
}

struct full_root {
  refined root;
  int kind;
};

// Fills out.minimisers (the refined roots within the tie threshold of the smallest R, merged
// when closer than the tie resolution, ascending), out.zero and out.at_qdot_root; returns the
// smallest R. Runs inside the caller's scoped_digits of P bits.
mpfr_real select_minimisers(hp_result& out, const std::vector<full_root>& refs, unsigned a_bits, unsigned want_bits) {
  using std::ldexp;
  using std::sqrt;
  const mpfr_real two_pi = 2 * pi_now();
  mpfr_real rmin = refs.front().root.radius_sq;
  int kmin = refs.front().kind;
  for (const auto& r : refs)
    if (r.root.radius_sq < rmin) { rmin = r.root.radius_sq; kmin = r.kind; }
  // A zero of R: |q| below 2^-(want_bits + a_bits) (relative to v = 1).
  const mpfr_real zero_level = ldexp(mpfr_real(1), -int(want_bits + a_bits + 32));
  out.zero = sqrt(rmin) < zero_level;
  const mpfr_real tie = out.zero ? mpfr_real(zero_level * zero_level)
                                 : mpfr_real(rmin * (1 + ldexp(mpfr_real(1), -int(want_bits / 2))));
  for (const auto& r : refs) {
    if (r.root.radius_sq > tie) continue;
    mpfr_real th = r.root.theta;
    if (th < 0) th += two_pi;
    if (th >= two_pi) th -= two_pi;
    // The same minimiser may be reached from two candidates (a q' and a z' root coincide
    // only at zeros of R); merge points closer than the tie resolution.
    bool dup = false;
    for (const auto& m : out.minimisers)
      if (abs(m - th) < ldexp(mpfr_real(1), -int(want_bits / 2))) dup = true;
    if (!dup) out.minimisers.push_back(th);
  }
  std::sort(out.minimisers.begin(), out.minimisers.end());
  out.at_qdot_root = kmin == 0;
  return rmin;
}

}  // namespace

hp_result hp_reference(const big_int& tau, const big_int& sigma, unsigned digits, const mpfr_real& guess,
                       bool force_local, int neighbours) {
  using std::sqrt;
  if (!(tau > sigma && sigma >= 1)) throw std::invalid_argument("hp_reference: need tau > sigma >= 1");
  const big_int a = tau + sigma;
  const unsigned a_bits = bit_length(a);
  const unsigned want_bits = want_bits_for(digits);

  hp_result out;
  std::vector<candidate> cands;
  if (!force_local && a <= hp_scan_max_order) {
    out.global = true;
    cands = scan_all(std::int64_t(tau), std::int64_t(sigma), out.critical_points);
  } else {
    cands = local_candidates(tau, a_bits, guess, neighbours);
    out.critical_points = cands.size();
  }

  // Candidates at a lower precision first (cheap): only those near the minimum go to full.
  const unsigned low_bits = 2 * a_bits + 160;
  std::vector<refined> low;
  for (const auto& c : cands) low.push_back(refine({tau, sigma, c.kind, c.i, a_bits}, 64, low_bits, c.start));
  gyrores::scoped_digits dl(gyrores::digits10_for_bits(low_bits));
  const full_plan plan = plan_full_pass(low, a_bits, want_bits, low_bits);
  out.bits = plan.full_bits;

  gyrores::scoped_digits d(gyrores::digits10_for_bits(plan.full_bits));
  std::vector<full_root> refs;
  for (std::size_t n = 0; n < cands.size(); ++n) {
    if (low[n].radius_sq > plan.keep) continue;
    refs.push_back({refine({tau, sigma, cands[n].kind, cands[n].i, a_bits}, want_bits, plan.full_bits), cands[n].kind});
  }
  out.candidates = refs.size();
  const mpfr_real rmin = select_minimisers(out, refs, a_bits, want_bits);
  if (!out.zero) {
    long e = 0;
    mpfr_real r0 = sqrt(rmin);
    mpfr_get_d_2exp(&e, r0.backend().data(), MPFR_RNDN);
    if (-e > plan.lg + 8) {
      std::ostringstream os;
      os << "hp reference: r_res ~ 2^" << e << " for (" << tau << ", " << sigma
         << ") is below the precision budget (lg = " << plan.lg << ")";
      throw std::logic_error(os.str());
    }
  }
  out.radius_sq = rmin;
  out.r_res = sqrt(rmin);
  out.theta_first = out.minimisers.front();
  out.t_first = sqrt(mpfr_real(tau)) * sqrt(mpfr_real(sigma)) * out.theta_first;
  out.first_half_period = floor_to_int(out.theta_first * mpfr_real(tau) / pi_now());
  return out;
}

hp_result hp_reference(const big_int& tau, const big_int& sigma, unsigned digits) {
  if (tau + sigma > hp_scan_max_order) throw std::invalid_argument("hp_reference: a guess is needed above the scan order");
  return hp_reference(tau, sigma, digits, mpfr_real(0));
}

hp_lobe_root_result hp_lobe_root(const big_int& tau, const big_int& sigma, const big_int& k, unsigned digits) {
  const big_int a = tau + sigma;
  const unsigned a_bits = bit_length(a);
  const big_int ilo = ((2 * k - 1) * tau) / a, ihi = ((2 * k + 1) * tau) / a;  // floors (k >= 1)
  const unsigned low_bits = 2 * a_bits + 160;
  big_int found = -1;
  int count = 0;
  for (big_int i = ilo; i <= ihi; ++i) {
    auto r = refine({tau, sigma, 0, i, a_bits}, 64, low_bits);
    gyrores::scoped_digits d(gyrores::digits10_for_bits(low_bits));
    const mpfr_real pi = pi_now();
    const mpfr_real alpha = mpfr_real(a) * r.theta / 2 - mpfr_real(k) * pi;
    if (abs(alpha) < pi / 2) {
      found = i;
      ++count;
    }
  }
  if (count != 1) {
    std::ostringstream os;
    os << "hp reference: " << count << " roots of q' in the paper's lobe k = " << k << " of (" << tau << ", "
       << sigma << ")";
    throw std::logic_error(os.str());
  }
  const unsigned full_bits = want_bits_for(digits) + 2 * a_bits + 96;
  auto r = refine({tau, sigma, 0, found, a_bits}, want_bits_for(digits), full_bits);
  return {std::move(r.theta), full_bits};
}

}  // namespace gyrores::test::hp
