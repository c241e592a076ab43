// Sweeps: every resonant pair with min_order <= tau + sigma <= max_order, evaluated and checked
// against the paper's claims, with a deterministic, mergeable summary.
//
// Per pair (sweep_evaluate<T>, amplitude v = 1; r_res is linear in v):
//  - the exact quantities from the lattice method (lattice.hpp): r_res, theta_first, t_first,
//    the global minimisers; the paper's proxy t_min_paper = pi/|n| and t_first/t_min_paper
//    (= theta_first b/pi);
//  - the checks named in sweep_config::checks (each pass, fail, or not applicable):
//    degeneracy  (P3) R(pi/2) = 0 iff delta = 2 mod 4, evaluated in lobe coordinates
//                (resonant.hpp: theta = pi/2 is the frame nearest pi/2, u = pi (a - 4k)/4), not
//                by the integer test the library uses to decide degenerate pairs; and for
//                non-degenerate pairs the lattice's numerical r_res satisfies
//                0 < r_res <= sqrt(R(pi/2)).
//    paper-node  (P5, non-degenerate pairs) one of the global minimisers lies in the paper's lobe
//                alpha = a theta/2 in (k pi - pi/2, k pi + pi/2), k = round(a/(2b)) (either k on a
//                tie, b = 1). Integer arithmetic on the minimiser frames. The row also says
//                whether the *first* minimiser is there (first_at_paper_node).
//    asy-bound   (P7, pairs with x = b/a < 1/2) |theta_c - theta_asy| <= pi^3 x^2/a in the lobe
//                k = round(a/(2b)) (the smaller k on a tie; the other is its mirror image), with
//                the error computed without cancellation (asymptotic.hpp); ratio = error/bound,
//                constant = error a/x^2 (its sup over a sweep estimates the sharp constant).
//    structure   (docs/mathematics.md §3) the number of global minimisers is 2 for delta odd, 4 for
//                delta = 0 mod 4 (2 for degenerate pairs: pi/2, 3 pi/2), and the strand offset
//                p.strand_offset_min() equals min over N of |a - 4N|. The lattice builds its
//                minimisers from that structure, so beyond the cross-check range this check is
//                a consistency check; within it, the cross-check confirms the count
//                independently (the global search counts ties itself).
//    cross-check the lattice method against the global search (cross_check.hpp), for
//                non-degenerate pairs of order <= cross_check_max_order (default 300: the global
//                search costs O(order) per pair, ~0.1 ms at order 300 in double).
//  A pair whose computation throws (compute_error, usage_error, domain_error) is an error row:
//  counted and listed, never silently dropped.
//
// Summary (sweep_accumulator): pairs, degenerate pairs, per check (pairs checked, violations, the
// first `max_examples` violating pairs in enumeration order), errors, the largest asy ratio and
// the largest constant error a/x^2 with their pairs (ties: the earlier pair), the number of
// non-degenerate pairs whose first minimiser is in the paper's lobe, and every value of
// t_first/(pi/|n|) over the non-degenerate pairs (degenerate pairs have exactly delta/2 there,
// by Thm. degenerate, and are left out). The values are kept exactly, one double each (1.5e7
// pairs: ~90 MB), so the quantiles are exact order statistics: q-quantile = sorted[floor(q (n-1))]
// (the median is the lower median). Accumulators merge exactly and in any grouping: counts add,
// examples are re-sorted by enumeration order (order a, then sigma) and cut, extremes compare by
// value then by enumeration order, values concatenate. Reals in the summary are doubles; with a
// wider T each is first printed (sweep_real_text) and read back, the same path a merge of row
// files takes, so single runs and merges agree bit for bit.
//
// Engine (sweep_run<T>): the calling thread enumerates nothing itself; `threads` workers take
// blocks of consecutive pairs from the shared lazy enumeration (coprime_pairs, sharded), evaluate
// them, and hand back per-block results; the calling thread consumes the blocks strictly in
// enumeration order (rows text, accumulator), so every output is independent of the thread
// count. A stop flag is honoured at block boundaries: blocks already taken are finished and
// delivered, so the pairs done are always a prefix of the shard's enumeration, which is what the
// resume state records. mpfr_real runs on one worker (Boost 1.74 keeps MPFR's default precision
// in one process-wide variable, which the lattice polish changes temporarily).
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gyrores/inscribed/asymptotic.hpp>
#include <gyrores/inscribed/cross_check.hpp>
#include <gyrores/core/decimal.hpp>
#include <gyrores/model/enumerate.hpp>
#include <gyrores/inscribed/lattice.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

