// include/gyrores/sweep/values.hpp: the values of a sweep and radix selection over them.
#include <gyrores/sweep/values.hpp>

#include <algorithm>
#include <bit>
#include <cstring>
#include <map>
#include <string>

#include <gyrores/core/error.hpp>

namespace gyrores {

std::uint64_t sweep_value_key(double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const std::uint64_t sign = std::uint64_t(1) << 63;
  // Negative doubles: larger magnitude is smaller, so all bits flip; positive: the sign bit is set
  // so they sort above every negative one.
  return (bits & sign) ? ~bits : (bits | sign);
}

double sweep_value_of_key(std::uint64_t key) {
  const std::uint64_t sign = std::uint64_t(1) << 63;
  return std::bit_cast<double>((key & sign) ? (key & ~sign) : ~key);
}

void sweep_values::add_source(sweep_value_source s, std::uint64_t count) {
  sources_.push_back(std::move(s));
  elsewhere_ += count;
}

void sweep_values::merge(const sweep_values& o) {
  sources_.insert(sources_.end(), o.sources_.begin(), o.sources_.end());
  elsewhere_ += o.elsewhere_;
  memory_.insert(memory_.end(), o.memory_.begin(), o.memory_.end());
}

void sweep_values::replay(const sweep_value_sink& sink) const {
  for (const auto& s : sources_) s(sink);
  if (!memory_.empty()) sink(memory_.data(), memory_.size());
}

namespace {

// One wanted rank, narrowed pass by pass: the values whose key starts with `prefix` (its top F
// bits; every unfinished target has gained the same bits on every pass) number `within`, and the
// wanted one is the `rank`-th of them.
struct target {
  std::uint64_t rank = 0, prefix = 0, within = 0;
  bool done = false;
  double value = 0;
};

// The values of one prefix in a pass: counted by their next bits, or (few) collected.
struct group {
  bool collect = false;
  std::vector<std::uint64_t> hist, keys;
};

}  // namespace

std::vector<double> sweep_order_statistics(const sweep_value_source& replay, std::uint64_t count,
                                           const std::vector<std::uint64_t>& ranks,
                                           const sweep_selection_options& opt) {
  if (opt.bits < 1 || opt.bits > 24) throw std::invalid_argument("sweep_order_statistics: bits must be 1..24");
  std::vector<target> targets;
  for (auto r : ranks) {
    if (r >= count)
      throw std::invalid_argument("sweep_order_statistics: rank " + std::to_string(r) + " of " + std::to_string(count) +
                                  " values");
    targets.push_back({r, 0, count, false, 0});
  }
  for (unsigned F = 0;; F += std::min(opt.bits, 64 - F)) {
    const unsigned nb = std::min(opt.bits, 64 - F);  // the bits this pass resolves
    std::map<std::uint64_t, group> groups;            // by prefix, at most one per rank
    for (const auto& t : targets) {
      if (t.done) continue;
      group& g = groups[t.prefix];
      g.collect = t.within <= opt.collect_limit;  // the same for every target of a prefix
      if (!g.collect && g.hist.empty()) g.hist.assign(std::size_t(1) << nb, 0);
    }
    if (groups.empty()) break;
    std::vector<std::uint64_t> prefixes;
    std::vector<group*> slots;
    for (auto& [prefix, g] : groups) {
      prefixes.push_back(prefix);
      slots.push_back(&g);
    }
    // For a short prefix (F <= 24: the first two passes), the group of a value by one table
    // look-up instead of a search of the groups (a mispredicted branch per value; at order 10^5
    // such a pass reads 1.27e9 values). (k >> 1) >> (63 - F): the top F bits, none for F = 0.
    std::vector<unsigned char> slot_of;
    if (F <= 24 && slots.size() < 255) {
      slot_of.assign(std::size_t(1) << F, 255);
      for (std::size_t j = 0; j < slots.size(); ++j) slot_of[std::size_t(prefixes[j])] = static_cast<unsigned char>(j);
    }
    std::uint64_t seen = 0;
    replay([&](const double* v, std::size_t n) {
      seen += n;
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t k = sweep_value_key(v[i] == 0 ? 0.0 : v[i]), top = (k >> 1) >> (63 - F);
        group* g = nullptr;
        if (!slot_of.empty()) {
          if (slot_of[std::size_t(top)] != 255) g = slots[slot_of[std::size_t(top)]];
        } else if (auto at = std::lower_bound(prefixes.begin(), prefixes.end(), top); at != prefixes.end() && *at == top) {
          g = slots[std::size_t(at - prefixes.begin())];
        }
        if (g && g->collect) g->keys.push_back(k);
        else if (g) ++g->hist[std::size_t((k << F) >> (64 - nb))];
      }
    });
    if (seen != count)
      throw compute_error("sweep quantiles: the values were replayed as " + std::to_string(seen) + ", expected " +
                          std::to_string(count));
    for (auto& t : targets) {
      if (t.done) continue;
      group& g = groups.at(t.prefix);
      if (g.collect) {
        if (g.keys.size() != t.within) throw compute_error("sweep quantiles: the values changed between passes");
        std::nth_element(g.keys.begin(), g.keys.begin() + std::ptrdiff_t(t.rank), g.keys.end());
        t.value = sweep_value_of_key(g.keys[t.rank]);
        t.done = true;
        continue;
      }
      std::uint64_t below = 0, total = 0;
      for (auto x : g.hist) total += x;
      if (total != t.within) throw compute_error("sweep quantiles: the values changed between passes");
      std::size_t bucket = 0;
      while (below + g.hist[bucket] <= t.rank) below += g.hist[bucket++];
      t.rank -= below;
      t.within = g.hist[bucket];
      t.prefix = (t.prefix << nb) | bucket;
      if (F + nb == 64) {  // the whole key: every candidate is this value
        t.value = sweep_value_of_key(t.prefix);
        t.done = true;
      }
    }
  }
  std::vector<double> out;
  for (auto& t : targets) out.push_back(t.value);
  return out;
}

}  // namespace gyrores
