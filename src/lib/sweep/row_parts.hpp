// What the sweep's sources share of a row (private to src/lib/sweep/): the facts a row's checks
// are decided from, whichever path established them, and the paths between which evaluate.cpp
// and engine.cpp choose.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/core/status.hpp>
#include <gyrores/model/pair.hpp>
#include <gyrores/model/resonant.hpp>
#include <gyrores/sweep/certified.hpp>
#include <gyrores/sweep/engine.hpp>
#include <gyrores/theorem/lobes.hpp>

namespace gyrores::sweep_rows {

// What the checks are decided from: exact integers, and facts about the reals (proved, or for
// double rows decided in double with a proved margin).
template <class L> struct row_facts {
  int128 quarter_R_scaled = 0;  // 4 a^2 R(pi/2) (sweep_quarter_R_scaled)
  int m_min = 0;
  paper_node<std::int64_t> node{};       // the paper's (paper_fast_node, theorem/lobes.hpp)
  std::span<const lobe_frame<L>> lobes;  // the minimisers' lobes (k in [0, a)), theta order
  bool lobes_hold = false;         // sweep_lobes_hold already found true
  bool r_positive = false;         // r_res > 0
  bool r_below_R_half_pi = false;  // r_res^2 <= R(pi/2)
  bool has_asy = false;            // asked for and x < 1/2
  bool asy_proved = false;         // its values formed
  bool asy_within_bound = false;   // error/bound <= 1
};

// The note of a failed check c (degeneracy or structure), appended to r's; and any note.
void fail_note(sweep_row_info& r, sweep_check c, const int128& quarter_R_scaled);
void add_note(std::string& note, const std::string& what);

// Every field of row r but the reals, from f (the checks of sweep/evaluate.hpp); or of a record
// r (the sweeps without rows, fast.cpp). Inline: it runs for every pair.
template <class R, class L>
inline void checks_from_facts(R& r, const resonant_pair<std::int64_t>& p, const row_facts<L>& f, const sweep_config& cfg) {
  constexpr bool row = std::is_base_of_v<sweep_row_info, R>;  // else a record: no notes or counts
  const auto& ck = cfg.checks;
  const bool degenerate = p.delta_mod4() == 2;
  auto set = [&r, &f](sweep_check c, bool ok) {
    r.status[int(c)] = ok ? sweep_status::pass : sweep_status::fail;
    if constexpr (row)
      if (!ok) fail_note(r, c, f.quarter_R_scaled);
  };
  if constexpr (row) r.minimiser_count = int(f.lobes.size());
  if (!degenerate) {
    // P5: whether the first minimiser, and any, lies in the paper's lobe: alpha = k pi + u with
    // |u| < pi/2, the lobes' k in [0, a), the node's k and (on a tie) k + 1 too.
    auto in_paper = [&f](const lobe_frame<L>& l) {
      return std::int64_t(l.k) == f.node.k || (f.node.tie && std::int64_t(l.k) == f.node.k + 1);
    };
    bool any = false;
    for (const auto& l : f.lobes) any = any || in_paper(l);
    r.has_ratio = true;
    r.first_at_paper_node = in_paper(f.lobes.front()) ? 1 : 0;
    if constexpr (row) r.paper_lobe_min = any ? 1 : 0;
    if (sweep_has_check(ck, sweep_check::paper_node))
      r.status[int(sweep_check::paper_node)] = any ? sweep_status::pass : sweep_status::fail;
  }
  // P3: R(pi/2) = 0 exactly iff delta = 2 mod 4; r_res = 0 there by the theorem (m_min = 0),
  // else 0 < r_res <= sqrt(R(pi/2)).
  if (sweep_has_check(ck, sweep_check::degeneracy))
    set(sweep_check::degeneracy, (f.quarter_R_scaled == 0) == degenerate &&
                                     (degenerate ? f.m_min == 0 : f.r_positive && f.r_below_R_half_pi));
  if (sweep_has_check(ck, sweep_check::structure))
    set(sweep_check::structure, f.lobes_hold || sweep_lobes_hold<L>(p, f.m_min, f.lobes));
  if (sweep_has_check(ck, sweep_check::asy_bound) && f.has_asy) {
    r.has_asy = f.asy_proved;
    r.status[int(sweep_check::asy_bound)] = f.asy_proved && f.asy_within_bound ? sweep_status::pass : sweep_status::fail;
  }
}

// A fresh row of p with its identity columns, in place (sweep_evaluate_to's first step).
template <class T> void row_reset(sweep_row<T>& r, const resonant_pair<std::int64_t>& p);

// The certified double row of p in the theorem's double-double balls (certified_filter.cpp):
// proved, with r filled, or not (r untouched).
proof_status certified_filter_row(sweep_row<double>& r, const resonant_pair<std::int64_t>& p, const sweep_config& cfg);

// The pairs of one block of a double sweep without rows into blk.summary (fast.cpp): each
// pair's record from the theorem's series form where that decides it, else from its row.
// `known` is the largest asy constant computed so far in the run (updated).
void fast_block(const std::vector<resonant_pair<std::int64_t>>& pairs, sweep_block& blk, const sweep_config& cfg,
                double& known);

}  // namespace gyrores::sweep_rows