// ---------------------------------------------------------------------------------------------
// Checks

enum class sweep_check : int { degeneracy = 0, paper_node = 1, asy_bound = 2, structure = 3, cross_check = 4 };
inline constexpr int sweep_check_count = 5;
using sweep_check_set = unsigned;  // bit i: check i
inline constexpr sweep_check_set sweep_all_checks = (1u << sweep_check_count) - 1;

inline const char* sweep_check_name(int i) {
  static const char* names[sweep_check_count] = {"degeneracy", "paper-node", "asy-bound", "structure", "cross-check"};
  return names[i];
}
// Row column of the check's pass/fail status.
inline const char* sweep_check_column(int i) {
  static const char* names[sweep_check_count] = {"check_degeneracy", "check_paper_node", "check_asy_bound",
                                                 "check_structure", "check_cross_check"};
  return names[i];
}
inline bool sweep_has_check(sweep_check_set s, sweep_check c) { return (s >> int(c)) & 1u; }

// "all" or a comma-separated list of check names (usage_error names an unknown one).
inline sweep_check_set sweep_parse_checks(const std::string& list) {
  if (list == "all") return sweep_all_checks;
  sweep_check_set s = 0;
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    std::string name = list.substr(start, end - start);
    int found = -1;
    for (int i = 0; i < sweep_check_count; ++i)
      if (name == sweep_check_name(i)) found = i;
    if (name == "all") {
      s = sweep_all_checks;
    } else if (found < 0) {
      throw usage_error("unknown check '" + name +
                        "' (expected all, degeneracy, paper-node, asy-bound, structure, cross-check)");
    } else {
      s |= 1u << found;
    }
    start = end + 1;
  }
  return s;
}
inline std::vector<std::string> sweep_check_names(sweep_check_set s) {
  std::vector<std::string> out;
  for (int i = 0; i < sweep_check_count; ++i)
    if ((s >> i) & 1u) out.push_back(sweep_check_name(i));
  return out;
}

// Default order limit of the cross-check in sweeps (the global search is O(order) per pair).
inline constexpr std::int64_t sweep_cross_check_default_max_order = 300;
// Orders beyond this are refused: the int64/int128 fast paths and the phi sieve assume it,
// and a sweep there (~1.5e17 pairs) is out of reach anyway.
inline constexpr std::int64_t sweep_max_order_limit = std::int64_t(1) << 40;

struct sweep_config {
  std::int64_t min_order = 3;  // below 3 is treated as 3
  std::int64_t max_order = 0;
  std::int64_t shard_index = 0, shard_count = 1;
  sweep_check_set checks = sweep_all_checks;
  std::int64_t cross_check_max_order = sweep_cross_check_default_max_order;
  std::size_t max_examples = 5;  // violating pairs listed per check
  unsigned digits = 17;          // significant digits of reals in rows when T is wider than double
  bool operator==(const sweep_config&) const = default;
};

inline void sweep_validate(const sweep_config& c) {
  if (c.max_order < 3) throw usage_error("--max-order must be >= 3, got " + std::to_string(c.max_order));
  if (c.max_order > sweep_max_order_limit)
    throw usage_error("--max-order must be <= 2^40, got " + std::to_string(c.max_order));
  if (c.min_order > c.max_order)
    throw usage_error("--min-order " + std::to_string(c.min_order) + " exceeds --max-order " +
                      std::to_string(c.max_order));
  if (c.shard_count < 1 || c.shard_index < 0 || c.shard_index >= c.shard_count)
    throw usage_error("shard must be I/N with 0 <= I < N, got " + std::to_string(c.shard_index) + "/" +
                      std::to_string(c.shard_count));
  if (c.cross_check_max_order < 0) throw usage_error("--cross-check-max-order must be >= 0");
}

