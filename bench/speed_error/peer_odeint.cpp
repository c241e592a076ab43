// The simulation peer: time-domain simulation with Boost.Odeint, as a user without gyrores would do it.
//
// The ODE q'' + n z' + q = 0, z'' - n q' + z = 0 from (q, q', z, z') = (0, 1, 0, 0) is integrated
// over its first period t in [0, 2 pi sqrt(tau sigma)] (theta in [0, 2 pi)); every local minimum
// of H_q = (q^2 + q'^2)/2 (where dH_q/dt = -n q' z' changes sign from - to +) is located inside
// its step and the smallest is kept: r_res = sqrt(2 H_q,min) = sqrt(q^2 + q'^2), theta = t/sqrt(tau sigma).
//  - odeint_dopri5(tol=...): runge_kutta_dopri5 with step-size control (abs = rel = tol) and dense
//    output; the minimum is located on the dense output (TOMS 748 on dH_q/dt).
//  - odeint_symplectic(N=...): symplectic_rkn_sb3a_mclachlan (4th order), fixed step, N steps per
//    period 2 pi/Omega. Odeint's symplectic steppers need a separable Hamiltonian, and the
//    gyroscopic force is velocity dependent, so the system is integrated in the Larmor frame
//    rotating at n/2: w = q + i z = exp(i n t/2) y turns it into the isotropic oscillator
//    y'' = -Omega^2 y, Omega^2 = 1 + n^2/4, and (q, q', z, z') are rotated back at each step. The
//    minimum is located by re-stepping from the step's start with a partial step (TOMS 748).
// The simulation finds one of the tied minimisers (mirror images have equal R), so its theta is
// scored against the nearest true minimiser. Evaluations: calls of the right-hand side (force).
#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdio>
#include <limits>

#include "case_support.hpp"
#include "methods.hpp"

