// gyrores coupling N | --n2 P/Q [--horizon T] [--convergents K] [--digits D] [--json]
// Any coupling n (include/gyrores/coupling.hpp): exact resonance test on n^2; the pair analysis
// when resonant; the minimum of H_q over [0, T] with its first time; the infimum over all time;
// the continued-fraction convergents of W1/W2 as resonant pairs.
#include <sstream>

#include <gyrores/design/coupling.hpp>
#include <gyrores/gyrores.hpp>

#include "cli_output.hpp"
#include "commands.hpp"
#include "verified_pair.hpp"

namespace gyrores::cli {
namespace {

struct coupling_args {
  std::string n, n2, horizon = "100";
  int digits = 12;
  std::int64_t convergents = 8;
  bool json = false;
};

// t_first of a resonant pair at 256 bits (decides horizon >= t_first).
mpfr_real pair_t_first_256(const resonant_pair<big_int>& p) {
  scoped_digits d(digits10_for_bits(256));
  if (p.degenerate()) {
    auto c = resonant_constants_of<mpfr_real>(p, mpfr_real(1));
    return c.sqrt_ts * c.pi / 2;
  }
  return inscribed_lattice<mpfr_real>(p, mpfr_real(1)).t_first;
}

std::string run_coupling(const coupling_args& a) {
  if (a.n.empty() == a.n2.empty()) throw usage_error("give exactly one of N (the coupling) or --n2 P/Q (its square)");
  if (a.digits < 1 || a.digits > 1000) throw usage_error("--digits must be in [1, 1000], got " + std::to_string(a.digits));
  if (a.convergents < 0 || a.convergents > 60) throw usage_error("--convergents must be in [0, 60]");
  coupling_spec spec = a.n.empty() ? coupling_spec::from_n2(parse_rational(a.n2, "--n2"))
                                   : coupling_spec::from_n(parse_rational(a.n, "N"));
  const big_rational horizon = parse_rational(a.horizon, "--horizon");
  if (horizon < 0) throw usage_error("--horizon must be >= 0, got " + a.horizon);
  const bool negative = spec.n && *spec.n < 0;
  const auto pair = coupling_resonant_pair(spec);

  std::optional<pair_values> pv;
  bool horizon_covers_first = false;
  if (pair) {
    pv = pair_values_verified(*pair, unsigned(a.digits));
    scoped_digits d(digits10_for_bits(256));
    mpfr_real tf = pair_t_first_256(*pair);
    mpfr_real T = real_from_int<mpfr_real>(big_int(boost::multiprecision::numerator(horizon))) /
                  real_from_int<mpfr_real>(big_int(boost::multiprecision::denominator(horizon)));
    horizon_covers_first = T >= tf;
  }

  // |n|, pi/|n| and (unless the pair analysis answers it) the minimum over [0, T], verified.
  bool at_end = false;
  std::size_t crit = 0;
  auto compute = [&](const precision_plan& plan) {
    return with_real_type(plan, [&](auto tag) {
      using T = decltype(tag);
      T n = spec.abs_n<T>();
      real_fields f;
      f["n"] = {real_to_mpfr(n)};
      f["t_min_paper"] = {real_to_mpfr(T(real_pi<T>() / n))};
      if (!horizon_covers_first) {
        T h = real_from_int<T>(big_int(boost::multiprecision::numerator(horizon))) /
              real_from_int<T>(big_int(boost::multiprecision::denominator(horizon)));
        auto r = horizon_minimum<T>(n, T(1), h);
        f["h_min_horizon"] = {real_to_mpfr(r.h_min)};
        f["t_min_horizon"] = {real_to_mpfr(r.t_min)};
        at_end = r.at_horizon_end;
        crit = r.critical_points;
      }
      return f;
    });
  };
  verified_run run = compute_verified(unsigned(a.digits), false, compute);
  std::string h_min_h, t_min_h, source;
  if (horizon_covers_first) {
    h_min_h = pv->h_min;
    t_min_h = pv->t_first;
    source = "the pair analysis: the horizon contains t_first, where the global minimum H_min is first attained";
  } else {
    h_min_h = run.fields.at("h_min_horizon")[0];
    t_min_h = run.fields.at("t_min_horizon")[0];
    source = "critical points of H_q (roots of q' and z' bracketed exactly, " + std::to_string(crit) +
             " examined) and the end point" + std::string(at_end ? "; the minimum is at the end point t = T" : "");
  }

  std::string inf_value, inf_reason;
  bool inf_attained = false;
  if (pair) {
    inf_value = pv->h_min;
    inf_attained = true;
    inf_reason = "resonant pair " + pair->str() + ": the motion is periodic; min H_q = r_res^2/2, first attained at t_first = " +
                 pv->t_first + (pair->degenerate() ? " (delta = 2 mod 4: H_q = 0 exactly)" : "");
  } else {
    inf_value = "0";
    inf_reason = "W1/W2 is irrational (n^2 (n^2 + 4) = D/Q^2 with D = " + spec.discriminant().str() +
                 " not a perfect square): the line (W1 t, W2 t) is dense on the torus and passes arbitrarily close to "
                 "(pi/2, -pi/2), where q = q' = 0; the infimum 0 is approached but never attained";
  }

  struct conv_row {
    ratio_convergent c;
    std::optional<resonant_pair<big_int>> p;
    std::optional<pair_values> v;
  };
  std::vector<conv_row> convs;
  for (auto& c : coupling_convergents(spec, std::size_t(a.convergents))) {
    conv_row row{c, std::nullopt, std::nullopt};
    if (c.p > c.q) {
      row.p = resonant_pair<big_int>(c.p, c.q);
      row.v = pair_values_verified(*row.p, unsigned(a.digits));
    }
    convs.push_back(row);
  }

  if (a.json) {
    json j;
    j["input"] = a.n.empty() ? json{{"n2", a.n2}} : json{{"n", a.n}};
    j["n2"] = rational_str(spec.n2);
    j["n"] = run.fields.at("n")[0];
    j["n_negative"] = negative;
    j["discriminant"] = json_integer(spec.discriminant().str());
    j["resonant"] = bool(pair);
    if (pair) {
      j["pair"] = {{"tau", json_integer(pair->tau().str())}, {"sigma", json_integer(pair->sigma().str())}};
      j["pair_analysis"] = pair_values_json(*pair, *pv);
    } else {
      j["pair"] = nullptr;
    }
    j["t_min_paper"] = run.fields.at("t_min_paper")[0];
    j["horizon"] = a.horizon;
    j["h_min_horizon"] = h_min_h;
    j["t_min_horizon"] = t_min_h;
    j["min_at_horizon_end"] = at_end;
    j["horizon_source"] = source;
    j["inf_all_time"] = inf_value;
    j["inf_attained"] = inf_attained;
    j["inf_reason"] = inf_reason;
    json arr = json::array();
    for (auto& r : convs) {
      json c;
      c["partial_quotient"] = json_integer(r.c.partial_quotient.str());
      c["tau"] = json_integer(r.c.p.str());
      c["sigma"] = json_integer(r.c.q.str());
      if (r.v) {
        c["n"] = r.v->n;
        c["r_res"] = r.v->r_res;
        c["t_first"] = r.v->t_first;
        c["t_min_paper"] = r.v->t_min_paper;
        c["degenerate"] = r.v->degenerate;
      } else {
        c["note"] = "ratio 1: no resonant pair (tau = sigma)";
      }
      arr.push_back(c);
    }
    j["convergents"] = arr;
    j["digits"] = a.digits;
    return json_dump(j) + "\n";
  }
  std::ostringstream os;
  os << "coupling n^2 = " << rational_str(spec.n2) << (spec.n ? "  (n = " + rational_str(*spec.n) + ", exact)" : "") << "\n"
     << "  |n|           " << run.fields.at("n")[0] << (negative ? "  (n < 0 mirrors the motion; |n| is used)" : "") << "\n"
     << "  resonance     D = P (P + 4Q) = " << spec.discriminant().str()
     << (pair ? " is a perfect square: RESONANT, pair " + pair->str() : " is not a perfect square: not resonant") << "\n";
  if (pair) {
    os << "  r_res         " << radius_text(*pv) << "\n"
       << "  H_q min       " << pv->h_min << "\n"
       << "  t_first       " << pv->t_first << "\n"
       << "  (more: gyrores pair " << pair->tau().str() << " " << pair->sigma().str() << ")\n";
  }
  os << "  pi/|n|        " << run.fields.at("t_min_paper")[0] << "  (the paper's proxy)\n"
     << "over [0, " << a.horizon << "]:\n"
     << "  min H_q       " << h_min_h << "\n"
     << "  first at t =  " << t_min_h << "\n"
     << "  from          " << source << "\n"
     << "over all time:\n"
     << "  inf H_q       " << inf_value << (inf_attained ? "" : " (not attained)") << "\n"
     << "  because       " << inf_reason << "\n";
  if (!convs.empty()) {
    os << "resonant approximations (continued-fraction convergents of W1/W2):\n"
       << "  a_k    pair                  n                 r_res             t_first\n";
    for (auto& r : convs) {
      std::string pr = "(" + r.c.p.str() + ", " + r.c.q.str() + ")";
      std::string ak = r.c.partial_quotient.str();
      os << "  " << ak << std::string(ak.size() < 7 ? 7 - ak.size() : 1, ' ') << pr
         << std::string(pr.size() < 22 ? 22 - pr.size() : 1, ' ');
      if (r.v) os << r.v->n << "  " << r.v->r_res << "  " << r.v->t_first << "\n";
      else os << "ratio 1: no pair\n";
    }
  }
  os << "  " << a.digits << " digits, each verified\n";
  return os.str();
}

command_runner install_coupling(CLI::App& app) {
  auto a = std::make_shared<coupling_args>();
  auto* sub = app.add_subcommand("coupling", "Any coupling n: resonance test, min of H_q over a horizon, resonant approximations");
  sub->add_option("N", a->n, "the coupling n: decimal (0.25, 1e-3) or fraction (1/4)");
  sub->add_option("--n2", a->n2, "the square n^2 as a fraction or decimal (e.g. 1/12 for n = 1/sqrt(12))");
  sub->add_option("--horizon", a->horizon, "horizon T: minimum of H_q over [0, T]")->capture_default_str();
  sub->add_option("--convergents", a->convergents, "how many convergents of W1/W2 (0..60)")->capture_default_str();
  sub->add_option("--digits", a->digits, "significant digits of every real printed")->capture_default_str();
  sub->add_flag("--json", a->json, "one JSON object on stdout");
  return [a] { return run_coupling(*a); };
}

const command_registration registration{"coupling", install_coupling};

}  // namespace
}  // namespace gyrores::cli
