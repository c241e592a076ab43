// verify_envelope: paper Prop. convexEnvelope (docs/mathematics.md §2, P2), for every pair up to --max-order.
//
// Notation (proofs/README.md, P2). In units of rho0 the trajectory is
//   x(theta) = (sin tau theta, w1 cos tau theta) + (sin sigma theta, w2 cos sigma theta),
// w1 = sqrt(tau/sigma), w2 = 1/w1. For a direction u(phi) = (cos phi, sin phi) the support
// function of the filled ellipse E_w is h_w(phi) = sqrt(cos^2 phi + w^2 sin^2 phi), attained at the
// phase theta_w*(phi) = pi/2 - psi_w(phi), where psi_w is the continuous angle of
// (cos phi, w sin phi):
//   psi_w(phi) = phi + atan((w - 1) sin phi cos phi / (cos^2 phi + w sin^2 phi)).
// <u, x(theta)> = h_1 cos(tau theta - theta_1*) + h_2 cos(sigma theta - theta_2*), so the
// trajectory reaches the envelope's support line in direction phi iff there is theta with
// tau theta = theta_1*, sigma theta = theta_2* (mod 2 pi), i.e. (the closed line is
// {sigma p1 - tau p2 in 2 pi Z}) iff
//   F(phi) = sigma theta_1* - tau theta_2* = -b pi/2 - sigma psi_1 + tau psi_2  lies in 2 pi Z.
// F is strictly increasing (F' = sqrt(tau sigma) [1/h_2^2 - 1/h_1^2] >= 0, zero only at
// sin phi = 0) and F(2 pi) - F(0) = 2 pi b: exactly b touching directions per period (README).
// Between two, the trajectory stays strictly inside; with d = dist(F(phi), 2 pi Z),
//   gap(phi) = h_1 + h_2 - max_theta <u, x> >= (2/pi^2) d^2 / (sigma^2/h_1 + tau^2/h_2)   (Jordan),
//   gap(phi) <= min(h_2 (1 - cos(pi/tau)), h_1 (1 - cos(pi/sigma))).
//
// Per pair the program decides:
//   P2.touch   b touching directions exist: each is bracketed, phi_lo < phi_N < phi_hi, by
//              F(phi_lo) < 2 pi N < F(phi_hi) in MPFI (or is phi = 0, pi exactly when 4 | b), and the
//              trajectory point there is consistent with the Prop.'s x_d(phi) (overlapping
//              enclosures); "exactly b" is the monotonicity lemma, not a computation.
//   P2.gap     at each of the b directions with F = 2 pi N + pi (half-way between touches) the
//              Jordan lower bound on the gap is > 0: the trajectory does not reach the envelope.
//   P2.literal (reported) the Prop.'s "boundary set" is the boundary of the trajectory's convex
//              hull: refuted whenever P2.gap is proved (the hull misses the envelope there).
// The log gives per pair: b, the smallest and largest relative gap lower bound
// (gap/(h_1 + h_2)) over the b half-way directions, and the largest relative upper bound.
#include <cmath>

#include "verify_common.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;
using namespace gyrores::proofs;

namespace {

struct env_pair {
  std::int64_t tau, sigma, b;
};

template <class T> T psi(const T& w, const T& phi) {
  using std::atan;
  using std::cos;
  using std::sin;
  T s = sin(phi), c = cos(phi);
  return phi + atan((w - 1) * s * c / (c * c + w * s * s));
}

template <class T> T F_of(const env_pair& P, const T& w1, const T& w2, const T& pi, const T& phi) {
  return -T(double(P.b)) * pi / 2 - T(double(P.sigma)) * psi(w1, phi) + T(double(P.tau)) * psi(w2, phi);
}

// phi in [lo, hi] with F(phi) = target, F increasing (double bisection).
double solve_F(const env_pair& P, double target, double lo, double hi) {
  const double w1 = std::sqrt(double(P.tau) / double(P.sigma)), w2 = 1 / w1;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * (1 + std::fabs(lo)); ++it) {
    double mid = (lo + hi) / 2;
    if (F_of<double>(P, w1, w2, M_PI, mid) < target) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}

// Extended Euclid: returns (i, k) with sigma i - tau k = -N.
std::pair<__int128, __int128> bezout(std::int64_t tau, std::int64_t sigma, std::int64_t N) {
  __int128 r0 = sigma, r1 = tau, s0 = 1, s1 = 0, t0 = 0, t1 = 1;  // r = s sigma + t tau
  while (r1 != 0) {
    __int128 q = r0 / r1;
    __int128 r = r0 - q * r1; r0 = r1; r1 = r;
    __int128 s = s0 - q * s1; s0 = s1; s1 = s;
    __int128 t = t0 - q * t1; t0 = t1; t1 = t;
  }
  // s0 sigma + t0 tau = 1  ->  sigma (-N s0) - tau (N t0) = -N
  return {-__int128(N) * s0, __int128(N) * t0};
}

// The pair in units of rho0 at the working precision: the ellipses' axes w1 = sqrt(tau/sigma),
// w2 = 1/w1, the trajectory x(theta), the Prop.'s envelope x_d(phi), and F(phi).
struct envelope_geometry {
  env_pair P;
  mpfi_real pi, two_pi, T, S, w1, w2;

