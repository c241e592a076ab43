// The coupling certificates of certify/horizon_certificate.hpp, written from the horizon
// theorem's proofs (theorem/horizon.hpp): the decisions and integers as they are, the brackets
// and claims as outward decimal text of the proofs' enclosures.
#include <gyrores/certify/horizon_certificate.hpp>

#include <gyrores/core/error.hpp>
#include <gyrores/model/rotation.hpp>

namespace gyrores {
namespace {

// An exact zero, as the format writes it.
const decimal_bracket zero_bracket{"0", "0"};

// A proved bracket: its ends' decimals to certificate_digits(digits) (proved with them), or an
// exact 0.
decimal_bracket bracket_text(const proved_bracket& bracket, unsigned digits) {
  if (bracket.ends.is_exact()) return zero_bracket;
  // A proof made for a report only, or for fewer digits: its decimals are not proved.
  if (bracket.decimals != certificate_digits(digits))
    throw compute_error("coupling certificate: the proof was not made for a certificate of these digits");
  return bracket.ends.outward(certificate_digits(digits));
}

// A claim: the enclosure rounded outward to digits + 3 digits; compute_error unless its
// relative width is at most 10^-(digits + 1) (the outward rounding then adds at most
// 2 10^-(digits + 2): the claim is within the checker's 10^-digits).
decimal_bracket claim_of(const enclosure& e, unsigned digits, const char* name) {
  if (!e.is_exact()) {
    const big_rational lo = e.lo_rational(), width = e.hi_rational() - lo;
    if (lo <= 0 || width * big_rational(boost::multiprecision::pow(big_int(10), digits + 1)) > lo)
      throw compute_error(std::string("coupling certificate: the claim ") + name + " is wider than " +
                          std::to_string(digits) + " digits (the proof was made with fewer)");
  }
  return e.outward(digits + 3);
}

certificate_lobe lobe_entry(const quadratic_number& x, const lobe_root& r, unsigned digits) {
  certificate_lobe l;
  l.k = r.lobe.k;
  l.j = (x * quadratic_number(r.lobe.k)).floor();
  l.side = r.lobe.k == 0 ? 1 : r.lobe.side;  // lobe 0: only u >= 0 is in [0, T]
  l.root = bracket_text(r.bracket, digits);
  return l;
}

}  // namespace

void check_certificate_horizon(const horizon_time& T, const char* what) {
  if (T.times_pi)
    throw usage_error(std::string(what) + " states its horizon as a rational, and " + T.str() +
                      " is a multiple of pi: give T as a decimal or a fraction");
  if (T.value <= 0) throw usage_error(std::string(what) + " needs a horizon T > 0, got " + rational_str(T.value));
}

horizon_certificate horizon_certificate_of(const coupling_spec& c, const horizon_minimum_proof& p, unsigned digits) {
  check_certificate_horizon(p.horizon);
  horizon_certificate out;
  out.theorem = horizon_theorem_id;
  out.n2 = c.n2;
  out.horizon = p.horizon.value;
  out.digits = digits;
  out.cut_lobe = p.cut_lobe;
  out.cut_lobe_reached = p.cut_lobe_reached;
  out.at_horizon_end = p.at_horizon_end;
  out.cut_root = bracket_text(p.cut.bracket, digits);
  // The admissible lobes are 0..K_T; at the horizon's end the best of them is still stated, as
  // the checker needs its value to prove R(T) below it.
  if (p.best) out.lobe = lobe_entry(p.x, *p.best, digits);
  const bool zero = !p.at_horizon_end && p.best && p.best->lobe.nu.sign() == 0;
  out.h_min = zero ? zero_bracket : claim_of(p.h_min, digits, "h_min");
  out.t_min = claim_of(p.t_min, digits, "t_min");
  return out;
}

below_certificate below_certificate_of(const coupling_spec& c, const first_below_proof& p, unsigned digits) {
  const quadratic_number x = coupling_rotation_number(c);
  below_certificate out;
  out.level = p.level;
  switch (p.kase) {
    case below_case::start:
      out.kase = "start";
      out.t_below = zero_bracket;
      return out;
    case below_case::zero:
      out.kase = "zero";
      out.lobe = lobe_entry(x, *p.lobe, digits);
      out.t_below = claim_of(p.t_below, digits, "t_below");
      return out;
    case below_case::never: out.kase = "never"; break;
    case below_case::lobe: out.kase = "lobe"; break;
  }
  // Below V(1/2) (never, or a lobe k* >= 1): the level's root and delta, as the proof decided them.
  if (p.level_root && (p.kase == below_case::never || p.lobe->lobe.k > 0)) {
    out.level_root = bracket_text(*p.level_root, digits);
    out.delta = bracket_text(*p.delta, digits);
  }
  if (p.kase == below_case::never) return out;
  out.lobe = lobe_entry(x, *p.lobe, digits);
  out.crossing = bracket_text(*p.crossing, digits);
  out.t_below = claim_of(p.t_below, digits, "t_below");
  return out;
}

horizon_certificate certify_horizon_minimum(const coupling_spec& c, const big_rational& T, unsigned digits) {
  const horizon_time horizon(T);
  check_certificate_horizon(horizon);
  return horizon_certificate_of(c, prove_horizon_minimum(c, horizon, {digits, {}}, proof_use::certificate), digits);
}

}  // namespace gyrores
