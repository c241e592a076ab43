// The cover certificate of the tests' reference (tests/reference/: the retired format /1, an
// oracle for the theorem's certificates and the proof programs, no longer part of the product):
// enclosures contain independent references (src/testing/high_precision_reference.hpp,
// naive formulation in MPFR, no lobe-frame code), widths meet the digits, the checker accepts
// honest certificates at 20, 100 and 1000 digits and rejects tampered ones; the JSON form reads
// back to the same certificate; the cover the proof programs use.
#include <catch2/catch.hpp>

#include <gyrores/core/decimal.hpp>
#include "reference/interval.hpp"
#include "reference/lattice.hpp"
#include <gyrores/model/enumerate.hpp>

#include <limits>

#include "reference/certificate_json.hpp"
#include "reference/certify.hpp"
#include "reference/check.hpp"
#include "reference/cover.hpp"
#include "reference/proof_steps.hpp"
#include "testing/high_precision_reference.hpp"

using namespace gyrores;

namespace {

mpfi_real claim_interval(const std::pair<std::string, std::string>& c) {
  return interval_from_decimal(c.first, c.second);
}

bool claim_contains(const std::pair<std::string, std::string>& c, const mpfr_real& v) {
  return certainly_subset(interval_point(v), claim_interval(c));
}

// Move the last printed digit of "d.ddd...e+XX" by `delta` units (inward shifts of one ulp at
// the printed precision).
std::string shift_last_digit(const std::string& s, int delta) {
  auto e = s.find('e');
  std::string mant = s.substr(0, e), exp = s.substr(e + 1);
  bool neg = mant[0] == '-';
  if (neg) mant.erase(0, 1);
  auto dot = mant.find('.');
  std::string digits = mant.substr(0, dot) + (dot == std::string::npos ? "" : mant.substr(dot + 1));
  big_int v(digits);
  v += neg ? -delta : delta;
  std::string nd = v.str();
  long ex = std::stol(exp) + long(nd.size()) - long(digits.size());
  std::string out = (neg ? "-" : "") + nd.substr(0, 1) + (nd.size() > 1 ? "." + nd.substr(1) : "");
  char buf[32];
  std::snprintf(buf, sizeof buf, "e%c%02ld", ex < 0 ? '-' : '+', ex < 0 ? -ex : ex);
  return out + buf;
}

void check_against_reference(const certificate& c, const test::hp::hp_result& ref, const std::string& row) {
  INFO(row);
  if (c.degenerate) {
    CHECK(c.r_res.first == "0");
    CHECK(c.r_res.second == "0");
  } else {
    CHECK(claim_contains(c.r_res, ref.r_res));
  }
  if (c.global_minimality) {
    CHECK(claim_contains(c.theta_first, ref.theta_first));
    CHECK(claim_contains(c.t_first, ref.t_first));
    // The local-mode reference (huge pairs) cannot separate minimisers 1/a apart; there the
    // count is the structure's: 2 for delta odd, 4 for delta = 0 mod 4.
    if (ref.global) CHECK(c.minimiser_count == ref.minimisers.size());
    else CHECK(c.minimiser_count == (c.degenerate || (c.tau - c.sigma) % 2 == 1 ? 2u : 4u));
    scoped_digits sd(40);
    mpfr_real lim = pow(mpfr_real(10), -int(c.digits));
    for (auto* cl : {&c.theta_first, &c.t_first})
      CHECK(interval_rel_width(claim_interval(*cl)) <= lim);
    if (!c.degenerate) CHECK(interval_rel_width(claim_interval(c.r_res)) <= lim);
  }
}

}  // namespace

TEST_CASE("certificates contain the reference for every pair up to order 60", "[certificate]") {
  std::size_t n = 0;
  for (auto p : coprime_pairs(3, 60)) {
    resonant_pair<big_int> pb(p.tau(), p.sigma());
    auto c = certify_pair(pb, 20);
    REQUIRE(c.global_minimality);
    auto ref = test::hp::hp_reference(pb.tau(), pb.sigma(), 40);
    check_against_reference(c, ref, pb.str());
    auto v = check_certificate(c);
    INFO(pb.str() << ": " << v.failure);
    CHECK(v.holds);
    ++n;
  }
  std::int64_t expected = 0;
  for (std::int64_t a = 3; a <= 60; ++a) expected += coprime_pairs_of_order(a);
  CHECK(std::int64_t(n) == expected);
}

