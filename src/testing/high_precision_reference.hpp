// An independent high-precision reference for r_res, theta_first and t_first of any pair.
//
// Independence: nothing here uses the library's numerical code (no lobe frames, no local
// coordinates, no TOMS 748 wrapper, no lattice, no degenerate shortcut). From gyrores it takes
// only the types (big_int, mpfr_real), scoped_digits and integer -> mpfr conversion. It evaluates
// the paper's naive resonant forms (docs/mathematics.md §1), forming tau*theta directly:
//   q(theta)  = rho0 (sin tau theta + sin sigma theta),
//   q'(theta) = rho0 (W1 cos tau theta + W2 cos sigma theta),  W1 = sqrt(tau/sigma), W2 = 1/W1,
//   z'(theta) = rho0 (W1 sin tau theta - W2 sin sigma theta),  rho0 = v/(W1 + W2),
// and makes that safe for huge pairs by brute precision instead of by clever coordinates: the
// working precision is
//   P = bits_wanted + 2 log2(tau + sigma) + 96 bits,
// one log2(a) because tau*theta is rounded relative to its size (an absolute phase error of
// a 2^-P), one more because q = sin(tau theta) + sin(sigma theta) cancels down to r_res, which
// is as small as ~x = b/a ~ 1/a for delta = 1 (an absolute error of 2^-(bits_wanted + log2 a)
// in q is then still a relative 2^-bits_wanted in r_res).
//
// Critical points. dR/dt = -2 n q' z' (docs/mathematics.md §1): the minima of R = q^2 + q'^2 are roots of
// q' or of z'. At theta = i pi/tau, cos(tau theta) = (-1)^i and W1 > W2, so q' has the sign
// (-1)^i there: each interval I_i = [i pi/tau, (i+1) pi/tau] holds a root of q' (exactly one:
// q' is a trigonometric polynomial of degree tau). Likewise z' has the sign (-1)^i at
// (i + 1/2) pi/tau, so each J_i = [(i - 1/2) pi/tau, (i + 1/2) pi/tau] holds a root of z'.
// A root is solved by bisection at a base precision, then Newton steps with precision doubling
// (safeguarded by the bracket), then one confirming step at full precision. At a q' root, q is
// stationary (q' = dq/dt), so R = q^2 there is insensitive to the root's error while q'^2 is
// not (q'^2 would only add rounding noise): R is taken as q^2 at q' roots and as q^2 + q'^2 at
// z' roots (where R itself is stationary).
//
// Global minimality, two modes:
//  - global (small pairs, order <= hp_scan_max_order): every one of the 4 tau critical points is
//    located in double (naive formulation; Illinois false position on the sign-change
//    brackets above), R evaluated there, and every candidate within a slack of the smallest
//    (the slack covers the double phase error ~ a eps) is refined at full precision. This finds
//    the minimum whether it sits at a q' root or at a z' root.
//  - local (large pairs): the caller supplies a starting guess (e.g. the library's
//    theta_first: a guess only, it is not trusted). The reference examines the q' roots in the
//    2K+1 intervals I_i around the guess and around its mirror 2 pi - guess, and the z' roots
//    in the intervals J_i around them; the reference minimum is the smallest R among them.
//    Blind spot (stated): a minimum farther than K fast half-periods from the guess is not
//    seen; global minimality there rests on the global mode for the smaller pairs and on the
//    structure (docs/mathematics.md §3) the library relies on. The local mode still catches a wrong value
//    of r_res and a minimiser in the wrong lobe nearby.
// theta_first is the smallest theta in [0, 2 pi) among the minimisers (ties: R within a relative
// 2^-(bits_wanted/2) of the minimum). t_first = sqrt(tau sigma) theta_first.
// Degenerate pairs are not special-cased: the reference finds a q' root with q ~ 0 (|q| below
// 2^-(bits_wanted + log2 a)); `zero` reports that, and r_res is then the tiny computed value.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/real.hpp>

