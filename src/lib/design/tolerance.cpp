// include/gyrores/design/tolerance.hpp
#include <gyrores/design/tolerance.hpp>

#include <boost/multiprecision/integer.hpp>

#include <gyrores/core/error.hpp>

namespace gyrores {

std::pair<big_rational, big_rational> tolerance_band(const design_point& p, const big_rational& fraction) {
  // sqrt(tau sigma) in [s_lo, s_lo + 10^-12] from an integer square root.
  const big_int scale = boost::multiprecision::pow(big_int(10), 12);
  const big_int root = boost::multiprecision::sqrt(big_int(big_int(p.tau) * p.sigma * scale * scale));
  const big_rational s_lo(root, scale), s_hi(big_int(root + 1), scale), delta(p.tau - p.sigma);
  return {delta / s_hi * (1 - fraction), delta / s_lo * (1 + fraction)};
}

std::string tolerance_verdict_name(tolerance_verdict v) {
  switch (v) {
    case tolerance_verdict::meets: return "meets";
    case tolerance_verdict::fails: return "fails";
    default: return "undecided";
  }
}

tolerance_result design_with_tolerance(const std::vector<design_point>& ranked, design_problem problem,
                                       const tolerance_options& opt) {
  if (!(opt.fraction > 0) || !(opt.fraction < 1)) throw usage_error("the tolerance must be in (0%, 100%)");
  if (opt.level < 0) throw usage_error("the level E must be >= 0");
  tolerance_result out;
  const bool absorb = problem == design_problem::absorb;
  for (std::size_t i = 0; i < ranked.size() && i < opt.max_pairs; ++i) {
    const auto [n1, n2] = tolerance_band(ranked[i], opt.fraction);
    band_options bo = opt.band;
    bo.versus = opt.level;  // the verdict needs only the side of E, not every digit
    tolerance_check c{ranked[i], n1, n2,
                      absorb ? prove_band_absorption(n1, n2, opt.horizon, bo) : prove_band_containment(n1, n2, opt.horizon, bo),
                      tolerance_verdict::undecided};
    if (c.guarantee.interrupted) {  // the bracket reached is still proved: returned with the rest
      out.checked.push_back(std::move(c));
      out.interrupted = true;
      break;
    }
    const big_rational lo = c.guarantee.value.lo_rational(), hi = c.guarantee.value.hi_rational();
    // absorb: every coupling of the band drains to E (W <= E); contain: every one stays above (B >= E).
    if (absorb ? hi <= opt.level : lo >= opt.level) c.verdict = tolerance_verdict::meets;
    else if (absorb ? lo > opt.level : hi < opt.level) c.verdict = tolerance_verdict::fails;
    out.checked.push_back(std::move(c));
    if (out.checked.back().verdict == tolerance_verdict::meets) {
      out.chosen = out.checked.size() - 1;
      break;
    }
  }
  return out;
}

}  // namespace gyrores