TEST_CASE("hard cases: huge pairs, far-apart frequencies, degenerate", "[certificate]") {
  struct row {
    const char* tau;
    const char* sigma;
    bool expect_global;
  };
  for (auto r : {row{"1000001", "1000000", true}, row{"1000000000001", "1000000000000", true},
                 row{"1000000000000000001", "1000000000000000000", true},
                 row{"1000000000000000000000000000001", "1000000000000000000000000000000", true},
                 row{"4611686018427387905", "4611686018427387903", true},  // degenerate, sum 2^63
                 row{"1000", "1", true}, row{"101", "100", true}, row{"9", "4", true}, row{"5", "1", true},
                 row{"1000004", "3", false},  // x ~ 1 and order 10^6: cover not available, says so
                 row{"1000000000", "1", false}}) {
    resonant_pair<big_int> p{big_int(r.tau), big_int(r.sigma)};
    std::string name = p.str();
    INFO(name);
    auto c = certify_pair(p, 30);
    CHECK(c.global_minimality == r.expect_global);
    if (!r.expect_global) {
      CHECK(c.r_res.first == "0");
      CHECK(c.theta_first.first.empty());
      CHECK(c.minimiser_count == 0);
      CHECK(c.global_minimality_note.find("not proved") == 0);
    }
    // Reference: local mode around the library's theta_first (a guess only) for huge pairs.
    test::hp::hp_result ref;
    if (p.order() <= big_int(test::hp::hp_scan_max_order)) {
      ref = test::hp::hp_reference(p.tau(), p.sigma(), 45);
    } else {
      scoped_digits sd(60);
      auto lat = inscribed_lattice<mpfr_real>(p, mpfr_real(1));
      ref = test::hp::hp_reference(p.tau(), p.sigma(), 45, lat.theta_first);
    }
    if (c.global_minimality) {
      check_against_reference(c, ref, name);
    } else {
      // Only r_res <= hi is claimed; it must hold.
      CHECK(certainly_subset(interval_point(ref.r_res), claim_interval({"0", c.r_res.second})));
    }
    auto v = check_certificate(c);
    INFO(v.failure);
    CHECK(v.holds);
  }
}

TEST_CASE("the checker accepts certificates at 20, 100 and 1000 digits", "[certificate]") {
  for (unsigned digits : {20u, 100u, 1000u}) {
    for (auto [t, s] : {std::pair{6, 5}, {9, 4}, {11, 9}}) {
      resonant_pair<big_int> p{big_int(t), big_int(s)};
      auto c = certify_pair(p, digits);
      INFO(p.str() << " at " << digits << " digits, " << c.working_bits << " bits");
      CHECK(c.global_minimality);
      CHECK(c.working_bits >= digits * 3);  // at least log2(10) bits per digit
      auto v = check_certificate(c);
      INFO(v.failure);
      CHECK(v.holds);
    }
  }
}

TEST_CASE("the checker rejects tampered certificates", "[certificate]") {
  for (auto [t, s] : {std::pair{6, 5}, {5, 1}, {11, 9}}) {
    resonant_pair<big_int> p{big_int(t), big_int(s)};
    const auto good = certify_pair(p, 25);
    REQUIRE(check_certificate(good).holds);
    std::vector<std::pair<std::string, certificate>> bad;
    auto add = [&](const std::string& what, auto&& mutate) {
      certificate c = good;
      mutate(c);
      bad.push_back({what, c});
    };
    if (!good.degenerate) {
      add("r_res lo up one ulp", [](certificate& c) { c.r_res.first = shift_last_digit(c.r_res.first, 1); });
      add("r_res hi down one ulp", [](certificate& c) { c.r_res.second = shift_last_digit(c.r_res.second, -1); });
      add("r_res narrowed to a point", [](certificate& c) { c.r_res.second = c.r_res.first; });
      add("drop cover", [](certificate& c) {
        std::erase_if(c.obligations, [](auto& o) { return o.id == "cover"; });
      });
      add("drop basin", [](certificate& c) {
        std::erase_if(c.obligations, [](auto& o) { return o.id == "basin"; });
      });
      add("basin too small to hold the root", [](certificate& c) {
        for (auto& o : c.obligations)
          if (o.id == "basin") o.data["Y_hi"] = o.data["Y_lo"];
      });
      add("minimiser count", [](certificate& c) { c.minimiser_count += 1; });
    } else {
      add("drop degenerate", [](certificate& c) { c.obligations.clear(); });
      add("r_res not zero", [](certificate& c) { c.r_res.second = "1e-30"; });
      add("degenerate flag", [](certificate& c) { c.degenerate = false; });
    }
    add("theta_first lo up one ulp", [](certificate& c) { c.theta_first.first = shift_last_digit(c.theta_first.first, 1); });
    add("t_first hi down one ulp", [](certificate& c) { c.t_first.second = shift_last_digit(c.t_first.second, -1); });
    add("changed pair", [](certificate& c) { c.tau += 2; });
    add("format", [](certificate& c) { c.format = "gyrores-certificate/0"; });
    add("more digits than proved", [](certificate& c) { c.digits = 60; });
    for (auto& [what, c] : bad) {
      INFO(p.str() << ": " << what);
      check_verdict v;
      try {
        v = check_certificate(c);
      } catch (const usage_error&) {
        v = {false, "malformed"};
      }
      CHECK_FALSE(v.holds);
    }
  }
}

