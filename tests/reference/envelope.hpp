// The support function of the convex envelope (model/model.hpp, envelope_boundary), for the
// tests of the envelope and of the figures: the product draws the boundary only.
#pragma once
#include <gyrores/model/model.hpp>

namespace gyrores {

// Support function of the envelope in direction phi: max over the envelope of
// (cos phi, sin phi) . (q, q'). A trajectory point p lies in the envelope iff
// p . u(phi) <= envelope_support(phi) for every phi.
template <class T> T envelope_support(const T& n, const T& v, const T& phi) {
  const auto e = envelope_direction_of(n, v, phi);
  return e.r0 * (e.d1 + e.d2);
}

}  // namespace gyrores
