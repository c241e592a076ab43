// Exact numbers of Q(sqrt D) and the rotation minima (MinFrac, FirstHit) of the independent
// checkers (horizon_checker.cpp, band_checker.cpp), written from proofs/horizon-theorem.md
// ("Exact arithmetic in Q(sqrt D)", "Rotation minima"). FLINT only; no header of include/gyrores/.
#pragma once
#include <optional>

#include "checker_support.hpp"

namespace gyrores_checker::exact {

using support::Z;

// (p + q sqrt D)/r, r > 0; D is 0 when it is a perfect square (then q = 0 throughout).
struct field {
  Z D;
};
struct QD {
  Z p, q, r{1};
};
struct minimum {
  QD value;
  Z k;
};

void normalise(QD& a);
QD rational(long p, long r);
QD integer(const Z& z);
QD add(const QD& a, const QD& b);
QD neg(const QD& a);
QD sub(const QD& a, const QD& b);
QD mul(const field& F, const QD& a, const QD& b);
QD inv(const field& F, const QD& a);
QD div(const field& F, const QD& a, const QD& b);
int sign(const field& F, const QD& a);
int cmp(const field& F, const QD& a, const QD& b);
Z floor_of(const field& F, const QD& a);
Z ceil_of(const field& F, const QD& a);
QD frac(const field& F, const QD& a);
// MinFrac(alpha, beta, K) = (min over 0 <= k <= K of {k alpha + beta}, its smallest argmin).
minimum min_frac(const field& F, const QD& alpha, const QD& beta, const Z& K);
// FirstHit(alpha, beta, w, K): the smallest k in [0, K] with {k alpha + beta} <= w, or none.
std::optional<Z> first_hit(const field& F, const QD& alpha, const QD& beta, const QD& w, const Z& K);
// The first k in [0, K] with nu_k <= d (d in [0, 1/2)).
std::optional<Z> first_lobe_at_most(const field& F, const QD& x, const QD& d, const Z& K);

// A ball of a at prec bits (Arb): p and q sqrt D may cancel, so they are formed at a working
// precision their bit lengths give.
support::B ball_of(const field& F, const QD& a, long prec);

}  // namespace gyrores_checker::exact