namespace gyrores::test::hp {

using gyrores::big_int;
using gyrores::mpfr_real;

// Orders up to which the reference enumerates every critical point (in double: ~4 tau root
// solves of ~6 evaluations each; order 2e6 takes about a second at -O2).
inline constexpr std::int64_t hp_scan_max_order = 2100000;

struct hp_result {
  mpfr_real r_res, radius_sq;        // min sqrt(R), min R (amplitude v = 1)
  mpfr_real theta_first, t_first;    // smallest minimiser in [0, 2 pi), sqrt(tau sigma) theta_first
  std::vector<mpfr_real> minimisers; // every (tied) minimiser found, ascending
  bool zero = false;                 // r_res below the resolution: a zero of R (degenerate pair)
  bool global = false;               // global mode (all critical points) or local mode
  bool at_qdot_root = true;          // the minimum is at a q' root (false: at a z' root)
  unsigned bits = 0;                 // working precision P
  std::size_t candidates = 0;        // critical points refined at full precision
  std::size_t critical_points = 0;   // critical points examined (double scan or local)
};

namespace detail {

inline unsigned bit_length(const big_int& v) {
  return v == 0 ? 1u : unsigned(boost::multiprecision::msb(boost::multiprecision::abs(v))) + 1u;
}

// floor(x) as an integer (x finite).
inline big_int floor_to_int(const mpfr_real& x) {
  big_int z;
  mpfr_get_z(z.backend().data(), x.backend().data(), MPFR_RNDD);
  return z;
}

// Naive model at the current default precision (rebuilt per precision level).
struct model {
  mpfr_real tau, sigma, w1, w2, rho0, pi;
  model(const big_int& t, const big_int& s) {
    using std::sqrt;
    tau = mpfr_real(t);
    sigma = mpfr_real(s);
    w1 = sqrt(tau / sigma);
    w2 = sqrt(sigma / tau);
    rho0 = 1 / (w1 + w2);
    pi = boost::math::constants::pi<mpfr_real>();
  }
  // kind 0: f = q'/rho0, kind 1: f = z'/rho0; and df/dtheta. Also q/rho0 and q'/rho0.
  struct values {
    mpfr_real f, df, q, qdot;
  };
  values eval(int kind, const mpfr_real& th) const {
    using std::cos;
    using std::sin;
    mpfr_real p1 = tau * th, p2 = sigma * th;
    mpfr_real s1 = sin(p1), c1 = cos(p1), s2 = sin(p2), c2 = cos(p2);
    values v;
    v.q = s1 + s2;
    v.qdot = w1 * c1 + w2 * c2;
    if (kind == 0) {
      v.f = v.qdot;
      v.df = -(w1 * tau * s1 + w2 * sigma * s2);
    } else {
      v.f = w1 * s1 - w2 * s2;
      v.df = w1 * tau * c1 - w2 * sigma * c2;
    }
    return v;
  }
};

// Bracket of critical point (kind, i) as theta = pi * num / (2 tau): q' root in
// [2i, 2i+2], z' root in [2i-1, 2i+1]; f has the sign (-1)^i at the left end for q' and
// (-1)^(i-1) for z' (z' = (-1)^i W1 + ... at (i + 1/2) pi/tau).
inline void bracket_nums(int kind, const big_int& i, big_int& lo, big_int& hi) {
  lo = kind == 0 ? big_int(2 * i) : big_int(2 * i - 1);
  hi = lo + 2;
}

struct refined {
  mpfr_real theta, radius_sq;
};

// Solve f_kind = 0 in bracket i to full precision P; R at the root (v = 1).
// a_bits = bit length of tau + sigma; want_bits = accuracy wanted in theta (absolute, theta = O(1)).
// `start`: a root estimate accurate to ~2^-20 of the bracket (e.g. from the double scan), or
// NaN: bisection to 2^-40 of the bracket first.
inline refined refine(const big_int& tau, const big_int& sigma, int kind, const big_int& i, unsigned a_bits,
                      unsigned want_bits, unsigned full_bits, double start = std::nan("")) {
  using std::fabs;
  using std::ldexp;
  big_int nlo, nhi;
  bracket_nums(kind, i, nlo, nhi);
  // Base level: phases accurate to 2^-(a_bits + 96), enough for the signs in a bracket of
  // width pi/tau where |f'| may be as small as O(1) (delta = 1: f ~ 2 cos(a theta/2) cos(theta/2)).
  // Bisection to 2^-40 of the bracket.
  const unsigned base = std::min(full_bits, 2 * a_bits + 96);
  mpfr_real th, lo, hi;
  {
    gyrores::scoped_digits d(gyrores::digits10_for_bits(base));
    model m(tau, sigma);
    const mpfr_real den = 2 * m.tau;
    lo = m.pi * mpfr_real(nlo) / den;
    hi = m.pi * mpfr_real(nhi) / den;
    mpfr_real flo = m.eval(kind, lo).f, fhi = m.eval(kind, hi).f;
    if (flo == 0) {
      th = lo;
    } else if (fhi == 0) {
      th = hi;
    } else if ((flo < 0) == (fhi < 0)) {
      std::ostringstream os;
      os << "hp reference: no sign change for kind " << kind << " at bracket " << i << " of (" << tau << ", "
         << sigma << ")";
      throw std::logic_error(os.str());
    } else if (!std::isnan(start)) {
      th = mpfr_real(start);
      if (th <= lo || th >= hi) th = (lo + hi) / 2;
    } else {
      const bool lo_neg = flo < 0;
      const mpfr_real width = ldexp(hi - lo, -40);
      while (hi - lo > width) {
        mpfr_real mid = (lo + hi) / 2;
        if ((m.eval(kind, mid).f < 0) == lo_neg) lo = mid; else hi = mid;
      }
      th = (lo + hi) / 2;
    }
  }
  // Newton with precision doubling: `acc` = bits of theta known beyond 2^-a_bits; a level of
  // 2 a_bits + 2 acc + 32 bits resolves the next doubling even where |f'| = O(1). The bracket
  // [lo, hi] is a safeguard (a step leaving it bisects instead).
  unsigned acc = std::isnan(start) ? 40 : 20, level = base;
  while (level < full_bits) {
    level = std::min(full_bits, std::max(level, 2 * a_bits + 2 * acc + 32));
    gyrores::scoped_digits d(gyrores::digits10_for_bits(level));
    model m(tau, sigma);
    auto v = m.eval(kind, th);
    mpfr_real next = th - v.f / v.df;
    if (next <= lo || next >= hi) next = (lo + hi) / 2;
    th = next;
    acc *= 2;
  }
  // Full precision: steps until |step| <= 2^-(want_bits + a_bits + 8) (theta >= ~2^-a_bits, so
  // this is a relative 2^-want_bits), at most 4.
  gyrores::scoped_digits d(gyrores::digits10_for_bits(full_bits));
  model m(tau, sigma);
  const mpfr_real tol = ldexp(mpfr_real(1), -int(want_bits + a_bits + 8));
  for (int it = 0;; ++it) {
    auto v = m.eval(kind, th);
    mpfr_real step = v.f / v.df;
    th = th - step;
    if (fabs(step) <= tol) break;
    if (it == 4) {
      std::ostringstream os;
      os << "hp reference: Newton did not converge for (" << tau << ", " << sigma << ") kind " << kind
         << " bracket " << i;
      throw std::logic_error(os.str());
    }
  }
  auto fin = m.eval(kind, th);
  refined r;
  r.theta = th;
  mpfr_real q = m.rho0 * fin.q;
  if (kind == 0) {
    r.radius_sq = q * q;  // q stationary at a q' root
  } else {
    mpfr_real qd = m.rho0 * fin.qdot;
    r.radius_sq = q * q + qd * qd;  // R stationary at a z' root
  }
  return r;
}

// Double scan of all critical points (global mode). Returns (kind, i, R) of the candidates
// within the slack of the smallest R.
struct scan_candidate {
  int kind;
  std::int64_t i;
  double theta, radius_sq;
};

inline std::vector<scan_candidate> scan_all(std::int64_t tau, std::int64_t sigma, std::size_t& examined) {
  const double pi = boost::math::constants::pi<double>();
  const double t = double(tau), s = double(sigma);
  const double w1 = std::sqrt(t / s), w2 = std::sqrt(s / t), rho0 = 1 / (w1 + w2);
  auto f = [&](int kind, double th) {
    return kind == 0 ? w1 * std::cos(t * th) + w2 * std::cos(s * th) : w1 * std::sin(t * th) - w2 * std::sin(s * th);
  };
  std::vector<scan_candidate> all;
  all.reserve(std::size_t(4 * tau));
  double rmin = 1e300;
  for (std::int64_t i = 0; i < 2 * tau; ++i) {
    for (int kind = 0; kind < 2; ++kind) {
      std::int64_t nlo = kind == 0 ? 2 * i : 2 * i - 1;
      double lo = pi * double(nlo) / (2 * t), hi = pi * double(nlo + 2) / (2 * t);
      double flo = f(kind, lo), fhi = f(kind, hi);
      double c = 0.5 * (lo + hi);
      if ((flo < 0) == (fhi < 0) && flo != 0 && fhi != 0) {
        // Impossible in exact arithmetic (|W2| < W1); in double only if the phase error
        // reached W1 - W2 = b/sqrt(tau sigma), far beyond the orders scanned here.
        std::ostringstream os;
        os << "hp reference scan: no sign change for kind " << kind << " at bracket " << i << " of (" << tau << ", "
           << sigma << ")";
        throw std::logic_error(os.str());
      }
      {
        // Illinois false position to ~1e-7 of the bracket (R is stationary at the root).
        const double tol = 1e-7 * (hi - lo);
        int side = 0;
        for (int it = 0; it < 40 && hi - lo > tol; ++it) {
          c = (lo * fhi - hi * flo) / (fhi - flo);
          if (!(c > lo && c < hi)) c = 0.5 * (lo + hi);
          double fc = f(kind, c);
          if (fc == 0) break;
          if ((fc < 0) == (flo < 0)) {
            lo = c; flo = fc;
            if (side == -1) fhi /= 2;
            side = -1;
          } else {
            hi = c; fhi = fc;
            if (side == 1) flo /= 2;
            side = 1;
          }
        }
      }
      double q = rho0 * (std::sin(t * c) + std::sin(s * c));
      double r = q * q;
      if (kind == 1) {
        double qd = rho0 * (w1 * std::cos(t * c) + w2 * std::cos(s * c));
        r += qd * qd;
      }
      all.push_back({kind, i, c, r});
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
  std::vector<scan_candidate> out;
  for (const auto& c : all)
    if (c.radius_sq <= bound) out.push_back(c);
  return out;
}

}  // namespace detail

// The reference for the pair (tau, sigma), amplitude v = 1, accurate to `digits` decimal digits
// (relative, in r_res, theta_first and t_first). `guess` (any precision, in [0, 2 pi)) is used
// only in local mode (order > hp_scan_max_order, or force_local); `neighbours` = K.
// The result is at precision P (see the header); compare inside a scoped_digits of at least
// `digits` + a few.
inline hp_result hp_reference(const big_int& tau, const big_int& sigma, unsigned digits, const mpfr_real& guess,
                              bool force_local = false, int neighbours = 4) {
  using std::ldexp;
  using std::sqrt;
  if (!(tau > sigma && sigma >= 1)) throw std::invalid_argument("hp_reference: need tau > sigma >= 1");
  const big_int a = tau + sigma;
  const unsigned a_bits = detail::bit_length(a);
  const unsigned want_bits = unsigned(std::ceil(digits * 3.3219280948873623)) + 8;

  hp_result out;
  struct cand {
    int kind;
    big_int i;
  };
  std::vector<cand> cands;
  std::vector<double> starts;  // double root estimates (global mode), NaN otherwise
  if (!force_local && a <= hp_scan_max_order) {
    out.global = true;
    auto sc = detail::scan_all(std::int64_t(tau), std::int64_t(sigma), out.critical_points);
    for (const auto& c : sc) {
      cands.push_back({c.kind, big_int(c.i)});
      starts.push_back(c.theta);
    }
  } else {
    // Local mode: intervals around the guess and its mirror.
    gyrores::scoped_digits d(gyrores::digits10_for_bits(a_bits + 128));
    const mpfr_real pi = boost::math::constants::pi<mpfr_real>();
    const mpfr_real g = mpfr_real(guess);
    // The guess, its mirror 2 pi - guess and both shifted by pi (the symmetry theta -> theta + pi
    // of pairs with tau, sigma odd); the extra centres are harmless for other pairs.
    for (const mpfr_real& c : {g, mpfr_real(2 * pi - g), mpfr_real(g < pi ? g + pi : g - pi),
                               mpfr_real(g < pi ? pi - g : 3 * pi - g)}) {
      big_int i0 = detail::floor_to_int(c * mpfr_real(tau) / pi);
      for (int k = -neighbours; k <= neighbours; ++k) {
        big_int i = i0 + k;
        cands.push_back({0, i});
        cands.push_back({1, i});
        starts.push_back(std::nan(""));
        starts.push_back(std::nan(""));
      }
    }
    out.critical_points = cands.size();
  }
  out.candidates = cands.size();

  // Candidates at a lower precision first (cheap): only those near the minimum go to full.
  const unsigned low_bits = 2 * a_bits + 160;
  std::vector<std::pair<detail::refined, std::size_t>> low;
  for (std::size_t n = 0; n < cands.size(); ++n)
    low.push_back({detail::refine(tau, sigma, cands[n].kind, cands[n].i, a_bits, 64, low_bits, starts[n]), n});
  gyrores::scoped_digits dl(gyrores::digits10_for_bits(low_bits));
  mpfr_real lmin = low.front().first.radius_sq;
  for (const auto& l : low)
    if (l.first.radius_sq < lmin) lmin = l.first.radius_sq;
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
  const unsigned full_bits = want_bits + a_bits + unsigned(lg) + 96;
  out.bits = full_bits;

  gyrores::scoped_digits d(gyrores::digits10_for_bits(full_bits));
  const mpfr_real pi = boost::math::constants::pi<mpfr_real>();
  const mpfr_real two_pi = 2 * pi;
  std::vector<std::pair<detail::refined, int>> refs;
  for (const auto& l : low) {
    if (l.first.radius_sq > keep) continue;
    const auto& c = cands[l.second];
    refs.push_back({detail::refine(tau, sigma, c.kind, c.i, a_bits, want_bits, full_bits), c.kind});
  }
  out.candidates = refs.size();
  mpfr_real rmin = refs.front().first.radius_sq;
  int kmin = refs.front().second;
  for (const auto& r : refs)
    if (r.first.radius_sq < rmin) { rmin = r.first.radius_sq; kmin = r.second; }
  // A zero of R: |q| below 2^-(want_bits + a_bits) (relative to v = 1).
  const mpfr_real zero_level = ldexp(mpfr_real(1), -int(want_bits + a_bits + 32));
  out.zero = sqrt(rmin) < zero_level;
  const mpfr_real tie = out.zero ? mpfr_real(zero_level * zero_level)
                                 : mpfr_real(rmin * (1 + ldexp(mpfr_real(1), -int(want_bits / 2))));
  for (const auto& r : refs) {
    if (r.first.radius_sq > tie) continue;
    mpfr_real th = r.first.theta;
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
  if (!out.zero) {
    long e = 0;
    mpfr_real r0 = sqrt(rmin);
    mpfr_get_d_2exp(&e, r0.backend().data(), MPFR_RNDN);
    if (-e > lg + 8) {
      std::ostringstream os;
      os << "hp reference: r_res ~ 2^" << e << " for (" << tau << ", " << sigma
         << ") is below the precision budget (lg = " << lg << ")";
      throw std::logic_error(os.str());
    }
  }
  out.radius_sq = rmin;
  out.r_res = sqrt(rmin);
  out.at_qdot_root = kmin == 0;
  out.theta_first = out.minimisers.front();
  out.t_first = sqrt(mpfr_real(tau)) * sqrt(mpfr_real(sigma)) * out.theta_first;
  return out;
}

// Convenience: global mode (no guess needed); requires tau + sigma <= hp_scan_max_order.
inline hp_result hp_reference(const big_int& tau, const big_int& sigma, unsigned digits) {
  if (tau + sigma > hp_scan_max_order) throw std::invalid_argument("hp_reference: a guess is needed above the scan order");
  return hp_reference(tau, sigma, digits, mpfr_real(0));
}

}  // namespace gyrores::test::hp
