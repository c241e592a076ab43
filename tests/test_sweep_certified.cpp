// Certified sweeps (sweep/certified.hpp, `gyrores sweep --certified`): the exact R(pi/2) against
// the paper's naive forms, the proved enclosures against the independent high-precision
// references, the certified checks against the floating-point ones, the structure check failing
// on wrong integers, and certified rows taking their values from the enclosures.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <numeric>

#include <gyrores/app/sweep.hpp>
#include <gyrores/io/sweep_files.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/model/enumerate.hpp>

#include "testing/cli_run.hpp"
#include "testing/high_precision_reference.hpp"
#include "testing/naive_forms.hpp"
#include "sweep_summary_core.hpp"
#include "testing/test_support.hpp"

using namespace gyrores;

namespace {

sweep_config certified_config(std::int64_t max_order) {
  sweep_config c;
  c.max_order = max_order;
  c.certified = true;
  return c;
}

sweep_engine_options engine(unsigned threads) {
  sweep_engine_options e;
  e.threads = threads;
  e.block_size = 16;
  return e;
}

sweep_accumulator run_acc(const sweep_config& c) {
  sweep_accumulator acc;
  acc.max_examples = c.max_examples;
  REQUIRE(sweep_run<double>(c, engine(2), [&](sweep_block& b) { acc.merge(b.summary); }).complete);
  return acc;
}

// u_a: the root of u + tan u = s in (0, pi/2), by Newton in MPFR at the current precision.
mpfr_real u_plus_tan_root_hp(const mpfr_real& s) {
  mpfr_real u = s / 2;
  for (int i = 0; i < 200; ++i) {
    mpfr_real t = tan(u), step = (u + t - s) / (2 + t * t);
    u -= step;
    if (abs(step) < abs(u) * pow(mpfr_real(2), -int(mpfr_real::default_precision() * 3)) || step == 0) break;
  }
  return u;
}

}  // namespace

TEST_CASE("certified sweep: 4 a^2 R(pi/2) is the naive forms' R(pi/2), and 0 exactly iff delta = 2 mod 4",
          "[sweep][certified]") {
  scoped_digits sd(50);
  const mpfr_real half_pi = real_pi<mpfr_real>() / 2;
  int zeros = 0;
  for (auto p : coprime_pairs(3, 120)) {
    const std::int64_t a = std::int64_t(p.order()), b = p.delta();
    const int128 N = sweep_quarter_R_scaled(a, b);
    test::naive_forms<mpfr_real> f{mpfr_real(p.tau()), mpfr_real(p.sigma())};
    const mpfr_real R = f.R(half_pi);
    INFO(p.str());
    CHECK(abs(mpfr_real(to_big(N)) / (4 * mpfr_real(a) * mpfr_real(a)) - R) < mpfr_real("1e-40"));
    CHECK((N == 0) == (p.delta_mod4() == 2));
    zeros += N == 0;
  }
  CHECK(zeros > 100);
  // Orders near 2^40 stay exact (int128): (2^39 + 1, 2^39 - 1), delta = 2.
  CHECK(sweep_quarter_R_scaled((std::int64_t(1) << 40), 2) == 0);
  CHECK(sweep_quarter_R_scaled((std::int64_t(1) << 40) + 1, 1) > 0);
}

namespace {

// lo <= v <= hi for an enclosure X = [lo, hi] and a reference value v.
bool holds(const fixed_mpfi& X, const mpfr_real& v) {
  return mpfr_cmp(X.left(), v.backend().data()) <= 0 && mpfr_cmp(v.backend().data(), X.right()) <= 0;
}

}  // namespace

