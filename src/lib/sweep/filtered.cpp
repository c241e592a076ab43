// include/gyrores/sweep/filtered.hpp: the outcome counts of a filter.
#include <gyrores/sweep/filtered.hpp>

#include <cstdio>
#include <cstdlib>

namespace gyrores {

filter_counts::filter_counts(const char* name) : name_(name), enabled_(std::getenv("GYRORES_FILTER_STATS") != nullptr) {}

// A reason is a static text (core/status.hpp): its address is its key, taken by the first free
// slot.
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
  for (std::size_t i = 0; i < slots && reason_[i].load(); ++i)
    std::fprintf(stderr, "  %-40s %llu\n", reason_[i].load(), (unsigned long long)count_[i].load());
}

}  // namespace gyrores
