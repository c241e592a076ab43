#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace gyrores::bench {

namespace {

bool has(double v) { return v == v; }

const measurement* find_row(const std::vector<measurement>& rows, const std::string& method, const std::string& prec,
                            const std::string& pair) {
  for (const auto& m : rows)
    if (!m.failed && m.method == method && m.precision == prec && m.pair == pair && has(m.median_ns)) return &m;
  return nullptr;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string ratio_text(double r) {
  if (r >= 100) return fmt("%.0fx", r);
  if (r >= 10) return fmt("%.1fx", r);
  return fmt("%.2fx", r);
}

// "1.234...e-05" -> the first 30 significant digits and the exponent.
std::string short_decimal(const std::string& v) {
  const auto e = v.find_first_of("eE");
  const std::string mant = v.substr(0, e), ex = e == std::string::npos ? "" : v.substr(e);
  return mant.substr(0, std::min<std::size_t>(mant.size(), 31)) + "…" + ex;
}

std::ofstream open_out(const std::string& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  return f;
}

}  // namespace

std::string format_time(double ns) {
  if (!has(ns)) return "n/a";
  if (ns < 999.5) return fmt("%.3g ns", ns);
  if (ns < 999.5e3) return fmt("%.3g µs", ns / 1e3);
  if (ns < 999.5e6) return fmt("%.3g ms", ns / 1e6);
  return fmt("%.3g s", ns / 1e9);
}

std::string format_digits(double d) { return has(d) ? fmt("%.1f", d) : ""; }

std::map<const measurement*, double> ratios_to_best(const std::vector<measurement>& rows,
                                                   const std::vector<precision>& precisions) {
  std::map<std::pair<std::string, std::string>, std::vector<const measurement*>> groups;
  for (const auto& m : rows)
    if (!m.failed && has(m.median_ns)) groups[{m.pair, m.precision}].push_back(&m);
  std::map<const measurement*, double> out;
  for (auto& [key, g] : groups) {
    double nominal = 1e9;
    for (const auto& pr : precisions)
      if (pr.name == key.second) nominal = pr.digits;
    double top = -1;
    for (auto* m : g)
      if (has(m->digits())) top = std::max(top, m->digits());
    const double target = std::min(nominal, top) - 1;
    double best = -1;
    for (auto* m : g)
      if (has(m->digits()) && m->digits() >= target && (best < 0 || m->median_ns < best)) best = m->median_ns;
    if (best <= 0) continue;
    for (auto* m : g) out[m] = m->median_ns / best;
  }
  return out;
}

std::vector<headline> compute_headlines(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  std::vector<headline> out;
  {
    headline h{"H1", "Exact r_res in double costs at most 2x the paper's asymptotic theta_asy alone, for every pair size",
               {}, 0, 0, ""};
    for (const auto& bp : pairs) {
      const auto* e = find_row(rows, "exact", "double", bp.name);
      const auto* t = find_row(rows, "theta_asy", "double", bp.name);
      if (!e) continue;
      if (!t) {
        h.values.push_back({bp.name, "n/a: theta_asy undefined for x >= 1/2 (exact " + format_time(e->median_ns) + ")"});
        continue;
      }
      const double r = e->median_ns / t->median_ns;
      ++h.total;
      if (r <= 2) ++h.met;
      h.values.push_back({bp.name, ratio_text(r) + " (exact " + format_time(e->median_ns) + ", theta_asy " +
                                       format_time(t->median_ns) + ")"});
    }
    // Where the time goes: the exact method's own q' evaluations against its total.
    std::vector<double> share;
    for (const auto& bp : pairs) {
      const auto* e = find_row(rows, "exact", "double", bp.name);
      const auto* o = find_row(rows, "one_eval", "double", bp.name);
      if (e && o && e->evaluations) share.push_back(double(*e->evaluations) * o->median_ns / e->median_ns);
    }
    if (!share.empty()) {
      std::sort(share.begin(), share.end());
      h.remark = "In double the exact method's own evaluations of q' (its evals x one_eval) are " +
                 fmt("%.0f", 100 * share.front()) + "-" + fmt("%.0f", 100 * share.back()) +
                 "% of its time; the rest is fixed cost (integer lattice arithmetic, constants, the minimiser list).";
    }
    out.push_back(h);
  }
  {
    headline h{"H2a", "At 1000 digits, exact r_res costs at most 4x one evaluation of (q, q') at that precision", {}, 0, 0, ""};
    for (const auto& bp : pairs) {
      const auto* e = find_row(rows, "exact", "mp1000", bp.name);
      const auto* o = find_row(rows, "one_eval", "mp1000", bp.name);
      if (!e || !o) continue;
      const double r = e->median_ns / o->median_ns;
      ++h.total;
      if (r <= 4) ++h.met;
      h.values.push_back({bp.name, ratio_text(r) + " (exact " + format_time(e->median_ns) + ", one evaluation " +
                                       format_time(o->median_ns) + ")"});
    }
    out.push_back(h);
  }
  {
    headline h{"H2b", "At 1000 digits, exact r_res is at least 5x faster than plain TOMS748 on the naive formulation",
               {}, 0, 0, ""};
    for (const auto& bp : pairs) {
      const auto* e = find_row(rows, "exact", "mp1000", bp.name);
      const auto* n = find_row(rows, "naive_toms748", "mp1000", bp.name);
      if (!e || !n) continue;
      const double r = n->median_ns / e->median_ns;
      ++h.total;
      if (r >= 5) ++h.met;
      h.values.push_back({bp.name, ratio_text(r) + " (naive " + format_time(n->median_ns) + " with " +
                                       format_digits(n->digits()) + " digits; exact " + format_time(e->median_ns) +
                                       " with " + format_digits(e->digits()) + ")"});
    }
    out.push_back(h);
  }
  {
    headline h{"H3",
               "Against time-domain simulation reaching 1e-8 relative error in r_res, gyrores (exact, double) is at "
               "least 1000x faster and reaches full precision",
               {}, 0, 0, ""};
    for (const auto& bp : pairs) {
      const auto* e = find_row(rows, "exact", "double", bp.name);
      if (!e) continue;
      const measurement* best = nullptr;
      bool any = false;
      for (const auto& m : rows) {
        if (m.failed || m.pair != bp.name || m.method.rfind("odeint_", 0) != 0 || !has(m.median_ns)) continue;
        any = true;
        if (has(m.digits_r) && m.digits_r >= 8 && (!best || m.median_ns < best->median_ns)) best = &m;
      }
      if (!any) continue;
      ++h.total;
      if (!best) {
        h.values.push_back({bp.name, "no simulation setting reached 1e-8 in r_res"});
        continue;
      }
      const double r = best->median_ns / e->median_ns;
      const bool full = e->digits() >= 14.5;
      if (r >= 1000 && full) ++h.met;
      h.values.push_back({bp.name, ratio_text(r) + " (" + best->method + ": " + format_time(best->median_ns) + ", " +
                                       format_digits(best->digits_r) + " digits in r_res; exact " +
                                       format_time(e->median_ns) + ", " + format_digits(e->digits()) + " digits)"});
    }
    out.push_back(h);
  }
  {
    headline h{"H4", "Certified r_res at 30 digits costs at most 5x uncertified (exact at 30 digits)", {}, 0, 0, ""};
    for (const auto& bp : pairs) {
      const auto* c = find_row(rows, "certified", "mp30", bp.name);
      const auto* e = find_row(rows, "exact", "mp30", bp.name);
      if (!c || !e) continue;
      const double r = c->median_ns / e->median_ns;
      ++h.total;
      if (r <= 5) ++h.met;
      h.values.push_back({bp.name, ratio_text(r) + " (certified " + format_time(c->median_ns) + ", exact " +
                                       format_time(e->median_ns) + ")"});
    }
    out.push_back(h);
  }
  {
    headline h{"H5",
               "At 1000 and 10000 digits, exact theta and r_res together in at most 1.5x the time Arb takes to refine "
               "the root alone",
               {}, 0, 0, ""};
    for (const char* prec : {"mp1000", "mp10000"})
      for (const auto& bp : pairs) {
        const auto* e = find_row(rows, "exact", prec, bp.name);
        const auto* a = find_row(rows, "arb_newton", prec, bp.name);
        if (!e || !a) continue;
        const double r = e->median_ns / a->median_ns;
        ++h.total;
        if (r <= 1.5) ++h.met;
        h.values.push_back({bp.name + " " + prec, ratio_text(r) + " (exact " + format_time(e->median_ns) + ", Arb " +
                                                      format_time(a->median_ns) + ")"});
      }
    // Cost in units of the library's own evaluation: MPFR one_eval against Arb's.
    for (const char* prec : {"mp1000", "mp10000"}) {
      std::vector<double> ev_ratio, exact_units, arb_units;
      for (const auto& bp : pairs) {
        const auto* o = find_row(rows, "one_eval", prec, bp.name);
        const auto* ao = find_row(rows, "arb_one_eval", prec, bp.name);
        const auto* e = find_row(rows, "exact", prec, bp.name);
        const auto* a = find_row(rows, "arb_newton", prec, bp.name);
        if (!o || !ao || !e || !a) continue;
        ev_ratio.push_back(o->median_ns / ao->median_ns);
        exact_units.push_back(e->median_ns / o->median_ns);
        arb_units.push_back(a->median_ns / ao->median_ns);
      }
      if (ev_ratio.empty()) continue;
      auto med = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
      };
      h.remark += std::string(h.remark.empty() ? "" : " ") + "At " + prec + " (medians over the pairs): one MPFR " +
                  "evaluation (one_eval, four separate sin/cos) costs " + fmt("%.2g", med(ev_ratio)) +
                  "x one Arb evaluation (arb_one_eval, two arb_sin_cos); exact costs " + fmt("%.2g", med(exact_units)) +
                  " MPFR evaluations, Arb's refinement " + fmt("%.2g", med(arb_units)) + " Arb evaluations.";
    }
    out.push_back(h);
  }
  return out;
}

