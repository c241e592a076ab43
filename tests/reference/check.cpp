// The independent checker (reference/check.hpp), in named steps: the header, the degenerate case,
// the cover level (basin and cover), the working level (claims against the checker's own
// enclosures).
#include "reference/check.hpp"

#include <limits>
#include <optional>

#include "reference/cover.hpp"
#include "reference/proof_steps.hpp"
#include <gyrores/core/decimal.hpp>
#include <gyrores/core/error.hpp>
#include <gyrores/model/pair.hpp>

namespace gyrores {

namespace {

using proof::I;
using claim_text = std::pair<std::string, std::string>;

check_verdict fail(const std::string& why) { return {false, why}; }

// A claim holds if its exact decimal interval contains the checker's enclosure: the endpoints
// are read inward (decimal_interval_contains), 64 bits finer than the working precision so that
// an honest claim, rounded outward to its digits, is never missed.
bool claim_contains(const certificate& c, const claim_text& claim, const I& mine) {
  scoped_digits fine(digits10_for_bits(c.working_bits + 64));
  return decimal_interval_contains(claim.first, claim.second, mine);
}

bool claim_meets_digits(const certificate& c, const claim_text& claim) {
  scoped_digits sd(digits10_for_bits(c.working_bits) + 10);
  return proof::meets_digits(interval_from_decimal(claim.first, claim.second), c.digits);
}

std::string field(const certificate_obligation& o, const char* key) {
  auto it = o.data.find(key);
  if (it == o.data.end()) throw usage_error("obligation " + o.id + ": missing field " + key);
  return it->second;
}

// Format, pair, degenerate flag and ranges; the pair when they hold.
std::optional<check_verdict> check_header(const certificate& c, const certify_options& opt,
                                          std::optional<resonant_pair<big_int>>& pair) {
  if (c.format != certificate_format) return fail("format: expected " + std::string(certificate_format));
  try {
    pair.emplace(c.tau, c.sigma);
  } catch (const usage_error& e) {
    return fail(std::string("pair: ") + e.what());
  }
  if (c.degenerate != pair->degenerate()) return fail("degenerate: the pair's delta mod 4 says otherwise");
  if (c.working_bits < 16 || c.working_bits > opt.max_bits || c.cover_bits < 16 || c.cover_bits > opt.max_bits)
    return fail("working_bits: out of range");
  if (c.digits < 1 || c.digits > 10000) return fail("digits: out of range");
  return std::nullopt;
}

// delta = 2 mod 4: the integer facts, r_res = [0, 0], and theta_first = pi/2.
check_verdict check_degenerate(const certificate& c, const resonant_pair<big_int>& p) {
  const auto* deg = find_obligation(c, "degenerate");
  if (!deg) return fail("obligation degenerate: missing");
  if (p.delta_mod4() != 2 || int_mod(big_int(p.tau() + p.sigma()), big_int(4)) != 0)
    return fail("obligation degenerate: integer facts do not hold");
  if (field(*deg, "delta_mod4") != std::to_string(p.delta_mod4()) ||
      field(*deg, "tau_mod4") != int_mod(p.tau(), big_int(4)).str() ||
      field(*deg, "sigma_mod4") != int_mod(p.sigma(), big_int(4)).str())
    return fail("obligation degenerate: recorded residues differ from the pair's");
  if (c.global_minimality_note != degenerate_note)
    return fail(std::string("global_minimality_note: must be \"") + degenerate_note + "\"");
  scoped_digits sd(digits10_for_bits(c.working_bits));
  auto K = proof::constants_of(p);
  I th = K.c.pi / 2, t = K.c.sqrt_ts * th;
  if (c.r_res.first != "0" || c.r_res.second != "0") return fail("claim r_res: must be exactly [0, 0]");
  if (!claim_contains(c, c.theta_first, th)) return fail("claim theta_first: does not contain pi/2");
  if (!claim_contains(c, c.t_first, t)) return fail("claim t_first: does not contain sqrt(tau sigma) pi/2");
  if (!claim_meets_digits(c, c.theta_first) || !claim_meets_digits(c, c.t_first))
    return fail("claims: fewer digits than stated");
  if (c.minimiser_count != 2) return fail("claim minimiser_count: degenerate pairs have exactly 2 zeros");
  if (!c.global_minimality) return fail("claim global_minimality: must be true for a degenerate pair");
  if (c.cover_bits != c.working_bits) return fail("cover_bits: must equal working_bits for a degenerate pair");
  return {true, ""};
}

// The local root's frame and the number of symmetry images, as recorded, against the checker's.
std::optional<check_verdict> check_recorded_frame(const certificate& c, const proof::minimiser_enclosures& loc) {
  const auto& root = *find_obligation(c, "local-root");
  if (field(root, "k") != loc.frame.k.str() || field(root, "j") != loc.frame.j.str() ||
      field(root, "m") != loc.frame.m.str())
    return fail("obligation local-root: the frame (k, j, m) is not the minimiser's");
  if (field(*find_obligation(c, "symmetry"), "images") != std::to_string(loc.images.size()))
    return fail("obligation symmetry: the minimiser has " + std::to_string(loc.images.size()) + " images");
  return std::nullopt;
}

// The recorded root box X (working level): it contains the checker's own box and lies in the
// basin Y, so the claims come from the root the basin and the cover are about.
std::optional<check_verdict> check_recorded_root(const certificate& c, const proof::minimiser_enclosures& loc) {
  const auto& root = *find_obligation(c, "local-root");
  const auto& basin = *find_obligation(c, "basin");
  scoped_digits fine(digits10_for_bits(c.working_bits + 64));
  if (!decimal_interval_contains(field(root, "X_lo"), field(root, "X_hi"), loc.X))
    return fail("obligation local-root: X does not contain the checker's root box");
  if (!decimal_interval_contains(field(basin, "Y_lo"), field(basin, "Y_hi"),
                                 interval_from_decimal(field(root, "X_lo"), field(root, "X_hi"))))
    return fail("obligation local-root: X is not inside the basin Y");
  return std::nullopt;
}

// At cover_bits: the local root, the basin on the stated Y, and (when global minimality is
// claimed) the cover with the stated strategy and Rayleigh t, against the checker's r_hi^2.
std::optional<check_verdict> check_cover_level(const certificate& c, const resonant_pair<big_int>& p,
                                               const certify_options& opt) {
  const auto& basin = *find_obligation(c, "basin");
  scoped_digits sd(digits10_for_bits(c.cover_bits));
  auto K = proof::constants_of(p);
  auto loc = proof::enclose_minimisers(p, K);
  I mu = proof::mu_of(K, loc.frame.m);
  I Y = interval_from_decimal(field(basin, "Y_lo"), field(basin, "Y_hi"));
  if (!certainly_subset(loc.X, Y)) return fail("obligation basin: Y does not contain the certified root");
  if (!proof::certify_basin(K, mu, Y)) return fail("obligation basin: does not hold on Y");
  if (auto bad = check_recorded_frame(c, loc)) return bad;
  const auto& cover = *find_obligation(c, "cover");
  const std::string bits = std::to_string(c.cover_bits);
  if (field(basin, "bits") != bits || field(cover, "bits") != bits) return fail("obligations basin, cover: bits differ from cover_bits");
  I bound = interval_point(interval_upper(interval_sqr(loc.r)));
  if (field(cover, "bound") != cover_bound_text(interval_upper(bound), c.cover_bits))
    return fail("obligation cover: bound is not r_hi^2 at cover_bits");
  const std::string strategy = field(cover, "strategy");
  const std::string& note = c.global_minimality_note;
  if (c.global_minimality ? note != proved_note(strategy) : note.rfind("not proved", 0) != 0)
    return fail("global_minimality_note: must be \"proved (strategy)\" or start with \"not proved\"");
  if (strategy.empty()) {  // no cover was attempted (the pair is beyond the producer's limits)
    if (c.global_minimality || field(cover, "lobes") != "0" || field(cover, "boxes") != "0")
      return fail("obligation cover: no strategy, yet lobes, boxes or global minimality are recorded");
    return std::nullopt;
  }
  std::string t;
  if (strategy == "slow-nodes" && c.global_minimality) {
    const auto* ray = find_obligation(c, "rayleigh");
    if (!ray) return fail("obligation rayleigh: missing");
    t = field(*ray, "t");
  }
  // The recorded strategy is re-run (without the producer's order limit): it must prove exactly
  // when global minimality is claimed, with the recorded number of lobes and boxes.
  certify_options any_order = opt;
  any_order.max_lobes = std::numeric_limits<std::int64_t>::max();
  auto res = proof::run_cover(K, proof::basins_by_lobe(K, loc.images, Y), bound, any_order, strategy, t);
  if (c.global_minimality && !res.proved) return fail("obligation cover: " + res.note);
  if (!c.global_minimality && res.proved) return fail("obligation cover: proves, but global minimality is not claimed");
  if (field(cover, "lobes") != std::to_string(res.stats.lobes) || field(cover, "boxes") != std::to_string(res.stats.boxes))
    return fail("obligation cover: recorded lobes or boxes differ from the checker's run");
  return std::nullopt;
}

// Global minimality claimed: every claim contains the checker's enclosure and meets the digits.
check_verdict check_global_claims(const certificate& c, const proof::minimiser_enclosures& loc) {
  if (!claim_contains(c, c.r_res, loc.r)) return fail("claim r_res: does not contain the checker's enclosure");
  if (!claim_contains(c, c.theta_first, loc.theta_first))
    return fail("claim theta_first: does not contain the checker's enclosure");
  if (!claim_contains(c, c.t_first, loc.t_first))
    return fail("claim t_first: does not contain the checker's enclosure");
  if (!claim_meets_digits(c, c.r_res)) return fail("claim r_res: fewer digits than stated");
  if (!claim_meets_digits(c, c.theta_first)) return fail("claim theta_first: fewer digits than stated");
  if (!claim_meets_digits(c, c.t_first)) return fail("claim t_first: fewer digits than stated");
  if (c.minimiser_count != loc.images.size())
    return fail("claim minimiser_count: the symmetry images number " + std::to_string(loc.images.size()));
  return {true, ""};
}

// Not proved globally: only r_res <= hi may be claimed (the claim is [0, hi]), and it must hold:
// |q| at the certified root is one value of sqrt(R), so the minimum is at most it.
check_verdict check_upper_bound_claim(const certificate& c, const proof::minimiser_enclosures& loc) {
  if (c.r_res.first != "0") return fail("claim r_res: without global minimality the lower end must be 0");
  if (!claim_contains(c, c.r_res, loc.r)) return fail("claim r_res: upper bound below the checker's enclosure");
  {  // hi is the D-digit upper end of |q| at the root: [checker's lower end, hi] is D digits narrow
    scoped_digits sd(digits10_for_bits(c.working_bits) + 10);
    const I hi = interval_from_decimal(c.r_res.second, c.r_res.second);
    if (!proof::meets_digits(interval_of(interval_lower(loc.r), interval_upper(hi)), c.digits))
      return fail("claim r_res: the upper bound is not within the stated digits of the checker's |q|");
  }
  if (!c.theta_first.first.empty() || !c.t_first.first.empty() || c.minimiser_count != 0)
    return fail("claims: theta_first, t_first and minimiser_count need global minimality");
  return {true, ""};
}

}  // namespace

check_verdict check_certificate(const certificate& c, const certify_options& opt) {
  std::optional<resonant_pair<big_int>> pair;
  if (auto bad = check_header(c, opt, pair)) return *bad;
  const auto& p = *pair;
  if (p.degenerate()) return check_degenerate(c, p);
  for (const char* id : {"local-root", "basin", "symmetry", "cover"})
    if (!find_obligation(c, id)) return fail(std::string("obligation ") + id + ": missing");
  if (auto bad = check_cover_level(c, p, opt)) return *bad;
  scoped_digits sd(digits10_for_bits(c.working_bits));
  auto K = proof::constants_of(p);
  auto loc = proof::enclose_minimisers(p, K);
  if (auto bad = check_recorded_root(c, loc)) return *bad;
  return c.global_minimality ? check_global_claims(c, loc) : check_upper_bound_claim(c, loc);
}

}  // namespace gyrores
