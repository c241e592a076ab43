// include/gyrores/sweep/filtered.hpp: the outcome counts of a filter.
#include <gyrores/sweep/filtered.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace gyrores {

filter_counts::filter_counts(const char* name) : name_(name), enabled_(std::getenv("GYRORES_FILTER_STATS") != nullptr) {}

// A reason is a static text (core/status.hpp): its address is its key, taken by the first free
// slot; equal texts at two addresses are added up when printed.
void filter_counts::add(const char* reason) {
  for (std::size_t i = 0; i < slots; ++i) {
    const char* have = reason_[i].load(std::memory_order_acquire);
    if (have == nullptr && reason_[i].compare_exchange_strong(have, reason)) have = reason;
    if (have == reason) {
      count_[i].fetch_add(1, std::memory_order_relaxed);
      return;
    }
  }
}

filter_counts::~filter_counts() {
  std::uint64_t undecided = 0;
  for (const auto& c : count_) undecided += c.load();
  if (!enabled_ || decided_.load() + undecided == 0) return;
  std::fprintf(stderr, "%s: %llu pairs, %llu to the exact evaluation\n", name_,
               (unsigned long long)(decided_.load() + undecided), (unsigned long long)undecided);
  for (std::size_t i = 0; i < slots; ++i) {
    const char* r = reason_[i].load();
    bool first = r != nullptr;  // the first slot of its text prints the text's total
    std::uint64_t n = 0;
    for (std::size_t j = 0; first && j < slots; ++j)
      if (reason_[j].load() && std::strcmp(reason_[j].load(), r) == 0) {
        first = j >= i;
        n += count_[j].load();
      }
    if (first) std::fprintf(stderr, "  %-40s %llu\n", r, (unsigned long long)n);
  }
}

}  // namespace gyrores