// The exact decimal of v + 2^-shift (or - 2^-shift), printed exactly: a bound that differs from
// the checker's own endpoint v by far less than one unit of the precision claims are read at.
std::string nudged(const mpfr_real& v, int shift, int sign) {
  scoped_digits sd(digits10_for_bits(unsigned(shift) + 64));
  mpfr_real w = v;
  w += sign * ldexp(mpfr_real(1), -shift);
  return format_scientific(w, digits10_for_bits(unsigned(shift) + 64) + 10, sign > 0 ? MPFR_RNDU : MPFR_RNDD);
}

TEST_CASE("claims are compared exactly: a bound inside the checker's enclosure by a hair is refused",
          "[certificate]") {
  resonant_pair<big_int> p{big_int(6), big_int(5)};
  const auto good = certify_pair(p, 20);
  REQUIRE(check_certificate(good).holds);
  scoped_digits sd(digits10_for_bits(good.working_bits));
  const auto loc = proof::enclose_minimisers(p, proof::constants_of(p));
  // 2^-(bits + 100) is far below one unit at the checker's parse precision (bits + 64): rounding
  // the claim outward there would put the bound back onto the enclosure and accept it.
  const int shift = int(good.working_bits) + 100;
  certificate lo_up = good, hi_down = good;
  lo_up.r_res.first = nudged(interval_lower(loc.r), shift, +1);
  hi_down.r_res.second = nudged(interval_upper(loc.r), shift, -1);
  for (const auto* c : {&lo_up, &hi_down}) {
    auto v = check_certificate(*c);
    CHECK_FALSE(v.holds);
    CHECK(v.failure.find("claim r_res") == 0);
  }
  // The exact endpoints themselves are accepted (as long as the digits are met).
  certificate exact = good;
  exact.r_res = {nudged(interval_lower(loc.r), shift, -1), nudged(interval_upper(loc.r), shift, +1)};
  exact.digits = 15;
  auto v = check_certificate(exact);
  INFO(v.failure);
  CHECK(v.holds);
}

TEST_CASE("without global minimality only [0, hi] may be claimed for r_res", "[certificate]") {
  // (6, 1) with covers capped below its order and node count: not proved, r_res <= hi only.
  resonant_pair<big_int> p{big_int(6), big_int(1)};
  certify_options capped;
  capped.max_lobes = 3;
  capped.max_nodes = 1;
  const auto c = certify_pair(p, 20, capped);
  REQUIRE_FALSE(c.global_minimality);
  REQUIRE(c.r_res.first == "0");
  REQUIRE(check_certificate(c).holds);
  for (const char* lo : {"0.04", "1e-300", "0.0", "-0"}) {
    INFO(lo);
    certificate t = c;
    t.r_res.first = lo;
    auto v = check_certificate(t);
    CHECK_FALSE(v.holds);
    CHECK(v.failure.find("lower end must be 0") != std::string::npos);
  }
  certificate below = c;
  below.r_res.second = shift_last_digit(c.r_res.second, -1);
  CHECK_FALSE(check_certificate(below).holds);
}

