// The one Arb kit of the library's proofs (src/lib only, not installed): an arb_t and an fmpz_t
// that clean up after themselves; exact integers, rationals, Q(sqrt d) numbers and enclosures as
// balls; and the ends of a ball as an enclosure (core/enclosure.hpp) or as exact rationals.
// A source file that includes it is listed in src/CMakeLists.txt (it needs Arb's include path).
#pragma once
#include <arb.h>

#include <algorithm>

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/fixed_precision.hpp>
#include <gyrores/core/quadratic.hpp>
#include <gyrores/core/rational.hpp>

namespace gyrores::arb_support {

// An arb_t that cleans up after itself.
class ball {
 public:
  ball() { arb_init(v_); }
  ball(const ball& o) : ball() { arb_set(v_, o.v_); }
  ball& operator=(const ball& o) {
    arb_set(v_, o.v_);
    return *this;
  }
  ~ball() { arb_clear(v_); }
  arb_ptr get() { return v_; }
  arb_srcptr get() const { return v_; }
  operator arb_ptr() { return v_; }
  operator arb_srcptr() const { return v_; }

 private:
  arb_t v_;
};

class fmpz_holder {
 public:
  fmpz_holder() { fmpz_init(v_); }
  explicit fmpz_holder(const big_int& v) : fmpz_holder() { fmpz_set_mpz(v_, v.backend().data()); }
  ~fmpz_holder() { fmpz_clear(v_); }
  fmpz_holder(const fmpz_holder&) = delete;
  fmpz_holder& operator=(const fmpz_holder&) = delete;
  operator fmpz*() { return v_; }
  big_int value() const {
    big_int out;
    fmpz_get_mpz(out.backend().data(), v_);
    return out;
  }

 private:
  fmpz_t v_;
};

inline void set_int(arb_t out, const big_int& v) { arb_set_fmpz(out, fmpz_holder(v)); }

inline void set_rational(arb_t out, const big_rational& q, slong prec) {
  ball den;
  set_int(out, big_int(boost::multiprecision::numerator(q)));
  set_int(den, big_int(boost::multiprecision::denominator(q)));
  arb_div(out, out, den, prec);
}

// (p + q sqrt d)/r with `prec` bits relative: p and q sqrt d can cancel, but never below
// 1/(2 max(|p|, |q| sqrt d)) (the norm p^2 - q^2 d is a non-zero integer), so the sum is formed
// with twice their bit length more.
inline void set_quadratic(arb_t out, const quadratic_number& v, slong prec) {
  const auto bits = [](const big_int& z) { return z == 0 ? slong(0) : slong(boost::multiprecision::msb(z < 0 ? big_int(-z) : z)); };
  const slong work = prec + 2 * std::max(bits(v.p()), bits(v.q()) + bits(v.d()) / 2 + 1) + 16;
  ball t;
  set_int(out, v.p());
  if (!v.is_rational()) {
    set_int(t, v.d());
    arb_sqrt(t, t, work);
    ball q;
    set_int(q, v.q());
    arb_mul(t, t, q, work);
    arb_add(out, out, t, work);
  }
  set_int(t, v.r());
  arb_div(out, out, t, prec);
}

// The ball holding [lo, hi] (lo <= hi, exact rationals).
inline void set_interval(arb_t out, const big_rational& lo, const big_rational& hi, slong prec) {
  ball a, b;
  set_rational(a, lo, prec);
  set_rational(b, hi, prec);
  arb_union(out, a, b, prec);
}

// An exact copy of a finite arf, an MPFR number of its own bits.
inline exact_binary binary_of(const arf_t v) {
  exact_binary out(std::max<slong>(2, arf_bits(v)));
  arf_get_mpfr(out.get(), v, MPFR_RNDN);
  return out;
}

// The interval of a finite ball (its ends rounded outward to the interval's precision), and the
// ball of an interval.
inline void interval_of(fixed_mpfi& out, const arb_t v) {
  mpfi_ptr p = out;
  arb_get_interval_mpfr(&p->left, &p->right, v);
}
inline void set_ball(arb_t out, const fixed_mpfi& v, slong prec) { arb_set_interval_mpfr(out, v.left(), v.right(), prec); }

// The ball holding an enclosure, and the enclosure of a finite ball (its ends exactly, at `prec`
// bits rounded outward: arb_get_interval_mpfr).
inline void set_enclosure(arb_t out, const enclosure& e, slong prec) {
  arb_set_interval_mpfr(out, e.lo(), e.hi(), prec);
}
inline enclosure enclosure_of(const arb_t v, slong prec) {
  exact_binary lo(prec), hi(prec);
  arb_get_interval_mpfr(lo.get(), hi.get(), v);
  return enclosure(lo, hi);
}

// The exact rational value of a finite arf; a rational lower (upper) bound of every value of v
// (its ends rounded outward to prec bits, as arb_get_lbound_arf/arb_get_ubound_arf round them).
inline big_rational arf_rational(const arf_t v) { return rational_of(binary_of(v)); }
inline big_rational lower_rational(const arb_t v, slong prec) { return enclosure_of(v, prec).lo_rational(); }
inline big_rational upper_rational(const arb_t v, slong prec) { return enclosure_of(v, prec).hi_rational(); }

}  // namespace gyrores::arb_support