// ---------------------------------------------------------------------------------------------
// Reals as text: doubles print in the shortest form that reads back exactly (std::to_chars);
// wider types print `digits` significant digits, correctly rounded (decimal.hpp).

inline std::string sweep_double_text(double v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}
template <class T> std::string sweep_real_text(const T& v, unsigned digits) {
  if constexpr (std::is_same_v<T, double>) return sweep_double_text(v);
  else return format_scientific(real_to_mpfr(v), digits < 17 ? 17 : digits);
}
// Text to double (correctly rounded); compute_error on malformed text.
inline double sweep_text_double(const std::string& s) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) throw compute_error("not a real number: '" + s + "'");
  return v;
}

// ---------------------------------------------------------------------------------------------
// One pair

enum class sweep_status : unsigned char { none = 0, pass = 1, fail = 2 };
inline const char* sweep_status_text(sweep_status s) {
  return s == sweep_status::pass ? "pass" : s == sweep_status::fail ? "fail" : "";
}

template <class T> struct sweep_row {
  std::int64_t tau = 0, sigma = 0;
  int delta_mod4 = 0;
  int strand_offset = 0;        // p.strand_offset_min()
  bool failed = false;          // the computation threw: `note` holds the message
  std::string note;             // error message, or why a check failed
  T r_res{}, theta_first{}, t_first{}, t_min_paper{};
  bool has_ratio = false;       // non-degenerate: t_ratio = t_first/t_min_paper
  T t_ratio{};
  int first_at_paper_node = -1;  // -1: not applicable (degenerate), 0/1
  int paper_lobe_min = -1;       // a global minimiser in the paper's lobe: -1/0/1
  bool has_asy = false;          // asy-bound requested and x < 1/2
  T asy_error{}, asy_bound{}, asy_ratio{}, asy_constant{};
  int minimiser_count = 0;
  std::array<sweep_status, sweep_check_count> status{};
};

