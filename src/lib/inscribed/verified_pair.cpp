// include/gyrores/inscribed/verified_pair.hpp
#include <gyrores/inscribed/verified_pair.hpp>

#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/core/rational.hpp>
#include <gyrores/core/verified_digits.hpp>

namespace gyrores {
namespace {

// Beyond 2^900 the pair's integers leave double's (and float128's) exponent range; well before,
// the quantities do: r_res falls like a^-2.5 (x near 1), h_min like its square, and the
// asymptotics work with x^2 ~ a^-2 (TOMS 748 on denormals failed at a ~ 1e160). From 2^180 on
// every run is MPFR, whose exponent range holds them all.
bool pair_needs_mpfr(const resonant_pair<big_int>& p) { return boost::multiprecision::msb(p.order()) > 180; }

// f(p) with p as 64-bit integers when they fit (the fast path), else as big integers.
template <class F> auto with_pair_integer(const resonant_pair<big_int>& p, F&& f) {
  if (pair_fits_int64(p)) return f(pair_cast<std::int64_t>(p));
  return f(p);
}

// The fields whose exact value follows from the integers (and qdot0's decimal text), as exact
// rationals: they are rounded once from that value (format_rational_scientific, ties to even),
// never verified in floating point (an exact value on a rounding boundary, such as the beat
// ratio 2305843009213693950 at 18 digits, could never pass Ziv's test). beat_ratio = a/b always;
// qdot0 when its text is an exact decimal; n = b/sqrt(tau sigma) and rho0 = qdot0 sqrt(tau
// sigma)/a when tau sigma is a square; omega1 = sqrt(tau/sigma), omega2 = 1/omega1 when tau and
// sigma are squares (coprime); h_z_max = qdot0^2/2 for degenerate pairs (r_res = h_min = 0).
using exact_fields = std::map<std::string, big_rational>;

exact_fields exact_fields_of(const resonant_pair<big_int>& p, const std::string& qdot0) {
  exact_fields e;
  const big_int a = p.order(), b = big_int(p.delta()), tau = p.tau(), sigma = p.sigma();
  e["beat_ratio"] = big_rational(a, b);
  std::optional<big_rational> v;
  try {
    v = parse_rational(qdot0, "qdot0");
  } catch (const usage_error&) {
    // A decimal form parse_rational does not take (e.g. "1e999999"): qdot0 stays a float field.
  }
  if (v) e["qdot0"] = *v;
  big_int rts, rt, rs;
  if (int_is_square(big_int(tau * sigma), rts)) {
    e["n"] = big_rational(b, rts);
    if (v) e["rho0"] = *v * big_rational(rts, a);
  }
  if (int_is_square(tau, rt) && int_is_square(sigma, rs)) {
    e["omega1"] = big_rational(rt, rs);
    e["omega2"] = big_rational(rs, rt);
  }
  if (p.degenerate() && v) e["h_z_max"] = *v * *v / 2;
  return e;
}

// Diagnostics (core/verified_digits.hpp): the paper's asymptotics, which are approximations
// compared with the answer, not the answer; they never block it.
bool is_diagnostic_field(const std::string& name) {
  return name.rfind("asy.", 0) == 0 || name == "r_res_asy" || name == "r_res_asy_rel_error";
}

// Which fields a run reports: all of analyse_pair's, or the verified_pair_values subset.
enum class field_set { values, full };

template <class T> void put_asymptotic_fields(real_fields& f, const asymptotic_report<T>& asy) {
  for (std::size_t i = 0; i < asy.lobes.size(); ++i) {
    const auto& lo = asy.lobes[i];
    const std::string pre = "asy." + std::to_string(i) + ".";
    for (auto [name, val] : {std::pair{"s", &lo.s}, {"u_asy", &lo.u_asy}, {"theta_asy", &lo.theta_asy},
                             {"theta_c", &lo.theta_c}, {"error", &lo.error}, {"bound", &lo.bound}, {"ratio", &lo.ratio}})
      put_field(f, pre + name, *val);
  }
  if (asy.applicable) {
    put_field(f, "r_res_asy", asy.r_res_asy);
    put_field(f, "r_res_asy_rel_error", asy.r_res_asy_rel_error);
  }
}

// The floating fields of a run: every field of `set` but the exact ones (exact_fields_of).
// Without the asymptotics (`with_asymptotics` false) once a run could not compute them.
template <class T>
real_fields analysis_fields(const pair_analysis<T>& a, field_set set, const exact_fields& exact,
                            bool with_asymptotics) {
  real_fields f;
  put_field(f, "n", a.n);
  put_field(f, "r_res", a.inscribed.r_res);
  put_field(f, "h_min", a.inscribed.h_min);
  put_field(f, "theta_first", a.inscribed.theta_first);
  put_field(f, "t_first", a.inscribed.t_first);
  put_field(f, "t_min_paper", a.t_min_paper);
  if (set == field_set::values) {
    for (const auto& [name, value] : exact) f.erase(name);
    return f;
  }
  put_field(f, "beat_ratio", a.beat_ratio);
  put_field(f, "omega1", a.omega1);
  put_field(f, "omega2", a.omega2);
  put_field(f, "rho0", a.rho0);
  put_field(f, "qdot0", a.qdot0);
  put_field(f, "h_z_max", a.inscribed.h_z_max);
  for (const auto& m : a.inscribed.minimisers) f["minimisers"].push_back(real_to_mpfr(m));
  if (with_asymptotics) put_asymptotic_fields(f, a.asymptotic);
  for (const auto& [name, value] : exact) f.erase(name);
  return f;
}

// r_res_asy_rel_error = |r_res_asy - r_res|/r_res of a non-degenerate pair is never zero, but
// both runs print 0 when r_res_asy and r_res round alike in each (they agree to 1e-900 for some
// pairs): a shared rounding that Ziv's test, which takes an exact zero as settled, cannot see. It
// is then reported as the estimated bound 2^-(bits - 12) of the plan's run (bits: its precision),
// with no digit settled.
void bound_cancelled_zero(verified_run& run) {
  auto it = run.fields.find("r_res_asy_rel_error");
  if (it == run.fields.end() || run.unsettled.count(it->first)) return;
  scoped_digits sd(30);
  if (mpfr_real(it->second.at(0)) != 0) return;
  it->second = {format_scientific(ldexp(mpfr_real(1), -int(run.plan.bits) + 12), 2, MPFR_RNDU)};
  run.unsettled[it->first] = 0;
}

// analyse_pair in each plan's type, verified. The cross-check (it runs in double whatever the
// plan) is done in the first run only; cross_checked says whether it was.
// The exact fields are left out of the runs and added to the result, rounded once. When a run
// cannot compute the asymptotics (a diagnostic), asymptotic_failure says why and every later
// run leaves them out (the check run's lack drops them from the result).
verified_run verified_analysis(const resonant_pair<big_int>& p, unsigned digits, const std::string& qdot0,
                               const analysis_options& opt, field_set set, bool& cross_checked,
                               std::string& asymptotic_failure) {
  const exact_fields exact = exact_fields_of(p, qdot0);
  bool first = true;
  auto compute = [&](const precision_plan& plan) {
    analysis_options o = opt;
    if (!first) o.cross_check_max_order = 0;
    real_fields f = with_real_type(plan, [&](auto tag) {
      using T = decltype(tag);
      const T v = real_from_decimal<T>(qdot0, "qdot0");
      return with_pair_integer(p, [&](const auto& pp) {
        auto a = analyse_pair<T>(pp, v, o);
        if (first && a.cross_checked) cross_checked = true;
        if (asymptotic_failure.empty()) asymptotic_failure = a.asymptotic_failure;
        return analysis_fields(a, set, exact, asymptotic_failure.empty());
      });
    });
    first = false;
    return f;
  };
  verified_run run = compute_verified(digits, pair_needs_mpfr(p), compute, is_diagnostic_field);
  for (const auto& [name, value] : exact)
    if (set == field_set::full || name == "n") run.fields[name] = {format_rational_scientific(value, digits)};
  if (!p.degenerate()) bound_cancelled_zero(run);
  return run;
}

// The integer and boolean parts of the asymptotics (precision independent): in double, or in
// MPFR at 40 digits beyond double's range.
struct asymptotic_exact {
  bool applicable = false;
  std::string reason;
  std::vector<verified_asymptotic_lobe> lobes;  // k, m, holds_global_min only
};

template <class T> asymptotic_exact exact_part(const asymptotic_report<T>& rep) {
  asymptotic_exact e;
  e.applicable = rep.applicable;
  e.reason = rep.reason;
  for (const auto& lo : rep.lobes) {
    verified_asymptotic_lobe l;
    l.k = lo.k.str();
    l.m = lo.m.str();
    l.holds_global_min = lo.holds_global_min;
    e.lobes.push_back(l);
  }
  return e;
}

asymptotic_exact asymptotic_exact_of(const resonant_pair<big_int>& p) {
  if (pair_needs_mpfr(p)) {
    scoped_digits sd(40);
    return exact_part(paper_asymptotics<mpfr_real>(p, mpfr_real(1)));
  }
  return with_pair_integer(p, [](const auto& pp) { return exact_part(paper_asymptotics<double>(pp, 1.0)); });
}

// The asymptotics of the report: the exact parts merged with the verified reals; when they could
// not be computed (a diagnostic: never an error), not applicable, with the reason.
void set_asymptotics(verified_pair_report& r, const resonant_pair<big_int>& p, const verified_run& run,
                     const std::string& failure);

const std::string& first_value(const verified_run& run, const std::string& name) { return run.fields.at(name).at(0); }

// The lobes' verified reals ("asy.<i>.<name>") merged into their exact parts.
std::vector<verified_asymptotic_lobe> merged_lobes(const verified_run& run, std::vector<verified_asymptotic_lobe> lobes) {
  std::size_t count = 0;
  while (run.fields.count("asy." + std::to_string(count) + ".theta_asy")) ++count;
  if (count != lobes.size())
    throw compute_error("the asymptotic lobes differ between double (" + std::to_string(lobes.size()) +
                        ") and the working precision (" + std::to_string(count) + ")");
  for (std::size_t i = 0; i < count; ++i) {
    const std::string pre = "asy." + std::to_string(i) + ".";
    auto& l = lobes[i];
    for (auto [name, val] : {std::pair{"s", &l.s}, {"u_asy", &l.u_asy}, {"theta_asy", &l.theta_asy},
                             {"theta_c", &l.theta_c}, {"error", &l.error}, {"bound", &l.bound}, {"ratio", &l.ratio}})
      *val = first_value(run, pre + name);
  }
  return lobes;
}

void fill_pair_report(verified_pair_report& r, const verified_run& run) {
  for (auto [name, val] : {std::pair{"beat_ratio", &r.beat_ratio}, {"n", &r.n}, {"omega1", &r.omega1},
                           {"omega2", &r.omega2}, {"rho0", &r.rho0}, {"qdot0", &r.qdot0}, {"r_res", &r.r_res},
                           {"h_min", &r.h_min}, {"h_z_max", &r.h_z_max}, {"theta_first", &r.theta_first},
                           {"t_first", &r.t_first}, {"t_min_paper", &r.t_min_paper}})
    *val = first_value(run, name);
  r.minimisers = run.fields.at("minimisers");
  if (run.fields.count("r_res_asy")) {
    r.r_res_asy = first_value(run, "r_res_asy");
    r.r_res_asy_rel_error = first_value(run, "r_res_asy_rel_error");
  }
  for (const auto& [name, settled] : run.unsettled)
    r.unsettled[name.rfind("asy.", 0) == 0 ? "asymptotic.lobes." + name.substr(4) : name] = settled;
}

std::string method_of(const resonant_pair<big_int>& p, solver_choice solver) {
  if (p.degenerate()) return method_name(inscribed_method::degenerate_exact);
  return method_name(solver == solver_choice::lattice ? inscribed_method::lattice : inscribed_method::global_search);
}

template <class T, pair_integer I> real_fields paper_lobe_fields(const resonant_pair<I>& p, const big_int& k) {
  real_fields f;
  const auto rep = paper_asymptotics<T>(p, T(1));
  const auto c = resonant_constants_of<T>(p, T(1));
  for (const auto& l : rep.lobes) {
    if (l.k != k) continue;
    put_field(f, "u_asy", l.u_asy);
    put_field(f, "theta_asy", l.theta_asy);
    put_field(f, "qdot_asy", l.qdot_asy);
    put_field(f, "qdot_asy_rho0", T(l.qdot_asy / c.rho0));
    put_field(f, "error", l.error);
    put_field(f, "bound", l.bound);
    put_field(f, "theta_c", l.theta_c);
    put_field(f, "r_c", l.r_c);
  }
  return f;
}

void set_asymptotics(verified_pair_report& r, const resonant_pair<big_int>& p, const verified_run& run,
                     const std::string& failure) {
  std::string why = failure;
  if (why.empty()) {
    try {
      asymptotic_exact exact = asymptotic_exact_of(p);
      r.lobes = merged_lobes(run, std::move(exact.lobes));
      r.asymptotic_applicable = exact.applicable;
      r.asymptotic_reason = exact.reason;
      return;
    } catch (const compute_error& e) {
      why = e.what();
    }
  }
  r.asymptotic_applicable = false;
  r.asymptotic_reason = "the asymptotics could not be computed (" + why + ")";
  r.lobes.clear();
  r.r_res_asy.reset();
  r.r_res_asy_rel_error.reset();
  for (auto it = r.unsettled.begin(); it != r.unsettled.end();)
    it = (is_diagnostic_field(it->first) || it->first.rfind("asymptotic.", 0) == 0) ? r.unsettled.erase(it)
                                                                                    : std::next(it);
}

}  // namespace

void check_qdot0_text(const std::string& text, const std::string& what) {
  scoped_digits d(30);
  const mpfr_real v = real_from_decimal<mpfr_real>(text, what);
  if (!(v > 0)) throw usage_error(what + " must be > 0, got " + text);
}

verified_pair_report verify_pair(const resonant_pair<big_int>& p, const verified_pair_options& opt) {
  check_verified_digits(opt.digits);
  check_qdot0_text(opt.qdot0, "qdot0");
  analysis_options analysis;
  analysis.solver = opt.solver;
  analysis.cross_check_max_order = opt.cross_check_max_order;
  verified_pair_report r;
  std::string asymptotic_failure;
  const verified_run run =
      verified_analysis(p, opt.digits, opt.qdot0, analysis, field_set::full, r.cross_checked, asymptotic_failure);
  fill_pair_report(r, run);
  set_asymptotics(r, p, run, asymptotic_failure);
  r.degenerate = p.degenerate();
  r.method = method_of(p, opt.solver);
  r.digits = opt.digits;
  r.working_precision = run.plan;
  return r;
}

verified_pair_values verify_pair_values(const resonant_pair<big_int>& p, unsigned digits) {
  check_verified_digits(digits);
  verified_pair_values v;
  std::string asymptotic_failure;  // the values set has no asymptotics
  const verified_run run =
      verified_analysis(p, digits, "1", analysis_options{}, field_set::values, v.cross_checked, asymptotic_failure);
  for (auto [name, val] : {std::pair{"n", &v.n}, {"r_res", &v.r_res}, {"h_min", &v.h_min}, {"t_first", &v.t_first},
                           {"theta_first", &v.theta_first}, {"t_min_paper", &v.t_min_paper}})
    *val = first_value(run, name);
  v.degenerate = p.degenerate();
  return v;
}

verified_pair_values verify_pair_values(std::int64_t tau, std::int64_t sigma, unsigned digits) {
  return verify_pair_values(resonant_pair<big_int>(big_int(tau), big_int(sigma)), digits);
}

verified_paper_lobe verify_paper_lobe(const resonant_pair<big_int>& p, const big_int& k, unsigned digits) {
  check_verified_digits(digits);
  const verified_run run = compute_verified_per_type(digits, pair_needs_mpfr(p), [&](auto tag) {
    using T = decltype(tag);
    return with_pair_integer(p, [&](const auto& pp) { return paper_lobe_fields<T>(pp, k); });
  });
  if (run.fields.empty()) throw compute_error("pair " + p.str() + " has no asymptotic lobe k = " + k.str());
  verified_paper_lobe l;
  for (auto [name, val] : {std::pair{"u_asy", &l.u_asy}, {"theta_asy", &l.theta_asy}, {"qdot_asy", &l.qdot_asy},
                           {"qdot_asy_rho0", &l.qdot_asy_over_rho0}, {"error", &l.error}, {"bound", &l.bound},
                           {"theta_c", &l.theta_c}, {"r_c", &l.r_c}})
    *val = first_value(run, name);
  return l;
}

}  // namespace gyrores