  envelope_geometry(const env_pair& p, const mpfi_real& pi_)
      : P(p), pi(pi_), two_pi(2 * pi_), T(mpfi_real(p.tau)), S(mpfi_real(p.sigma)), w1(sqrt(T / S)), w2(sqrt(S / T)) {}

  mpfi_real F(const mpfi_real& phi) const { return F_of<mpfi_real>(P, w1, w2, pi, phi); }
  std::pair<mpfi_real, mpfi_real> x_traj(const mpfi_real& th) const {  // x(theta)/rho0
    return std::pair{sin(T * th) + sin(S * th), w1 * cos(T * th) + w2 * cos(S * th)};
  }
  std::pair<mpfi_real, mpfi_real> x_env(const mpfi_real& phi) const {  // the Prop.'s x_d(phi)/rho0
    mpfi_real c = cos(phi), s = sin(phi);
    mpfi_real h1 = sqrt(c * c + w1 * w1 * s * s), h2 = sqrt(c * c + w2 * w2 * s * s);
    return std::pair{c / h1 + c / h2, w1 * w1 * s / h1 + w2 * w2 * s / h2};
  }
  // N from ceil(-b/4) to ceil(-b/4) + b - 1 (exact integers): 2 pi N in [F(0), F(2 pi)).
  std::int64_t first_N() const { return -(P.b / 4); }  // ceil(-b/4) for b >= 0
};

bool overlap(const mpfi_real& u, const mpfi_real& v) {
  return !(interval_upper(u) < interval_lower(v) || interval_upper(v) < interval_lower(u));
}

// The touching directions F(phi) = 2 pi N: each bracketed in MPFI (or exact when 4 | b), and the
// trajectory point there compared with x_d.
struct touches {
  std::int64_t found = 0;
  bool consistent = true;
  std::vector<double> phi;
};

// phi with F(phi) = 2 pi N as an enclosure (nullopt when not bracketed), and its double value.
std::optional<std::pair<mpfi_real, double>> touching_phi(const envelope_geometry& G, std::int64_t N) {
  const std::int64_t b = G.P.b;
  if (b % 4 == 0 && (4 * N == -b)) return std::pair{mpfi_real(0), 0.0};  // F(0) = -b pi/2 = 2 pi N exactly
  if (b % 4 == 0 && (4 * N == b)) return std::pair{G.pi, M_PI};          // F(pi) = b pi/2 = 2 pi N exactly
  double phid = solve_F(G.P, 2 * M_PI * double(N), 0, 2 * M_PI);
  double h = 1e-9 * (1 + phid);
  mpfi_real lo = mpfi_real(phid - h), hi = mpfi_real(phid + h);
  mpfi_real target = G.two_pi * mpfi_real(N);
  if (!(phid - h > 0 && phid + h < 2 * M_PI && certainly_less(G.F(lo), target) && certainly_less(target, G.F(hi))))
    return std::nullopt;
  return std::pair{interval_hull(lo, hi), phid};
}

touches find_touches(const envelope_geometry& G) {
  touches out;
  const std::int64_t n0 = G.first_N();
  for (std::int64_t N = n0; N < n0 + G.P.b; ++N) {
    auto t = touching_phi(G, N);
    if (!t) continue;
    ++out.found;
    out.phi.push_back(t->second);
    // The trajectory point at theta = (theta_1* + 2 pi i)/tau, sigma i - tau k = -N.
    auto [i, k] = bezout(G.P.tau, G.P.sigma, N);
    (void)k;
    mpfi_real th1 = G.pi / 2 - psi(G.w1, t->first);
    mpfi_real th = (th1 + G.two_pi * real_from_int<mpfi_real>(to_big(i))) / G.T;
    auto xt = G.x_traj(th);
    auto xe = G.x_env(t->first);
    if (!(overlap(xt.first, xe.first) && overlap(xt.second, xe.second))) out.consistent = false;
  }
  return out;
}

// The gap half-way between touches (F = 2 pi N + pi): Jordan lower bound and the upper bound,
// relative to h_1 + h_2.
struct gaps {
  verdict v = verdict::proved;
  mpfr_real lb_min = 10, lb_max = 0, ub_max = 0;
};

gaps half_way_gaps(const envelope_geometry& G) {
  gaps out;
  const std::int64_t b = G.P.b, n0 = G.first_N();
  const mpfi_real &pi = G.pi, &T = G.T, &S = G.S;
  for (std::int64_t N = n0 - 1; N < n0 + b; ++N) {
    double target = 2 * M_PI * double(N) + M_PI;
    if (target < -double(b) * M_PI / 2 || target >= -double(b) * M_PI / 2 + 2 * M_PI * double(b)) continue;
    mpfi_real phi = mpfi_real(solve_F(G.P, target, 0, 2 * M_PI));
    // d = dist(F, 2 pi Z) >= pi - |F - (2 pi N + pi)|
    mpfi_real d = pi - interval_abs(G.F(phi) - (G.two_pi * mpfi_real(N) + pi));
    mpfi_real c = cos(phi), s = sin(phi);
    mpfi_real h1 = sqrt(c * c + G.w1 * G.w1 * s * s), h2 = sqrt(c * c + G.w2 * G.w2 * s * s);
    mpfi_real lb = 2 / (pi * pi) * interval_sqr(d) / (S * S / h1 + T * T / h2);
    mpfi_real rel = lb / (h1 + h2);
    mpfi_real ub1 = h2 * (1 - cos(pi / T)), ub2 = h1 * (1 - cos(pi / S));
    mpfi_real ub = (interval_upper(ub1) < interval_upper(ub2) ? ub1 : ub2) / (h1 + h2);
    out.v = verdict_and(out.v, certainly_positive(d) ? decide_positive(lb) : verdict::undecided);
    if (interval_lower(rel) < out.lb_min) out.lb_min = interval_lower(rel);
    if (interval_lower(rel) > out.lb_max) out.lb_max = interval_lower(rel);
    if (interval_upper(ub) > out.ub_max) out.ub_max = interval_upper(ub);
  }
  return out;
}

std::string log_line(const std::string& name, std::int64_t b, const touches& t, const gaps& g, verdict v_touch) {
  std::string phis;
  for (double f : t.phi) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " %.6f", f);
    phis += buf;
  }
  return name + " b=" + std::to_string(b) + " touch_phi=" + (b <= 8 ? phis : " (" + std::to_string(t.found) + ")") +
         " | gap_lb_rel min " + format_scientific(g.lb_min, 4) + " max " + format_scientific(g.lb_max, 4) +
         " | gap_ub_rel max " + format_scientific(g.ub_max, 4) + " | " + verdict_name(v_touch) + " " +
         verdict_name(g.v);
}

