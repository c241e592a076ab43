// include/gyrores/model/coupling.hpp
#include <gyrores/model/coupling.hpp>

namespace gyrores {

coupling_spec coupling_spec::from_n(const big_rational& n) {
  if (n == 0) throw usage_error("n = 0 means no coupling: H_q = qdot0^2/2 for all t (nothing to analyse)");
  return {n * n, n};
}

coupling_spec coupling_spec::from_n2(const big_rational& n2) {
  if (n2 < 0) throw usage_error("n^2 must be > 0, got " + rational_str(n2));
  if (n2 == 0) throw usage_error("n^2 = 0 means no coupling: H_q = qdot0^2/2 for all t (nothing to analyse)");
  return {n2, std::nullopt};
}

big_int coupling_spec::P() const { return boost::multiprecision::numerator(n2); }
big_int coupling_spec::Q() const { return boost::multiprecision::denominator(n2); }
big_int coupling_spec::discriminant() const { return P() * (P() + 4 * Q()); }

std::optional<resonant_pair<big_int>> coupling_resonant_pair(const coupling_spec& c) {
  big_int root;
  if (!int_is_square(c.discriminant(), root)) return std::nullopt;
  return pair_from_ratio(c.P() + 2 * c.Q() + root, 2 * c.Q());
}

namespace {

// The convergents p_k/q_k from the partial quotients a_k (p_k = a_k p_{k-1} + p_{k-2}, same for q).
class convergent_list {
 public:
  explicit convergent_list(std::size_t max_terms) : max_terms_(max_terms) {}
  bool full() const { return out_.size() >= max_terms_; }
  void push(const big_int& a) {
    big_int p = a * p_prev_ + p_prev2_, q = a * q_prev_ + q_prev2_;
    out_.push_back({a, p, q});
    p_prev2_ = p_prev_;
    p_prev_ = p;
    q_prev2_ = q_prev_;
    q_prev_ = q;
  }
  std::vector<ratio_convergent> take() { return std::move(out_); }

 private:
  std::size_t max_terms_;
  std::vector<ratio_convergent> out_;
  big_int p_prev_ = 1, p_prev2_ = 0, q_prev_ = 0, q_prev2_ = 1;  // p_{-1}, p_{-2}, q_{-1}, q_{-2}
};

// Plain Euclid on the reduced fraction num/den (num, den > 0).
std::vector<ratio_convergent> fraction_convergents(big_int num, big_int den, std::size_t max_terms) {
  convergent_list out(max_terms);
  big_int g = int_gcd(num, den);
  num /= g;
  den /= g;
  while (den != 0 && !out.full()) {
    big_int a = num / den;
    big_int r = num - a * den;
    out.push(a);
    num = den;
    den = r;
  }
  return out.take();
}

// The quadratic irrational (m + sqrt D)/d with d | D - m^2 (sq = isqrt D, D not a square).
std::vector<ratio_convergent> quadratic_convergents(big_int m, big_int d, const big_int& D, const big_int& sq,
                                                    std::size_t max_terms) {
  convergent_list out(max_terms);
  while (!out.full()) {
    // a = floor((m + sqrt D)/d). For d > 0 it is floor((m + sq)/d); for d < 0, -(m + sqrt D)
    // lies in (-(m + sq + 1), -(m + sq)), so it is floor(-(m + sq + 1)/(-d)).
    const big_int a = d > 0 ? int_floor_div<big_int>(m + sq, d) : int_floor_div<big_int>(-(m + sq + 1), -d);
    out.push(a);
    big_int m_next = a * d - m;
    big_int d_next = (D - m_next * m_next) / d;
    m = m_next;
    d = d_next;
  }
  return out.take();
}

}  // namespace

std::vector<ratio_convergent> coupling_convergents(const coupling_spec& c, std::size_t max_terms) {
  const big_int P = c.P(), Q = c.Q(), D = c.discriminant();
  const big_int m = P + 2 * Q, d = 2 * Q;  // W1/W2 = (m + sqrt D)/d; D - m^2 = -4 Q^2
  big_int sq;
  if (int_is_square(D, sq)) return fraction_convergents(m + sq, d, max_terms);
  return quadratic_convergents(m, d, D, sq, max_terms);
}

quadratic_number coupling_rotation_number(const coupling_spec& c) {
  const big_int P = c.P(), Q = c.Q(), D = c.discriminant();
  big_int root;
  if (int_is_square(D, root)) return quadratic_number(root, P + 4 * Q);
  return quadratic_number(0, 1, P + 4 * Q, D);
}

}  // namespace gyrores
