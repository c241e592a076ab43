// gyrores pair TAU SIGMA [--digits D] [--qdot0 V] [--json] [--method lattice|global] [--estimate]
// The report of inscribed/verified_pair.hpp (verify_pair), as JSON or text, with the proved
// enclosures of r_res, theta_first and t_first (certify/theorem_certificate.hpp) unless
// --estimate asks for the verified-digit estimates alone.
#include <optional>
#include <sstream>

#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/core/verified_digits.hpp>
#include <gyrores/inscribed/global_search.hpp>
#include <gyrores/inscribed/verified_pair.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/io/report_json.hpp>

#include "cli_options.hpp"
#include "commands.hpp"
#include "pair_output.hpp"

namespace gyrores::cli {
namespace {

struct pair_args {
  std::string tau, sigma, qdot0 = "1", method = "lattice";
  int digits = 17;
  bool json = false, estimate = false;
};

solver_choice parse_method(const std::string& method) {
  if (method == "lattice") return solver_choice::lattice;
  if (method == "global") return solver_choice::global_search;
  throw usage_error("--method must be 'lattice' or 'global', got '" + method + "'");
}

// "  <key padded to 14 columns><value>".
void text_line(std::ostringstream& os, const std::string& key, const std::string& value) {
  os << "  " << key << std::string(14 - std::min<std::size_t>(13, key.size()), ' ') << value << "\n";
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// A diagnostic's value with its mark when it did not settle to D digits (verified_pair_report::unsettled).
std::string diagnostic_text(const verified_pair_report& r, const std::string& name, const std::string& value) {
  auto it = r.unsettled.find(name);
  if (it == r.unsettled.end()) return value;
  if (it->second == 0) return "< " + value + " [no digit settled; estimated bound on |value|]";
  return value + " [" + std::to_string(it->second) + " digits settled]";
}

std::string enclosure_text(const std::pair<std::string, std::string>& e) { return "[" + e.first + ", " + e.second + "]"; }

std::string pair_report_text(const resonant_pair<big_int>& p, const verified_pair_report& r,
                             const std::optional<certified_enclosures>& proved) {
  std::ostringstream os;
  os << "pair " << p.str() << "  (order " << p.order().str() << ", delta " << big_int(p.delta()).str() << " = "
     << p.delta_mod4() << " mod 4, v2(delta) = " << p.v2_delta() << ")\n";
  text_line(os, "coupling n", r.n);
  text_line(os, "W1, W2", r.omega1 + ", " + r.omega2);
  text_line(os, "qdot0", r.qdot0);
  text_line(os, "rho0", r.rho0);
  text_line(os, "r_res", r.r_res + (p.degenerate() ? "  (exact: delta = 2 mod 4)" : ""));
  text_line(os, "H_q min", r.h_min);
  text_line(os, "H_z max", r.h_z_max);
  text_line(os, "theta_first", r.theta_first);
  text_line(os, "t_first", r.t_first);
  if (proved) {
    text_line(os, "proved", "r_res in " + enclosure_text(proved->r_res));
    text_line(os, "", "theta_first in " + enclosure_text(proved->theta_first));
    text_line(os, "", "t_first in " + enclosure_text(proved->t_first));
    text_line(os, "", "(interval arithmetic on " + proved->theorem + ", proofs/lattice-theorem.md)");
  }
  text_line(os, "pi/|n|", r.t_min_paper + "  (the paper's proxy for the first-hit time)");
  text_line(os, "minimisers", joined(r.minimisers));
  if (r.r_res_asy)
    text_line(os, "r_res_asy", diagnostic_text(r, "r_res_asy", *r.r_res_asy) +
                                   "  (the x -> 0 limit v x |sin u* tan u*|; rel. error " +
                                   diagnostic_text(r, "r_res_asy_rel_error", *r.r_res_asy_rel_error) + ")");
  for (std::size_t i = 0; i < r.lobes.size(); ++i) {
    const auto& l = r.lobes[i];
    const std::string pre = "asymptotic.lobes." + std::to_string(i) + ".";
    text_line(os, i == 0 ? "paper lobe" : "",
              "theta_asy " + diagnostic_text(r, pre + "theta_asy", l.theta_asy) + ", theta_c " +
                  diagnostic_text(r, pre + "theta_c", l.theta_c) + ", |error| " +
                  diagnostic_text(r, pre + "error", l.error) + " <= bound " +
                  diagnostic_text(r, pre + "bound", l.bound));
  }
  os << "  method " << r.method << (r.cross_checked ? " (cross-checked against the global search)" : "") << "; "
     << r.digits << " digits, each verified" << (r.unsettled.empty() ? "" : " (diagnostics marked [..] excepted)")
     << "; working precision " << r.working_precision.name() << " ("
     << r.working_precision.bits << " bits)\n";
  return os.str();
}

std::string run_pair(const pair_args& args) {
  check_digits_flag(args.digits, 1, int(verified_digits_max));
  const resonant_pair<big_int> p = parse_pair_arguments(args.tau, args.sigma);
  check_qdot0_text(args.qdot0, "--qdot0");  // before any work
  verified_pair_options opt;
  opt.digits = unsigned(args.digits);
  opt.qdot0 = args.qdot0;
  opt.solver = parse_method(args.method);
  const std::int64_t global_limit = global_search_options{}.max_order;
  if (opt.solver == solver_choice::global_search && p.order() > big_int(global_limit))
    throw compute_error("the global search is limited to order tau + sigma <= " + std::to_string(global_limit) +
                        "; use --method lattice for " + p.str());
  const verified_pair_report r = verify_pair(p, opt);
  std::optional<certified_enclosures> proved;
  if (!args.estimate) proved = certify_enclosures(p, unsigned(args.digits), args.qdot0);
  if (!args.json) return pair_report_text(p, r, proved);
  json j = pair_report_json(p, r);
  add_enclosures_json(j, proved ? &*proved : nullptr);
  return json_dump(j) + "\n";
}

command_runner install_pair(CLI::App& app) {
  auto args = std::make_shared<pair_args>();
  auto sub = options(app).subcommand("pair", "Inscribed radius, minimisers and first-hit time of a resonant pair");
  add_pair_arguments(sub, args->tau, args->sigma);
  add_digits_option(sub, args->digits, "significant digits of every real printed (1..10000)");
  sub.add("--qdot0", args->qdot0, "impulse amplitude qdot0 > 0 (decimal)", show::with_default);
  sub.add("--method", args->method, "lattice (any pair, cross-checked up to order 20000) or global (order <= 1e5)", show::with_default);
  add_json_flag(sub, args->json);
  sub.flag("--estimate", args->estimate,
           "the verified-digit estimates alone, without the proved enclosures of r_res, theta_first, t_first");
  return [args] { return run_pair(*args); };
}

const command_registration registration{"pair", install_pair};

}  // namespace
}  // namespace gyrores::cli
