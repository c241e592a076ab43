// include/gyrores/sweep/values.hpp: the values of a sweep and radix selection over them.
#include <gyrores/sweep/values.hpp>

#include <algorithm>
#include <bit>
#include <cstring>
#include <map>
#include <string>
#include <utility>

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

// One wanted rank, narrowed pass by pass: the values whose key starts with `prefix` (its top
// `fixed` bits) number `within`, and the wanted one is the `rank`-th of them.
struct target {
  std::uint64_t rank = 0, prefix = 0, within = 0;
  unsigned fixed = 0;
  bool done = false;
  double value = 0;
};

// Targets with one prefix are served by one histogram or one candidate list.
using group_id = std::pair<unsigned, std::uint64_t>;  // (fixed, prefix)

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
    targets.push_back({r, 0, count, 0, false, 0});
  }
  for (;;) {
    // This pass: a histogram of the next bits for each prefix with too many values, the values
    // themselves for the others.
    std::map<group_id, std::vector<std::uint64_t>> histograms, candidates;
    for (auto& t : targets) {
      if (t.done) continue;
      const group_id g{t.fixed, t.prefix};
      if (t.within <= opt.collect_limit) candidates[g];
      else histograms.try_emplace(g, std::size_t(1) << std::min(opt.bits, 64 - t.fixed), 0);
    }
    if (histograms.empty() && candidates.empty()) break;
    // Every unfinished target has gained the same bits on every pass, so the groups of a pass
    // share `fixed` (F): a value belongs to the group whose prefix is its top F bits, found by
    // one shift and a scan of the few groups (at most one per rank), in prefix order.
    const unsigned F = (histograms.empty() ? candidates.begin()->first : histograms.begin()->first).first;
    struct slot {
      std::uint64_t prefix;
      std::uint64_t* hist;             // counters by the next b bits, or
      std::vector<std::uint64_t>* keys;  // the candidates themselves
    };
    std::vector<slot> slots;
    for (auto& [g, h] : histograms) slots.push_back({g.second, h.data(), nullptr});
    for (auto& [g, c] : candidates) slots.push_back({g.second, nullptr, &c});
    for (const auto& g : histograms) if (g.first.first != F) throw compute_error("sweep quantiles: targets out of step");
    for (const auto& g : candidates) if (g.first.first != F) throw compute_error("sweep quantiles: targets out of step");
    std::sort(slots.begin(), slots.end(), [](const slot& x, const slot& y) { return x.prefix < y.prefix; });
    const unsigned nb = std::min(opt.bits, 64 - F);  // the bits this pass resolves
    // For a short prefix (F <= 24: the second pass), the slot of each prefix by one table
    // look-up instead of a scan of the slots (a mispredicted branch per value; at order 10^5
    // this pass reads 1.27e9 values).
    std::vector<unsigned char> slot_of;
    if (F > 0 && F <= 24 && slots.size() < 255) {
      slot_of.assign(std::size_t(1) << F, 255);
      for (std::size_t j = 0; j < slots.size(); ++j) slot_of[std::size_t(slots[j].prefix)] = static_cast<unsigned char>(j);
    }
    std::uint64_t seen = 0;
    replay([&](const double* v, std::size_t n) {
      seen += n;
      if (F == 0) {  // one group: every value
        const slot& s = slots.front();
        if (s.hist) {
          for (std::size_t i = 0; i < n; ++i) ++s.hist[std::size_t(sweep_value_key(v[i] == 0 ? 0.0 : v[i]) >> (64 - nb))];
        } else {
          for (std::size_t i = 0; i < n; ++i) s.keys->push_back(sweep_value_key(v[i] == 0 ? 0.0 : v[i]));
        }
        return;
      }
      if (!slot_of.empty()) {
        for (std::size_t i = 0; i < n; ++i) {
          const std::uint64_t k = sweep_value_key(v[i] == 0 ? 0.0 : v[i]);
          const unsigned j = slot_of[std::size_t(k >> (64 - F))];
          if (j == 255) continue;
          const slot& s = slots[j];
          if (s.hist) ++s.hist[std::size_t((k << F) >> (64 - nb))];
          else s.keys->push_back(k);
        }
        return;
      }
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t k = sweep_value_key(v[i] == 0 ? 0.0 : v[i]), top = k >> (64 - F);
        for (const slot& s : slots) {
          if (s.prefix < top) continue;
          if (s.prefix == top) {
            if (s.hist) ++s.hist[std::size_t((k << F) >> (64 - nb))];
            else s.keys->push_back(k);
          }
          break;
        }
      }
    });
    if (seen != count)
      throw compute_error("sweep quantiles: the values were replayed as " + std::to_string(seen) + ", expected " +
                          std::to_string(count));
    for (auto& t : targets) {
      if (t.done) continue;
      const group_id g{t.fixed, t.prefix};
      if (auto c = candidates.find(g); c != candidates.end()) {
        auto& keys = c->second;
        if (keys.size() != t.within)
          throw compute_error("sweep quantiles: the values changed between passes");
        std::nth_element(keys.begin(), keys.begin() + std::ptrdiff_t(t.rank), keys.end());
        t.value = sweep_value_of_key(keys[t.rank]);
        t.done = true;
        continue;
      }
      const auto& h = histograms.at(g);
      const unsigned b = std::min(opt.bits, 64 - t.fixed);
      std::uint64_t below = 0, total = 0;
      for (auto x : h) total += x;
      if (total != t.within) throw compute_error("sweep quantiles: the values changed between passes");
      std::size_t bucket = 0;
      while (below + h[bucket] <= t.rank) below += h[bucket++];
      t.rank -= below;
      t.within = h[bucket];
      t.prefix = (t.fixed == 0 ? 0 : t.prefix << b) | bucket;
      t.fixed += b;
      if (t.fixed == 64) {  // the whole key: every candidate is this value
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