TEST_CASE("certified sweep: the proved enclosures hold the independent high-precision references",
          "[sweep][certified]") {
  std::vector<resonant_pair<std::int64_t>> pairs;
  for (auto p : coprime_pairs(3, 30)) pairs.push_back(p);
  for (auto [t, s] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {1000, 1}, {19999, 2}, {30001, 10000}, {1000001, 1000000}, {999999, 4}, {1000003, 1}})
    pairs.emplace_back(t, s);
  for (unsigned bits : {53u, 161u}) {
    for (const auto& p : pairs) {
      INFO(p.str() << " at " << bits << " bits");
      sweep_proof_options opt;
      opt.bits = bits;
      opt.asy = true;
      const auto pr = sweep_prove_pair(p, opt);
      REQUIRE(pr.minimum);
      REQUIRE(pr.note.empty());
      const auto& M = *pr.minimum;
      const std::int64_t a = std::int64_t(p.order());
      const int extra = 2 * p.delta() < a ? 2 * int(std::bit_width(std::uint64_t(a))) + 8 : 0;
      CHECK(M.prec == mpfr_prec_t(bits) + 32 + extra);  // the first precision suffices
      scoped_digits sd(80);
      const auto ref = test::hp::hp_reference(to_big(p.tau()), to_big(p.sigma()), 60);
      CHECK(holds(M.theta_first, ref.theta_first));
      CHECK(holds(M.t_first, ref.t_first));
      const mpfr_real pi = real_pi<mpfr_real>(), proxy = pi * sqrt(mpfr_real(p.tau()) * mpfr_real(p.sigma())) / p.delta();
      CHECK(holds(M.t_min_paper, proxy));
      if (p.delta_mod4() == 2) {
        CHECK(mpfr_zero_p(M.r_res.left()));
        CHECK(mpfr_zero_p(M.r_res.right()));
      } else {
        CHECK(holds(M.r_res, ref.r_res));
        CHECK(holds(M.t_ratio, ref.t_first / proxy));
        CHECK(fixed_narrow(M.r_res, int(bits) + 8));  // narrow, not merely true
        CHECK(pr.r_below_R_half_pi);
      }
      CHECK(fixed_narrow(M.theta_first, int(bits) + 8));
    }
  }
}

TEST_CASE("certified sweep: the enclosure of the paper's error holds the high-precision error", "[sweep][certified]") {
  // theta_c by the independent reference, theta_asy from u + tan u = s at high precision.
  for (auto [tau, sigma] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {6, 5}, {30, 29}, {150, 149}, {9, 4}, {13, 7}, {101, 60}, {1000, 999}, {5001, 4000}, {1000001, 1000000},
           {5, 3}, {2, 1}, {1001, 500}}) {
    const resonant_pair<std::int64_t> p(tau, sigma);
    INFO(p.str());
    const std::int64_t a = std::int64_t(p.order()), b = p.delta();
    REQUIRE(2 * b < a);
    sweep_proof_options opt;
    opt.asy = true;
    const auto pr = sweep_prove_pair(p, opt);
    REQUIRE(pr.has_asy);
    REQUIRE(pr.asy);
    const auto& E = *pr.asy;
    const std::int64_t twob = 2 * b, rem = a % twob;
    const std::int64_t k = rem == b ? (a - b) / twob : (a + b) / twob;
    const auto c = test::hp::hp_lobe_root(to_big(tau), to_big(sigma), to_big(k), 40);
    scoped_digits sd(bits_to_digits10(c.bits));
    const mpfr_real pi = real_pi<mpfr_real>(), A = mpfr_real(a);
    const mpfr_real s = pi * mpfr_real(a - 2 * k * b) / mpfr_real(twob);
    const mpfr_real ua = s < 0 ? mpfr_real(-u_plus_tan_root_hp(-s)) : u_plus_tan_root_hp(s);
    const mpfr_real theta_asy = 2 * (pi * mpfr_real(k) + ua) / A;
    const mpfr_real x = mpfr_real(b) / A;
    const mpfr_real error = abs(c.theta - theta_asy), bound = pi * pi * pi * x * x / A;
    CHECK(holds(E.bound, bound));
    if (a - 2 * k * b == 0) {  // (5, 3): s = 0, u_a = u_c = 0 exactly
      CHECK(error < mpfr_real("1e-40"));
      CHECK(E.ratio.hi() == 0);
    } else {
      CHECK(holds(E.error, error));
      CHECK(holds(E.ratio, error / bound));
      CHECK(holds(E.constant, error * A / (x * x)));
      CHECK(fixed_narrow(E.ratio, 53 + 8));  // narrow, not merely true
    }
    CHECK(E.ratio.hi() < 0.0554);  // Lemma 7.1's sharper constant (docs/mathematics.md, P7)
    // The double row (Newton's method without cancellation, src/lib/sweep/evaluate.cpp) and the
    // certified row (upper bounds) agree with it.
    sweep_config cfg;
    cfg.max_order = a;
    const auto row = sweep_evaluate<double>(p, cfg);
    REQUIRE(row.has_asy);
    cfg.certified = true;
    const auto cert = sweep_evaluate<double>(p, cfg);
    CHECK(mpfr_real(cert.asy_bound) <= bound);
    if (a - 2 * k * b == 0) {
      CHECK(row.asy_ratio == 0);
      CHECK(cert.asy_ratio == 0);
      continue;
    }
    CHECK(abs(mpfr_real(row.asy_ratio) - error / bound) <= mpfr_real("1e-14") * (error / bound));
    CHECK(abs(mpfr_real(row.asy_error) - error) <= mpfr_real("1e-14") * error);
    CHECK(mpfr_real(cert.asy_ratio) >= error / bound);
    CHECK(mpfr_real(cert.asy_error) >= error);
    CHECK(cert.asy_ratio == Approx(row.asy_ratio).epsilon(1e-14));
  }
}

