// The t_first/(pi/|n|) values of a sweep and their exact order statistics, in bounded memory.
//
// A sweep to order 10^5 has 1.27e9 non-degenerate pairs, one double each: 10 GB, too much to
// hold, and an exact quantile cannot be had from a one-pass summary of the stream. So the values
// are kept exactly but not necessarily in memory: a sweep_values holds some in memory and names
// the rest by *sources*, callables that replay values kept elsewhere (the io layer's files,
// io/sweep_values_file.hpp); this layer never touches a file.
//
// Order statistics are found by radix selection on the order-preserving 64-bit key of each
// double (sweep_value_key): a pass over all values counts them by the top `bits` bits of the key
// among the values that share the prefix found so far; the bucket holding the wanted rank
// extends the prefix; once the candidates are few (at most `collect_limit`) they are collected
// and the rank is picked by nth_element. With 20 bits a pass and ~10^9 values spread over a few
// binades, that is two passes over the values; memory is ~8 MB per histogram plus the collected
// candidates, whatever the count. All wanted ranks share each pass.
//
// The result is exactly the element sorted[rank] of the sorted values (the same as sorting
// them all): keys order doubles as < does, -0 is stored as +0 (they compare equal, and the
// printed quantile must not depend on which one a pair gave), NaNs sort after +inf.
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
  // Every value: those in memory and those held by sources.
  std::uint64_t size() const { return elsewhere_ + memory_.size(); }
  // The values in memory (the ones not handed to a source yet).
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
