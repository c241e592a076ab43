// Certified sweeps (sweep/certified.hpp, `gyrores sweep --certified`): the exact R(pi/2) against
// the paper's naive forms, the proved enclosures against the independent high-precision
// references, the certified checks against the floating-point ones, and the checks failing when
// the lattice values they vouch for are wrong.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>

#include <gyrores/io/sweep_files.hpp>
#include <gyrores/io/sweep_merge.hpp>
#include <gyrores/io/sweep_summary.hpp>
#include <gyrores/model/enumerate.hpp>

#include "testing/cli_run.hpp"
#include "testing/high_precision_reference.hpp"
#include "testing/naive_forms.hpp"

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

TEST_CASE("certified sweep: the proved enclosures hold the independent high-precision references",
          "[sweep][certified]") {
  std::vector<resonant_pair<std::int64_t>> pairs;
  for (auto p : coprime_pairs(3, 30)) pairs.push_back(p);
  for (auto [t, s] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {1000, 1}, {19999, 2}, {30001, 10000}, {1000001, 1000000}, {999999, 4}, {1000003, 1}})
    pairs.emplace_back(t, s);
  for (const auto& p : pairs) {
    INFO(p.str());
    const auto pr = sweep_prove_pair(p, true);
    REQUIRE(pr.enclosed);
    REQUIRE(pr.note.empty());
    scoped_digits sd(40);
    const auto ref = test::hp::hp_reference(to_big(p.tau()), to_big(p.sigma()), 30);
    CHECK(mpfr_real(pr.r_lo) <= ref.r_res);
    CHECK(ref.r_res <= mpfr_real(pr.r_hi));
    CHECK(mpfr_real(pr.theta_lo) <= ref.theta_first);
    CHECK(ref.theta_first <= mpfr_real(pr.theta_hi));
    if (p.delta_mod4() == 2) {
      CHECK(pr.r_hi == 0);
    } else {
      CHECK(pr.r_hi - pr.r_lo <= std::ldexp(pr.r_lo, -40));  // narrow, not merely true
      CHECK(pr.r_below_R_half_pi);
    }
    CHECK(pr.theta_hi - pr.theta_lo <= std::ldexp(pr.theta_lo, -40));
  }
}

TEST_CASE("certified sweep: the enclosure of the paper's error holds the high-precision error", "[sweep][certified]") {
  // theta_c by the independent reference, theta_asy from u + tan u = s at high precision.
  for (auto [tau, sigma] : std::vector<std::pair<std::int64_t, std::int64_t>>{
           {6, 5}, {30, 29}, {150, 149}, {9, 4}, {13, 7}, {101, 60}, {1000, 999}, {5001, 4000}, {1000001, 1000000}}) {
    const resonant_pair<std::int64_t> p(tau, sigma);
    INFO(p.str());
    const std::int64_t a = std::int64_t(p.order()), b = p.delta();
    REQUIRE(2 * b < a);
    const auto pr = sweep_prove_pair(p, true);
    REQUIRE(pr.asy_enclosed);
    const std::int64_t twob = 2 * b, rem = a % twob;
    const std::int64_t k = rem == b ? (a - b) / twob : (a + b) / twob;
    const auto c = test::hp::hp_lobe_root(to_big(tau), to_big(sigma), to_big(k), 40);
    scoped_digits sd(bits_to_digits10(c.bits));
    const mpfr_real pi = real_pi<mpfr_real>(), A = mpfr_real(a);
    const mpfr_real s = pi * mpfr_real(a - 2 * k * b) / mpfr_real(twob);
    const mpfr_real ua = s < 0 ? mpfr_real(-u_plus_tan_root_hp(-s)) : u_plus_tan_root_hp(s);
    const mpfr_real theta_asy = 2 * (pi * mpfr_real(k) + ua) / A;
    const mpfr_real x = mpfr_real(b) / A;
    const mpfr_real ratio = abs(c.theta - theta_asy) / (pi * pi * pi * x * x / A);
    CHECK(mpfr_real(pr.asy_ratio_lo) <= ratio);
    CHECK(ratio <= mpfr_real(pr.asy_ratio_hi));
    // Narrow, not merely true: the second-order mean-value enclosure is tight to O(D^2),
    // D = tan u_a - arctan(x tan u_a)/x ~ x^2 tan^3 u_a/3.
    const double x2 = double(b) * double(b) / (double(a) * double(a));
    CHECK(pr.asy_ratio_hi - pr.asy_ratio_lo <= (1e-12 + x2 * x2) * pr.asy_ratio_hi);
    CHECK(pr.asy_ratio_hi < 0.0554);  // Lemma 7.1's sharper constant (docs/mathematics.md, P7)
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

TEST_CASE("certified sweep: structure fails when the lattice values are not the proved ones", "[sweep][certified]") {
  const sweep_config cfg = certified_config(100);
  for (auto [t, s] : std::vector<std::pair<std::int64_t, std::int64_t>>{{6, 5}, {5, 1}, {9, 4}, {7, 5}}) {
    const resonant_pair<std::int64_t> p(t, s);
    INFO(p.str());
    const auto good = inscribed_lattice<double>(p, 1.0);
    auto status = [&](const inscribed_result<double>& lr) {
      auto r = detail::sweep_row_of<double>(p);
      detail::sweep_check_certified(r, p, lr, cfg);
      return r.status[int(sweep_check::structure)];
    };
    CHECK(status(good) == sweep_status::pass);
    auto bad = good;
    bad.r_res = good.r_res == 0 ? 1e-300 : good.r_res * (1 + 1e-11);
    CHECK(status(bad) == sweep_status::fail);
    bad = good;
    bad.theta_first = good.theta_first * (1 - 1e-11);
    CHECK(status(bad) == sweep_status::fail);
    bad = good;
    bad.minimisers.pop_back();
    CHECK(status(bad) == sweep_status::fail);
  }
}

TEST_CASE("certified sweep: shards merge to the single run, and the summary keeps what is proved", "[sweep][certified]") {
  test::temp_dir d("test_sweep_certified");
  const std::int64_t M = 50;
  sweep_files single;
  single.summary_path = d / "single.json";
  REQUIRE(sweep_to_files<double>(certified_config(M), single, engine(2)).complete);
  const json want = sweep_summary_core(json::parse(test::read_text(single.summary_path)));
  CHECK(want.at("proved").size() == 3);
  std::vector<std::string> rows;
  for (int i = 0; i < 3; ++i) {
    sweep_config c = certified_config(M);
    c.shard_index = i;
    c.shard_count = 3;
    sweep_files f;
    f.rows_path = d / ("shard" + std::to_string(i) + ".csv");
    REQUIRE(sweep_to_files<double>(c, f, engine(1)).complete);
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
  REQUIRE(sweep_to_files<double>(c, f, engine(1)).complete);
  CHECK_THROWS_AS(sweep_merge({rows[0], rows[1], f.rows_path}), usage_error);
}
