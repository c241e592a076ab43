// gyrores certify TAU SIGMA [--digits D] [--out FILE]
// gyrores check FILE        (exit 0: holds; 1: a claim or obligation fails; 2: unreadable/malformed)
#include <cstdlib>
#include <iostream>

#include <gyrores/gyrores.hpp>

#include <gyrores/io/files.hpp>
#include "certificate_json.hpp"
#include "cli_output.hpp"
#include "commands.hpp"

namespace gyrores::cli {
namespace {

struct certify_args {
  std::string tau, sigma, out;
  int digits = 30;
};

std::string run_certify(const certify_args& a) {
  if (a.digits < 1 || a.digits > 10000)
    throw usage_error("--digits must be in [1, 10000], got " + std::to_string(a.digits));
  resonant_pair<big_int> p(parse_big_int(a.tau, "TAU"), parse_big_int(a.sigma, "SIGMA"));
  certificate c = certify_pair(p, unsigned(a.digits));
  std::string text = json_dump(certificate_to_json(c)) + "\n";
  if (a.out.empty()) return text;
  write_file_atomically(a.out, text);
  return "";
}

command_runner install_certify(CLI::App& app) {
  auto a = std::make_shared<certify_args>();
  auto* sub = app.add_subcommand("certify", "Interval certificate of r_res, theta_first and t_first (qdot0 = 1)");
  sub->add_option("TAU", a->tau, "tau (integer > sigma; any size)")->required();
  sub->add_option("SIGMA", a->sigma, "sigma (integer >= 1, coprime to tau)")->required();
  sub->add_option("--digits", a->digits, "correct digits every enclosure must reach (1..10000)")->capture_default_str();
  sub->add_option("--out", a->out, "write the certificate to FILE (atomically) instead of stdout");
  return [a] { return run_certify(*a); };
}

struct check_args {
  std::string file;
};

std::string run_check(const check_args& a) {
  std::string text;
  certificate c;
  try {
    text = read_file(a.file);
    c = certificate_from_text(text);
  } catch (const usage_error& e) {
    std::cerr << "gyrores check: unreadable or malformed: " << e.what() << "\n";
    std::exit(2);
  }
  check_verdict v;
  try {
    v = check_certificate(c);
  } catch (const usage_error& e) {
    std::cerr << "gyrores check: malformed: " << e.what() << "\n";
    std::exit(2);
  } catch (const compute_error& e) {
    v = {false, e.what()};
  }
  if (!v.holds) {
    std::cerr << "gyrores check: FAILS: " << v.failure << "\n";
    std::exit(1);
  }
  return "gyrores check: certificate holds: " + std::string(c.global_minimality ? "r_res, theta_first, t_first of "
                                                                                 : "r_res <= upper bound of ") +
         resonant_pair<big_int>(c.tau, c.sigma).str() + " to " + std::to_string(c.digits) + " digits\n";
}

command_runner install_check(CLI::App& app) {
  auto a = std::make_shared<check_args>();
  auto* sub = app.add_subcommand("check", "Re-prove a certificate independently (exit 0 holds, 1 fails, 2 malformed)");
  sub->add_option("FILE", a->file, "certificate written by gyrores certify")->required();
  return [a] { return run_check(*a); };
}

const command_registration reg_certify{"certify", install_certify};
const command_registration reg_check{"check", install_check};

}  // namespace
}  // namespace gyrores::cli