TEST_CASE("certified sweep: the checks agree with the floating-point sweep and every claim is proved",
          "[sweep][certified]") {
  const std::int64_t M = 80;
  sweep_config plain = certified_config(M);
  plain.certified = false;
  const auto want = run_acc(plain);
  const auto got = run_acc(certified_config(M));
  CHECK(got.pairs == want.pairs);
  CHECK(got.errors.violations == 0);
  for (int i = 0; i < sweep_check_count; ++i) {
    INFO(sweep_check_name(i));
    CHECK(got.checks[i].checked == want.checks[i].checked);
    CHECK(got.checks[i].violations == want.checks[i].violations);
    CHECK(got.checks[i].examples == want.checks[i].examples);
  }
  CHECK(got.checks[int(sweep_check::paper_node)].violations > 0);  // P5 is false: (6,1), (9,4), ...
  // The worst ratio is a proved upper bound of the floating-point one, at the same pair.
  CHECK(got.asy_ratio_max.pair == want.asy_ratio_max.pair);
  CHECK(got.asy_ratio_max.value >= want.asy_ratio_max.value * (1 - 1e-14));
  CHECK(got.asy_ratio_max.value == Approx(want.asy_ratio_max.value).epsilon(1e-8));
  CHECK(got.first_at_paper_node == want.first_at_paper_node);

  sweep_accumulator acc = got;
  json run = sweep_run_json<double>(certified_config(M));
  const json s = sweep_summary_json(acc, run, 0);
  CHECK(s.at("proved") == json({"degeneracy", "asy-bound", "structure"}));  // check order
  CHECK(s.at("theorem") == lattice_theorem_id);
  const std::string text = sweep_summary_text(s);
  CHECK(text.find("proved for every pair: degeneracy asy-bound structure") != std::string::npos);
  CHECK(text.find("paper-node fails for") != std::string::npos);
  // Uncertified runs say nothing of proofs, and are another run (no resume or merge across).
  CHECK_FALSE(sweep_run_json<double>(plain).contains("certified"));
  sweep_accumulator acc2 = want;
  CHECK_FALSE(sweep_summary_json(acc2, sweep_run_json<double>(plain), 0).contains("proved"));
}

