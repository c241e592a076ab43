// gyrores pair TAU SIGMA [--digits D] [--qdot0 V] [--json] [--method lattice|global]
#include <sstream>

#include <gyrores/gyrores.hpp>

#include "cli_output.hpp"
#include "commands.hpp"
#include "precision.hpp"

namespace gyrores::cli {
namespace {

struct pair_args {
  std::string tau, sigma, qdot0 = "1", method = "lattice";
  int digits = 17;
  bool json = false;
};

// All real fields of the pair report in T, as exact MPFR copies.
template <class T, pair_integer I>
real_fields pair_fields(const resonant_pair<I>& p, const pair_args& args, solver_choice solver, bool cross_check) {
  T v = real_from_decimal<T>(args.qdot0, "--qdot0");
  analysis_options opt;
  opt.solver = solver;
  if (!cross_check) opt.cross_check_max_order = 0;
  auto a = analyse_pair<T>(p, v, opt);
  real_fields f;
  auto put = [&](const char* name, const T& x) { f[name] = {real_to_mpfr(x)}; };
  put("beat_ratio", a.beat_ratio);
  put("n", a.n);
  put("omega1", a.omega1);
  put("omega2", a.omega2);
  put("rho0", a.rho0);
  put("qdot0", a.qdot0);
  put("r_res", a.inscribed.r_res);
  put("h_min", a.inscribed.h_min);
  put("h_z_max", a.inscribed.h_z_max);
  put("theta_first", a.inscribed.theta_first);
  put("t_first", a.inscribed.t_first);
  for (auto& m : a.inscribed.minimisers) f["minimisers"].push_back(real_to_mpfr(m));
  put("t_min_paper", a.t_min_paper);
  const auto& asy = a.asymptotic;
  for (std::size_t i = 0; i < asy.lobes.size(); ++i) {
    const auto& lo = asy.lobes[i];
    std::string pre = "asy." + std::to_string(i) + ".";
    for (auto [name, val] : {std::pair{"s", &lo.s}, {"u_asy", &lo.u_asy}, {"theta_asy", &lo.theta_asy},
                             {"theta_c", &lo.theta_c}, {"error", &lo.error}, {"bound", &lo.bound}, {"ratio", &lo.ratio}})
      f[pre + name] = {real_to_mpfr(*val)};
  }
  if (asy.applicable) {
    put("r_res_asy", asy.r_res_asy);
    put("r_res_asy_rel_error", asy.r_res_asy_rel_error);
  }
  return f;
}

// The integer and boolean parts of the asymptotic block (precision independent).
struct asymptotic_exact {
  bool applicable = false;
  std::string reason;
  std::vector<std::tuple<std::string, std::string, bool>> lobes;  // k, m, holds_global_min
};

template <pair_integer I> asymptotic_exact asymptotic_exact_of(const resonant_pair<I>& p) {
  auto rep = paper_asymptotics<double>(p, 1.0);
  asymptotic_exact e;
  e.applicable = rep.applicable;
  e.reason = rep.reason;
  for (auto& lo : rep.lobes) e.lobes.emplace_back(lo.k.str(), lo.m.str(), lo.holds_global_min);
  return e;
}

std::string run_pair(const pair_args& args) {
  if (args.digits < 1 || args.digits > 10000)
    throw usage_error("--digits must be in [1, 10000], got " + std::to_string(args.digits));
  big_int tau = parse_big_int(args.tau, "TAU"), sigma = parse_big_int(args.sigma, "SIGMA");
  resonant_pair<big_int> p(tau, sigma);
  {
    // Reject a non-positive or malformed amplitude before any work.
    scoped_digits d(30);
    mpfr_real v = real_from_decimal<mpfr_real>(args.qdot0, "--qdot0");
    if (!(v > 0)) throw usage_error("--qdot0 must be > 0, got " + args.qdot0);
  }
  solver_choice solver;
  if (args.method == "lattice") solver = solver_choice::lattice;
  else if (args.method == "global") solver = solver_choice::global_search;
  else throw usage_error("--method must be 'lattice' or 'global', got '" + args.method + "'");
  if (solver == solver_choice::global_search && p.order() > big_int(global_search_options{}.max_order))
    throw compute_error("the global search is limited to order tau + sigma <= " +
                        std::to_string(global_search_options{}.max_order) + "; use --method lattice for " + p.str());

  const bool needs_mpfr = boost::multiprecision::msb(p.order()) > 900;
  const bool small = pair_fits_int64(p);
  bool cross_checked = false;
  auto compute = [&](const precision_plan& plan) {
    // Cross-check once (it runs in double, whatever the plan).
    bool do_check = !cross_checked;
    real_fields f = with_real_type(plan, [&](auto tag) {
      using T = decltype(tag);
      if (small) return pair_fields<T>(pair_cast<std::int64_t>(p), args, solver, do_check);
      return pair_fields<T>(p, args, solver, do_check);
    });
    if (do_check && solver == solver_choice::lattice && !p.degenerate() &&
        p.order() <= big_int(cross_check_default_max_order))
      cross_checked = true;
    return f;
  };
  verified_run run = compute_verified(unsigned(args.digits), needs_mpfr, compute);

  const std::string method = p.degenerate() ? "degenerate-exact"
                             : solver == solver_choice::lattice ? "lattice" : "global-search";
  if (args.json) {
    json j;
    j["tau"] = json_integer(p.tau().str());
    j["sigma"] = json_integer(p.sigma().str());
    j["delta"] = json_integer(big_int(p.delta()).str());
    j["delta_mod4"] = p.delta_mod4();
    j["v2_delta"] = p.v2_delta();
    j["degenerate"] = p.degenerate();
    j["order"] = json_integer(p.order().str());
    auto one = [&](const char* k) { j[k] = run.fields.at(k).at(0); };
    one("beat_ratio");
    one("n");
    one("omega1");
    one("omega2");
    one("rho0");
    one("qdot0");
    one("r_res");
    one("h_min");
    one("h_z_max");
    one("theta_first");
    one("t_first");
    j["minimisers"] = run.fields.at("minimisers");
    one("t_min_paper");
    {
      asymptotic_exact e = needs_mpfr ? asymptotic_exact{} : small ? asymptotic_exact_of(pair_cast<std::int64_t>(p))
                                                                   : asymptotic_exact_of(p);
      if (needs_mpfr) {
        scoped_digits sd(40);
        auto rep = paper_asymptotics<mpfr_real>(p, mpfr_real(1));
        e.applicable = rep.applicable;
        e.reason = rep.reason;
        for (auto& lo : rep.lobes) e.lobes.emplace_back(lo.k.str(), lo.m.str(), lo.holds_global_min);
      }
      json asy;
      asy["applicable"] = e.applicable;
      asy["reason"] = e.reason;
      json lobes = json::array();
      for (std::size_t i = 0; i < e.lobes.size(); ++i) {
        json lo;
        lo["k"] = json_integer(std::get<0>(e.lobes[i]));
        lo["m"] = json_integer(std::get<1>(e.lobes[i]));
        std::string pre = "asy." + std::to_string(i) + ".";
        for (const char* name : {"s", "u_asy", "theta_asy", "theta_c", "error", "bound", "ratio"})
          lo[name] = run.fields.at(pre + name).at(0);
        lo["holds_global_min"] = std::get<2>(e.lobes[i]);
        lobes.push_back(lo);
      }
      asy["lobes"] = lobes;
      j["asymptotic"] = asy;
      if (e.applicable) {
        j["r_res_asy"] = run.fields.at("r_res_asy").at(0);
        j["r_res_asy_rel_error"] = run.fields.at("r_res_asy_rel_error").at(0);
      } else {
        j["r_res_asy"] = nullptr;
        j["r_res_asy_rel_error"] = nullptr;
      }
    }
    j["method"] = method;
    j["cross_checked"] = cross_checked;
    j["digits"] = args.digits;
    j["working_precision"] = {{"type", run.plan.name()}, {"bits", run.plan.bits}};
    return json_dump(j) + "\n";
  }
  std::ostringstream os;
  auto line = [&](const std::string& k, const std::string& v) { os << "  " << k << std::string(14 - std::min<std::size_t>(13, k.size()), ' ') << v << "\n"; };
  os << "pair " << p.str() << "  (order " << p.order().str() << ", delta " << big_int(p.delta()).str() << " = "
     << p.delta_mod4() << " mod 4, v2(delta) = " << p.v2_delta() << ")\n";
  line("coupling n", run.fields.at("n")[0]);
  line("W1, W2", run.fields.at("omega1")[0] + ", " + run.fields.at("omega2")[0]);
  line("qdot0", run.fields.at("qdot0")[0]);
  line("rho0", run.fields.at("rho0")[0]);
  line("r_res", run.fields.at("r_res")[0] + (p.degenerate() ? "  (exact: delta = 2 mod 4)" : ""));
  line("H_q min", run.fields.at("h_min")[0]);
  line("H_z max", run.fields.at("h_z_max")[0]);
  line("theta_first", run.fields.at("theta_first")[0]);
  line("t_first", run.fields.at("t_first")[0]);
  line("pi/|n|", run.fields.at("t_min_paper")[0] + "  (the paper's proxy for the first-hit time)");
  std::string mins;
  for (auto& m : run.fields.at("minimisers")) mins += (mins.empty() ? "" : ", ") + m;
  line("minimisers", mins);
  if (run.fields.count("r_res_asy"))
    line("r_res_asy", run.fields.at("r_res_asy")[0] + "  (observed closed form v x |sin u* tan u*|; rel. error " +
                          run.fields.at("r_res_asy_rel_error")[0] + ")");
  for (std::size_t i = 0; run.fields.count("asy." + std::to_string(i) + ".theta_asy"); ++i) {
    std::string pre = "asy." + std::to_string(i) + ".";
    line(i == 0 ? "paper lobe" : "", "theta_asy " + run.fields.at(pre + "theta_asy")[0] + ", theta_c " +
                                         run.fields.at(pre + "theta_c")[0] + ", |error| " +
                                         run.fields.at(pre + "error")[0] + " <= bound " + run.fields.at(pre + "bound")[0]);
  }
  os << "  method " << method << (cross_checked ? " (cross-checked against the global search)" : "")
     << "; " << args.digits << " digits, each verified; working precision " << run.plan.name() << " ("
     << run.plan.bits << " bits)\n";
  return os.str();
}

command_runner install_pair(CLI::App& app) {
  auto args = std::make_shared<pair_args>();
  auto* sub = app.add_subcommand("pair", "Inscribed radius, minimisers and first-hit time of a resonant pair");
  sub->add_option("TAU", args->tau, "tau (integer > sigma; any size)")->required();
  sub->add_option("SIGMA", args->sigma, "sigma (integer >= 1, coprime to tau)")->required();
  sub->add_option("--digits", args->digits, "significant digits of every real printed (1..10000)")->capture_default_str();
  sub->add_option("--qdot0", args->qdot0, "impulse amplitude qdot0 > 0 (decimal)")->capture_default_str();
  sub->add_option("--method", args->method, "lattice (any pair, cross-checked up to order 20000) or global (order <= 1e5)")->capture_default_str();
  sub->add_flag("--json", args->json, "one JSON object on stdout");
  return [args] { return run_pair(*args); };
}

const command_registration registration{"pair", install_pair};

}  // namespace

}  // namespace gyrores::cli