TEST_CASE("certificate JSON: the text reads back to the same certificate; malformed text is a usage_error",
          "[certificate]") {
  for (auto [t, s] : {std::pair<const char*, const char*>{"6", "5"}, {"11", "9"}, {"1000004", "3"},
                      {"1000000000000000000000000000001", "1000000000000000000000000000000"}}) {
    resonant_pair<big_int> p{big_int(t), big_int(s)};
    INFO(p.str());
    const auto c = certify_pair(p, 20);
    const std::string text = json_dump(certificate_to_json(c));
    const auto back = certificate_from_text(text);
    CHECK(json_dump(certificate_to_json(back)) == text);
    CHECK(back.tau == c.tau);
    CHECK(back.sigma == c.sigma);
    CHECK(back.r_res == c.r_res);
    CHECK(back.theta_first == c.theta_first);
    CHECK(back.obligations.size() == c.obligations.size());
    CHECK(check_certificate(back).holds);
  }
  const std::string good = json_dump(certificate_to_json(certify_pair(resonant_pair<big_int>(6, 5), 10)));
  auto without = [&](const std::string& key) {
    auto j = nlohmann::json::parse(good);
    j.erase(key);
    return j.dump();
  };
  CHECK_THROWS_AS(certificate_from_text("not json"), usage_error);
  CHECK_THROWS_AS(certificate_from_text(good.substr(0, good.size() / 2)), usage_error);
  for (const char* key : {"format", "tau", "digits", "claims", "minimiser_count", "obligations"})
    CHECK_THROWS_AS(certificate_from_text(without(key)), usage_error);
  auto j = nlohmann::json::parse(good);
  j["tau"] = "6";
  CHECK_THROWS_AS(certificate_from_text(j.dump()), usage_error);
  j = nlohmann::json::parse(good);
  j["claims"]["r_res"] = nlohmann::json::array({"1"});
  CHECK_THROWS_AS(certificate_from_text(j.dump()), usage_error);
}

TEST_CASE("the proof steps used by the proofs: basins by lobe and the cover with bound 0", "[certificate]") {
  // (7, 3): delta = 4, R > 0 everywhere (proofs/verify_degenerate.cpp, P3.positive).
  resonant_pair<big_int> p(7, 3);
  scoped_digits sd(digits10_for_bits(72));
  auto K = proof::constants_of(p);
  certify_options any;
  any.max_lobes = any.max_nodes = std::numeric_limits<std::int64_t>::max();
  auto all = proof::run_cover(K, {}, interval_point(mpfr_real(0)), any, "all-lobes", "");
  CHECK(all.proved);
  CHECK(all.strategy == "all-lobes");
  CHECK(all.stats.lobes == 10u);
  // A bound above r_res^2 cannot be proved without basins.
  auto c = certify_pair(p, 10);
  auto hi = interval_from_decimal(c.r_res.second, c.r_res.second);
  auto fails = proof::run_cover(K, {}, interval_sqr(hi), any, "all-lobes", "");
  CHECK_FALSE(fails.proved);
  CHECK(fails.note.find("not proved") == 0);
  CHECK_FALSE(proof::run_cover(K, {}, interval_point(mpfr_real(0)), any, "no-such", "").proved);
  CHECK(proof::run_cover(K, {}, interval_point(mpfr_real(0)), any, "slow-nodes", "").proved);  // x = 0.4 < 1/2
  auto K51 = proof::constants_of(resonant_pair<big_int>(5, 1));  // x = 2/3: no slow-nodes cover
  auto slow = proof::run_cover(K51, {}, interval_point(mpfr_real(0)), any, "slow-nodes", "");
  CHECK_FALSE(slow.proved);
  CHECK(slow.note == "slow-nodes cover needs x < 1/2");
  CHECK(proof::run_cover(K51, {}, interval_point(mpfr_real(0)), any, "", "").strategy == "all-lobes");
  // Basins: one entry per image lobe k mod a, mirrored images negated.
  auto imgs = proof::images_of(K, big_int(3), big_int(1), true);
  auto basins = proof::basins_by_lobe(K, imgs, interval_of(mpfr_real("0.1"), mpfr_real("0.2")));
  std::size_t n = 0;
  for (auto& [k, ys] : basins) {
    CHECK(k >= 0);
    CHECK(k < K.a);
    n += ys.size();
  }
  CHECK(n == imgs.size());
}