int verify(const options& opt) {
  run R("verify_envelope", "paper Prop. convexEnvelope (P2): trajectory vs the Minkowski-sum envelope", opt);
  auto& c_touch = R.add_claim("P2.touch",
                              "the trajectory touches the envelope x_d in b = tau - sigma directions (each bracketed; "
                              "the trajectory point is consistent with x_d there)",
                              true);
  auto& c_gap = R.add_claim("P2.gap",
                            "half-way between consecutive touching directions the trajectory stays strictly inside "
                            "(Jordan lower bound on the support gap > 0)",
                            true);
  auto& c_lit = R.add_claim("P2.literal",
                            "the Prop.'s x_d is the boundary of the convex hull of the trajectory (paper wording "
                            "'boundary set')",
                            false);
  R.log("# per pair: (tau,sigma) b touches | gap lower bound rel. to h1+h2: min max over the b half-way directions | "
        "gap upper bound rel. (max) | decisions");
  scoped_digits sd(digits10_for_bits(128));
  const mpfi_real pi = real_pi<mpfi_real>();
  double worst_lb = 0;
  std::string worst_pair;
  for_each_pair(R, opt, [&](const resonant_pair<std::int64_t>& p) {
    envelope_geometry G(env_pair{p.tau(), p.sigma(), p.delta()}, pi);
    const std::string name = p.str();
    const std::int64_t b = G.P.b;
    touches t = find_touches(G);
    verdict v_touch = t.found == b ? (t.consistent ? verdict::proved : verdict::refuted) : verdict::undecided;
    c_touch.add(v_touch, name, t.found == b ? "" : "bracketed " + std::to_string(t.found) + " of " + std::to_string(b));
    gaps g = half_way_gaps(G);
    c_gap.add(g.v, name);
    c_lit.add(g.v == verdict::proved ? verdict::refuted : verdict::undecided, name,
              g.v == verdict::proved ? "the hull misses the envelope half-way between touches" : "");
    if (double(g.lb_max) > worst_lb) {
      worst_lb = double(g.lb_max);
      worst_pair = name;
    }
    if (R.logging()) R.log(log_line(name, b, t, g, v_touch));
  });
  if (!worst_pair.empty())
    R.note("largest proved relative gap lower bound: " + std::to_string(worst_lb) + " at " + worst_pair);
  return R.finish();
}

}  // namespace

int main(int argc, char** argv) {
  return run_program("verify_envelope", "verify_envelope: paper Prop. convexEnvelope (P2)", {}, argc, argv, verify);
}
