// include/gyrores/model/fractions.hpp; the arguments are proofs/band-theorem.md, Step 3.
#include <gyrores/model/fractions.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores {

namespace {

// (num + t v_num)/(den + t v_den) for vectors (num, den).
fraction plus_times(const fraction& a, const big_int& t, const fraction& v) { return {a.p + t * v.p, a.q + t * v.q}; }

// The least t >= 1 with (a + t v) strictly beyond `end` on v's side, for a on the other side of
// `end` than v: (a_p + t v_p) > end (a_q + t v_q) when v lies above end (above = true), < when below.
// With s = v_p - end v_q (of v's sign side, nonzero) and r = end a_q - a_p: t s > r (above) or
// t s < r (below), i.e. t > r/s in both cases after dividing by s (s > 0 above, s < 0 below).
big_int first_beyond(const fraction& a, const fraction& v, const quadratic_number& end) {
  const quadratic_number r = end * quadratic_number(a.q) - quadratic_number(a.p);
  const quadratic_number s = quadratic_number(v.p) - end * quadratic_number(v.q);
  const big_int t = (r / s).floor() + 1;
  return t < 1 ? big_int(1) : t;
}

}  // namespace

simplest_fraction simplest_in(const quadratic_number& a, const quadratic_number& b) {
  if (a.sign() < 0 || b > quadratic_number(1)) throw usage_error("simplest_in: needs 0 <= a < b <= 1");
  fraction left{0, 1}, right{1, 0};
  // Each pass consumes one run (one partial quotient of an end); an interval of width w needs
  // O(log 1/w) of them. The bound only stops a call whose ends are out of order (a >= b).
  for (int runs = 0;; ++runs) {
    if (runs > 100000) throw usage_error("simplest_in: the interval is empty or its ends are out of order");
    const fraction mid{left.p + right.p, left.q + right.q};
    const quadratic_number m(mid.p, mid.q);
    if (m <= a) {
      // Move right by the whole run: the largest k with (left + k right) <= a, at least 1.
      const quadratic_number num = a * quadratic_number(left.q) - quadratic_number(left.p);
      const quadratic_number den = quadratic_number(right.p) - a * quadratic_number(right.q);
      big_int k = (num / den).floor();
      if (k < 1) k = 1;
      left = plus_times(left, k, right);
    } else if (m >= b) {
      // Move left by the whole run: the largest k with (right + k left) >= b (right = 1/0 too).
      const quadratic_number num = quadratic_number(right.p) - b * quadratic_number(right.q);
      const quadratic_number den = b * quadratic_number(left.q) - quadratic_number(left.p);
      big_int k = (num / den).floor();
      if (k < 1) k = 1;
      right = plus_times(right, k, left);
    } else {
      return {mid, left, right};
    }
  }
}

fraction least_of_parity_in(const quadratic_number& a, const quadratic_number& b, int parity) {
  const simplest_fraction s = simplest_in(a, b);
  if (int(s.simplest.q % 2) == parity) return s.simplest;
  // The fractions in (a, b) are the simplest one and its descendants parent + t v (t >= 1) and
  // deeper ones; the least denominator of the wanted parity has the parent's coefficient 1
  // (band-theorem.md, the parities of the descendants), with the least t that stays inside and
  // has the parity: t or t + 1.
  const fraction& v = s.simplest;
  fraction best{0, 0};
  for (int side = 0; side < 2; ++side) {
    const fraction& parent = side == 0 ? s.left : s.right;
    const big_int t0 = first_beyond(parent, v, side == 0 ? a : b);
    for (big_int t = t0; t <= t0 + 1; ++t) {
      const fraction c = plus_times(parent, t, v);
      if (int(c.q % 2) == parity) {
        if (best.q == 0 || c.q < best.q) best = c;
        break;
      }
    }
  }
  return best;
}

peak_piece peak_piece_of(const fraction& peak, const big_int& K) {
  const big_int& P = peak.p;
  const big_int& Q = peak.q;
  if (Q % 2 == 0 || Q > 2 * K - 1 || int_gcd(P < 0 ? big_int(-P) : P, Q) != 1)
    throw usage_error("peak_piece_of: needs an odd Q <= 2K - 1 coprime to P");
  const big_int inv = int_inverse_mod(big_int(((P % Q) + Q) % Q), Q);
  // The largest q <= 2K, q even, q == res (mod Q): the class res + Q (if res is odd) mod 2Q.
  const auto largest = [&](big_int res) {
    res = ((res % Q) + Q) % Q;
    if (res % 2 != 0) res += Q;
    return big_int(res + ((2 * K - res) / (2 * Q)) * 2 * Q);
  };
  const big_int q1 = largest(inv), q2 = largest(-inv);
  return {{big_int((q1 * P - 1) / Q), q1}, {big_int((P * q2 + 1) / Q), q2}};
}

}  // namespace gyrores
