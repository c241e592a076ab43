// Arb balls and FLINT integers that clean up after themselves, for the Arb peers
// (peer_arb.cpp, peer_theorem.cpp). Only compiled where the bench has Arb.
#pragma once
#include <arb.h>
#include <flint/fmpz.h>

#include <gyrores/core/integer.hpp>

namespace gyrores::bench {

struct arb_ball {
  arb_t v;
  arb_ball() { arb_init(v); }
  ~arb_ball() { arb_clear(v); }
  arb_ball(const arb_ball&) = delete;
  arb_ball& operator=(const arb_ball&) = delete;
  operator arb_ptr() { return v; }
  operator arb_srcptr() const { return v; }
};

struct fmpz_int {
  fmpz_t v;
  fmpz_int() { fmpz_init(v); }
  explicit fmpz_int(const big_int& z) : fmpz_int() { fmpz_set_mpz(v, z.backend().data()); }
  ~fmpz_int() { fmpz_clear(v); }
  fmpz_int(const fmpz_int&) = delete;
  fmpz_int& operator=(const fmpz_int&) = delete;
  operator fmpz*() { return v; }
  operator const fmpz*() const { return v; }
};

}  // namespace gyrores::bench
