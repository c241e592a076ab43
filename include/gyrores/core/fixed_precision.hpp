// MPFR numbers and MPFI intervals at an explicit precision, for code that must not depend on the
// process-wide default precision of Boost's wrappers (the sweep's worker threads) or that wants
// no heap traffic in a hot path (the certificates). Thin RAII owners: arithmetic is the C API.
// Up to 256 bits the significands live inside the object (MPFR's custom interface: such a
// variable works with every MPFR function but mpfr_set_prec and mpfr_clear), so the many
// short-lived temporaries of a proof cost no allocation; beyond, they are MPFR's own. The objects
// cannot be copied or moved (the variable points into them).
#pragma once
#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace gyrores {

namespace detail {
inline constexpr std::size_t fixed_inline_limbs = 4;  // 256 bits
// Initialises v at prec on buf (true) or on the heap (false).
inline bool fixed_init(mpfr_ptr v, mpfr_prec_t prec, mp_limb_t* buf) {
  if (mpfr_custom_get_size(prec) > fixed_inline_limbs * sizeof(mp_limb_t)) {
    mpfr_init2(v, prec);
    return false;
  }
  mpfr_custom_init(buf, prec);
  mpfr_custom_init_set(v, MPFR_NAN_KIND, 0, prec, buf);
  return true;
}
}  // namespace detail

class fixed_mpfr {
 public:
  explicit fixed_mpfr(mpfr_prec_t prec) : inline_(detail::fixed_init(v_, prec, buf_)) {}
  ~fixed_mpfr() {
    if (!inline_) mpfr_clear(v_);
  }
  fixed_mpfr(const fixed_mpfr&) = delete;
  fixed_mpfr& operator=(const fixed_mpfr&) = delete;
  operator mpfr_ptr() { return v_; }
  operator mpfr_srcptr() const { return v_; }

 private:
  mpfr_t v_;
  mp_limb_t buf_[detail::fixed_inline_limbs];
  bool inline_;
};

class fixed_mpfi {
 public:
  explicit fixed_mpfi(mpfr_prec_t prec)
      : inline_left_(detail::fixed_init(&v_->left, prec, left_)), inline_right_(detail::fixed_init(&v_->right, prec, right_)) {}
  ~fixed_mpfi() {
    if (!inline_left_) mpfr_clear(&v_->left);
    if (!inline_right_) mpfr_clear(&v_->right);
  }
  fixed_mpfi(const fixed_mpfi&) = delete;
  fixed_mpfi& operator=(const fixed_mpfi&) = delete;
  operator mpfi_ptr() { return v_; }
  operator mpfi_srcptr() const { return v_; }
  mpfr_srcptr left() const { return &v_->left; }
  mpfr_srcptr right() const { return &v_->right; }
  // The ends as doubles, rounded outward.
  double lo() const { return mpfr_get_d(&v_->left, MPFR_RNDD); }
  double hi() const { return mpfr_get_d(&v_->right, MPFR_RNDU); }

 private:
  mpfi_t v_;
  mp_limb_t left_[detail::fixed_inline_limbs], right_[detail::fixed_inline_limbs];
  bool inline_left_, inline_right_;
};

// Relative width (hi - lo)/min(|lo|, |hi|) <= 2^-e, for an interval not containing 0 (false if
// it does).
inline bool fixed_narrow(const fixed_mpfi& A, int e) {
  if (mpfi_has_zero(A)) return false;
  fixed_mpfr w(mpfi_get_prec(A)), m(mpfi_get_prec(A));
  mpfr_sub(w, A.right(), A.left(), MPFR_RNDU);
  if (mpfr_cmpabs(A.left(), A.right()) < 0) mpfr_abs(m, A.left(), MPFR_RNDD);
  else mpfr_abs(m, A.right(), MPFR_RNDD);
  mpfr_mul_2si(m, m, -e, MPFR_RNDD);
  return mpfr_cmp(w, m) <= 0;
}

}  // namespace gyrores
