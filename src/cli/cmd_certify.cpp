// gyrores certify TAU SIGMA [--digits D] [--cover] [--out FILE]
// gyrores check FILE        (exit 0: holds; 1: a claim or obligation fails; 2: unreadable/malformed)
//
// certify writes a lattice-theorem certificate ("gyrores-certificate/2") by default, the cover
// certificate ("gyrores-certificate/1", proved without the theorem) with --cover. check reads
// either: /2 with the independent Arb checker (src/checker/), /1 with check_certificate.

#include <gyrores/certify/check.hpp>
#include <gyrores/certify/certify.hpp>
#include <gyrores/certify/theorem_certificate.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/io/files.hpp>

#include "certificate_checker.hpp"
#include "cli_options.hpp"
#include "commands.hpp"

namespace gyrores::cli {
namespace {

struct certify_args {
  std::string tau, sigma, out;
  int digits = 30;
  bool cover = false;
};

std::string run_certify(const certify_args& a) {
  check_digits_flag(a.digits, 1, 10000);
  auto p = parse_pair_arguments(a.tau, a.sigma);
  std::string text = json_dump(a.cover ? certificate_to_json(certify_pair(p, unsigned(a.digits)))
                                       : certificate_to_json(certify_by_theorem(p, unsigned(a.digits)))) +
                     "\n";
  if (a.out.empty()) return text;
  write_file_atomically(a.out, text);
  return "";
}

command_runner install_certify(CLI::App& app) {
  auto a = std::make_shared<certify_args>();
  auto sub = options(app).subcommand("certify", "Interval certificate of r_res, theta_first and t_first (qdot0 = 1)");
  add_pair_arguments(sub, a->tau, a->sigma);
  add_digits_option(sub, a->digits, "correct digits every enclosure must reach (1..10000)");
  sub.flag("--cover", a->cover,
           "the cover certificate (format /1: interval cover of every lobe, independent of the lattice theorem; "
           "limited to the orders docs/mathematics.md gives)");
  sub.add("--out", a->out, "write the certificate to FILE (atomically) instead of stdout");
  return [a] { return run_certify(*a); };
}

// What `gyrores check` ends with: its exit status (0 holds, 1 fails, 2 unreadable or malformed)
// and its one line (stdout when it holds, stderr otherwise).
struct check_outcome {
  int status = 0;
  std::string line;
};

check_outcome check_file(const std::string& file) {
  std::string text = read_file(file);
  if (certificate_format_of(text) == theorem_certificate_format) {
    auto v = gyrores_checker::check_theorem_certificate(text);
    return {v.status, "gyrores check: " + v.message};
  }
  certificate c;
  try {
    c = certificate_from_text(text);
  } catch (const usage_error& e) {
    return {2, std::string("gyrores check: unreadable or malformed: ") + e.what()};
  }
  check_verdict v;
  try {
    v = check_certificate(c);
  } catch (const usage_error& e) {
    return {2, std::string("gyrores check: malformed: ") + e.what()};
  } catch (const compute_error& e) {
    v = {false, e.what()};
  }
  if (!v.holds) return {1, "gyrores check: FAILS: " + v.failure};
  return {0, "gyrores check: certificate holds: " +
                 std::string(c.global_minimality ? "r_res, theta_first, t_first of " : "r_res <= upper bound of ") +
                 resonant_pair<big_int>(c.tau, c.sigma).str() + " to " + std::to_string(c.digits) + " digits"};
}

command_runner install_check(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  auto sub = options(app).subcommand("check", "Re-prove a certificate independently (exit 0 holds, 1 fails, 2 malformed)");
  sub.add("FILE", *file, "certificate written by gyrores certify", show::required);
  return [file] {
    auto out = check_file(*file);
    if (out.status != 0) throw command_exit{out.status, out.line};
    return out.line + "\n";
  };
}

const command_registration reg_certify{"certify", install_certify};
const command_registration reg_check{"check", install_check};

}  // namespace
}  // namespace gyrores::cli
