// Mutation tests of the cover reference's proof steps (reference/mutation.hpp): with each fault switched on in turn,
// the checks below (the kinds test_certificate makes: honest certificates against an independent
// reference, and statements the steps must refuse) must fail somewhere. A fault that no check
// notices would be a proof step that the tests run without really testing.
#include <catch2/catch.hpp>

#include "reference/interval.hpp"

#include <string>
#include <vector>

#include "reference/certify.hpp"
#include "reference/check.hpp"
#include "reference/cover.hpp"
#include "reference/mutation.hpp"
#include "reference/proof_steps.hpp"
#include "testing/high_precision_reference.hpp"
#include "testing/naive_forms.hpp"

using namespace gyrores;
using proof::mutation;

namespace {

struct reference_case {
  resonant_pair<big_int> p;
  test::hp::hp_result ref;
};

// Computed once, before any mutation, by src/testing (the naive formulation, no proof steps).
const std::vector<reference_case>& references() {
  static const std::vector<reference_case> refs = [] {
    std::vector<reference_case> out;
    for (auto [t, s] : {std::pair{6, 5}, {9, 4}, {5, 1}, {7, 3}}) {
      resonant_pair<big_int> p{big_int(t), big_int(s)};
      out.push_back({p, test::hp::hp_reference(p.tau(), p.sigma(), 30)});
    }
    return out;
  }();
  return refs;
}

bool claim_holds(const std::pair<std::string, std::string>& claim, const mpfr_real& v) {
  scoped_digits sd(60);
  return !claim.first.empty() && decimal_interval_contains(claim.first, claim.second, interval_point(v));
}

// Honest certificates: proved, containing the reference values, with the reference's number of
// minimisers, and accepted by the checker. Appends what fails to `failed`.
void check_certificates(std::vector<std::string>& failed) {
  for (const auto& [p, ref] : references()) {
    const std::string name = p.str();
    try {
      const auto c = certify_pair(p, 20);
      if (!c.global_minimality) failed.push_back(name + ": not proved");
      if (!claim_holds(c.r_res, ref.r_res)) failed.push_back(name + ": r_res misses the reference");
      if (!claim_holds(c.theta_first, ref.theta_first)) failed.push_back(name + ": theta_first misses the reference");
      if (c.minimiser_count != ref.minimisers.size()) failed.push_back(name + ": minimiser count");
      if (!check_certificate(c).holds) failed.push_back(name + ": checker refuses");
    } catch (const std::exception& e) {
      failed.push_back(name + ": " + e.what());
    }
  }
}

// f = q'/(s v) in the minimiser's frame against the naive q'(theta) (src/testing/naive_forms.hpp)
// at points across the lobe: the same sign, and a ratio that does not depend on the point.
void check_frame_formula(std::vector<std::string>& failed) {
  const resonant_pair<big_int> p{big_int(6), big_int(5)};
  scoped_digits sd(30);
  const auto K = proof::constants_of(p);
  proof::minimiser_enclosures loc;
  {
    proof::scoped_mutation honest(mutation::none);
    loc = proof::enclose_minimisers(p, K);
  }
  const proof::I mu = proof::mu_of(K, loc.frame.m);
  const int s = int_mod(big_int(loc.frame.k + loc.frame.j), big_int(2)) == 0 ? 1 : -1;
  const test::naive_forms<mpfr_real> naive(mpfr_real(6), mpfr_real(5));
  std::vector<mpfr_real> ratios;
  for (const char* u : {"-1.2", "-0.6", "0.3", "0.9", "1.4"}) {
    const proof::I U = interval_point(mpfr_real(u));
    const mpfr_real f = s * interval_mid_point(proof::f_of(K, mu, U));
    const mpfr_real qd = naive.qdot(interval_mid_point(proof::theta_of(K, loc.frame.k, U)));
    if ((f > 0) != (qd > 0)) failed.push_back(std::string("f has the wrong sign at u = ") + u);
    ratios.push_back(f / qd);
  }
  for (const auto& r : ratios)
    if (abs(r / ratios.front() - 1) > mpfr_real("1e-20")) failed.push_back("f is not proportional to the naive q'");
}

// Statements the steps must refuse, for (6, 5) in the minimiser's frame: a cover of R > bound with
// the bound above the minimum and no basin cut out; a basin away from the root (no sign change
// of q'); interval Newton on a small box without a root.
void check_refusals(std::vector<std::string>& failed) {
  const resonant_pair<big_int> p{big_int(6), big_int(5)};
  scoped_digits sd(30);
  const auto K = proof::constants_of(p);
  proof::minimiser_enclosures loc;
  {
    proof::scoped_mutation honest(mutation::none);  // the enclosures themselves are not under test here
    loc = proof::enclose_minimisers(p, K);
  }
  const proof::I bound = interval_point(interval_upper(interval_sqr(loc.r)) * (1 + ldexp(mpfr_real(1), -20)));
  if (proof::run_cover(K, {}, bound, certify_options{}, "", "").proved)
    failed.push_back("cover proved R > bound above the minimum");
  const proof::I mu = proof::mu_of(K, loc.frame.m);
  const mpfr_real far = interval_upper(loc.X) + mpfr_real("0.1");
  if (proof::certify_basin(K, mu, interval_of(far, mpfr_real(far + mpfr_real("0.1")))))
    failed.push_back("basin accepted without the root");
  if (proof::certify_root(K, mu, far, mpfr_real("1e-3")))
    failed.push_back("interval Newton proved a root where there is none");
}

std::vector<std::string> failures() {
  std::vector<std::string> failed;
  check_certificates(failed);
  check_frame_formula(failed);
  check_refusals(failed);
  return failed;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : "; ") + x;
  return s;
}

}  // namespace

TEST_CASE("without a mutation every check passes", "[mutation]") {
  REQUIRE(proof::active_mutation() == mutation::none);
  const auto failed = failures();
  INFO(joined(failed));
  CHECK(failed.empty());
}

TEST_CASE("every mutated proof step is caught", "[mutation]") {
  references();  // before any mutation
  for (auto [m, name] : {std::pair{mutation::root_always, "root_always"}, {mutation::root_never, "root_never"},
                         {mutation::basin_always, "basin_always"}, {mutation::basin_never, "basin_never"},
                         {mutation::exclude_always, "exclude_always"}, {mutation::exclude_never, "exclude_never"},
                         {mutation::theta_off_by_one, "theta_off_by_one"}, {mutation::f_sign_flip, "f_sign_flip"},
                         {mutation::images_no_mirror, "images_no_mirror"}}) {
    proof::scoped_mutation on(m);
    const auto failed = failures();
    INFO(name << " caught by: " << joined(failed));
    CHECK_FALSE(failed.empty());
  }
  CHECK(proof::active_mutation() == mutation::none);
}
