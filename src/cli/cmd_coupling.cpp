// gyrores coupling N | --n2 P/Q | --pair TAU SIGMA [--qdot0 V] [--horizon T] [--below E]
//                  [--convergents K] [--digits D] [--json] [--certificate FILE]
//                  [--band N1:N2 | --tolerance P%]
// gyrores coupling --mass M --stiffness K --gyro G --velocity V [--horizon-s T] [--below E]
//                  [--tolerance P%] ... (a physical plant, app/plant.hpp, docs/units.md: joules and seconds)
// Any coupling n (app/coupling.hpp, report/coupling_report.hpp): exact resonance test on n^2;
// the pair analysis when resonant; the minimum of H_q over [0, T] with its first time and the
// first time H_q <= E (the horizon theorem, proved), with their certificate from the same
// proofs; the infimum over all time; the continued-fraction convergents of W1/W2 as resonant
// pairs; the guarantees over a band of couplings (app/band.hpp). This file parses, asks the app
// layer (app/coupling_input.hpp chooses the coupling, units and band) and prints.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <sstream>

#include <gyrores/app/band.hpp>
#include <gyrores/app/coupling.hpp>
#include <gyrores/app/coupling_input.hpp>
#include <gyrores/app/plant.hpp>
#include <gyrores/theorem/band.hpp>
#include <gyrores/io/files.hpp>
#include <gyrores/io/certificate_json.hpp>
#include <gyrores/io/json.hpp>
#include <gyrores/io/report_json.hpp>
#include <gyrores/report/scales.hpp>

#include "cli_options.hpp"
#include "cli_signals.hpp"
#include "commands.hpp"
#include "frontend/number_text.hpp"
#include "pair_output.hpp"

