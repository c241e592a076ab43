// gyrores pair TAU SIGMA [--digits D] [--qdot0 V] [--json] [--enclosures]
// The report of report/pair_report.hpp (prove_pair), as text or JSON: every real the correct
// rounding of a proved enclosure.
#include <sstream>

#include <gyrores/app/pair.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/theorem/lobes.hpp>
#include <gyrores/report/pair_report.hpp>

#include "cli_options.hpp"
#include "commands.hpp"
#include "frontend/number_text.hpp"

namespace gyrores::cli {

using frontend::decimal_text;
using frontend::energy_text;
using frontend::plain;

namespace {

struct pair_args {
  std::string tau, sigma, qdot0 = "1";
  int digits = 17;
  bool json = false, enclosures = false;
};

// "  <key padded to 14 columns><value>".
void text_line(std::ostringstream& os, const std::string& key, const std::string& value) {
  os << "  " << key << std::string(14 - std::min<std::size_t>(13, key.size()), ' ') << value << "\n";
}

// A real, with its enclosure when asked.
std::string real_text(const proved_real& r, bool enclosures) {
  if (!enclosures) return plain(r);
  return plain(r) + "  in [" + plain(r.enclosure.first) + ", " + plain(r.enclosure.second) + "]";
}

std::string joined(const std::vector<proved_real>& items, bool enclosures) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + real_text(s, enclosures);
  return out;
}

void asymptotic_text(std::ostringstream& os, const pair_report& r, bool enc) {
  if (!r.asymptotic_applicable) {
    text_line(os, "paper lobe", "not applicable: " + r.asymptotic_reason);
    return;
  }
  text_line(os, "r_res_asy", real_text(*r.r_res_asy, enc) + "  (the x -> 0 limit v x |sin u tan u|, u + tan u = pi m_min/(2b))");
  text_line(os, "", "relative error against r_res " + real_text(*r.r_res_asy_rel_error, enc));
  for (std::size_t i = 0; i < r.lobes.size(); ++i) {
    const auto& l = r.lobes[i];
    text_line(os, i == 0 ? "paper lobe" : "",
              "k = " + l.k.str() + ", m = " + l.m.str() + (l.holds_global_min ? " (holds a global minimiser)" : ""));
    text_line(os, "", "theta_asy " + real_text(l.theta_asy, enc) + ", theta_c " + real_text(l.theta_c, enc));
    text_line(os, "", "|error| " + real_text(l.error, enc) + " <= bound pi^3 x^2/a " + real_text(l.bound, enc) +
                          " (ratio " + real_text(l.ratio, enc) + ")");
  }
  if (!r.asymptotic_reason.empty()) text_line(os, "", r.asymptotic_reason);
}

std::string pair_report_text(const resonant_pair<big_int>& p, const pair_report& r, bool enc) {
  std::ostringstream os;
  os << "pair " << p.str() << "  (order " << p.order().str() << ", delta " << big_int(p.delta()).str() << " = "
     << p.delta_mod4() << " mod 4, v2(delta) = " << p.v2_delta() << ")\n";
  text_line(os, "coupling n", real_text(r.n, enc));
  text_line(os, "W1, W2", real_text(r.omega1, enc) + ", " + real_text(r.omega2, enc));
  text_line(os, "qdot0", real_text(r.qdot0, enc));
  text_line(os, "rho0", real_text(r.rho0, enc));
  text_line(os, "r_res", real_text(r.r_res, enc) + (p.degenerate() ? "  (exact: delta = 2 mod 4)" : ""));
  text_line(os, "H_q min", p.degenerate() ? real_text(r.h_min, enc) + "  (exact: delta = 2 mod 4)"
                                           : real_text(r.h_min, enc) + "  (" + plain(r.h_min_share) + "% of H_q(0))");
  text_line(os, "H_z max", real_text(r.h_z_max, enc));
  text_line(os, "theta_first", real_text(r.theta_first, enc));
  text_line(os, "t_first", real_text(r.t_first, enc));
  text_line(os, "pi/|n|", real_text(r.t_min_paper, enc) + "  (the paper's proxy for the first-hit time)");
  text_line(os, "minimisers", joined(r.minimisers, enc));
  asymptotic_text(os, r, enc);
  os << "  " << r.digits << " digits, each the correct rounding of a proved enclosure (" << lattice_theorem_id
     << ", proofs/lattice-theorem.md; interval arithmetic at " << r.bits << " bits)\n";
  return os.str();
}

std::string run_pair(const pair_args& args) {
  check_digits_flag(args.digits, 1, int(report_digits_max));
  app::pair_request request{parse_pair_arguments(args.tau, args.sigma), {}};
  request.options.qdot0 = parse_rational(args.qdot0, "--qdot0");
  if (!(request.options.qdot0 > 0)) throw usage_error("--qdot0 must be > 0, got " + args.qdot0);
  request.options.digits = unsigned(args.digits);
  request.options.enclosures = args.enclosures;
  const resonant_pair<big_int>& p = request.pair;
  const pair_report r = app::run_pair(request);
  if (!args.json) return pair_report_text(p, r, args.enclosures);
  return json_dump(pair_report_json(p, r, args.enclosures)) + "\n";
}

command_runner install_pair(CLI::App& app) {
  auto args = std::make_shared<pair_args>();
  auto sub = options(app).subcommand("pair", "Inscribed radius, minimisers and first-hit time of a resonant pair (proved)");
  add_pair_arguments(sub, args->tau, args->sigma);
  add_digits_option(sub, args->digits, "significant digits of every real printed (1.." + std::to_string(report_digits_max) + ")");
  sub.add("--qdot0", args->qdot0, "impulse amplitude qdot0 > 0 (an exact decimal or fraction)", show::with_default);
  add_json_flag(sub, args->json);
  sub.flag("--enclosures", args->enclosures, "also print the proved enclosure [lo, hi] of every real");
  return [args] { return run_pair(*args); };
}

const command_registration registration{"pair", install_pair};

}  // namespace
}  // namespace gyrores::cli
