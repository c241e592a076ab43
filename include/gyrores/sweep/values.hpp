// The t_first/(pi/|n|) values of a sweep and their exact order statistics in bounded memory
// (docs/formats.md, "Quantiles": 10 GB of them at order 10^5, and no one-pass summary of a stream
// gives an exact quantile). A sweep_values holds some values in memory and names the rest by
// *sources*, callables that replay values kept elsewhere (io/sweep_values_file.hpp); this layer
// never touches a file. Radix selection on the order-preserving 64-bit key of each double: each
// pass counts the values sharing the prefix found so far by their next `bits` key bits, the
// bucket holding the wanted rank extends the prefix, and at most `collect_limit` candidates are
// collected for nth_element; all ranks share each pass. The result is exactly sorted[rank]:
// -0 is stored as +0 (the printed quantile must not depend on which one a pair gave), NaNs sort
// after +inf.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace gyrores {

// The key of v: unsigned order of keys = numeric order of the doubles (-0 and +0 apart).
std::uint64_t sweep_value_key(double v);
double sweep_value_of_key(std::uint64_t key);

using sweep_value_sink = std::function<void(const double* values, std::size_t count)>;
// Replays every value of a source, in chunks, in the same order each time; throws (the io layer:
// usage_error) if the values cannot be read back.
using sweep_value_source = std::function<void(const sweep_value_sink&)>;

struct sweep_selection_options {
  unsigned bits = 20;                      // key bits resolved per pass (1..24: 2^bits counters)
  std::uint64_t collect_limit = 1u << 22;  // candidates (8 bytes each) collected for nth_element at most
};

// sorted[rank] for each rank (each < count), over the `count` values `replay` gives. Every pass
// counts what it sees: a replay that gives a different number of values is a compute_error.
std::vector<double> sweep_order_statistics(const sweep_value_source& replay, std::uint64_t count,
                                           const std::vector<std::uint64_t>& ranks,
                                           const sweep_selection_options& opt = {});

class sweep_values {
 public:
  void add(double v) { memory_.push_back(v == 0 ? 0.0 : v); }
  // Room for n more values in memory (a block knows how many it will add).
  void reserve(std::size_t n) { memory_.reserve(memory_.size() + n); }
  std::uint64_t size() const { return elsewhere_ + memory_.size(); }
  // Every value is in memory (no source).
  bool in_memory() const { return sources_.empty(); }
  // The values not handed to a source yet.
  const std::vector<double>& memory() const { return memory_; }
  // The owner has stored the values in memory elsewhere (and will add a source for them). The
  // capacity stays: a sweep refills it block by block (8 MB at a time), and growing it again
  // from nothing copied every value about twice more.
  void clear_memory() { memory_.clear(); }
  // `count` more values, replayed by `s`.
  void add_source(sweep_value_source s, std::uint64_t count);
  // Concatenation (the values are a multiset: order carries no meaning).
  void merge(const sweep_values& o);
  // Every value: the sources' in the order they were added, then memory.
  void replay(const sweep_value_sink& sink) const;

 private:
  std::vector<double> memory_;
  std::vector<sweep_value_source> sources_;
  std::uint64_t elsewhere_ = 0;
};

}  // namespace gyrores
