// include/gyrores/theorem/minimum_series.hpp: the pass frames' k of a block of pairs.
#include <gyrores/theorem/minimum_series.hpp>

#include <gyrores/core/integer.hpp>

namespace gyrores {
namespace {

// x y mod A for x, y < A < 2^31 by Barrett's reduction with M = floor((2^64 - 1)/A): the
// estimate q = floor(z M/2^64) of floor(z/A) (z = x y < 2^62) is short by at most 2.
struct barrett {
  std::uint64_t A, M;
  explicit barrett(std::uint64_t mod) : A(mod), M(~std::uint64_t(0) / mod) {}
  std::uint64_t mul(std::uint64_t x, std::uint64_t y) const {
    const std::uint64_t z = x * y, q = std::uint64_t((unsigned __int128)z * M >> 64);
    std::uint64_t r = z - q * A;
    if (r >= A) r -= A;
    if (r >= A) r -= A;
    return r;
  }
};

// The pass frames' k of pairs[lo, hi), all of order a (odd or 2 mod 4, a < 2^31): c_i = 4 sigma
// (m_min = 1, ah = a) or 2 sigma (m_min = 2, ah = a/2) reduced mod ah, all invertible (sigma is
// coprime to a, ah is odd); k_i = c_i^-1 mod ah. The prefix products P_i = c_1 ... c_i, one
// inverse of P_n, then backwards c_i^-1 = P_n^-1 (c_n ... c_(i+1)) P_(i-1).
// Why k = c^-1: the pass frame has (2j+1) ah - k d = 1 with d = 2b (m = 1) or b (m = 2), so
// k d = -1 mod ah, and d = -4 sigma or -2 sigma mod ah (b = a - 2 sigma); 0 < k < ah.
void pass_ks_of_order(const std::vector<resonant_pair<std::int64_t>>& pairs, std::size_t lo, std::size_t hi,
                      std::int64_t a, std::vector<std::int64_t>& ks) {
  const bool odd = a % 2 != 0;
  const std::uint64_t ah = std::uint64_t(odd ? a : a / 2);
  const barrett B(ah);
  thread_local std::vector<std::uint64_t> c, prefix;
  c.resize(hi - lo);
  prefix.resize(hi - lo);
  std::uint64_t P = 1;
  for (std::size_t i = lo; i < hi; ++i) {
    std::uint64_t ci = std::uint64_t(pairs[i].sigma()) * (odd ? 4 : 2);  // < 2 ah
    if (ci >= ah) ci -= ah;
    prefix[i - lo] = P;  // P_(i-1)
    c[i - lo] = ci;
    P = B.mul(P, ci);
  }
  std::uint64_t inv = std::uint64_t(int_inverse_mod(std::int64_t(P), std::int64_t(ah)));  // (c_lo ... c_i)^-1
  for (std::size_t i = hi; i-- > lo;) {
    ks[i] = std::int64_t(B.mul(inv, prefix[i - lo]));
    inv = B.mul(inv, c[i - lo]);
  }
}

}  // namespace

void pass_ks_of_block(const std::vector<resonant_pair<std::int64_t>>& pairs, std::vector<std::int64_t>& ks) {
  ks.assign(pairs.size(), 0);
  std::size_t lo = 0;
  while (lo < pairs.size()) {
    const std::int64_t a = std::int64_t(pairs[lo].order());
    std::size_t hi = lo + 1;
    while (hi < pairs.size() && std::int64_t(pairs[hi].order()) == a) ++hi;
    if (a % 4 != 0 && a < (std::int64_t(1) << 31)) pass_ks_of_order(pairs, lo, hi, a, ks);
    lo = hi;
  }
}

}  // namespace gyrores
