// An energy as a share of the initial energy H_q(0) = qdot0^2/2, in percent, proved: the share is
// the exact rational multiple 200/qdot0^2 of the energy, so its enclosure is the energy's
// enclosure times that rational (each end rounded outward), and the text is the correct rounding
// of that enclosure (core/enclosure.hpp), never a rescaled decimal.
#pragma once

#include <gyrores/core/enclosure.hpp>
#include <gyrores/core/rational.hpp>

namespace gyrores {

// Significant digits of a share as the text outputs print it ("0.2575%").
inline constexpr unsigned share_digits = 4;

// 100 / H_q(0) = 200/qdot0^2 (qdot0 > 0).
big_rational share_factor(const big_rational& qdot0 = 1);

// e times k > 0: exact when e is, else each end multiplied with outward rounding.
enclosure scaled(const enclosure& e, const big_rational& k);

}  // namespace gyrores