namespace detail {

// Lobe index (mod a) of the point (k, u) of a lobe frame, |u| < pi: the paper's lobe is
// alpha = a theta/2 in (k pi - pi/2, k pi + pi/2).
template <class T> std::int64_t sweep_lobe_of(std::int64_t k, const T& u, std::int64_t a) {
  T h = real_pi<T>() / 2;
  if (u > h) ++k;
  if (u < -h) --k;
  return int_mod(k, a);
}

template <class T> void sweep_evaluate_into(sweep_row<T>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  using std::fabs;
  using std::sqrt;
  const std::int64_t a = std::int64_t(p.order()), b = p.delta();
  const bool degenerate = p.degenerate();
  const T v = T(1);
  auto c = resonant_constants_of<T>(p, v);
  auto lr = inscribed_lattice<T>(p, v);
  r.r_res = lr.r_res;
  r.theta_first = lr.theta_first;
  r.t_first = lr.t_first;
  r.t_min_paper = c.pi / c.n;
  r.minimiser_count = int(lr.minimisers.size());
  if (!degenerate) {
    r.has_ratio = true;
    r.t_ratio = lr.theta_first * real_from_int<T>(b) / c.pi;
  }
  const auto& ck = cfg.checks;

  // Lobes of the global minimisers (mod a) and the paper's lobe(s) k = round(a/(2b)).
  std::array<std::int64_t, 4> min_lobes{};
  std::size_t n_lobes = 0;
  if (degenerate) {
    min_lobes = {a / 4, 3 * a / 4};
    n_lobes = 2;
  } else {
    const std::int64_t k1 = sweep_lobe_of(std::int64_t(lr.first.k), lr.first.u, a);
    min_lobes[n_lobes++] = k1;
    min_lobes[n_lobes++] = int_mod(a - k1, a);
    if (p.strand_offset_min() == 2) {
      const std::int64_t ks = int_mod(k1 + a / 2, a);
      min_lobes[n_lobes++] = ks;
      min_lobes[n_lobes++] = int_mod(a - ks, a);
    }
  }
  if (!degenerate) {
    const std::int64_t twob = 2 * b, rem = int_mod(a, twob);
    const bool tie = rem == b;  // a/(2b) is a half-integer: both neighbours
    const std::int64_t k0 = tie ? (a - b) / twob : int_floor_div(a + b, twob);
    const std::int64_t kp0 = int_mod(k0, a), kp1 = tie ? int_mod(k0 + 1, a) : kp0;
    auto in_paper = [&](std::int64_t k) { return k == kp0 || k == kp1; };
    r.first_at_paper_node = in_paper(min_lobes[0]) ? 1 : 0;
    r.paper_lobe_min = 0;
    for (std::size_t i = 0; i < n_lobes; ++i)
      if (in_paper(min_lobes[i])) r.paper_lobe_min = 1;
    if (sweep_has_check(ck, sweep_check::paper_node))
      r.status[int(sweep_check::paper_node)] = r.paper_lobe_min ? sweep_status::pass : sweep_status::fail;
  }

  if (sweep_has_check(ck, sweep_check::degeneracy)) {
    // R(pi/2) in lobe coordinates: frame nearest theta = pi * 1/2.
    using L = int128;
    const L A = a, B = b;
    auto f = lobe_frame_near(A, B, L(1), L(2));
    auto fr = lobe_frame_real_of(c, f, A);
    T u = lobe_u_at(c, f, A, L(1), L(2));
    T R = lobe_eval(c, fr, u).radius_sq();
    bool zero = R == 0;
    bool ok = zero == (p.delta_mod4() == 2);
    if (ok && !degenerate) ok = lr.r_res > 0 && lr.r_res * lr.r_res <= R * (1 + 16 * real_epsilon<T>());
    if (ok && degenerate) ok = lr.r_res == 0;
    r.status[int(sweep_check::degeneracy)] = ok ? sweep_status::pass : sweep_status::fail;
    if (!ok) r.note = "degeneracy: R(pi/2) = " + sweep_real_text(R, cfg.digits) + ", r_res = " + sweep_real_text(lr.r_res, cfg.digits);
  }

  if (sweep_has_check(ck, sweep_check::structure)) {
    const int amod = int(int_mod(a, std::int64_t(4)));
    const int m_indep = std::min(amod, 4 - amod);
    const std::size_t expected = p.strand_offset_min() == 2 ? 4 : 2;
    bool ok = m_indep == p.strand_offset_min() && lr.minimisers.size() == expected;
    r.status[int(sweep_check::structure)] = ok ? sweep_status::pass : sweep_status::fail;
    if (!ok)
      r.note += std::string(r.note.empty() ? "" : "; ") + "structure: " + std::to_string(lr.minimisers.size()) +
                " minimisers (expected " + std::to_string(expected) + "), m_min " +
                std::to_string(p.strand_offset_min()) + " vs min|a - 4N| = " + std::to_string(m_indep);
  }

  if (sweep_has_check(ck, sweep_check::asy_bound) && 2 * b < a) {
    // The paper's lobe k = round(a/(2b)) (the smaller on a tie): m = a - 2 k b, s = pi m/(2b).
    const std::int64_t twob = 2 * b, rem = int_mod(a, twob);
    const std::int64_t k = rem == b ? (a - b) / twob : int_floor_div(a + b, twob);
    const std::int64_t m = a - 2 * k * b;
    const T s = c.pi * real_from_ratio<T>(m, twob);
    const T u_asy = u_plus_tan_u_root(s);
    const T e = asymptotic_error_scaled(c.x, s, u_asy, c.pi);
    const T at = real_from_int<T>(a), x2 = c.x * c.x, pi3 = c.pi * c.pi * c.pi;
    r.has_asy = true;
    r.asy_constant = 2 * fabs(e);
    r.asy_error = r.asy_constant * x2 / at;
    r.asy_bound = pi3 * x2 / at;
    r.asy_ratio = r.asy_constant / pi3;
    bool ok = r.asy_ratio <= 1;
    r.status[int(sweep_check::asy_bound)] = ok ? sweep_status::pass : sweep_status::fail;
  }

  if (sweep_has_check(ck, sweep_check::cross_check) && !degenerate && a <= cfg.cross_check_max_order) {
    try {
      cross_check_lattice(p, v, lr);
      r.status[int(sweep_check::cross_check)] = sweep_status::pass;
    } catch (const compute_error& e) {
      r.status[int(sweep_check::cross_check)] = sweep_status::fail;
      r.note += std::string(r.note.empty() ? "" : "; ") + e.what();
    }
  }
}

template <class T> sweep_row<T> sweep_failed_row(const resonant_pair<std::int64_t>& p, const char* what) {
  sweep_row<T> r;
  r.tau = p.tau();
  r.sigma = p.sigma();
  r.delta_mod4 = p.delta_mod4();
  r.strand_offset = p.strand_offset_min();
  r.failed = true;
  r.note = what;
  return r;
}

}  // namespace detail

