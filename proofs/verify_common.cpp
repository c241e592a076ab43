// The scaffolding of the proof programs (proofs/verify_common.hpp).
#include "verify_common.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <ctime>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <gyrores/core/error.hpp>

namespace gyrores::proofs {

const char* verdict_name(verdict v) {
  switch (v) {
    case verdict::proved: return "proved";
    case verdict::refuted: return "refuted";
    case verdict::undecided: return "undecided";
    default: return "n/a";
  }
}

verdict decide_less(const mpfi_real& a, const mpfi_real& b) {
  if (certainly_less(a, b)) return verdict::proved;
  if (interval_lower(a) >= interval_upper(b)) return verdict::refuted;
  return verdict::undecided;
}

verdict decide_positive(const mpfi_real& a) {
  if (certainly_positive(a)) return verdict::proved;
  if (interval_upper(a) <= 0) return verdict::refuted;
  return verdict::undecided;
}

verdict verdict_and(verdict a, verdict b) {
  if (a == verdict::refuted || b == verdict::refuted) return verdict::refuted;
  if (a == verdict::undecided || b == verdict::undecided) return verdict::undecided;
  if (a == verdict::not_applicable) return b;
  if (b == verdict::not_applicable) return a;
  return verdict::proved;
}

std::string enc(const mpfi_real& x, unsigned d) {
  auto t = interval_to_decimal(x, d);
  return "[" + t.first + ", " + t.second + "]";
}

namespace {

std::string one_line(std::string s) {
  for (auto& ch : s)
    if (ch == '\n') ch = ' ';
  return s;
}

std::string joined(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

void add_own(CLI::App& app, const program_option& p) {
  CLI::Option* o = p.flag ? app.add_flag(p.name, *p.flag, p.help) : app.add_option(p.name, *p.value, p.help);
  if (!p.flag) {
    o->type_name(p.type_name);
    if (p.min != std::numeric_limits<std::int64_t>::min() || p.max != std::numeric_limits<std::int64_t>::max())
      o->check(CLI::Range(p.min, p.max));
    if (p.show_default) o->capture_default_str();
  }
}

}  // namespace

int run_program(const std::string& name, const std::string& description, const std::vector<program_option>& own,
                int argc, char** argv, const std::function<int(const options&)>& body) {
  CLI::App app{description, name};
  for (const auto& p : own) add_own(app, p);
  options o;
  o.command_line = joined(argc, argv);
  app.add_option("--max-order", o.max_order, "every pair with tau + sigma <= N (N >= 3)")->type_name("N")->required();
  app.add_option("--min-order", o.min_order, "and tau + sigma >= M (below 3 means 3)")
      ->type_name("M")
      ->capture_default_str();
  app.add_option("--log", o.log_path, "write the per-pair log to FILE")->type_name("FILE");
  try {
    app.parse(argc, argv);
    if (o.max_order < 3)
      throw CLI::ValidationError("--max-order", "N must be >= 3, got " + std::to_string(o.max_order));
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << name << ": error: " << one_line(e.what()) << " (see " << name << " --help)\n";
    return 3;
  }
  for (const auto& p : own)
    if (p.given) *p.given = app.get_option(p.name)->count() > 0;
  if (o.min_order < 3) o.min_order = 3;
  try {
    return body(o);
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << one_line(e.what()) << "\n";
    return 3;
  }
}

void claim::add(verdict v, const std::string& pair, const std::string& detail) {
  ++count[int(v)];
  std::string what = pair + (detail.empty() ? "" : " (" + detail + ")");
  if (v == verdict::refuted) {
    if (first_refuted.empty()) first_refuted = what;
    if (refuted_examples.size() < 8) refuted_examples.push_back(pair);
  }
  if (v == verdict::undecided && first_undecided.empty()) first_undecided = what;
}

run::run(std::string program, std::string purpose, const options& o)
    : program_(std::move(program)), purpose_(std::move(purpose)), opt_(o), start_(std::chrono::steady_clock::now()) {
  if (!o.log_path.empty()) {
    log_ = std::make_unique<std::ofstream>(o.log_path);
    if (!*log_) throw usage_error("cannot write log '" + o.log_path + "'");
  }
  std::time_t now = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
  log("# " + program_ + ": " + purpose_ + "\n# command: " + o.command_line + "\n# started: " + buf +
      "\n# pairs: all coprime tau > sigma >= 1 with " + std::to_string(o.min_order) + " <= tau + sigma <= " +
      std::to_string(o.max_order) +
      ", by order then sigma ascending\n# decisions: proved / refuted / undecided / n/a (interval arithmetic, MPFI, "
      "outward rounding; integers exact)");
}

claim& run::add_claim(const std::string& id, const std::string& statement, bool asserted) {
  claim c;
  c.id = id;
  c.statement = statement;
  c.asserted = asserted;
  claims_.push_back(std::move(c));
  log("# claim " + id + (asserted ? " [asserted]" : " [reported]") + ": " + statement);
  return claims_.back();
}

claim& run::get(const std::string& id) {
  for (auto& c : claims_)
    if (c.id == id) return c;
  throw std::logic_error("no claim " + id);
}

double run::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string run::summary_line(const claim& c) const {
  std::ostringstream s;
  s << "#  " << c.id << (c.asserted ? " [asserted]" : " [reported]") << ": proved " << c.count[0] << ", refuted "
    << c.count[1] << ", undecided " << c.count[2] << ", n/a " << c.count[3];
  if (!c.first_refuted.empty()) s << "; first refuted: " << c.first_refuted;
  if (!c.first_undecided.empty()) s << "; first undecided: " << c.first_undecided;
  s << "\n";
  if (c.refuted_examples.size() > 1) {
    s << "#     refuted (first " << c.refuted_examples.size() << "):";
    for (auto& e : c.refuted_examples) s << " " << e;
    s << "\n";
  }
  return s.str();
}

int run::finish() {
  std::ostringstream s;
  char tbuf[64];
  std::snprintf(tbuf, sizeof tbuf, "%.1f", seconds());
  s << "# summary: " << program_ << ", " << pairs_ << " pairs, orders " << opt_.min_order << ".." << opt_.max_order
    << ", " << tbuf << " s\n";
  int code = 0;
  for (auto& c : claims_) {
    s << summary_line(c);
    if (c.asserted && c.count[1] > 0) code = 1;
    if (code == 0 && c.count[2] > 0) code = 2;
  }
  for (auto& n : notes_) s << "# note: " << n << "\n";
  s << "# result: "
    << (code == 0 ? "every decision made; every asserted claim proved for every pair"
                  : code == 1 ? "FAILURE: an asserted claim was refuted" : "INCOMPLETE: undecided decisions")
    << "\n";
  std::cout << s.str();
  if (log_) *log_ << s.str();
  return code;
}

}  // namespace gyrores::proofs
