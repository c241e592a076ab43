// The integer half of the lattice theorem (proofs/lattice-theorem.md, id "lattice-theorem/1"):
// which lobes hold the global minimisers of R, found by one modular inverse, and the paper's
// fast node. Exact integers only (L: int64, int128 or big_int); nothing here is a real number.
//
// Lobe frames (model/resonant.hpp): integers k, j with m = (2j+1) a - 2 k b, a = tau + sigma,
// b = tau - sigma. The theorem (items 4, 5): the global minimisers are the points u = sign(m) u*
// of exactly the lobes whose frame has |m| = m_min, where m_min = 0, 1, 2 as a = 0 mod 4, a odd,
// a = 2 mod 4: 2 lobes (m = +-1) for delta odd, 4 (m = +-2, twice each) for delta = 0 mod 4.
// A minimiser's place on [0, 2 pi) is decided by integers: theta = 2 (k pi + u)/a with
// |u| < pi/2, so lobes are ordered by k, and a k = 0 lobe with u < 0 wraps to just below 2 pi.
// No theta formed in floating point is ever compared or reduced mod 2 pi.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include <gyrores/core/integer.hpp>
#include <gyrores/model/resonant.hpp>

namespace gyrores {

inline constexpr const char* lattice_theorem_id = "lattice-theorem/1";

// m_min = min over N of |a - 4N|: 0 for a = 0 mod 4 (delta = 2 mod 4, degenerate), 1 for a odd
// (delta odd), 2 for a = 2 mod 4 (delta = 0 mod 4). The same integer as
// resonant_pair::strand_offset_min(), from a alone.
template <class L> int theorem_m_min(const L& a) {
  int r;
  if constexpr (std::is_same_v<L, big_int>) r = int(int_mod(a, L(4)));
  else r = int(a & L(3));  // machine integers (two's complement): a mod 4 without a division
  return std::min(r, 4 - r);
}

// The place of a minimiser lobe on [0, 2 pi) (k reduced): k, or a for the k = 0 lobe with m < 0
// (its minimiser u = -u* lies just below 2 pi).
template <class L> L lobe_order_key(const lobe_frame<L>& f, const L& a) { return f.k == 0 && f.m < 0 ? a : f.k; }

// At most four lobe frames, in place (no allocation: the sweeps form one per pair).
template <class L> class lobe_list {
 public:
  void push_back(const lobe_frame<L>& f) { items_[count_++] = f; }
  std::size_t size() const { return count_; }
  const lobe_frame<L>& operator[](std::size_t i) const { return items_[i]; }
  const lobe_frame<L>& front() const { return items_[0]; }
  lobe_frame<L>* begin() { return items_.data(); }
  lobe_frame<L>* end() { return items_.data() + count_; }
  const lobe_frame<L>* begin() const { return items_.data(); }
  const lobe_frame<L>* end() const { return items_.data() + count_; }
  std::vector<lobe_frame<L>> to_vector() const { return {begin(), end()}; }

 private:
  std::array<lobe_frame<L>, 4> items_{};
  std::size_t count_ = 0;
};

// The minimisers' lobes of a pair from its pass frame, the frame with m = +m_min: (2j+1) a - 2 k b
// = m_min = 1 or 2, 0 < k < ah, ah = a or a/2, as minimiser_lobes_euclid_into below describes
// them, into `out`; their count returned. Also for the pass frames of theorem/minimum_series.hpp.
template <class L>
[[gnu::always_inline]] inline std::size_t minimiser_lobes_of_pass(const L& a, const L& b, const lobe_frame<L>& pass,
                                                                  std::array<lobe_frame<L>, 4>& out) {
  const int m = int(pass.m);
  const L ah = m == 1 ? a : L(a / 2);
  const lobe_frame<L> mirror{L(a - pass.k), L(b - 1 - pass.j), L(-m)};
  const bool pass_first = 2 * pass.k < ah;
  if (m == 1) {
    out[0] = pass_first ? pass : mirror;
    out[1] = pass_first ? mirror : pass;
    return 2;
  }
  const lobe_frame<L> shift{L(pass.k + a / 2), L(pass.j + b / 2), L(m)};
  const lobe_frame<L> shift_mirror{L(a / 2 - pass.k), L(b / 2 - 1 - pass.j), L(-m)};
  out[0] = pass_first ? pass : shift_mirror;
  out[1] = pass_first ? shift_mirror : pass;
  out[2] = pass_first ? shift : mirror;
  out[3] = pass_first ? mirror : shift;
  return 4;
}

// The lobes of the global minimisers over one period, k in [0, a), in increasing theta (item 4
// of the theorem). Degenerate pairs (m_min = 0): the two lobes of the zeros pi/2 and 3 pi/2
// (u = 0, m = 0). By one extended Euclid and no sort, in machine integers (int64 with a < 2^62,
// int128 with a < 2^126) or big integers (tests/reference/lattice.hpp orders the same frames
// from a modular inverse, tests/test_double_double.cpp compares them). With ah = a, d = 2b
// (m_min = 1) or ah = a/2, d = b (m_min = 2), Euclid gives s ah + t d = 1 with |s| < d, |t| < ah
// (every cofactor and remainder stays below 2a: no overflow); s taken into (0, d) is 2j+1 and
// -t is k of the pass frame, (2j+1) a - 2 k b = m_min, 0 < k < ah (k = 0 would need ah = 1).
// The mirror (a - k) and, for m_min = 2, the shift (k + a/2) and its mirror (a/2 - k) then lie
// in [0, a) already, and their order follows from 2k < ah or not (2k = ah is impossible: ah
// odd). usage_error if Euclid's gcd is not 1 (tau, sigma not coprime). Written into `out`, with
// their count returned (the double path's minimum keeps them in its own array: no copy).
template <class L>
[[gnu::always_inline]] inline std::size_t minimiser_lobes_euclid_into(const L& a, const L& b, std::array<lobe_frame<L>, 4>& out) {
  const int m = theorem_m_min(a);
  if (m == 0) {
    out[0] = {L(a / 4), L((b - 2) / 4), L(0)};
    out[1] = {L(3 * (a / 4)), L((3 * b - 2) / 4), L(0)};
    return 2;
  }
  const L ah = m == 1 ? a : L(a / 2), d = m == 1 ? L(2 * b) : b;
  // Euclid on (d, ah), r = s ah + t d throughout. The first quotient d/ah is 0 or 1 (d < 2 ah: b
  // < a), so it needs no division; then the two rows take turns (no moves between them), each
  // step one division whose quotient and remainder come together.
  L r0 = d, r1 = ah, s0 = 0, s1 = 1, t0 = 1, t1 = 0;
  if (r0 >= r1) r0 -= r1, s0 -= s1, t0 -= t1;
  for (;;) {  // here r0 < r1
    if (r0 == 0) {  // the gcd is r1
      r0 = r1, s0 = s1, t0 = t1;
      break;
    }
    L q = r1 / r0;
    r1 -= q * r0, s1 -= q * s0, t1 -= q * t0;
    if (r1 == 0) break;  // the gcd is r0
    q = r0 / r1;
    r0 -= q * r1, s0 -= q * s1, t0 -= q * t1;
  }
  if (r0 != 1) throw usage_error("minimiser lobes: tau and sigma are not coprime");
  if (s0 < 0) s0 += d, t0 -= ah;
  return minimiser_lobes_of_pass(a, b, {L(-t0), L((s0 - 1) >> 1), L(m)}, out);  // s0 - 1 >= 0 and even
}
template <class L> lobe_list<L> minimiser_lobes(const L& a, const L& b) {
  std::array<lobe_frame<L>, 4> frames{};
  lobe_list<L> out;
  const std::size_t n = minimiser_lobes_euclid_into(a, b, frames);
  for (std::size_t i = 0; i < n; ++i) out.push_back(frames[i]);
  return out;
}

// minimiser_lobes for a pair held in big integers: in int64 for orders below 2^62 (the same
// list without big-integer arithmetic).
inline lobe_list<big_int> minimiser_lobes_big(const big_int& a, const big_int& b) {
  if (a >= big_int(std::int64_t(1) << 62)) return minimiser_lobes(a, b);
  lobe_list<big_int> out;
  for (const auto& f : minimiser_lobes(a.convert_to<std::int64_t>(), b.convert_to<std::int64_t>()))
    out.push_back({big_int(f.k), big_int(f.j), big_int(f.m)});
  return out;
}

// The paper's fast node k = round(a/(2b)) for a, b > 0, exactly: {k, tie}; on a tie
// (a/(2b) = k + 1/2, which for a coprime pair happens exactly when b = 1) both k and k + 1 are
// the paper's nodes and `k` is the smaller. The lobe's offset is m = a - 2 k b (frame j = 0),
// |m| <= b.
template <class L> struct paper_node {
  L k;
  bool tie;
};
// By one division: q = floor((a + b)/(2b)); a tie (a = b mod 2b) is a + b = 0 mod 2b, and then
// k = q - 1 = (a - b)/(2b).
template <class L> paper_node<L> paper_fast_node(const L& a, const L& b) {
  const L twob = 2 * b, q = L((a + b) / twob);
  const bool tie = q * twob == a + b;
  return {tie ? L(q - 1) : q, tie};
}

}  // namespace gyrores