namespace gyrores::bench {

namespace {

namespace odeint = boost::numeric::odeint;

struct sim_result {
  double theta, r;
  std::uint64_t evaluations;
};

struct sim_constants {
  double sqrt_ts, n, period;
};
sim_constants sim_constants_of(double tau, double sigma) {
  const double sts = std::sqrt(tau) * std::sqrt(sigma);
  return {sts, (tau - sigma) / sts, 2 * boost::math::constants::pi<double>() * sts};
}

using state4 = std::array<double, 4>;

sim_result simulate_dopri5(double tau, double sigma, double tol) {
  const auto k = sim_constants_of(tau, sigma);
  std::uint64_t calls = 0;
  const double n = k.n;
  auto sys = [&calls, n](const state4& x, state4& dx, double) {
    ++calls;
    dx[0] = x[1];
    dx[1] = -n * x[3] - x[0];
    dx[2] = x[3];
    dx[3] = n * x[1] - x[2];
  };
  auto g = [n](const state4& x) { return -n * x[1] * x[3]; };  // dH_q/dt
  auto stepper = odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<state4>());
  const state4 x0{0.0, 1.0, 0.0, 0.0};
  stepper.initialize(x0, 0.0, 0.01);
  double best_r2 = std::numeric_limits<double>::infinity(), best_t = 0, g_old = g(x0);
  while (stepper.current_time() < k.period) {
    auto span = stepper.do_step(sys);
    const double g_new = g(stepper.current_state());
    if (g_old < 0 && g_new >= 0) {
      auto gt = [&](double t) {
        state4 x;
        stepper.calc_state(t, x);
        return g(x);
      };
      boost::uintmax_t it = 100;
      auto br = boost::math::tools::toms748_solve(gt, span.first, span.second, g_old, g_new,
                                                  boost::math::tools::eps_tolerance<double>(50), it);
      const double tm = (br.first + br.second) / 2;
      state4 x;
      stepper.calc_state(tm, x);
      const double r2 = x[0] * x[0] + x[1] * x[1];
      if (tm <= k.period && r2 < best_r2) {
        best_r2 = r2;
        best_t = tm;
      }
    }
    g_old = g_new;
  }
  return {best_t / k.sqrt_ts, std::sqrt(best_r2), calls};
}

using coor = std::array<double, 2>;
using phase = std::pair<coor, coor>;  // (y, y') in the Larmor frame

sim_result simulate_symplectic(double tau, double sigma, int steps_per_period) {
  const auto k = sim_constants_of(tau, sigma);
  const double n = k.n, omega2 = 1 + n * n / 4, omega = std::sqrt(omega2);
  std::uint64_t calls = 0;
  auto coor_f = [](const coor& p, coor& dqdt) { dqdt = p; };
  auto mom_f = [&calls, omega2](const coor& q, coor& dpdt) {
    ++calls;
    dpdt[0] = -omega2 * q[0];
    dpdt[1] = -omega2 * q[1];
  };
  auto sys = std::make_pair(coor_f, mom_f);
  // (q, q', z, z') from the Larmor frame at time t.
  auto physical = [n](const phase& s, double t) {
    const double c = std::cos(n * t / 2), sn = std::sin(n * t / 2);
    const coor& y = s.first;
    const coor& p = s.second;
    const double v1 = p[0] - n / 2 * y[1], v2 = p[1] + n / 2 * y[0];
    return state4{c * y[0] - sn * y[1], c * v1 - sn * v2, sn * y[0] + c * y[1], sn * v1 + c * v2};
  };
  auto g = [n](const state4& x) { return -n * x[1] * x[3]; };
  odeint::symplectic_rkn_sb3a_mclachlan<coor> stepper;
  phase s{{0.0, 0.0}, {1.0, 0.0}};  // w(0) = 0, w'(0) = q'(0) + i z'(0) = 1
  const double dt = 2 * boost::math::constants::pi<double>() / omega / steps_per_period;
  double t = 0, best_r2 = std::numeric_limits<double>::infinity(), best_t = 0;
  double g_old = g(physical(s, 0));
  while (t < k.period) {
    const phase start = s;
    const double t0 = t, h = std::min(dt, k.period - t);
    stepper.do_step(sys, s, t0, h);
    t = t0 + h;
    const double g_new = g(physical(s, t));
    if (g_old < 0 && g_new >= 0) {
      auto gh = [&](double hh) {
        phase ss = start;
        if (hh > 0) stepper.do_step(sys, ss, t0, hh);
        return g(physical(ss, t0 + hh));
      };
      boost::uintmax_t it = 100;
      auto br = boost::math::tools::toms748_solve(gh, 0.0, h, g_old, g_new, boost::math::tools::eps_tolerance<double>(50), it);
      const double hm = (br.first + br.second) / 2;
      phase ss = start;
      stepper.do_step(sys, ss, t0, hm);
      const state4 x = physical(ss, t0 + hm);
      const double r2 = x[0] * x[0] + x[1] * x[1];
      if (r2 < best_r2) {
        best_r2 = r2;
        best_t = t0 + hm;
      }
    }
    g_old = g_new;
  }
  return {best_t / k.sqrt_ts, std::sqrt(best_r2), calls};
}

std::string skip_sim(const bench_pair& bp, const precision& pr) {
  if (pr.kind != real_kind::dbl)
    return "the simulation runs in double: its error is set by the tolerance (1e-12 at best here), not by the "
           "type, and a higher-order-accurate simulation would need ~10^(d/5) steps per period";
  if (bp.order() > 10000)
    return "the first period 2 pi sqrt(tau sigma) spans ~tau fast oscillations: ~10^6 for (10^6+1,10^6), i.e. ~10^4 "
           "times the (101,100) run (~30 s per call at tol 1e-12), and 1e-8 of its r_res = 2.8e-7 would need an "
           "absolute error ~3e-15 after 10^6 oscillations, beyond double; ~10^12 and more oscillations for the larger "
           "pairs (weeks to ages per call)";
  return "";
}

sim_result run_sim(const std::string& kind, double param, const bench_pair& bp) {
  const double tau = double(bp.p.tau()), sigma = double(bp.p.sigma());
  if (kind == "dopri5") return simulate_dopri5(tau, sigma, param);
  return simulate_symplectic(tau, sigma, int(param));
}

method_def sim_method(const std::string& kind, double param) {
  char name[64];
  if (kind == "dopri5")
    std::snprintf(name, sizeof name, "odeint_dopri5(tol=%.0e)", param);
  else
    std::snprintf(name, sizeof name, "odeint_symplectic(N=%d)", int(param));
  const std::string nm = name;
  const std::string family = kind == "dopri5" ? "odeint_dopri5" : "odeint_symplectic";
  const std::string desc =
      kind == "dopri5"
          ? "**peer, simulation**: Boost.Odeint runge_kutta_dopri5, adaptive (abs = rel = tol), dense output; "
            "minimum of H_q over the first period located on the dense output"
          : "**peer, simulation**: Boost.Odeint symplectic_rkn_sb3a_mclachlan, N fixed steps per oscillation, in "
            "the Larmor frame (the symplectic steppers need a separable Hamiltonian); minimum located by partial "
            "re-steps";
  return {nm, family, desc, skip_sim, [nm, kind, param](const bench_pair& bp, const precision& pr, const reference&) {
            return make_case(
                nm, pr, bp, [=] { return run_sim(kind, param, bp); },
                [](const sim_result& r) {
                  outcome o;
                  o.theta = real_text(r.theta);
                  o.theta_any_minimiser = true;
                  o.r_res = real_text(r.r);
                  o.evaluations = r.evaluations;
                  return o;
                });
          }};
}

}  // namespace

std::vector<method_def> odeint_methods(const run_config& cfg) {
  std::vector<method_def> out;
  for (double tol : {1e-6, 1e-8, 1e-10, 1e-12}) out.push_back(sim_method("dopri5", tol));
  for (int n : {32, 128, 512, 2048}) out.push_back(sim_method("symplectic", n));
  (void)cfg;
  return out;
}

}  // namespace gyrores::bench
