// speed_error/report.hpp: the headline figures (L1-L2: gyrores' paths against the theorem-aware
// peers; H1-H5: the theorem's path against the methods from before it and the other peers) and
// the ratio to the best row, computed from the rows of one run.
#include <algorithm>
#include <string>

#include "report.hpp"

namespace gyrores::bench {

namespace {

const measurement* find_row(const std::vector<measurement>& rows, const std::string& method, const std::string& prec,
                            const std::string& pair) {
  for (const auto& m : rows)
    if (!m.failed && m.method == method && m.precision == prec && m.pair == pair && is_measured(m.median_ns)) return &m;
  return nullptr;
}

std::string ratio_text(double r) {
  if (r >= 100) return format_number("%.0fx", r);
  if (r >= 10) return format_number("%.1fx", r);
  return format_number("%.2fx", r);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The time ratio n/d of two rows: the median over rounds of the ratio within each round (every
// round runs each case once, so the two repetitions of a round are seconds apart at most and
// share the machine's load, which cancels; a burst that slows one method's median in one round
// and the other's in another does not). Rows without rounds (the mpmath peer, timed in its own
// process) give the ratio of the medians.
double paired_ratio(const measurement& n, const measurement& d) {
  const std::size_t k = std::min(n.round_ns.size(), d.round_ns.size());
  if (k == 0) return n.median_ns / d.median_ns;
  std::vector<double> r;
  for (std::size_t i = 0; i < k; ++i) r.push_back(n.round_ns[i] / d.round_ns[i]);
  std::sort(r.begin(), r.end());
  return k % 2 ? r[k / 2] : (r[k / 2 - 1] + r[k / 2]) / 2;
}

// The ratios time(num)/time(den) at `prec`, one per pair where both rows ran, in the pairs' order.
std::vector<double> pair_ratios(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs,
                                const std::string& num, const std::string& den, const std::string& prec) {
  std::vector<double> r;
  for (const auto& bp : pairs) {
    const auto* n = find_row(rows, num, prec, bp.name);
    const auto* d = find_row(rows, den, prec, bp.name);
    if (n && d) r.push_back(paired_ratio(*n, *d));
  }
  return r;
}

// A headline target met per pair when time(num)/time(den) <= limit (at_most) or >= limit, at
// precision `prec`: one value per pair where both rows ran, "<ratio> (<describe(num, den)>)",
// labelled by the pair name and `suffix`.
struct ratio_target {
  std::string prec, num, den;
  bool at_most;
  double limit;
  std::string suffix;
};

// A headline with no values yet.
headline new_headline(std::string id, std::string target) {
  headline h;
  h.id = std::move(id);
  h.target = std::move(target);
  return h;
}

// One more value of h, labelled `label`, which meets the target or not.
void add_value(headline& h, const std::string& label, bool met, const std::string& text) {
  ++h.total;
  if (met) ++h.met;
  h.values.push_back({label, text});
}

// The theorem's double row of a pair (the numerator or reference of most headlines).
const measurement* theorem_row(const std::vector<measurement>& rows, const bench_pair& bp) {
  return find_row(rows, "theorem_double", "double", bp.name);
}

template <class Describe>
void add_ratios(headline& h, const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs,
                const ratio_target& t, Describe describe) {
  for (const auto& bp : pairs) {
    const auto* n = find_row(rows, t.num, t.prec, bp.name);
    const auto* d = find_row(rows, t.den, t.prec, bp.name);
    if (!n || !d) continue;
    const double r = paired_ratio(*n, *d);
    add_value(h, bp.name + t.suffix, t.at_most ? r <= t.limit : r >= t.limit,
              ratio_text(r) + " (" + describe(*n, *d) + ")");
  }
}

// What the double path costs in units of one evaluation of (q, q') (one_eval), and what the
// reference lattice from before the theorem costs against it (medians over the pairs).
std::string h1_remark(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  // (theorem_row's method and precision)
  const std::vector<double> units = pair_ratios(rows, pairs, "theorem_double", "one_eval", "double");
  const std::vector<double> lattice = pair_ratios(rows, pairs, "ref_lattice", "theorem_double", "double");
  std::string out;
  if (!units.empty())
    out = "In double theorem_minimum_double takes the time of " + format_number("%.2g", median(units)) +
          " evaluations of (q, q', z, z') (one_eval, two sin_cos; median over the pairs) for the lobes by integers, "
          "u* of H(u) = x u + arctan(x tan u) = mu by expansions and Newton steps proved in double-double, r_res, "
          "theta_first and t_first within an ulp.";
  if (!lattice.empty())
    out += std::string(out.empty() ? "" : " ") + "The reference lattice from before the theorem (ref_lattice) takes " +
           format_number("%.2g", median(lattice)) + "x its time.";
  return out;
}

headline h1(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  headline h = new_headline("H1",
             "The theorem's r_res in double (theorem_minimum_double) costs at most 1.5x the paper's asymptotic "
             "theta_asy alone, for every pair size");
  for (const auto& bp : pairs) {
    const auto* e = theorem_row(rows, bp);
    const auto* t = find_row(rows, "theta_asy", "double", bp.name);
    if (!e) {
      if (t)
        h.values.push_back({bp.name, "n/a: theorem_minimum_double takes pairs of order below 2^120 (theta_asy " +
                                         format_time(t->median_ns) + ")"});
      continue;
    }
    if (!t) {
      h.values.push_back(
          {bp.name, "n/a: theta_asy undefined for x >= 1/2 (theorem " + format_time(e->median_ns) + ")"});
      continue;
    }
    const double r = paired_ratio(*e, *t);
    add_value(h, bp.name, r <= 1.5,
              ratio_text(r) + " (theorem " + format_time(e->median_ns) + ", theta_asy " + format_time(t->median_ns) +
                  ")");
  }
  h.remark = h1_remark(rows, pairs);
  return h;
}

// A headline made of add_ratios alone.
template <class Describe>
headline ratio_headline(const char* id, const char* target, const std::vector<measurement>& rows,
                        const std::vector<bench_pair>& pairs, const ratio_target& t, Describe describe) {
  headline h = new_headline(id, target);
  add_ratios(h, rows, pairs, t, describe);
  return h;
}

// "<num_label> <time>, <den_label> <time>".
auto times_of(const std::string& num_label, const std::string& den_label) {
  return [=](const measurement& n, const measurement& d) {
    return num_label + " " + format_time(n.median_ns) + ", " + den_label + " " + format_time(d.median_ns);
  };
}

std::string naive_against_proved(const measurement& n, const measurement& e) {
  return "naive " + format_time(n.median_ns) + " with " + format_digits(n.digits()) + " digits; proved " +
         format_time(e.median_ns) + " with " + format_digits(e.digits());
}

// The fastest simulation of `pair` reaching 1e-8 in r_res (nullptr if none); `any`: whether a
// simulation ran there at all.
const measurement* fastest_simulation(const std::vector<measurement>& rows, const std::string& pair, bool& any) {
  const measurement* best = nullptr;
  any = false;
  for (const auto& m : rows) {
    if (m.failed || m.pair != pair || m.method.rfind("odeint_", 0) != 0 || !is_measured(m.median_ns)) continue;
    any = true;
    if (is_measured(m.digits_r) && m.digits_r >= 8 && (!best || m.median_ns < best->median_ns)) best = &m;
  }
  return best;
}

headline h3(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  headline h = new_headline("H3",
             "Against time-domain simulation reaching 1e-8 relative error in r_res, the theorem in double "
             "(theorem_minimum_double) is at least 1000x faster and reaches full precision");
  for (const auto& bp : pairs) {
    const auto* e = theorem_row(rows, bp);
    if (!e) continue;
    bool any = false;
    const measurement* best = fastest_simulation(rows, bp.name, any);
    if (!any) continue;
    if (!best) {
      add_value(h, bp.name, false, "no simulation setting reached 1e-8 in r_res");
      continue;
    }
    const double r = paired_ratio(*best, *e);
    const bool full = e->digits() >= 14.5;
    add_value(h, bp.name, r >= 1000 && full,
              ratio_text(r) + " (" + best->method + ": " + format_time(best->median_ns) + ", " +
                  format_digits(best->digits_r) + " digits in r_res; theorem " + format_time(e->median_ns) + ", " +
                  format_digits(e->digits()) + " digits)");
  }
  return h;
}

// The certificate against the proof it writes down, and against the unproved value from before
// the theorem (remark).
headline h4(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  headline h = ratio_headline(
      "H4",
      "A certificate at 30 digits (certify_by_theorem) costs at most 3x the theorem's proved minimum at 30 digits "
      "(prove_minimum)",
      rows, pairs, {"mp30", "certificate", "theorem_proved", true, 3, ""}, times_of("certificate", "proved"));
  std::vector<double> lattice = pair_ratios(rows, pairs, "certificate", "ref_lattice", "mp30");
  if (!lattice.empty()) {
    std::sort(lattice.begin(), lattice.end());
    h.remark = "Against the unproved 30-digit value of the reference lattice from before the theorem (ref_lattice), "
               "the certificate costs " +
               ratio_text(lattice.front()) + "-" + ratio_text(lattice.back()) + ".";
  }
  return h;
}

// Cost in units of one evaluation: MPFR one_eval against Arb's, at `prec` (medians over the
// pairs); "" when a row is missing everywhere.
std::string h5_remark(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs, const char* prec) {
  std::vector<double> ev_ratio, proved_units, arb_units;
  for (const auto& bp : pairs) {
    const auto* o = find_row(rows, "one_eval", prec, bp.name);
    const auto* ao = find_row(rows, "arb_one_eval", prec, bp.name);
    const auto* e = find_row(rows, "theorem_proved", prec, bp.name);
    const auto* a = find_row(rows, "arb_newton", prec, bp.name);
    if (!o || !ao || !e || !a) continue;
    ev_ratio.push_back(paired_ratio(*o, *ao));
    proved_units.push_back(paired_ratio(*e, *o));
    arb_units.push_back(paired_ratio(*a, *ao));
  }
  if (ev_ratio.empty()) return "";
  return std::string("At ") + prec + " (medians over the pairs): one MPFR evaluation (one_eval, two real_sin_cos: " +
         "Arb's arb_sin_cos at the working precision) costs " + format_number("%.2g", median(ev_ratio)) +
         "x one Arb evaluation (arb_one_eval, two arb_sin_cos); the theorem's proved minimum costs " +
         format_number("%.2g", median(proved_units)) + " MPFR evaluations, Arb's refinement " +
         format_number("%.2g", median(arb_units)) + " Arb evaluations.";
}

headline h5(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  headline h = new_headline("H5",
             "At 1000 and 10000 digits, the theorem's proved enclosures of theta and r_res (prove_minimum) take at "
             "most 1.5x the time Arb takes to refine the root alone");
  for (const char* prec : {"mp1000", "mp10000"})
    add_ratios(h, rows, pairs, {prec, "theorem_proved", "arb_newton", true, 1.5, std::string(" ") + prec},
               times_of("proved", "Arb"));
  for (const char* prec : {"mp1000", "mp10000"}) {
    const std::string r = h5_remark(rows, pairs, prec);
    if (!r.empty()) h.remark += std::string(h.remark.empty() ? "" : " ") + r;
  }
  return h;
}

// ---- the limits: gyrores' paths against the theorem-aware peers (peer_theorem.cpp) ----------

std::string with_digits(const std::string& label, const measurement& m) {
  return label + " " + format_time(m.median_ns) + ", " + format_digits(m.digits()) + " d";
}

// L1: gyrores' double path against peer_newton. Pairs beyond theorem_minimum_double's int128
// (order >= 2^120) have no double path: their row is the proved minimum at 16 digits
// (theorem_proved at double), what gyrores offers for them, and it counts against the target.
headline l1(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  headline h = new_headline("L1",
             "Exact double: gyrores' double path (theorem_minimum_double) takes at most 1.25x the plain "
             "theorem-aware peer (peer_newton), for every pair");
  for (const auto& bp : pairs) {
    const auto* d = find_row(rows, "peer_newton", "double", bp.name);
    const auto* e = theorem_row(rows, bp);
    const auto* big = e ? nullptr : find_row(rows, "theorem_proved", "double", bp.name);
    if (!d || !(e || big)) continue;
    const measurement& n = e ? *e : *big;
    const double r = paired_ratio(n, *d);
    add_value(h, bp.name, r <= 1.25,
              ratio_text(r) + " (" +
                  (e ? with_digits("theorem_minimum_double", n)
                     : "no double path: theorem_minimum_double takes orders below 2^120; the proved minimum at 16 "
                       "digits instead, " + with_digits("prove_minimum", n)) +
                  "; " + with_digits("peer_newton", *d) + ")");
  }
  h.remark = "theorem_minimum_double also forms every minimiser (2 or 4) and its lobe; peer_newton forms theta_first "
             "alone. peer_newton takes u* by Newton on H with libm's tan and atan from pi m_min/(4b); "
             "theorem_minimum_double starts from H's expansions and proves its last step in double-double.";
  return h;
}

// A ratio num/den of two rows at (prec, pair) as text, or "" when one is missing.
std::string ratio_of(const std::vector<measurement>& rows, const std::string& num, const std::string& den,
                     const std::string& prec, const std::string& pair) {
  const auto* n = find_row(rows, num, prec, pair);
  const auto* d = find_row(rows, den, prec, pair);
  return n && d ? ratio_text(paired_ratio(*n, *d)) : "";
}

// L2: the certificate against peer_arb_ball, which proves the same claims and writes them (and
// rounds them); prove_minimum, prove_pair and peer_arb_calc against the same peer, for context.
headline l2(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  headline h = new_headline("L2",
             "Certified: a certificate (certify_by_theorem, what `gyrores certify` computes) takes at most 1.3x the "
             "Arb ball peer (peer_arb_ball), which proves and writes the same claims, at 30, 1000 and 10000 digits");
  for (const char* prec : {"mp30", "mp1000", "mp10000"})
    for (const auto& bp : pairs) {
      const auto* c = find_row(rows, "certificate", prec, bp.name);
      const auto* d = find_row(rows, "peer_arb_ball", prec, bp.name);
      if (!c || !d) continue;
      const double r = paired_ratio(*c, *d);
      std::string more;
      for (const auto& [label, method] : {std::pair<const char*, const char*>{"prove_minimum", "theorem_proved"},
                                          {"prove_pair", "theorem_report"},
                                          {"peer_arb_calc", "peer_arb_calc"}}) {
        const std::string t = ratio_of(rows, method, "peer_arb_ball", prec, bp.name);
        if (!t.empty()) more += "; " + std::string(label) + " " + t;
      }
      add_value(h, bp.name + " " + prec, r <= 1.3,
                ratio_text(r) + " (" + with_digits("certificate", *c) + "; " + with_digits("peer_arb_ball", *d) +
                    more + ")");
    }
  h.remark =
      "Like for like: both prove a bracket of u* and enclosures of r_res, theta_first and t_first of relative width "
      "<= 10^-(digits+1) and write them out as decimal claims (the certificate also lists the 2 or 4 minimiser "
      "lobes, integers; peer_arb_ball also decides the correct roundings to the digits from its claims). For "
      "context, each value also gives, as ratios to peer_arb_ball: prove_minimum (theorem_proved: the enclosures "
      "of r_res and every minimiser, no decimal text), prove_pair (theorem_report: everything `gyrores pair` "
      "prints, every real correctly rounded) and peer_arb_calc (Arb's arb_calc_refine_root_newton, the same "
      "claims). Digits: the certificate is scored at its claims' midpoints, peer_arb_ball on its roundings to the "
      "digits.";
  return h;
}

// ---- every headline against the theorem-aware peers ------------------------------------------

// "Against the theorem-aware peer <peer> (medians over the pairs): <label> <ratio>, ... at <prec>; ...",
// the ratios time(method)/time(peer) at (prec, pair); "" when no pair has both rows.
std::string peer_remark(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs,
                        const std::string& peer, const std::vector<std::pair<std::string, std::string>>& methods,
                        const std::vector<std::string>& precs) {
  std::vector<std::string> parts;
  for (const auto& prec : precs) {
    std::vector<std::string> items;
    for (const auto& [label, method] : methods) {
      const std::vector<double> r = pair_ratios(rows, pairs, method, peer, prec);
      if (!r.empty()) items.push_back(label + " " + ratio_text(median(r)));
    }
    if (items.empty()) continue;
    std::string part;
    for (std::size_t i = 0; i < items.size(); ++i) part += (i ? ", " : "") + items[i];
    parts.push_back(part + (precs.size() > 1 ? " at " + prec : ""));
  }
  if (parts.empty()) return "";
  std::string out = "Against the theorem-aware peer " + peer + " (medians over the pairs): ";
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? "; " : "") + parts[i];
  return out + ".";
}

// H3's simulations against peer_newton: the fastest reaching 1e-8 in r_res, per pair.
std::string h3_peer_remark(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  std::vector<double> r;
  for (const auto& bp : pairs) {
    bool any = false;
    const auto* s = fastest_simulation(rows, bp.name, any);
    const auto* d = find_row(rows, "peer_newton", "double", bp.name);
    if (s && d) r.push_back(paired_ratio(*s, *d));
  }
  std::string out = peer_remark(rows, pairs, "peer_newton", {{"theorem_minimum_double", "theorem_double"}}, {"double"});
  if (!r.empty())
    out += std::string(out.empty() ? "" : " ") + "The fastest simulation reaching 1e-8 takes " +
           ratio_text(median(r)) + " peer_newton's time (median over the pairs).";
  return out;
}

void add_remark(headline& h, const std::string& r) {
  if (!r.empty()) h.remark += (h.remark.empty() ? "" : " ") + r;
}

}  // namespace

std::map<const measurement*, double> ratios_to_best(const std::vector<measurement>& rows,
                                                   const std::vector<precision>& precisions) {
  std::map<std::pair<std::string, std::string>, std::vector<const measurement*>> groups;
  for (const auto& m : rows)
    if (!m.failed && is_measured(m.median_ns)) groups[{m.pair, m.precision}].push_back(&m);
  std::map<const measurement*, double> out;
  for (auto& [key, g] : groups) {
    double nominal = 1e9;
    for (const auto& pr : precisions)
      if (pr.name == key.second) nominal = pr.digits;
    double top = -1;
    for (auto* m : g)
      if (is_measured(m->digits())) top = std::max(top, m->digits());
    const double target = std::min(nominal, top) - 1;
    double best = -1;
    for (auto* m : g)
      if (is_measured(m->digits()) && m->digits() >= target && (best < 0 || m->median_ns < best)) best = m->median_ns;
    if (best <= 0) continue;
    for (auto* m : g) out[m] = m->median_ns / best;
  }
  return out;
}

std::vector<headline> compute_headlines(const std::vector<measurement>& rows, const std::vector<bench_pair>& pairs) {
  std::vector<headline> out{l1(rows, pairs), l2(rows, pairs), h1(rows, pairs),
          ratio_headline("H2a",
                         "At 1000 digits, the theorem's proved r_res (prove_minimum) costs at most 4x one evaluation "
                         "of (q, q') at that precision",
                         rows, pairs, {"mp1000", "theorem_proved", "one_eval", true, 4, ""},
                         times_of("proved", "one evaluation")),
          ratio_headline("H2b",
                         "At 1000 digits, the theorem's proved r_res is at least 5x faster than plain TOMS748 on the "
                         "naive formulation",
                         rows, pairs, {"mp1000", "naive_toms748", "theorem_proved", false, 5, ""},
                         naive_against_proved),
          h3(rows, pairs), h4(rows, pairs), h5(rows, pairs)};
  // Every figure also as a ratio to the theorem-aware peers.
  for (auto& h : out) {
    if (h.id == "H1")
      add_remark(h, peer_remark(rows, pairs, "peer_newton",
                                {{"theorem_minimum_double", "theorem_double"}, {"theta_asy", "theta_asy"}},
                                {"double"}));
    if (h.id == "H2a")
      add_remark(h, peer_remark(rows, pairs, "peer_arb_ball",
                                {{"prove_minimum", "theorem_proved"}, {"one evaluation", "one_eval"}}, {"mp1000"}));
    if (h.id == "H2b")
      add_remark(h, peer_remark(rows, pairs, "peer_arb_ball",
                                {{"naive TOMS 748", "naive_toms748"}, {"prove_minimum", "theorem_proved"}},
                                {"mp1000"}));
    if (h.id == "H3") add_remark(h, h3_peer_remark(rows, pairs));
    if (h.id == "H4")
      add_remark(h, peer_remark(rows, pairs, "peer_arb_ball",
                                {{"certificate", "certificate"}, {"prove_minimum", "theorem_proved"}}, {"mp30"}));
    if (h.id == "H5")
      add_remark(h, peer_remark(rows, pairs, "peer_arb_ball",
                                {{"prove_minimum", "theorem_proved"}, {"Arb's root refinement alone", "arb_newton"}},
                                {"mp1000", "mp10000"}));
  }
  return out;
}

}  // namespace gyrores::bench