TEST_CASE("certified sweep: structure fails when the theorem's integers are wrong", "[sweep][certified]") {
  for (auto [t, s] : std::vector<std::pair<std::int64_t, std::int64_t>>{{6, 5}, {5, 1}, {9, 4}, {7, 5}, {13, 1}}) {
    const resonant_pair<std::int64_t> p(t, s);
    INFO(p.str());
    const auto pr = sweep_prove_pair(p);
    const std::vector<lobe_frame<int128>> good = pr.lobes;
    auto holds_for = [&](const std::vector<lobe_frame<int128>>& lobes, int m_min) {
      return sweep_lobes_hold<int128>(p, m_min, lobes);
    };
    REQUIRE(holds_for(good, pr.m_min));
    CHECK(good.size() == (pr.m_min == 2 ? 4u : 2u));
    CHECK_FALSE(holds_for(good, (pr.m_min + 1) % 3));  // another m_min
    auto bad = good;
    bad.pop_back();  // a minimiser missing
    CHECK_FALSE(holds_for(bad, pr.m_min));
    bad = good;
    bad.push_back(good.front());  // one too many
    CHECK_FALSE(holds_for(bad, pr.m_min));
    bad = good;
    bad[0].k += 1;  // a frame that does not satisfy its equation
    CHECK_FALSE(holds_for(bad, pr.m_min));
    bad = good;
    std::swap(bad[0], bad[1]);  // out of theta order: the first minimiser is not first
    CHECK_FALSE(holds_for(bad, pr.m_min));
    bad = good;
    bad[0] = lobe_frame_of(int128(p.order()), int128(p.delta()), bad[0].k, bad[0].j + 1);  // |m| != m_min
    CHECK_FALSE(holds_for(bad, pr.m_min));
  }
}

TEST_CASE("certified sweep: rows take their values from the enclosures, no other solver", "[sweep][certified]") {
  sweep_config plain;
  plain.max_order = 200;
  sweep_config cert = plain;
  cert.certified = true;
  for (auto p : coprime_pairs(3, 200)) {
    INFO(p.str());
    const auto a = sweep_evaluate<double>(p, plain), b = sweep_evaluate<double>(p, cert);
    REQUIRE_FALSE(b.failed);
    CHECK(b.r_res == Approx(a.r_res).epsilon(4e-15));
    CHECK(b.theta_first == Approx(a.theta_first).epsilon(4e-16));
    CHECK(b.t_first == Approx(a.t_first).epsilon(4e-16));
    CHECK(b.t_min_paper == Approx(a.t_min_paper).epsilon(4e-16));
    CHECK(b.minimiser_count == a.minimiser_count);
    CHECK(b.status == a.status);
    // The values are the exact values rounded to double: every point of the enclosure, its
    // midpoint too, rounds to them.
    const auto pr = sweep_prove_pair(p);
    REQUIRE(pr.minimum);
    const auto& M = *pr.minimum;
    fixed_mpfr mid(M.prec);
    mpfi_mid(mid, M.theta_first);
    CHECK(mpfr_get_d(mid, MPFR_RNDN) == b.theta_first);
    mpfi_mid(mid, M.r_res);
    CHECK(mpfr_get_d(mid, MPFR_RNDN) == b.r_res);
  }
}

TEST_CASE("certified sweep: shards merge to the single run, and the summary keeps what is proved", "[sweep][certified]") {
  test::temp_dir d("test_sweep_certified");
  const std::int64_t M = 50;
  sweep_files single;
  single.summary_path = d / "single.json";
  REQUIRE(app::sweep_to_files<double>(certified_config(M), single, engine(2)).complete);
  const json want = sweep_summary_core(json::parse(test::read_text(single.summary_path)));
  CHECK(want.at("proved").size() == 3);
  std::vector<std::string> rows;
  for (int i = 0; i < 3; ++i) {
    const sweep_config c = shard_of(certified_config(M), i, 3);
    sweep_files f;
    f.rows_path = d / ("shard" + std::to_string(i) + ".csv");
    REQUIRE(app::sweep_to_files<double>(c, f, engine(1)).complete);
    rows.push_back(f.rows_path);
  }
  CHECK(sweep_summary_core(sweep_merge(rows)) == want);
  // An uncertified shard is another sweep: the merge refuses it.
  sweep_config c = certified_config(M);
  c.certified = false;
  c.shard_index = 2;
  c.shard_count = 3;
  sweep_files f;
  f.rows_path = d / "plain2.csv";
  REQUIRE(app::sweep_to_files<double>(c, f, engine(1)).complete);
  CHECK_THROWS_AS(sweep_merge({rows[0], rows[1], f.rows_path}), usage_error);
}
