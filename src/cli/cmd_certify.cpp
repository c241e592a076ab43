// gyrores certify TAU SIGMA [--digits D] [--out FILE]
// gyrores check FILE        (exit 0: holds; 1: a claim or fact fails; 2: unreadable, malformed or retired)
//
// certify writes a lattice-theorem certificate ("gyrores-certificate/2"); check re-proves one with
// the independent Arb checkers (src/checker/), for each format (app/certify.hpp): lattice-theorem,
// coupling and band certificates. A file of the
// retired cover format ("gyrores-certificate/1") is refused at once with exit 2 and how to
// re-certify (docs/formats.md): nothing of it is read.

#include <gyrores/app/certify.hpp>
#include <gyrores/core/enclosure.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/io/files.hpp>

#include "cli_options.hpp"
#include "commands.hpp"

namespace gyrores::cli {
namespace {

struct certify_args {
  std::string tau, sigma, out;
  int digits = 30;
};

std::string run_certify(const certify_args& a) {
  check_digits_flag(a.digits, 1, int(report_digits_max));
  app::certify_request request{parse_pair_arguments(a.tau, a.sigma), unsigned(a.digits), {}};
  if (!a.out.empty()) check_output_path(a.out);  // before the work
  std::string text = certificate_text(app::run_certify(request));
  if (a.out.empty()) return text;
  write_file_atomically(a.out, text);
  return "";
}

command_runner install_certify(CLI::App& app) {
  auto a = std::make_shared<certify_args>();
  auto sub = options(app).subcommand("certify", "Interval certificate of r_res, theta_first and t_first (qdot0 = 1)");
  add_pair_arguments(sub, a->tau, a->sigma);
  add_digits_option(sub, a->digits, "correct digits every enclosure must reach (1.." + std::to_string(report_digits_max) + ")");
  sub.add("--out", a->out, "write the certificate to FILE (atomically) instead of stdout");
  return [a] { return run_certify(*a); };
}

// `gyrores check`: its exit status (0 holds, 1 fails, 2 unreadable, malformed or retired) and its
// one line (stdout when it holds, stderr otherwise).
struct check_outcome {
  int status = 0;
  std::string line;
};

check_outcome check_file(const std::string& file) {
  const app::check_verdict v = app::run_check(read_file(file, certificate_read_limit, "a certificate"));
  return {v.status, "gyrores check: " + v.message};
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