void write_csv(const std::string& path, const std::vector<measurement>& rows) {
  auto f = open_out(path);
  f << "method,precision,pair,median_ns,correct_digits,evaluations\n";
  for (const auto& m : rows) {
    f << m.method << ',' << m.precision << ',' << '"' << m.pair << '"' << ',';
    if (!m.failed && has(m.median_ns)) f << fmt("%.6g", m.median_ns);
    f << ',';
    if (has(m.digits())) f << fmt("%.2f", m.digits());
    f << ',';
    if (m.evaluations) f << *m.evaluations;
    f << '\n';
  }
}

namespace {

std::string verdict(const headline& h) {
  if (h.total == 0) return "**not measured** in this run";
  if (h.met == h.total) return "**met** for all " + std::to_string(h.total);
  if (h.met == 0) return "**not met** (0 of " + std::to_string(h.total) + ")";
  return "**not met**: " + std::to_string(h.met) + " of " + std::to_string(h.total) + " met";
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

}  // namespace

void write_markdown(const std::string& path, const run_context& ctx, const std::vector<measurement>& rows,
                    const std::vector<skip_note>& skips, const std::vector<method_def>& methods,
                    const std::vector<bench_pair>& pairs, const std::vector<precision>& precisions,
                    const std::map<std::string, reference>& refs) {
  auto f = open_out(path);
  auto ratios = ratios_to_best(rows, precisions);
  f << "# Speed against error\n\n";
  f << "Generated by `" << ctx.command << "` (bench/gyrores_bench.cpp); do not edit by hand: rerun `bench/run`.\n"
    << "Every number below was measured in one run of one process (plus the mpmath child process it\n"
    << "starts), so the ratios compare like with like on a shared, noisy machine.\n\n"
    << "Regenerate: `bench/run` (builds `gyrores-bench` if needed, then writes this file, `results.csv` and "
       "`speed_vs_error.svg`/`.png`). Quick check (< 60 s): `gyrores-bench --quick --csv FILE` or `bench/run --quick`.\n\n";
  f << "## Setup\n\n";
  f << "| | |\n|---|---|\n";
  f << "| date | " << ctx.date << " |\n";
  f << "| machine | " << ctx.cpu << ", " << ctx.cores << " logical CPUs, shared with other jobs (load average "
    << ctx.load_before << " at the start, " << ctx.load_after << " at the end) |\n";
  f << "| compiler | " << ctx.compiler << ", flags `" << ctx.flags << "` |\n";
  f << "| libraries | " << ctx.libraries << " |\n";
  f << "| mpmath peer | " << ctx.mpmath_status << " |\n";
  f << "| run time | " << fmt("%.0f", ctx.seconds) << " s for the whole run, of which " << fmt("%.0f", ctx.reference_seconds)
    << " s for the references |\n";
  f << "| inputs | fixed pairs, amplitude v = qdot0 = 1, no randomness |\n\n";
  f << "**Columns.** *time*: median over repetitions of the CPU time per call (Google Benchmark 1.7.1, thread CPU "
       "time; 5 repetitions, 3 when one call exceeds 0.5 s; each repetition runs enough calls to last about "
    << "the target time; the mpmath peer is timed inside Python with `time.process_time`, same scheme). "
       "*digits*: correct decimal digits, `-log10(|x - ref|/|ref|)`, the smallest over the quantities the method "
       "computes (theta_first and r_res; theta_c for theta_asy; theta for the root-only refiners), clipped to "
       "[0, reference digits]. *evals*: evaluations of the method's function (q' for the root solvers, u - atan(s - u) "
       "for the asymptotics, right-hand sides for the simulations; blank where not exposed). *ratio*: time over the "
       "time of the best method at the same pair and precision: the fastest whose digits are within 1 of the "
       "precision's own (16 for double, 19 long double, 34 float128, N for mpN; or of the most any method reached, if "
       "fewer). 1 = the best; a faster method with fewer digits gets a ratio below 1.\n\n";
  f << "**Reference.** tests/high_precision_reference.hpp, independent of the library's numerics: the naive "
       "formulation (sin(tau theta) formed directly) at brute precision (digits + 2 log2(a) + 96 bits), bisection then "
       "Newton with precision doubling; all 4 tau critical points for orders <= 1e5, +-4 fast half-periods around a "
       "guess and its symmetry images above. Accurate to "
    << ctx.reference_digits << " digits, i.e. beyond the most precise result measured.\n\n";

  f << "## Headline figures\n\n";
  for (const auto& h : compute_headlines(rows, pairs)) {
    f << "**" << h.id << ". " << h.target << "**: " << verdict(h) << ".\n\n";
    if (!h.remark.empty()) f << h.remark << "\n\n";
    if (!h.values.empty()) {
      f << "| pair | measured |\n|---|---|\n";
      for (const auto& [k, v] : h.values) f << "| " << k << " | " << v << " |\n";
      f << "\n";
    }
  }

  f << "## Speed against error\n\n![speed against error](speed_vs_error.svg)\n\n";
  f << "Time per call (CPU) against correct digits, one series per method, one panel per pair "
       "([PNG](speed_vs_error.png), raw data: [results.csv](results.csv)). Points at the bottom edge have no "
       "correct digit.\n\n";

  f << "## Tables\n\nEach cell: time, correct digits (d), evaluations (ev), ratio to the best. Blank: not run "
       "(see *Skipped combinations*).\n\n";
  std::vector<std::string> method_order;
  for (const auto& m : rows)
    if (std::find(method_order.begin(), method_order.end(), m.method) == method_order.end())
      method_order.push_back(m.method);
  for (const auto& pr : precisions) {
    bool any = false;
    for (const auto& m : rows) any = any || m.precision == pr.name;
    if (!any) continue;
    f << "### " << pr.name << "\n\n| method |";
    for (const auto& bp : pairs) f << " " << bp.name << " |";
    f << "\n|---|";
    for (std::size_t i = 0; i < pairs.size(); ++i) f << "---|";
    f << "\n";
    for (const auto& meth : method_order) {
      bool row_any = false;
      for (const auto& m : rows) row_any = row_any || (m.precision == pr.name && m.method == meth);
      if (!row_any) continue;
      f << "| " << meth << " |";
      for (const auto& bp : pairs) {
        const measurement* hit = nullptr;
        for (const auto& m : rows)
          if (m.precision == pr.name && m.method == meth && m.pair == bp.name) hit = &m;
        if (!hit) {
          f << " |";
          continue;
        }
        if (hit->failed) {
          f << " failed |";
          continue;
        }
        f << " " << format_time(hit->median_ns);
        if (has(hit->digits())) {
          f << "<br>" << format_digits(hit->digits()) << " d";
          if (has(hit->digits_theta) && has(hit->digits_r) && std::fabs(hit->digits_theta - hit->digits_r) >= 1)
            f << " (θ " << format_digits(hit->digits_theta) << ", r " << format_digits(hit->digits_r) << ")";
        }
        if (hit->evaluations) f << "<br>" << *hit->evaluations << " ev";
        auto it = ratios.find(hit);
        if (it != ratios.end()) f << "<br>×" << fmt(it->second >= 100 ? "%.0f" : "%.2g", it->second);
        f << " |";
      }
      f << "\n";
    }
    f << "\n";
  }

  f << "## Methods\n\n| method | what it computes |\n|---|---|\n";
  std::set<std::string> seen;
  for (const auto& m : methods) {
    std::string fam = m.family;
    if (fam.rfind("odeint", 0) == 0) {
      if (!seen.insert(fam).second) continue;
      f << "| " << fam << "(...) | " << m.description << " |\n";
      continue;
    }
    f << "| " << m.name << " | " << m.description << " |\n";
  }
  f << "| mpmath_findroot | peer (b): `mpmath.findroot(f, (x0, x1))` (default secant) on the naive q'(theta) at "
       "`mp.dps` = digits, from theta_first rounded to ceil(log10 a) + 8 digits and a point 1e-4 half-periods away "
       "(bench/mpmath_peer.py); then r = rho0 |sin tau theta + sin sigma theta| |\n\n";
  f << "Precisions: `double`, `long_double` (x87, 64-bit mantissa), `float128` (Boost.Multiprecision, libquadmath), "
       "`mpN` = N decimal digits (MPFR for gyrores and the naive peer, MPFI for certificates, Arb balls at the same "
       "number of bits, mpmath `mp.dps = N`).\n\n";
  f << "Pairs: ";
  {
    std::vector<std::string> names;
    for (const auto& bp : pairs) names.push_back(bp.name + " (" + bp.group + ")");
    f << join(names, ", ") << ". The last is beyond 64 bits.\n\n";
  }

  f << "## Skipped combinations\n\n";
  {
    // Grouped by (method family, reason); the simulation variants share one line.
    std::map<std::pair<std::string, std::string>, std::set<std::pair<std::string, std::string>>> by;
    std::vector<std::pair<std::string, std::string>> order;
    for (const auto& s : skips) {
      const auto paren = s.method.find('(');
      const std::string shown = paren == std::string::npos ? s.method : s.method.substr(0, paren) + "(...)";
      auto key = std::make_pair(shown, s.reason);
      if (!by.count(key)) order.push_back(key);
      by[key].insert({s.precision, s.pair});
    }
    auto index_of = [](const auto& list, const std::string& name) {
      for (std::size_t i = 0; i < list.size(); ++i)
        if (list[i].name == name) return i;
      return list.size();
    };
    for (const auto& key : order) {
      const auto& combos = by[key];
      std::vector<std::string> precs, prs;
      for (const auto& c : combos) {
        if (std::find(precs.begin(), precs.end(), c.first) == precs.end()) precs.push_back(c.first);
        if (std::find(prs.begin(), prs.end(), c.second) == prs.end()) prs.push_back(c.second);
      }
      std::sort(precs.begin(), precs.end(), [&](const std::string& a, const std::string& b) {
        return index_of(precisions, a) < index_of(precisions, b);
      });
      std::sort(prs.begin(), prs.end(), [&](const std::string& a, const std::string& b) {
        return index_of(pairs, a) < index_of(pairs, b);
      });
      std::string where;
      if (precs.size() * prs.size() == combos.size()) {
        where = join(precs, ", ") + " on " + (prs.size() == pairs.size() ? std::string("every pair") : join(prs, ", "));
      } else {
        std::vector<std::string> list;
        for (const auto& c : combos) list.push_back(c.first + " " + c.second);
        where = join(list, "; ");
      }
      f << "- `" << key.first << "` at " << where << ": " << key.second << ".\n";
    }
    f << "- `mpmath_findroot` runs at mp50, mp100 and mp1000 only (the issue's precisions): mpmath is arbitrary "
         "precision only, and pure-Python mpmath at 10000 digits is not a peer anyone would choose.\n\n";
  }

  std::vector<const measurement*> failed;
  for (const auto& m : rows)
    if (m.failed || !m.note.empty()) failed.push_back(&m);
  if (!failed.empty()) {
    f << "## Notes and failures\n\n| method | precision | pair | note |\n|---|---|---|---|\n";
    for (auto* m : failed) {
      if (m->note == "timed in Python (process_time)") continue;
      f << "| " << m->method << " | " << m->precision << " | " << m->pair << " | " << (m->failed ? "FAILED: " : "")
        << m->note << " |\n";
    }
    f << "\n";
  }

  f << "## References\n\n| pair | mode | r_res (30 digits) | theta_first (30 digits) | time |\n|---|---|---|---|---|\n";
  for (const auto& bp : pairs) {
    const auto& r = refs.at(bp.name);
    f << "| " << bp.name << " | " << (r.global ? "global" : "local") << " | " << short_decimal(r.r_res) << " | "
      << short_decimal(r.theta_first) << " | " << fmt("%.2f s", r.seconds) << " |\n";
  }
  f << "\n";
}

void write_plot_script(const std::string& dir, const run_context& ctx, const std::vector<measurement>& rows,
                       const std::vector<method_def>& methods, const std::vector<bench_pair>& pairs) {
  std::vector<std::string> families;
  std::map<std::string, std::string> family_of;
  for (const auto& m : methods) {
    family_of[m.name] = m.family;
    if (std::find(families.begin(), families.end(), m.family) == families.end()) families.push_back(m.family);
  }
  family_of["mpmath_findroot"] = "mpmath";
  families.push_back("mpmath");
  std::vector<std::string> panels;
  for (const char* want : {"(6,5)", "(101,100)", "(1000,1)", "(10^12+1,10^12)"})
    for (const auto& bp : pairs)
      if (bp.name == want) panels.push_back(bp.name);
  auto body = open_out(dir + "/speed_vs_error_body.gp");
  int n = 0;
  std::ostringstream plots;
  for (std::size_t pi = 0; pi < panels.size(); ++pi) {
    plots << "set title '" << panels[pi] << "'\nplot ";
    bool first = true;
    for (std::size_t fi = 0; fi < families.size(); ++fi) {
      std::vector<std::pair<double, double>> pts;
      for (const auto& m : rows) {
        if (m.failed || m.pair != panels[pi] || !has(m.median_ns) || !has(m.digits())) continue;
        auto it = family_of.find(m.method);
        if (it == family_of.end() || it->second != families[fi]) continue;
        pts.push_back({m.median_ns * 1e-9, std::max(m.digits(), 0.3)});
      }
      if (pts.empty()) continue;
      std::sort(pts.begin(), pts.end());
      const std::string block = "$d" + std::to_string(n++);
      body << block << " << EOD\n";
      for (auto& p : pts) body << fmt("%.6e", p.first) << ' ' << fmt("%.3f", p.second) << "\n";
      body << "EOD\n";
      plots << (first ? "" : ", \\\n     ") << block << " using 1:2 with linespoints ls " << fi + 1 << " title '"
            << families[fi] << "' noenhanced";
      first = false;
    }
    plots << "\n";
  }
  for (std::size_t fi = 0; fi < families.size(); ++fi)
    body << "set style line " << fi + 1 << " lc rgb '" << std::vector<std::string>{
        "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22",
        "#17becf", "#000000", "#aa0000", "#00aa88", "#0000aa"}[fi % 14]
         << "' pt " << (fi % 13) + 1 << " ps 1.1 lw 1.5\n";
  body << "set logscale xy\nset xlabel 'median CPU time per call [s]'\nset ylabel 'correct digits'\n"
       << "set format x '10^{%L}'\nset grid\nset key outside right top font ',9'\nset yrange [0.25:20000]\n";
  const std::string layout = panels.size() <= 3 ? "1," + std::to_string(panels.size()) : "2,2";
  body << "set multiplot layout " << layout << " title 'gyrores: speed against error (" << ctx.cpu << ", one run)'\n";
  body << plots.str();
  body << "unset multiplot\n";
  auto main = open_out(dir + "/speed_vs_error.gp");
  const bool wide = panels.size() <= 3;
  main << "# Generated by gyrores-bench; run with gnuplot from this directory.\n"
       << "set terminal svg size " << (wide ? "1800,600" : "1500,1000") << " dynamic font 'Helvetica,12'\n"
       << "set output 'speed_vs_error.svg'\nload 'speed_vs_error_body.gp'\n"
       << "set terminal pngcairo size " << (wide ? "1800,600" : "1500,1000") << " font 'Helvetica,10'\n"
       << "set output 'speed_vs_error.png'\nload 'speed_vs_error_body.gp'\n";
}

}  // namespace gyrores::bench