// Evaluate one pair (see the header comment). Never throws for a computation that fails: the
// row is marked `failed` with the message in `note`.
template <class T> sweep_row<T> sweep_evaluate(const resonant_pair<std::int64_t>& p, const sweep_config& cfg) {
  sweep_row<T> r;
  r.tau = p.tau();
  r.sigma = p.sigma();
  r.delta_mod4 = p.delta_mod4();
  r.strand_offset = p.strand_offset_min();
  try {
    detail::sweep_evaluate_into(r, p, cfg);
  } catch (const std::runtime_error& e) {
    return detail::sweep_failed_row<T>(p, e.what());
  } catch (const std::logic_error& e) {
    return detail::sweep_failed_row<T>(p, e.what());
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// What the summary needs of one row, in doubles (the merge of row files rebuilds exactly this).

struct sweep_record {
  std::int64_t tau = 0, sigma = 0;
  int delta_mod4 = 0;
  bool failed = false;
  std::array<sweep_status, sweep_check_count> status{};
  bool has_ratio = false;
  double t_ratio = 0;
  int first_at_paper_node = -1;
  bool has_asy = false;
  double asy_ratio = 0, asy_constant = 0;
  std::string asy_ratio_text, asy_constant_text;  // empty for T = double (text = shortest form)
};

template <class T> sweep_record sweep_record_of(const sweep_row<T>& r, unsigned digits) {
  sweep_record s;
  s.tau = r.tau;
  s.sigma = r.sigma;
  s.delta_mod4 = r.delta_mod4;
  s.failed = r.failed;
  s.status = r.status;
  s.first_at_paper_node = r.first_at_paper_node;
  auto key = [&](const T& v, std::string* text) -> double {
    if constexpr (std::is_same_v<T, double>) {
      return v;
    } else {
      std::string t = sweep_real_text(v, digits);
      if (text) *text = t;
      return sweep_text_double(t);
    }
  };
  if (r.has_ratio) {
    s.has_ratio = true;
    s.t_ratio = key(r.t_ratio, nullptr);
  }
  if (r.has_asy) {
    s.has_asy = true;
    s.asy_ratio = key(r.asy_ratio, &s.asy_ratio_text);
    s.asy_constant = key(r.asy_constant, &s.asy_constant_text);
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// The summary accumulator

using sweep_pair_id = std::pair<std::int64_t, std::int64_t>;  // (tau, sigma)

// Enumeration order: by order tau + sigma, then sigma.
inline bool sweep_pair_before(const sweep_pair_id& x, const sweep_pair_id& y) {
  std::int64_t ax = x.first + x.second, ay = y.first + y.second;
  return ax != ay ? ax < ay : x.second < y.second;
}

struct sweep_tally {
  std::uint64_t checked = 0, violations = 0;
  std::vector<sweep_pair_id> examples;  // first few, in enumeration order
  bool operator==(const sweep_tally&) const = default;
};

struct sweep_extreme {
  bool set = false;
  double value = 0;
  std::string text;  // exact text when the run was wider than double; empty: shortest form of value
  sweep_pair_id pair{0, 0};
  std::string str() const { return text.empty() ? sweep_double_text(value) : text; }
  // Larger value wins; on equal values the earlier pair.
  void offer(double v, const std::string& t, const sweep_pair_id& p) {
    if (std::isnan(v)) return;
    if (!set || v > value || (v == value && sweep_pair_before(p, pair))) {
      set = true;
      value = v;
      text = t;
      pair = p;
    }
  }
  void merge(const sweep_extreme& o) {
    if (o.set) offer(o.value, o.text, o.pair);
  }
  bool operator==(const sweep_extreme& o) const {
    return set == o.set && (!set || (value == o.value && pair == o.pair && str() == o.str()));
  }
};

struct sweep_quantiles {
  std::uint64_t count = 0;
  double min = 0, p01 = 0, p10 = 0, median = 0, p90 = 0, p99 = 0, max = 0;
};

struct sweep_accumulator {
  std::size_t max_examples = 5;
  std::uint64_t pairs = 0, degenerate = 0;
  std::uint64_t first_at_paper_node = 0;  // non-degenerate pairs whose first minimiser is in the paper's lobe
  std::array<sweep_tally, sweep_check_count> checks{};
  sweep_tally errors;  // checked = 0; violations = failed pairs
  sweep_extreme asy_ratio_max, sharp_constant;
  std::vector<double> t_ratios;  // t_first/(pi/|n|), non-degenerate pairs (order irrelevant)

  static void add_example(sweep_tally& t, const sweep_pair_id& p, std::size_t k) {
    if (t.examples.size() < k) {
      t.examples.push_back(p);
      return;
    }
    // Out-of-order input (merging shards): keep the k earliest.
    if (k > 0 && sweep_pair_before(p, t.examples.back())) {
      t.examples.back() = p;
      std::sort(t.examples.begin(), t.examples.end(), sweep_pair_before);
    }
  }

  void add(const sweep_record& r) {
    const sweep_pair_id id{r.tau, r.sigma};
    ++pairs;
    if (r.delta_mod4 == 2) ++degenerate;
    if (r.failed) {
      ++errors.violations;
      add_example(errors, id, max_examples);
      return;
    }
    for (int i = 0; i < sweep_check_count; ++i) {
      if (r.status[i] == sweep_status::none) continue;
      ++checks[i].checked;
      if (r.status[i] == sweep_status::fail) {
        ++checks[i].violations;
        add_example(checks[i], id, max_examples);
      }
    }
    if (r.first_at_paper_node == 1) ++first_at_paper_node;
    if (r.has_ratio) t_ratios.push_back(r.t_ratio);
    if (r.has_asy) {
      asy_ratio_max.offer(r.asy_ratio, r.asy_ratio_text, id);
      sharp_constant.offer(r.asy_constant, r.asy_constant_text, id);
    }
  }

  static void merge_tally(sweep_tally& t, const sweep_tally& o, std::size_t k) {
    t.checked += o.checked;
    t.violations += o.violations;
    std::vector<sweep_pair_id> all = t.examples;
    all.insert(all.end(), o.examples.begin(), o.examples.end());
    std::sort(all.begin(), all.end(), sweep_pair_before);
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (all.size() > k) all.resize(k);
    t.examples = std::move(all);
  }

  // Exact merge; the result does not depend on the grouping or order of merges.
  void merge(const sweep_accumulator& o) {
    pairs += o.pairs;
    degenerate += o.degenerate;
    first_at_paper_node += o.first_at_paper_node;
    for (int i = 0; i < sweep_check_count; ++i) merge_tally(checks[i], o.checks[i], max_examples);
    merge_tally(errors, o.errors, max_examples);
    asy_ratio_max.merge(o.asy_ratio_max);
    sharp_constant.merge(o.sharp_constant);
    t_ratios.insert(t_ratios.end(), o.t_ratios.begin(), o.t_ratios.end());
  }

  // Exact order statistics of t_ratios (reorders t_ratios; its order carries no meaning).
  sweep_quantiles quantiles() {
    sweep_quantiles q;
    auto& v = t_ratios;
    q.count = v.size();
    if (v.empty()) return q;
    const std::uint64_t n1 = v.size() - 1;
    auto at = [&](std::uint64_t num, std::uint64_t den) {
      // floor(num/den * (n-1)) without overflow for n < 2^53
      std::uint64_t i = std::uint64_t((unsigned __int128)n1 * num / den);
      std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(i), v.end());
      return v[i];
    };
    q.min = *std::min_element(v.begin(), v.end());
    q.max = *std::max_element(v.begin(), v.end());
    q.p01 = at(1, 100);
    q.p10 = at(10, 100);
    q.median = at(1, 2);
    q.p90 = at(90, 100);
    q.p99 = at(99, 100);
    return q;
  }
};

// ---------------------------------------------------------------------------------------------
// Counting pairs (for progress and for checking merges)

// Number of pairs with min_order <= tau + sigma <= max_order: sum of phi(a)/2 (phi sieve,
// 4 bytes per order: callers keep max_order <= sweep_count_limit, 40 MB).
inline constexpr std::int64_t sweep_count_limit = 10'000'000;
inline std::uint64_t sweep_total_pairs(std::int64_t min_order, std::int64_t max_order) {
  if (min_order < 3) min_order = 3;
  if (max_order < min_order) return 0;
  if (max_order > sweep_count_limit)
    throw usage_error("sweep_total_pairs: orders beyond " + std::to_string(sweep_count_limit) + " are not counted");
  std::vector<std::uint32_t> phi(std::size_t(max_order) + 1);
  for (std::size_t i = 0; i < phi.size(); ++i) phi[i] = std::uint32_t(i);
  for (std::size_t pr = 2; pr < phi.size(); ++pr)
    if (phi[pr] == pr)
      for (std::size_t m = pr; m < phi.size(); m += pr) phi[m] -= phi[m] / std::uint32_t(pr);
  std::uint64_t s = 0;
  for (std::int64_t a = min_order; a <= max_order; ++a) s += phi[std::size_t(a)] / 2;
  return s;
}
// Pairs of shard i of n: positions p < total with p = i mod n.
inline std::uint64_t sweep_shard_pairs(std::uint64_t total, std::int64_t i, std::int64_t n) {
  return total > std::uint64_t(i) ? (total - std::uint64_t(i) + std::uint64_t(n) - 1) / std::uint64_t(n) : 0;
}

// ---------------------------------------------------------------------------------------------
// The engine

// One block of consecutive pairs of the shard, delivered in order.
struct sweep_block {
  std::uint64_t first = 0, count = 0;  // shard-relative index of the first pair, number of pairs
  sweep_accumulator summary;           // of this block alone
  std::string rows;                    // formatted rows (when a row formatter is given)
  sweep_pair_id last{0, 0};            // last pair of the block
};

template <class T> using sweep_row_formatter = std::function<void(std::string&, const sweep_row<T>&)>;

struct sweep_engine_options {
  unsigned threads = 0;            // 0: std::thread::hardware_concurrency()
  std::size_t block_size = 1024;   // pairs per block (the stop flag is honoured between blocks)
  std::uint64_t start = 0;         // skip this many pairs of the shard (resume)
  std::uint64_t max_pairs = 0;     // stop after this many pairs in this call (0: no limit)
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by a signal handler) to stop cleanly
};

struct sweep_outcome {
  std::uint64_t done = 0;   // pairs of the shard done after this call (start + pairs evaluated)
  bool complete = false;    // the shard's enumeration was exhausted
  unsigned threads = 1;     // workers used
};

// Evaluate the pairs of cfg's shard from index opt.start on, handing each block to on_block in
// enumeration order (on the calling thread). format_row, if set, appends a row's text to the
// block's `rows` (runs on the workers). Returns when the shard is exhausted, max_pairs is
// reached, or *stop is set (after finishing and delivering every block already started).
// Exceptions thrown by on_block or by a worker (other than per-pair computation failures, which
// become error rows) stop the run and are rethrown here.
template <class T>
sweep_outcome sweep_run(const sweep_config& cfg, const sweep_engine_options& opt,
                        const std::function<void(sweep_block&)>& on_block,
                        const sweep_row_formatter<T>& format_row = {}) {
  sweep_validate(cfg);
  unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  if constexpr (is_variable_precision_v<T>) threads = 1;
  const std::size_t block_size = std::max<std::size_t>(1, opt.block_size);
  const std::uint64_t window = 4 * std::uint64_t(threads);  // blocks in flight

  coprime_pairs range(cfg.min_order, cfg.max_order, cfg.shard_index, cfg.shard_count);
  auto it = range.begin();
  std::uint64_t taken = 0;  // pairs handed out (shard-relative, from 0)
  while (taken < opt.start && !(it == range.end())) {
    ++it;
    ++taken;
  }
  const std::uint64_t limit = opt.max_pairs ? opt.start + opt.max_pairs : std::numeric_limits<std::uint64_t>::max();

  std::mutex mtx;
  std::condition_variable cv_work, cv_done;
  std::uint64_t next_id = 0, next_write = 0;
  std::map<std::uint64_t, sweep_block> ready;
  unsigned active = threads;
  bool abort = false;
  std::exception_ptr failure;
  bool exhausted = it == range.end();

  auto stop_requested = [&] { return opt.stop && opt.stop->load(std::memory_order_relaxed); };

  auto worker = [&] {
    std::vector<resonant_pair<std::int64_t>> pairs;
    pairs.reserve(block_size);
    for (;;) {
      std::uint64_t id, first;
      {
        std::unique_lock<std::mutex> lk(mtx);
        cv_work.wait(lk, [&] { return abort || next_id < next_write + window; });
        if (abort || exhausted || taken >= limit || stop_requested()) break;
        pairs.clear();
        first = taken;
        while (pairs.size() < block_size && taken < limit && !(it == range.end())) {
          pairs.push_back(*it);
          ++it;
          ++taken;
        }
        if (it == range.end()) exhausted = true;
        id = next_id++;
      }
      sweep_block blk;
      blk.first = first;
      blk.count = pairs.size();
      blk.summary.max_examples = cfg.max_examples;
      try {
        for (const auto& p : pairs) {
          auto row = sweep_evaluate<T>(p, cfg);
          blk.summary.add(sweep_record_of(row, cfg.digits));
          if (format_row) format_row(blk.rows, row);
        }
        if (!pairs.empty()) blk.last = {pairs.back().tau(), pairs.back().sigma()};
      } catch (...) {
        std::lock_guard<std::mutex> lk(mtx);
        if (!failure) failure = std::current_exception();
        abort = true;
        cv_work.notify_all();
        cv_done.notify_all();
        break;
      }
      {
        std::lock_guard<std::mutex> lk(mtx);
        ready.emplace(id, std::move(blk));
      }
      cv_done.notify_all();
    }
    std::lock_guard<std::mutex> lk(mtx);
    --active;
    cv_done.notify_all();
  };

  std::uint64_t done = taken;  // before the workers start taking
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (unsigned i = 0; i < threads; ++i) pool.emplace_back(worker);

  for (;;) {
    sweep_block blk;
    {
      std::unique_lock<std::mutex> lk(mtx);
      cv_done.wait(lk, [&] { return abort || ready.count(next_write) || (active == 0 && next_write == next_id); });
      if (abort) break;
      auto f = ready.find(next_write);
      if (f == ready.end()) break;  // all workers gone and every block delivered
      blk = std::move(f->second);
      ready.erase(f);
      ++next_write;
    }
    cv_work.notify_all();
    try {
      done = blk.first + blk.count;
      on_block(blk);
    } catch (...) {
      std::lock_guard<std::mutex> lk(mtx);
      if (!failure) failure = std::current_exception();
      abort = true;
      cv_work.notify_all();
      break;
    }
  }
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  sweep_outcome out;
  out.done = done;
  out.complete = it == range.end() && done == taken;
  out.threads = threads;
  return out;
}

}  // namespace gyrores
