// src/testing/naive_forms.hpp: the Illinois bracket.
#include "testing/naive_forms.hpp"

namespace gyrores::test {

double illinois_bracket::next() const {
  double c = (fhi - flo) != 0 ? (lo * fhi - hi * flo) / (fhi - flo) : 0.5 * (lo + hi);
  if (!(c > lo && c < hi)) c = 0.5 * (lo + hi);
  return c;
}

void illinois_bracket::update(double c, double fc) {
  if ((fc < 0) == (flo < 0)) {
    lo = c;
    flo = fc;
    if (side == -1) fhi /= 2;
    side = -1;
  } else {
    hi = c;
    fhi = fc;
    if (side == 1) flo /= 2;
    side = 1;
  }
}

}  // namespace gyrores::test