namespace gyrores::cli {

using frontend::decimal_text;
using frontend::energy_text;
using frontend::plain;

namespace {

struct coupling_args {
  std::string n, n2, horizon, below, band, tolerance, certificate, qdot0;
  std::vector<std::string> pair;                     // --pair TAU SIGMA
  std::string mass, stiffness, gyro, velocity, horizon_s;  // a plant (docs/units.md)
  int band_digits = 0;  // 0: --digits
  int digits = 12;
  std::int64_t convergents = 8;
  bool json = false, quiet = false;
};

// "(p, q)" padded, then n, r_res, t_first of each convergent's pair.
void convergents_text(std::ostringstream& os, const std::vector<coupling_convergent>& rows, unsigned digits, bool model_units) {
  if (rows.empty()) return;
  os << "resonant approximations (continued-fraction convergents of W1/W2" << (model_units ? "; model units, qdot0 = 1" : "")
     << "):\n"
     << "  a_k    pair                  " << value_columns_header({"n", "r_res", "t_first"}, digits) << "\n";
  for (const auto& r : rows) {
    std::string pr = "(" + r.convergent.p.str() + ", " + r.convergent.q.str() + ")";
    std::string ak = r.convergent.partial_quotient.str();
    os << "  " << ak << std::string(ak.size() < 7 ? 7 - ak.size() : 1, ' ') << pr
       << std::string(pr.size() < 22 ? 22 - pr.size() : 1, ' ');
    if (r.values) os << value_columns({r.values->n.value, r.values->r_res.value, r.values->t_first.value}, digits) << "\n";
    else os << "ratio 1: no pair\n";
  }
}

std::string lobe_text(const std::optional<horizon_lobe>& lobe) {
  if (!lobe) return "";
  char nu[32];
  std::snprintf(nu, sizeof nu, "%.6g", lobe->nu.approx());
  return "lobe k = " + lobe->k.str() + ", ||k x - 1/2|| ~ " + nu + " (exact: --json)";
}

// The coupling, units, horizon and band chosen (app/coupling_input.hpp), with what the text says
// of them: the horizon as given ("100", "2 s") and the units of energies and times.
struct unit_choice : app::coupling_selection {
  std::string horizon_text;
  std::string energy_unit() const { return plant ? " J" : ""; }
  std::string time_unit() const { return plant ? " s" : ""; }
};

// The level of --below as given, with its unit (a percentage of H_q(0) has none).
std::string level_text(const coupling_args& a, const unit_choice& u) {
  return a.below + (!a.below.empty() && a.below.back() == '%' ? std::string() : u.energy_unit());
}

// An energy with its unit and its share of H_q(0).
std::string energy_in(const unit_choice& u, const proved_real& e, const proved_real& share) {
  const std::string t = energy_text(e.value, share.value);
  if (u.energy_unit().empty() || t == "0 (exact)") return t;
  return plain(e) + u.energy_unit() + t.substr(plain(e).size());
}

std::string plant_text(const unit_choice& u, unsigned digits) {
  const plant_inputs& p = *u.plant;
  const app::plant_numbers& v = *u.numbers;
  std::ostringstream os;
  os << "plant m = " << decimal_text(p.mass, digits) << " kg, k = " << decimal_text(p.stiffness, digits)
     << " N/m, g = " << decimal_text(p.gyro, digits) << " N s/m, struck to q'(0) = V = " << decimal_text(p.velocity, digits)
     << " m/s (docs/units.md)\n"
     << "  omega0 = sqrt(k/m)      " << plain(v.omega0) << " rad/s\n"
     << "  n = g/sqrt(m k)         " << plain(v.n) << "\n"
     << "  time unit 1/omega0      " << plain(v.time_scale) << " s  (model time t = omega0 t_s)\n"
     << "  H_q(0) = m V^2/2        " << decimal_text(v.h_q0, digits)
     << " J  (the energy (m q'^2 + k q^2)/2 of q is m V^2 H_q: below, energies in J, times in s)\n";
  if (u.horizon_s && !u.horizon_s->exact)
    os << "  horizon                 " << u.horizon_text << " = T/omega0 with T irrational: proved over [0, T'], T' = "
       << plain(format_rational_scientific(u.horizon_s->model.value, digits + 20)) << (u.horizon_s->model.times_pi ? " pi" : "")
       << " >= T (T'/T - 1 < 10^-" << digits + 19 << ")\n";
  return os.str();
}

std::string coupling_text(const coupling_args& a, const unit_choice& u, const coupling_report& r) {
  std::ostringstream os;
  const auto& spec = r.spec;
  if (u.plant) os << plant_text(u, unsigned(a.digits));
  const horizon_minimum_report& h = r.horizon;
  const quadratic_number& x = h.proof.x;
  os << "coupling n^2 = " << rational_str(spec.n2) << (spec.n ? "  (n = " + rational_str(*spec.n) + ", exact)" : "") << "\n"
     << "  |n|           " << plain(r.abs_n) << (r.n_negative ? "  (n < 0 mirrors the motion; |n| is used)" : "") << "\n";
  if (u.qdot0 != 1)
    os << "  qdot0         " << decimal_text(u.qdot0, unsigned(a.digits)) << "  (H_q(0) = qdot0^2/2 = "
       << decimal_text(u.qdot0 * u.qdot0 / 2, unsigned(a.digits)) << ")\n";
  os
     << "  x = n/sqrt(n^2+4) = " << (x.str().size() <= 60 ? x.str() : "(exact: --json)")
     << (x.is_rational() ? "" : ", a quadratic irrational") << "\n"
     << "  resonance     D = P (P + 4Q) = " << spec.discriminant().str()
     << (r.pair ? " is a perfect square: RESONANT, pair " + r.pair->str() : " is not a perfect square: not resonant") << "\n";
  if (r.pair) {
    os << "  r_res         " << radius_text(*r.pair_values) << "\n"
       << "  H_q min       " << energy_text(*r.pair_values) << "\n"
       << "  t_first       " << plain(r.pair_values->t_first) << "\n"
       << "  (more: gyrores pair " << r.pair->tau().str() << " " << r.pair->sigma().str()
       << (u.qdot0 != 1 ? " --qdot0 " + a.qdot0 : std::string()) << ")\n";
    if (u.plant) os << "  (the pair's values in model units: time t omega0, qdot0 = 1)\n";
  }
  os << "  pi/|n|        " << plain(r.t_min_paper) << u.time_unit() << "  (the paper's proxy)\n"
     << "over [0, " << u.horizon_text << "]:\n"
     << "  min H_q       " << energy_in(u, h.h_min, h.h_min_share) << "  (" << (u.plant ? "amplitude " : "radius ")
     << plain(h.r_min) << (u.plant ? " m" : "") << ")\n"
     << "  first at t =  " << plain(h.t_min) << u.time_unit() << "\n"
     << "  from          "
     << (h.proof.at_horizon_end ? "the end point t = T: H_q still decreases there (lobe " + h.proof.cut_lobe.str() + " is cut before its minimum)"
                          : lobe_text(h.lobe) + " (the smallest of the lobes inside [0, T])")
     << "\n";
  if (r.below) {
    const first_below_report& b = *r.below;
    os << "first time H_q <= " << level_text(a, u) << ":\n";
    if (b.never) os << "  never         " << b.reason << "\n";
    else os << "  t =           " << plain(b.t_below) << u.time_unit() << "\n  because       " << b.reason << "\n";
  }
  os << "over all time:\n"
     << "  inf H_q       " << (r.pair ? energy_text(*r.pair_values) + (u.plant ? "  (model units, qdot0 = 1)" : "")
                                       : r.inf_all_time + " (not attained)") << "\n"
     << "  because       " << r.inf_reason << "\n";
  convergents_text(os, r.convergents, unsigned(a.digits), bool(u.plant));
  os << "  " << a.digits << " digits, each the correct rounding of a proved enclosure (" << horizon_theorem_id
     << ", lattice-theorem/1; "
     << (u.plant ? std::string("energies in J and times in s: the unit impulse's times m V^2 and sqrt(m/k)")
                 : "qdot0 = " + rational_str(u.qdot0) + ", H_q(0) = " + rational_str(u.qdot0 * u.qdot0 / 2))
     << ")\n";
  return os.str();
}

// Where a guarantee is attained: the exact coupling, its pair, its own minimum's lobe and time.
std::string attained_text(const app::band_attained& a, unsigned digits, const std::string& time_unit) {
  // A long fraction (an end of a band rounded outward) as its decimal; exact in --json.
  const std::string n2 = rational_str(a.coupling.spec.n2);
  std::string out = "at n^2 = " + (n2.size() <= 40 ? n2 : "~" + plain(format_rational_scientific(a.coupling.spec.n2, digits)) + " (exact: --json)");
  if (a.pair) out += ", the pair " + a.pair->str();
  if (a.minimum) {
    const horizon_minimum_report& m = *a.minimum;
    out += m.proof.at_horizon_end ? ", at the horizon's end t = " + plain(m.t_min) + time_unit
                            : ", lobe k = " + (m.lobe ? m.lobe->k.str() : std::string("?")) + ", t = " + plain(m.t_min) + time_unit;
  }
  if (a.first_below) out += a.first_below->never ? ", never" : ", its first time " + plain(a.first_below->t_below) + time_unit;
  return out;
}

// A guarantee (an energy, times the unit impulse's by energy_scale, in `unit`) with its share of
// H_q(0): the share correctly rounded when its enclosure decides it, else its proved bracket
// (report/scales.hpp).
std::string extreme_text(const band_extreme& e, unsigned digits, const unit_choice& u) {
  if (e.settled && e.value.hi_rational() == 0) return "0 (exactly)";
  const enclosure share = scaled(e.value, share_factor() / u.energy_scale());
  const unsigned sd = std::min(digits, share_digits);
  const auto rounded_share = share.rounded(sd);
  const auto [slo, shi] = share.outward(sd);
  const std::string share_text =
      "  (" + (rounded_share ? plain(*rounded_share) : "in [" + plain(slo) + ", " + plain(shi) + "]") + "% of H_q(0))";
  if (e.settled) return plain(*e.value.rounded(digits)) + u.energy_unit() + share_text;
  const auto [lo, hi] = e.value.outward(digits);
  return "in [" + plain(lo) + ", " + plain(hi) + "]" + u.energy_unit() + share_text + " (" +
         (e.interrupted ? std::string("interrupted") : "not settled: " + e.unsettled_reason) + ")";
}

std::string band_text(const coupling_args& a, const unit_choice& u, const app::band_request& q, const app::band_result& b,
                      const std::string& note) {
  std::ostringstream os;
  const unsigned d = q.digits;
  const std::string t_unit = u.time_unit();
  os << "band n in [" << decimal_text(q.n1, d) << ", " << decimal_text(q.n2, d) << "], over [0, " << u.horizon_text << "]:\n";
  if (!note.empty()) os << "  " << note << "\n";
  if (u.plant)
    os << "  (n = g/sqrt(m k): a tolerance on n is that tolerance on g at this m and k; energies in J, times in s)\n";
  os
     << "  absorption guarantee   " << extreme_text(b.absorption, d, u) << "\n"
     << "                         every n of the band has min H_q <= this over [0, T] (the highest minimum)\n";
  if (b.absorption_at) os << "                         " << attained_text(*b.absorption_at, d, t_unit) << "\n";
  os << "  containment guarantee  " << (b.containment ? extreme_text(*b.containment, d, u) : "not started (interrupted)") << "\n"
     << "                         every n of the band keeps H_q >= this on [0, T] (the lowest minimum)\n";
  if (b.containment_at) os << "                         " << attained_text(*b.containment_at, d, t_unit) << "\n";
  if (b.below) {
    const band_first_below& f = *b.below;
    os << "  first time H_q <= " << level_text(a, u) << (f.never ? "\n  never                  " + f.reason + "\n" : "");
    if (!f.never) {
      os << "\n                         t = ";
      if (f.settled) os << plain(*f.time.rounded(d)) << t_unit;
      else {
        const auto [lo, hi] = f.time.outward(d);
        os << "in [" << plain(lo) << ", " << plain(hi) << "]" << t_unit << " (" << (f.interrupted ? "interrupted" : "not settled: " + f.unsettled_reason) << ")";
      }
      os << ": every n of the band has H_q <= E by then (the latest first time)\n";
      if (b.below_at) os << "                         " << attained_text(*b.below_at, d, t_unit) << "\n";
    }
  }
  const bool settled = b.absorption.settled && (!b.containment || b.containment->settled) && (!b.below || b.below->settled);
  os << "  proof                  " << band_theorem_id << ": "
     << b.absorption.intervals + (b.containment ? b.containment->intervals : 0) + (b.below ? b.below->intervals : 0)
     << " intervals of the band, "
     << b.absorption.couplings + (b.containment ? b.containment->couplings : 0) + (b.below ? b.below->couplings : 0)
     << " couplings proved by the horizon theorem; "
     << (b.interrupted ? "interrupted: the brackets reached so far, proved, rounded outward\n"
                       : std::to_string(d) + " digits, each the correct rounding of a proved enclosure" +
                             (settled ? "\n" : " where settled, else a proved bracket\n"));
  return os.str();
}

// Progress of a band proof on stderr once it has run for a second: a redrawn line on a terminal
// (cleared at the end), otherwise a plain line then and every 10 s.
class band_progress_printer {
 public:
  band_progress_printer() : tty_(::isatty(2) == 1), start_(std::chrono::steady_clock::now()) {}
  ~band_progress_printer() {
    if (tty_ && drawn_) std::fputs("\r\x1b[K", stderr);
  }
  band_progress_printer(const band_progress_printer&) = delete;
  band_progress_printer& operator=(const band_progress_printer&) = delete;
  void operator()(const band_progress& p) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (t < 1 || (drawn_ && t - last_ < (tty_ ? 0.2 : 10.0))) return;
    last_ = t;
    char line[200];
    std::snprintf(line, sizeof line, "gyrores coupling: %s in [%.6e, %.6e]  %zu intervals, %zu couplings  %.0f s", p.what, p.lo,
                  p.hi, p.intervals, p.couplings, t);
    if (tty_) std::fprintf(stderr, "\r%s\x1b[K", line);
    else std::fprintf(stderr, "%s\n", line);
    std::fflush(stderr);
    drawn_ = true;
  }

