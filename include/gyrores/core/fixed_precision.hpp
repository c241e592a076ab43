// MPFR numbers and MPFI intervals at an explicit precision, for code that must not depend on the
// process-wide default precision of Boost's wrappers (the sweep's worker threads) or that wants
// no temporaries in a hot path (the certificates). Thin RAII owners: arithmetic is the C API.
#pragma once
#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>

namespace gyrores {

class fixed_mpfr {
 public:
  explicit fixed_mpfr(mpfr_prec_t prec) { mpfr_init2(v_, prec); }
  ~fixed_mpfr() { mpfr_clear(v_); }
  fixed_mpfr(const fixed_mpfr&) = delete;
  fixed_mpfr& operator=(const fixed_mpfr&) = delete;
  operator mpfr_ptr() { return v_; }
  operator mpfr_srcptr() const { return v_; }

 private:
  mpfr_t v_;
};

class fixed_mpfi {
 public:
  explicit fixed_mpfi(mpfr_prec_t prec) { mpfi_init2(v_, prec); }
  ~fixed_mpfi() { mpfi_clear(v_); }
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