 private:
  bool tty_;
  std::chrono::steady_clock::time_point start_;
  bool drawn_ = false;
  double last_ = 0;
};

// The band proofs of --band/--tolerance, with progress; Ctrl-C stops them with the bracket so far.
app::band_result run_band(app::band_request& q, signal_scope& signals, bool quiet) {
  q.stop = signals.token();
  band_progress_printer printer;
  if (!quiet) q.progress = [&printer](const band_progress& p) { printer(p); };
  return app::run_band(q);
}

// The CLI's spelling of each argument in a conflict's one-line message (app/coupling_input.hpp).
const app::coupling_names cli_names{"N", "--n2 P/Q", "--pair TAU SIGMA", "--mass, --stiffness, --gyro, --velocity",
                                    "--qdot0", "--horizon", "--horizon-s", "--band", "--tolerance", "--certificate"};

// Every argument parsed (each parser names its flag), then the coupling, its units, the horizon
// and the band chosen by the app layer. A plant is the four flags --mass, --stiffness, --gyro,
// --velocity together.
unit_choice units_of(const coupling_args& a) {
  app::coupling_given g;
  if (!a.n.empty()) g.n = parse_rational(a.n, "N");
  if (!a.n2.empty()) g.n2 = parse_rational(a.n2, "--n2");
  if (!a.pair.empty()) {
    if (a.pair.size() != 2) throw usage_error("--pair takes two integers TAU SIGMA, got " + std::to_string(a.pair.size()) + " values");
    g.pair = parse_pair_arguments(a.pair[0], a.pair[1]);
  }
  const std::string* plant_flags[4] = {&a.mass, &a.stiffness, &a.gyro, &a.velocity};
  static const std::string names[4] = {"--mass", "--stiffness", "--gyro", "--velocity"};
  int plant_given = 0;
  for (const std::string* f : plant_flags) plant_given += int(!f->empty());
  if (plant_given > 0 && plant_given < 4)
    for (int i = 0; i < 4; ++i)
      if (plant_flags[i]->empty())
        throw usage_error("a plant needs --mass, --stiffness, --gyro and --velocity: " + names[i] + " is missing");
  if (plant_given == 4) {
    check_digits_flag(a.digits, 1, int(app::coupling_digits_max));  // the plant's numbers are printed at --digits
    g.plant = parse_plant(a.mass, a.stiffness, a.gyro, a.velocity, names);
    g.digits = unsigned(a.digits);
  }
  if (!a.qdot0.empty()) g.qdot0 = parse_qdot0(a.qdot0, "--qdot0");
  if (!a.horizon.empty()) g.horizon = parse_horizon_time(a.horizon, "--horizon");
  if (!a.horizon_s.empty()) g.horizon_s = parse_horizon_time(a.horizon_s, "--horizon-s");
  if (!a.band.empty()) g.band = parse_band(a.band, "--band");
  g.tolerance = a.tolerance;
  g.certificate = !a.certificate.empty();
  unit_choice u;
  static_cast<app::coupling_selection&>(u) = app::select_coupling(g, cli_names);
  u.horizon_text = u.horizon_s ? a.horizon_s + " s" : (a.horizon.empty() ? "100" : a.horizon) + (u.plant ? " (model time t omega0)" : "");
  return u;
}

// The band request of --band/--tolerance: its digits are --band-digits, else --digits.
app::band_request band_request_of(const coupling_args& a, const unit_choice& u) {
  app::band_request q = app::band_request_of(u);
  q.certificate = !a.certificate.empty();
  if (q.certificate) check_output_path(a.certificate);  // before the work
  if (!a.below.empty()) q.below = parse_energy_level(a.below, "--below", u.energy_scale());
  q.digits = unsigned(a.band_digits > 0 ? a.band_digits : a.digits);
  check_flag_range(std::int64_t(q.digits), 1, std::int64_t(report_digits_max), a.band_digits > 0 ? "--band-digits" : "--digits");
  return q;
}
// A band's text or JSON; a Ctrl-C still prints the bracket reached, then exits 130.
std::string band_output(const coupling_args& a, const unit_choice& u, app::band_request& q, const std::string& note,
                        const std::string& before, json* whole, const std::string& horizon) {
  signal_scope signals;
  const app::band_result b = run_band(q, signals, a.quiet);
  // The band certificate, from the very proofs printed below (not when interrupted).
  if (b.certificate) write_file_atomically(a.certificate, certificate_text(*b.certificate));
  std::string out;
  if (!a.json) out = before + band_text(a, u, q, b, note);
  else if (whole) {
    (*whole)["band"] = app::band_result_json(q, b);
    out = json_dump(*whole) + "\n";
  } else out = json_dump(json{{"horizon", horizon}, {"theorem", band_theorem_id}, {"band", app::band_result_json(q, b)}}) + "\n";
  if (b.interrupted) throw partial_answer{out, ""};
  // A certificate asked for and not written says so on the one stderr line.
  const std::string no_certificate =
      a.certificate.empty() || b.certificate ? "" : "; no certificate written to " + a.certificate;
  for (const std::string* why : {&b.absorption.unsettled_reason, b.containment ? &b.containment->unsettled_reason : nullptr,
                                 b.below ? &b.below->unsettled_reason : nullptr})
    if (why && !why->empty()) throw partial_answer{out, *why + no_certificate};
  return out;
}

std::string run_coupling(const coupling_args& a) {
  const unit_choice u = units_of(a);
  // The horizon as the JSON states it: as given, or the model's horizon of --horizon-s.
  const std::string horizon = u.horizon_s ? u.horizon.str() : a.horizon.empty() ? "100" : a.horizon;
  // --tolerance around an irrational n: the band's ends are rounded outward.
  const std::string note =
      u.band_outward ? "this band contains the band n (1 -+ " + a.tolerance + ") asked, n = " + u.coupling +
                           " irrational: its ends are rounded outward (exact: --json); the guarantees of a band hold for every band inside it"
                     : "";
  if (!u.spec) {  // a band alone
    app::band_request q = band_request_of(a, u);
    return band_output(a, u, q, note, "", nullptr, horizon);
  }
  // With a band, --certificate is the band's certificate (both guarantees), refused before the work.
  const bool band_certificate = u.band && !a.certificate.empty();
  check_digits_flag(a.digits, 1, int(app::coupling_digits_max));
  check_flag_range(a.convergents, 0, std::int64_t(app::coupling_convergents_max), "--convergents");
  app::coupling_request request = app::coupling_request_of(u);
  coupling_report_options& opt = request.options;
  if (!a.below.empty()) opt.below = parse_energy_level(a.below, "--below", u.energy_scale());
  opt.digits = unsigned(a.digits);
  opt.convergents = std::size_t(a.convergents);
  request.certificate = !a.certificate.empty() && !band_certificate;
  if (band_certificate) {
    check_output_path(a.certificate);
    check_certificate_horizon(opt.horizon, "a band certificate");
  }
  if (request.certificate) {  // before the work
    check_output_path(a.certificate);
    check_certificate_horizon(opt.horizon);
  }
  const app::coupling_result result = app::run_coupling(request);
  const coupling_report& r = result.report;
  if (result.certificate) write_file_atomically(a.certificate, certificate_text(*result.certificate));
  json input = !a.n.empty() ? json{{"n", a.n}} : !a.n2.empty() ? json{{"n2", a.n2}} : json::object();
  if (!a.pair.empty()) input["pair"] = json::array({a.pair[0], a.pair[1]});
  if (u.plant) input = json{{"mass", a.mass}, {"stiffness", a.stiffness}, {"gyro", a.gyro}, {"velocity", a.velocity}};
  json j = coupling_report_json(input, horizon, unsigned(a.digits), r);
  app::add_units_json(j, u, a.horizon_s.empty() ? std::nullopt : std::optional<std::string>(a.horizon_s),
                      a.below.empty() ? std::nullopt : std::optional<std::string>(a.below));
  if (u.band) {
    app::band_request q = band_request_of(a, u);
    return band_output(a, u, q, note, coupling_text(a, u, r), &j, horizon);
  }
  if (!a.json) return coupling_text(a, u, r);
  return json_dump(j) + "\n";
}

command_runner install_coupling(CLI::App& app) {
  auto a = std::make_shared<coupling_args>();
  auto sub = options(app).subcommand("coupling", "Any coupling n: resonance test, min of H_q over a horizon, resonant approximations");
  sub.add("N", a->n, "the coupling n: decimal (0.25, 1e-3) or fraction (1/4)");
  sub.add("--n2", a->n2, "the square n^2 as a fraction or decimal (e.g. 1/12 for n = 1/sqrt(12))");
  sub.add("--pair", a->pair, "TAU SIGMA: the coupling of a resonant pair, n^2 = (tau - sigma)^2/(tau sigma) (e.g. with --tolerance)");
  sub.add("--qdot0", a->qdot0, "impulse amplitude qdot0 = q'(0) > 0 (exact decimal or fraction; default 1): energies scale by qdot0^2, radii by qdot0, times not");
  sub.add("--horizon", a->horizon, "horizon T: minimum of H_q over [0, T] (decimal, 1e30, fraction, or 100pi; model time t omega0; default 100)");
  sub.add("--mass", a->mass, "a physical plant (docs/units.md): the modes' mass m in kg (with --stiffness, --gyro, --velocity; instead of N)");
  sub.add("--stiffness", a->stiffness, "the plant's stiffness k in N/m");
  sub.add("--gyro", a->gyro, "the plant's gyroscopic coefficient g in N s/m: n = g/sqrt(m k)");
  sub.add("--velocity", a->velocity, "the plant's initial velocity q'(0) = V in m/s (an impulse J gives V = J/m): energies in J, times in s");
  sub.add("--horizon-s", a->horizon_s, "with a plant: the horizon in seconds (instead of --horizon)");
  sub.add("--certificate", a->certificate, "write a certificate of the horizon minimum (and --below) to FILE, or with --band/--tolerance the band's (both guarantees): gyrores check FILE");
  sub.add("--band", a->band, "a band of couplings N1:N2: its absorption and containment guarantees over [0, T], proved (N optional)");
  sub.add("--tolerance", a->tolerance, "the band n (1 -+ P%) around N, sqrt(--n2), --pair's n or the plant's n = g/sqrt(m k), e.g. 1% (n irrational: ends rounded outward)");
  sub.add("--band-digits", a->band_digits, "digits of the band's guarantees (default: --digits)");
  sub.add("--below", a->below, "level E: the first time H_q <= E (an energy at this qdot0, in J with a plant, or a percentage of H_q(0) = qdot0^2/2: 1%); with a band, the latest over the band");
  sub.add("--convergents", a->convergents, "how many convergents of W1/W2 (0..60)", show::with_default);
  add_digits_option(sub, a->digits);
  add_json_flag(sub, a->json);
  sub.flag("--quiet", a->quiet, "no progress on stderr (band proofs)");
  return [a] { return run_coupling(*a); };
}

const command_registration registration{"coupling", install_coupling};

}  // namespace
}  // namespace gyrores::cli
